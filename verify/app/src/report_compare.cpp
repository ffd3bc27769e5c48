#include <simpson/verify/report_compare.hpp>

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace simpson::verify {
namespace {

const std::set<std::string>& residual_keys() {
  static const std::set<std::string> keys{"max_residual", "bound_at_that_sample", "max_residual_over_bound"};
  return keys;
}

const std::set<std::string>& ignored_keys() {
  static const std::set<std::string> keys{"environment"};
  return keys;
}

std::string shown(const json& v) {
  const std::string text = v.dump();
  return text.size() > 120 ? text.substr(0, 117) + "..." : text;
}

/// Walks two values in step; `where` names the place for the report's reader.
void walk(const json& a, const json& b, const std::string& where, std::vector<std::string>& out) {
  if (a.is_object() && b.is_object()) {
    for (const auto& [key, value] : a.items()) {
      if (ignored_keys().count(key)) continue;
      const std::string at = where.empty() ? key : where + "." + key;
      if (!b.contains(key)) {
        out.push_back(at + ": only in the old report");
      } else if (residual_keys().count(key)) {
        continue;  // compared through within_bound
      } else {
        walk(value, b.at(key), at, out);
      }
    }
    for (const auto& [key, value] : b.items()) {
      if (!ignored_keys().count(key) && !a.contains(key)) out.push_back((where.empty() ? key : where + "." + key) + ": only in the new report");
    }
    return;
  }
  if (a.is_array() && b.is_array()) {
    if (a.size() != b.size()) {
      out.push_back(where + ": " + std::to_string(a.size()) + " entries → " + std::to_string(b.size()));
      return;
    }
    for (std::size_t k = 0; k < a.size(); ++k) walk(a[k], b[k], where + "[" + std::to_string(k) + "]", out);
    return;
  }
  if (a != b) out.push_back(where + ": " + shown(a) + " → " + shown(b));
}

/// "claims[3].evidence.x" → "claim <id>: evidence.x"; "experiments.table1.entries[2].ours" →
/// "section table1, entries row 2, column ours".
void compare_claims(const json& a, const json& b, std::vector<std::string>& out, bool subset = false) {
  std::map<std::string, const json*> old_claims;
  for (const json& c : a) old_claims[c.value("id", "")] = &c;
  std::set<std::string> seen;
  for (const json& c : b) {
    const std::string id = c.value("id", "");
    seen.insert(id);
    const auto it = old_claims.find(id);
    if (it == old_claims.end()) {
      out.push_back("claim " + id + ": only in the new report (verdict " + c.value("verdict", "?") + ")");
      continue;
    }
    std::vector<std::string> lines;
    walk(*it->second, c, "", lines);
    for (const std::string& line : lines) out.push_back("claim " + id + ": " + line);
  }
  for (const auto& [id, c] : old_claims) {
    if (!subset && !seen.count(id)) out.push_back("claim " + id + ": only in the old report (verdict " + c->value("verdict", "?") + ")");
  }
}

void compare_sections(const json& a, const json& b, std::vector<std::string>& out, bool subset = false) {
  for (const auto& [name, section] : a.items()) {
    if (subset && !b.contains(name)) continue;
    if (!b.contains(name)) {
      out.push_back("section " + name + ": only in the old report");
      continue;
    }
    const json& other = b.at(name);
    for (const auto& [table, rows] : section.items()) {
      if (!other.contains(table)) {
        out.push_back("section " + name + ", " + table + ": only in the old report");
        continue;
      }
      if (rows.is_array() && other.at(table).is_array() && rows.size() == other.at(table).size()) {
        for (std::size_t k = 0; k < rows.size(); ++k) {
          if (!rows[k].is_object() || !other.at(table)[k].is_object()) {
            walk(rows[k], other.at(table)[k], "section " + name + ", " + table + " row " + std::to_string(k), out);
            continue;
          }
          for (const auto& [column, value] : rows[k].items()) {
            if (ignored_keys().count(column)) continue;
            const std::string at = "section " + name + ", " + table + " row " + std::to_string(k) + ", column " + column;
            if (!other.at(table)[k].contains(column)) out.push_back(at + ": only in the old report");
            else walk(value, other.at(table)[k].at(column), at, out);
          }
        }
      } else {
        walk(rows, other.at(table), "section " + name + ", " + table, out);
      }
    }
  }
  for (const auto& [name, section] : b.items()) {
    if (!a.contains(name)) out.push_back("section " + name + ": only in the new report");
  }
}

}  // namespace

const std::vector<std::string>& comparison_tolerances() {
  static const std::vector<std::string> lines{
      "verdicts, expected verdicts, exact values, integers, words and flags: equal",
      "figures computed in floating point: equal to the digits printed",
      "numeric residuals (max_residual, bound_at_that_sample, max_residual_over_bound): digits may differ; within_bound must "
      "stay true",
      "run times (timing.json, not compared) and the environment (build, machine, timestamp, command line): ignored"};
  return lines;
}

std::vector<std::string> compare_reports(const json& a, const json& b) {
  std::vector<std::string> out;
  for (const auto& [key, value] : a.items()) {
    if (ignored_keys().count(key)) continue;
    if (!b.contains(key)) {
      out.push_back(key + ": only in the old report");
    } else if (key == "claims") {
      compare_claims(value, b.at(key), out);
    } else if (key == "experiments") {
      compare_sections(value, b.at(key), out);
    } else {
      walk(value, b.at(key), key, out);
    }
  }
  for (const auto& [key, value] : b.items()) {
    if (!ignored_keys().count(key) && !a.contains(key)) out.push_back(key + ": only in the new report");
  }
  return out;
}

std::vector<std::string> compare_report_subset(const json& a, const json& b) {
  std::vector<std::string> out;
  for (const char* key : {"schema_version", "tool", "scene", "paper", "seed", "samples", "precisions"}) {
    if (a.contains(key) != b.contains(key)) {
      out.push_back(std::string(key) + (a.contains(key) ? ": only in the old report" : ": only in the new report"));
    } else if (a.contains(key)) {
      walk(a.at(key), b.at(key), key, out);
    }
  }
  compare_claims(a.value("claims", json::array()), b.value("claims", json::array()), out, true);
  compare_sections(a.value("experiments", json::object()), b.value("experiments", json::object()), out, true);
  return out;
}

json load_report(const std::filesystem::path& given) {
  const std::filesystem::path file = std::filesystem::is_directory(given) ? given / "report.json" : given;
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::invalid_argument("compare: '" + given.string() + "': no report.json there");
  std::ostringstream text;
  text << in.rdbuf();
  json report;
  try {
    report = json::parse(text.str());
  } catch (const json::parse_error& e) {
    throw std::invalid_argument("compare: '" + file.string() + "': malformed JSON (" + std::string(e.what()) + ")");
  }
  if (!report.is_object() || report.value("tool", "") != "simpson-verify" || !report.contains("claims")) {
    throw std::invalid_argument("compare: '" + file.string() + "': not a simpson-verify report");
  }
  return report;
}

}  // namespace simpson::verify

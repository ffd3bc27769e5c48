#include <simpson/verify/report_compare.hpp>

#include <simpson/precision.hpp>
#include <simpson/verify/report_html.hpp>
#include <simpson/verify/utf8_text.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

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

std::string text_of_value(const json& v) { return v.dump(-1, ' ', false, json::error_handler_t::replace); }

/// A value as the reader needs it: whole up to 120 bytes; longer, cut at character boundaries
/// around `from`, where it differs from the value it is compared with ("..." where cut).
std::string shown(const json& v, std::size_t from = 0) { return utf8_around(text_of_value(v), from, 120); }

/// Two values that differ, each shown around where they differ.
std::string old_and_new(const json& a, const json& b) {
  const std::size_t at = utf8_first_difference(text_of_value(a), text_of_value(b));
  return shown(a, at) + " → " + shown(b, at);
}

/// Within round-off of a row's precision: 1024 ε. A formula that changes moves a figure far more.
constexpr double roundoff_units = 1024;

/// The unit round-off of the precision a row names ("precision": "double", or "epsilon": "2.22e-16"),
/// or nothing (an exact row, or none named).
std::optional<double> row_epsilon(const json& row) {
  try {
    if (row.contains("epsilon") && row.at("epsilon").is_string()) {
      const double e = std::stod(row.at("epsilon").get<std::string>());
      if (e > 0) return e;
    }
    if (row.contains("precision") && row.at("precision").is_string()) {
      const std::string e = simpson::precision::parse(row.at("precision").get<std::string>()).epsilon();
      const double v = std::stod(e);
      if (v > 0) return v;
    }
  } catch (const std::exception&) {
    // not a precision of ours: no round-off rule for this row
  }
  return std::nullopt;
}

/// A figure's value: a JSON number, or a decimal string ("-1.11e-16"); nothing for anything else.
std::optional<double> figure_value(const json& v) {
  if (v.is_number()) return v.get<double>();
  if (!v.is_string()) return std::nullopt;
  const std::string text = v.get<std::string>();
  std::size_t used = 0;
  try {
    const double x = std::stod(text, &used);
    if (used == text.size()) return x;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

/// Walks two values in step; `where` names the place for the report's reader; `epsilon` is the
/// unit round-off of the row being walked, if it names one.
void walk(const json& a, const json& b, const std::string& where, std::vector<std::string>& out,
          std::optional<double> epsilon = std::nullopt) {
  if (a.is_object() && b.is_object()) {
    if (const std::optional<double> e = row_epsilon(a); e && row_epsilon(b) == e) epsilon = e;
    for (const auto& [key, value] : a.items()) {
      if (ignored_keys().count(key)) continue;
      const std::string at = where.empty() ? key : where + "." + key;
      if (!b.contains(key)) {
        out.push_back(at + ": only in the old report");
      } else if (residual_keys().count(key)) {
        continue;  // compared through within_bound
      } else {
        walk(value, b.at(key), at, out, epsilon);
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
    for (std::size_t k = 0; k < a.size(); ++k) walk(a[k], b[k], where + "[" + std::to_string(k) + "]", out, epsilon);
    return;
  }
  if (a == b) return;
  if (epsilon) {
    const std::optional<double> x = figure_value(a), y = figure_value(b);
    const double limit = roundoff_units * *epsilon;
    if (x && y && std::abs(*x) <= limit && std::abs(*y) <= limit) return;  // both at round-off level
  }
  out.push_back(where + ": " + old_and_new(a, b));
}

/// Whether a run measured no run time (--no-timing).
bool untimed(const json& report) { return report.value("overrides", json::object()).value("timing", true) == false; }

/// A claim's Coq evidence checked by coqc in one run and only exported in the other: the rest of it
/// is compared, the status and Coq version noted.
bool coq_checked_in_one_run(const json& a, const json& b) {
  const auto status = [](const json& c) -> std::string {
    if (!c.contains("evidence") || !c.at("evidence").contains("coq")) return "";
    return c.at("evidence").at("coq").value("status", "");
  };
  const std::string x = status(a), y = status(b);
  return (x == "checked" && y == "exported") || (x == "exported" && y == "checked");
}

json without_coq_check(json claim) {
  json& coq = claim["evidence"]["coq"];
  coq.erase("status");
  coq.erase("coq_version");
  return claim;
}

/// "claims[3].evidence.x" → "claim <id>: evidence.x"; "experiments.table1.entries[2].ours" →
/// "section table1, entries row 2, column ours".
void compare_claims(const json& a, const json& b, std::vector<std::string>& out, report_comparison& result, bool subset = false) {
  std::size_t coq_noted = 0;
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
    if (coq_checked_in_one_run(*it->second, c)) {
      ++coq_noted;
      walk(without_coq_check(*it->second), without_coq_check(c), "", lines);
    } else {
      walk(*it->second, c, "", lines);
    }
    for (const std::string& line : lines) out.push_back("claim " + id + ": " + line);
  }
  for (const auto& [id, c] : old_claims) {
    if (!subset && !seen.count(id)) out.push_back("claim " + id + ": only in the old report (verdict " + c->value("verdict", "?") + ")");
  }
  if (coq_noted > 0) {
    result.notes.push_back(std::to_string(coq_noted) + " claims' Coq certificates were checked by coqc in one run and only exported in the "
                           "other (--no-certify, or no coqc): their Coq status is not compared, the certificates' files and lemmas are");
  }
}

void compare_sections(const json& a, const json& b, std::vector<std::string>& out, bool subset = false, bool timing_differs = false) {
  for (const auto& [name, section] : a.items()) {
    if (subset && !b.contains(name)) continue;
    if (!b.contains(name)) {
      out.push_back("section " + name + ": only in the old report");
      continue;
    }
    const json& other = b.at(name);
    for (const auto& [table, rows] : section.items()) {
      if (timing_differs && table == "title") continue;  // a timed section says so in its title
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
          for (const auto& [column, value] : other.at(table)[k].items()) {
            if (!ignored_keys().count(column) && !rows[k].contains(column)) {
              out.push_back("section " + name + ", " + table + " row " + std::to_string(k) + ", column " + column + ": only in the new report");
            }
          }
        }
      } else {
        walk(rows, other.at(table), "section " + name + ", " + table, out);
      }
    }
    for (const auto& [table, rows] : other.items()) {
      if (!section.contains(table)) out.push_back("section " + name + ", " + table + ": only in the new report");
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
      "figures at round-off level, in a row that names its precision: equal when both are at most 1024 epsilon of it",
      "what one run chose not to compute (Coq checks with --no-certify or without coqc; timing with --no-timing): noted, "
      "not a difference",
      "the paper: by its SHA-256 (the same bytes named 'embedded' in one report and by a path in the other: a note)",
      "run times (timing.json, not compared) and the environment (build, machine, timestamp, command line): ignored"};
  return lines;
}

namespace {

/// What --no-timing leaves out of one report, taken out of both: the timing files, and the plots of
/// run times (each plot says whether it shows run times).
json without_timed_parts(json report) {
  report.erase("timing_files");
  if (report.contains("overrides")) report["overrides"].erase("timing");
  if (report.contains("plots") && report["plots"].is_array()) {
    json kept = json::array();
    for (const json& p : report["plots"]) {
      if (!p.value("run_times", false)) kept.push_back(p);
    }
    report["plots"] = kept;
  }
  return report;
}

}  // namespace

namespace {

/// `from` with every string equal to `name` replaced by `as` (the paper's name in a report).
void rename_strings(json& from, const std::string& name, const std::string& as) {
  if (from.is_string()) {
    if (from.get<std::string>() == name) from = as;
  } else if (from.is_structured()) {
    for (json& item : from) rename_strings(item, name, as);
  }
}

/// The paper is compared by its SHA-256: the same bytes under another name (embedded, or the path
/// given with --paper) are one paper, and its name is a note, not a difference on every claim. Other
/// bytes are another document: one note says so, and its name is not a difference either (every
/// claim that read it names it): what its text changed is.
void paper_by_digest(json& a, json& b, report_comparison& result) {
  const auto digest = [](const json& r) { return r.value("environment", json::object()).value("paper_sha256", std::string()); };
  const json old_name = a.value("paper", json()), new_name = b.value("paper", json());
  const bool renamed = old_name.is_string() && new_name.is_string() && old_name != new_name;
  if (!digest(a).empty() && digest(a) == digest(b)) {
    if (renamed) {
      result.notes.push_back(fmt::format("the same paper (SHA-256 {}...) is '{}' in the old report and '{}' in the new one: compared as one",
                                         digest(a).substr(0, 12), old_name.get<std::string>(), new_name.get<std::string>()));
    }
  } else if (!digest(a).empty() && !digest(b).empty()) {
    result.notes.push_back(fmt::format("the documents differ: '{}' (SHA-256 {}...) in the old report, '{}' (SHA-256 {}...) in the new one; the "
                                       "differences below are what the new text changed",
                                       old_name.is_string() ? old_name.get<std::string>() : "?", digest(a).substr(0, 12),
                                       new_name.is_string() ? new_name.get<std::string>() : "?", digest(b).substr(0, 12)));
    for (json* r : {&a, &b}) {
      if (r->contains("provenance") && (*r)["provenance"].is_object()) (*r)["provenance"].erase("sha256");
    }
  }
  if (renamed) rename_strings(b, new_name.get<std::string>(), old_name.get<std::string>());
  for (json* r : {&a, &b}) {
    if (r->contains("overrides") && (*r)["overrides"].is_object()) (*r)["overrides"].erase("paper");
  }
}

/// What follows from the claims and the sections: the summary's counts and lines, the verdict table,
/// the earlier text's verdicts (provenance), all_as_expected and the list of files (a refuted certificate adds one).
bool derived_member(const std::string& place) {
  return place == "summary" || place == "verdicts" || place == "all_as_expected" || place == "provenance" || place == "files";
}

/// The unit a line "place: change" belongs to, and the change within it: "claim <id>", "section
/// <name>", or the report's member.
std::pair<std::string, std::string> unit_of(const std::string& line) {
  if (line.rfind("claim ", 0) == 0 || line.rfind("section ", 0) == 0) {
    const std::size_t colon = line.find(": "), comma = line.find(", ");
    const std::size_t cut = line.rfind("section ", 0) == 0 && comma != std::string::npos && comma < colon ? comma : colon;
    if (cut != std::string::npos) return {line.substr(0, cut), line.substr(cut + 2)};
  }
  const std::size_t cut = line.find_first_of(".[:");
  if (cut == std::string::npos) return {line, line};
  const std::size_t rest = line[cut] == ':' ? cut + 2 : cut + (line[cut] == '.' ? 1 : 0);
  return {line.substr(0, cut), line.substr(std::min(rest, line.size()))};
}

/// Lines grouped into one difference per unit, in the order first met; what follows from the
/// claims and the sections (derived_member) is one note when they differ.
void grouped(const std::vector<std::string>& lines, report_comparison& result) {
  std::vector<report_difference> units;
  for (const std::string& line : lines) {
    const std::pair<std::string, std::string> unit = unit_of(line);  // not a structured binding: the lambda below captures it
    const std::string &place = unit.first, &change = unit.second;
    auto it = std::find_if(units.begin(), units.end(), [&](const report_difference& d) { return d.place == place; });
    if (it == units.end()) {
      units.push_back({place, {}});
      it = units.end() - 1;
    }
    it->changes.push_back(change);
  }
  const bool primary = std::any_of(units.begin(), units.end(), [](const report_difference& d) { return !derived_member(d.place); });
  std::vector<std::string> derived;
  for (report_difference& d : units) {
    if (primary && derived_member(d.place)) {
      derived.push_back(fmt::format("{} ({} field{})", d.place, d.changes.size(), d.changes.size() == 1 ? "" : "s"));
      continue;
    }
    result.differences.push_back(std::move(d));
  }
  if (!derived.empty()) {
    std::string list;
    for (const std::string& d : derived) list += (list.empty() ? "" : ", ") + d;
    result.notes.push_back("what follows from the differences below also differs, as they make it: " + list);
  }
}

}  // namespace

std::vector<std::string> report_comparison::lines() const {
  std::vector<std::string> out;
  for (const report_difference& d : differences) {
    for (const std::string& change : d.changes) out.push_back(d.place + ": " + change);
  }
  return out;
}

bool is_selection(const json& report) {
  const json overrides = report.value("overrides", json::object());
  return overrides.is_object() && (overrides.contains("claims") || overrides.contains("sections"));
}

report_comparison compare_reports(const json& given_old, const json& given_new) {
  report_comparison result;
  json old_report = given_old, new_report = given_new;
  paper_by_digest(old_report, new_report, result);
  std::vector<std::string> out;
  const bool timing_differs = untimed(old_report) != untimed(new_report);
  const json a = timing_differs ? without_timed_parts(old_report) : old_report;
  const json b = timing_differs ? without_timed_parts(new_report) : new_report;
  if (timing_differs) {
    result.notes.push_back(std::string("the ") + (untimed(new_report) ? "new" : "old") +
                           " run measured no run time (--no-timing): timing files, plots of run times and the timed "
                           "section's title are not compared");
  }
  for (const auto& [key, value] : a.items()) {
    if (ignored_keys().count(key)) continue;
    if (!b.contains(key)) {
      out.push_back(key + ": only in the old report");
    } else if (key == "claims") {
      compare_claims(value, b.at(key), out, result);
    } else if (key == "experiments") {
      compare_sections(value, b.at(key), out, false, timing_differs);
    } else if (key == "summary") {
      json x = value, y = b.at(key);
      // Checked counts follow the Coq status: noted with it.
      if (x.value("coq_checked", 0) == 0 || y.value("coq_checked", 0) == 0) {
        x.erase("coq_checked");
        y.erase("coq_checked");
      }
      walk(x, y, key, out);
    } else {
      walk(value, b.at(key), key, out);
    }
  }
  for (const auto& [key, value] : b.items()) {
    if (!ignored_keys().count(key) && !a.contains(key)) out.push_back(key + ": only in the new report");
  }
  grouped(out, result);
  return result;
}

report_comparison compare_report_subset(const json& given_old, const json& given_new) {
  report_comparison result;
  json a = given_old, b = given_new;
  paper_by_digest(a, b, result);
  std::vector<std::string> out;
  for (const char* key : {"schema_version", "tool", "scene", "paper", "seed", "samples", "precisions"}) {
    if (a.contains(key) != b.contains(key)) {
      out.push_back(std::string(key) + (a.contains(key) ? ": only in the old report" : ": only in the new report"));
    } else if (a.contains(key)) {
      walk(a.at(key), b.at(key), key, out);
    }
  }
  const bool timing_differs = untimed(a) != untimed(b);
  compare_claims(a.value("claims", json::array()), b.value("claims", json::array()), out, result, true);
  compare_sections(a.value("experiments", json::object()), b.value("experiments", json::object()), out, true, timing_differs);
  grouped(out, result);
  return result;
}

std::string comparison_junit(const report_comparison& found, const std::string& old_name, const std::string& new_name) {
  std::string notes;
  for (const std::string& n : found.notes) notes += "note: " + n + "\n";
  const std::size_t tests = std::max<std::size_t>(1, found.differences.size());
  std::string xml = fmt::format("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"simpson-verify compare\" tests=\"{}\" failures=\"{}\">\n"
                                "  <testsuite name=\"compare\" tests=\"{}\" failures=\"{}\">\n"
                                "    <properties><property name=\"old\" value=\"{}\"/><property name=\"new\" value=\"{}\"/></properties>\n",
                                tests, found.differences.size(), tests, found.differences.size(), markup_escaped(old_name), markup_escaped(new_name));
  if (found.differences.empty()) {
    xml += fmt::format("    <testcase classname=\"compare\" name=\"the reports agree\"><system-out>{}</system-out></testcase>\n", markup_escaped(notes));
  }
  for (const report_difference& d : found.differences) {
    std::string body;
    for (const std::string& change : d.changes) body += change + "\n";
    xml += fmt::format("    <testcase classname=\"compare\" name=\"{}\"><failure type=\"difference\" message=\"{}\">{}</failure></testcase>\n",
                       markup_escaped(d.place), markup_escaped(d.changes.front()), markup_escaped(body));
  }
  if (!notes.empty()) xml += "    <system-out>" + markup_escaped(notes) + "</system-out>\n";
  return xml + "  </testsuite>\n</testsuites>\n";
}

json comparison_json(const report_comparison& found, const std::string& old_name, const std::string& new_name) {
  json differences = json::array();
  for (const report_difference& d : found.differences) differences.push_back({{"where", d.place}, {"what", d.changes}});
  return {{"old", old_name}, {"new", new_name}, {"agree", found.differences.empty()}, {"differences", differences}, {"notes", found.notes}};
}

json load_report(const std::filesystem::path& given, const std::string& who) {
  const std::filesystem::path file = std::filesystem::is_directory(given) ? given / "report.json" : given;
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::invalid_argument(who + ": '" + given.string() + "': no report.json there");
  std::ostringstream text;
  text << in.rdbuf();
  json report;
  try {
    report = json::parse(text.str());
  } catch (const json::parse_error& e) {
    throw std::invalid_argument(who + ": '" + file.string() + "': malformed JSON (" + std::string(e.what()) + ")");
  }
  if (!report.is_object() || report.value("tool", "") != "simpson-verify" || !report.contains("claims")) {
    throw std::invalid_argument(who + ": '" + file.string() + "': not a simpson-verify report");
  }
  return report;
}

}  // namespace simpson::verify

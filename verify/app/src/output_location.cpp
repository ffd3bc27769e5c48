#include <simpson/verify/output_location.hpp>

#include <simpson/verify/json.hpp>
#include <simpson/verify/sha256.hpp>

#include <fmt/format.h>

#include <fstream>
#include <set>
#include <stdexcept>

namespace simpson::verify {
namespace {

std::string joined(const json& names, const char* separator) {
  std::string out;
  for (const json& n : names) out += (out.empty() ? "" : separator) + n.get<std::string>();
  return out;
}

/// The experiment sections the run computes.
std::set<std::string> run_sections(const scene& s) {
  const std::vector<std::string> names = s.experiments.names();
  return std::set<std::string>(names.begin(), names.end());
}

std::string counted(std::size_t n, const char* noun) { return fmt::format("{} {}{}", n, noun, n == 1 ? "" : "s"); }

bool is_selection(const scene& s) { return s.overrides.contains("claims") || s.overrides.contains("sections"); }

/// The claims and sections of the report in `dir`, when it holds one.
std::optional<std::pair<std::set<std::string>, std::set<std::string>>> report_contents(const std::filesystem::path& dir) {
  std::ifstream in(dir / "report.json");
  if (!in) return std::nullopt;
  try {
    const json report = json::parse(in);
    std::set<std::string> claims, sections;
    for (const json& c : report.at("claims")) claims.insert(c.at("id").get<std::string>());
    for (const auto& [name, value] : report.at("experiments").items()) sections.insert(name);
    return std::make_pair(claims, sections);
  } catch (const json::exception&) {
    return std::nullopt;  // not a report this check can read: prepare_output_directory judges it
  }
}

}  // namespace

std::filesystem::path default_output_directory(const scene& s) {
  const std::filesystem::path base = "reports/out";
  if (!is_selection(s)) return base / s.name;
  std::string name = s.name;
  if (s.overrides.contains("claims")) {
    name += s.overrides["claims"].empty() ? "-no-claims" : "-claims-" + joined(s.overrides["claims"], "+");
  }
  if (s.overrides.contains("sections")) {
    // --claims alone runs no section: the name says so only when no claim runs either.
    const bool claims_run = s.overrides.contains("claims") && !s.overrides["claims"].empty();
    if (!s.overrides["sections"].empty()) name += "-sections-" + joined(s.overrides["sections"], "+");
    else if (!claims_run) name += "-no-sections";
  }
  if (name.size() > 80) name = s.name + "-selection-" + sha256_hex(name).substr(0, 12);
  return base / name;
}

std::filesystem::path output_directory(const scene& s, const std::optional<std::string>& given) {
  if (given && given->empty()) {
    throw std::invalid_argument("--out '': an empty directory name (an unset variable?); name the report directory, or leave "
                                "--out out for " + default_output_directory(s).string());
  }
  const std::filesystem::path dir = given ? std::filesystem::path(*given) : default_output_directory(s);
  if (!is_selection(s)) return dir;
  const auto held = report_contents(dir);
  if (!held) return dir;
  const std::set<std::string> claims(s.claims.begin(), s.claims.end()), sections = run_sections(s);
  std::size_t missing = 0;
  for (const std::string& id : held->first) missing += claims.count(id) == 0;
  for (const std::string& name : held->second) missing += sections.count(name) == 0;
  if (missing > 0) {
    throw std::invalid_argument(fmt::format(
        "--out '{}': holds a fuller report ({}, {}) that this selection ({}, {}) would replace; choose another --out "
        "(without --out, this selection writes {})",
        dir.string(), counted(held->first.size(), "claim"), counted(held->second.size(), "section"), counted(claims.size(), "claim"),
        counted(sections.size(), "section"), default_output_directory(s).string()));
  }
  return dir;
}

}  // namespace simpson::verify

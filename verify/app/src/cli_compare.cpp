// `simpson-verify compare` (cli_commands.hpp).

#include "cli_commands.hpp"

#include <simpson/verify/report_compare.hpp>

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <cstdio>
#include <set>
#include <string>

namespace simpson::verify {

/// `simpson-verify compare OLD NEW`: 0 when the reports agree, 1 on a difference (one line each), 2
/// on bad input.
int compare_report_directories(const cli_options& o) {
  const std::string& old_dir = o.compare_old;
  const std::string& new_dir = o.compare_new;
  const bool subset = o.compare_subset;
  const bool json_out = o.compare_format == "json";
  const bool quiet = o.quiet || json_out;
  json old_report, new_report;
  try {
    old_report = load_report(old_dir);
    new_report = load_report(new_dir);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "simpson-verify: %s\n", e.what());
    return 2;
  }
  // A selection against a fuller report compares only what both ran: that is --subset, or every
  // claim and section the selection left out is a difference.
  if (!subset && is_selection(new_report) && !is_selection(old_report)) {
    std::fprintf(stderr, "simpson-verify: compare: '%s' is a selection (--claims or --sections: %zu claims, %zu sections) and '%s' is a full run: "
                 "compare only what the selection ran with `simpson-verify compare --subset %s %s`\n",
                 new_dir.c_str(), new_report.value("claims", json::array()).size(), new_report.value("experiments", json::object()).size(),
                 old_dir.c_str(), old_dir.c_str(), new_dir.c_str());
    return 2;
  }
  if (subset) {
    // A selection against the fuller report, in that order: the other way round names the mistake.
    std::set<std::string> old_ids, new_ids;
    for (const json& c : old_report.value("claims", json::array())) old_ids.insert(c.value("id", ""));
    for (const json& c : new_report.value("claims", json::array())) new_ids.insert(c.value("id", ""));
    const bool new_has_more = std::includes(new_ids.begin(), new_ids.end(), old_ids.begin(), old_ids.end()) && new_ids.size() > old_ids.size();
    if (new_has_more) {
      std::fprintf(stderr, "simpson-verify: compare --subset OLD NEW: OLD ('%s', %zu claims) must be the fuller report (the reference) "
                   "and NEW ('%s', %zu claims) the selection; the two look swapped\n",
                   old_dir.c_str(), old_ids.size(), new_dir.c_str(), new_ids.size());
      return 2;
    }
  }
  const report_comparison found = subset ? compare_report_subset(old_report, new_report) : compare_reports(old_report, new_report);
  const std::vector<report_difference>& differences = found.differences;
  if (!quiet) {
    fmt::print("compare {} (old) with {} (new){}; tolerances:\n", old_dir, new_dir,
               subset ? fmt::format(", only the new report's {} claims and {} sections", new_report.value("claims", json::array()).size(),
                                    new_report.value("experiments", json::object()).size())
                      : std::string());
    for (const std::string& line : comparison_tolerances()) fmt::print("  - {}\n", line);
  }
  if (!o.compare_junit.empty()) {
    // Written whole or not at all: a temporary file beside it, renamed into place.
    const std::filesystem::path target(o.compare_junit), temporary = target.string() + ".partial";
    std::ofstream out(temporary, std::ios::binary);
    out << comparison_junit(found, old_dir, new_dir);
    out.close();
    std::error_code renamed;
    if (out) std::filesystem::rename(temporary, target, renamed);
    if (!out || renamed) {
      std::filesystem::remove(temporary, renamed);
      std::fprintf(stderr, "simpson-verify: compare --junit '%s': cannot be written\n", o.compare_junit.c_str());
      return 2;
    }
  }
  if (json_out) {
    fmt::print("{}\n", comparison_json(found, old_dir, new_dir).dump(2));
    return differences.empty() ? 0 : 1;
  }
  for (const std::string& line : found.notes) fmt::print("note: {}\n", line);
  for (const report_difference& d : differences) {
    fmt::print("{}: {}\n", d.place, d.changes.front());
    for (std::size_t k = 1; k < d.changes.size(); ++k) fmt::print("    {}\n", d.changes[k]);
  }
  fmt::print("{}\n", differences.empty() ? std::string("the reports agree")
                                          : fmt::format("{} {}", differences.size(), differences.size() == 1 ? "difference" : "differences"));
  return differences.empty() ? 0 : 1;
}

}  // namespace simpson::verify

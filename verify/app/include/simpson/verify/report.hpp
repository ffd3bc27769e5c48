#pragma once
// The report of a run: report.json (machine-readable) and report.md (for people), assembled from
// the run record, and the directory they are written to. Same scene and seed give byte-identical
// files apart from the "timing" members of report.json and the "environment" member.

#include <simpson/verify/report_directory.hpp>
#include <simpson/verify/run.hpp>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace simpson::verify {

json report_json(const run_record& r);
std::string report_markdown(const run_record& r);
/// One line: "48 claims: 42 held, 5 errata, 1 failed; all as expected".
std::string summary_line(const run_record& r);

/// Writes report.json, report.md, report.html, the sections' data files (CSV, .dat), the gnuplot
/// scripts (<plot>.gp) and the plots (SVG, PNG). Everything is made in a staging directory beside
/// `dir`, which then replaces `dir` whole (the previous report is removed only after the new one is
/// complete): no stale file of an earlier run survives, and an error or an interruption leaves the
/// previous report as it was and no partial files.
plot_outcome write_report_files(const std::filesystem::path& dir, const run_record& r);

/// Every file of the report directory, report.json first (its "files" member).
std::vector<std::string> report_file_names(const run_record& r, const plot_outcome& plots);

/// report.md with the outcome of the plots (a list of those not drawn, if any).
std::string report_markdown(const run_record& r, const plot_outcome& plots);
json report_json(const run_record& r, const plot_outcome& plots);

}  // namespace simpson::verify

#pragma once
// The report of a run: report.json (machine-readable, its JSON Schema in report.schema.json) and
// report.md (for people), assembled from the run record, and the directory they are written to.
// Run times are kept apart in timing.json and timing.md (and the files they link): for the same
// scene, seed and build every other file is byte-identical from run to run, apart from the
// timestamp and command line in report.json's "environment" (SOURCE_DATE_EPOCH fixes the first).

#include <simpson/verify/report_directory.hpp>
#include <simpson/verify/run.hpp>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace simpson::verify {

/// The version of report.json's layout, its member "schema_version" (verify/app/report.schema.json).
inline constexpr int report_schema_version = 3;

json report_json(const run_record& r);
std::string report_markdown(const run_record& r);
/// One line: "48 claims: 42 held, 5 errata, 1 failed; all as expected".
std::string summary_line(const run_record& r);
/// What the exit code says about the verdicts, in one line: "Exit code 0: every verdict is the one
/// the ledger records as expected ... 7 errata ... and 1 expected failure (table-values ...)".
std::string expectation_line(const run_record& r);
/// The findings in a referee's words, one sentence: "The paper's 68 claims: 1 substantive error, 5
/// typographical slips, ...; 5 remarks on claims that hold; 6 spelling slips apart."
std::string findings_headline(const run_record& r);

/// Writes report.json, report.md, report.html, the sections' data files (CSV, .dat), the gnuplot
/// scripts (<plot>.gp) and the plots (SVG, PNG). Everything is made in a staging directory beside
/// `dir`, which then replaces `dir` whole (the previous report is removed only after the new one is
/// complete): no stale file of an earlier run survives, and an error or an interruption leaves the
/// previous report as it was and no partial files.
plot_outcome write_report_files(const std::filesystem::path& dir, const run_record& r);

/// Every file of the report directory that holds no run time, report.json first (its "files").
std::vector<std::string> report_file_names(const run_record& r, const plot_outcome& plots);

/// The files that hold run times (report.json's "timing_files"): timing.json, timing.md,
/// timing.html, and the sections' timing tables and plots. None with --no-timing.
std::vector<std::string> timing_file_names(const run_record& r, const plot_outcome& plots);

/// timing.json: the seconds of each claim, of the GiNaC derivation and the headline claims, of each
/// section, and the sections' timing tables.
json timing_json(const run_record& r);

/// timing.md: the same for people, with the sections' timing tables and plots.
std::string timing_markdown(const run_record& r, const plot_outcome& plots);

/// report.md with the outcome of the plots (a list of those not drawn, if any).
std::string report_markdown(const run_record& r, const plot_outcome& plots);
json report_json(const run_record& r, const plot_outcome& plots);

}  // namespace simpson::verify

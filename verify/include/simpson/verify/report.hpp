#pragma once
// Running a scene and writing its report: report.json (machine-readable) and report.md (for
// people), both written atomically. Same scene and seed give byte-identical files apart from
// the "timing" members of report.json and the "environment" member (compiler, versions, commit).

#include <simpson/verify/claim.hpp>
#include <simpson/verify/experiments.hpp>
#include <simpson/verify/section_render.hpp>
#include <simpson/verify/scene.hpp>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace simpson::verify {

struct claim_outcome {
  const claim* checked = nullptr;
  verdict expected = verdict::holds;
  claim_result result;
  double seconds = 0;
};

struct run_record {
  scene run_scene;
  std::vector<claim_outcome> outcomes;
  json paper_configuration;
  json environment;
  std::vector<section_result> sections;  // the experiment sections the scene asked for, in order
  std::vector<double> section_seconds;
  double seconds = 0;
};

/// Called before and after each claim: (index, count, claim, outcome or nullptr).
using progress_callback = std::function<void(std::size_t, std::size_t, const claim&, const claim_outcome*)>;

/// Runs every claim of the scene; a check that throws is recorded as `fails` with the message.
/// Throws simpson::verify::interrupted when interruption_signal() is set (checked between claims
/// and between numeric samples).
/// Then runs the experiment sections the scene asks for (table1, work_precision, stability,
/// long_time), calling `section_progress(name, seconds)` after each.
run_record run(const scene& s, const progress_callback& progress = {},
               const std::function<void(const std::string&, double)>& section_progress = {});

/// True when every verdict equals its expected verdict.
bool all_as_expected(const run_record& r);

/// Φ_3, det Φ_3 − 1, Δ and H_d(Φ_3 y) − H_d(y) at m = 1, ω = 2π, h = 1/15 in each precision.
json paper_configuration(const std::vector<precision>& precisions);

/// Compiler, flags, library versions and git commit of this build.
json build_environment();

json report_json(const run_record& r);
std::string report_markdown(const run_record& r);
/// One line: "48 claims: 42 held, 5 errata, 1 failed; all as expected".
std::string summary_line(const run_record& r);

/// Checks, before anything runs, that `dir` can take a report: it does not exist yet (its parent
/// can be created and written), or it is empty, or it holds a previous simpson-verify report and
/// nothing else. Creates nothing. Throws std::invalid_argument naming the directory otherwise (a
/// directory with other files is refused, never cleared).
void prepare_output_directory(const std::filesystem::path& dir);

/// True when every entry of `dir` belongs to a simpson-verify report: the files its report.json
/// lists, or for a report written before that list existed, report.* and the section files
/// (.csv, .dat, .gp, .svg, .png).
bool holds_only_a_report(const std::filesystem::path& dir);

/// Plots drawn and plots that could not be drawn (gnuplot missing or failing), by the writer.
struct plot_outcome {
  std::vector<std::string> drawn;               // plot names, each with <name>.svg and <name>.png
  std::vector<std::string> failures;            // "<name>: <reason>"
};

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

#pragma once
// A report directory on disk: report.json, report.md, report.html, and the sections' CSV, data
// files, gnuplot scripts and plots. Written in a staging directory beside the target, which then
// replaces the target whole: no stale file of an earlier run survives, and an error or an
// interruption leaves the previous report as it was. A directory that holds anything but a
// simpson-verify report is refused, never cleared.

#include <simpson/verify/json.hpp>
#include <simpson/verify/section_render.hpp>

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace simpson::verify {

/// Plots drawn and plots that could not be drawn (gnuplot missing or failing).
struct plot_outcome {
  std::vector<std::string> drawn;     // plot names, each with <name>.svg and <name>.png
  std::vector<std::string> failures;  // "<name>: <reason>"
};

/// The documents of a report, made once the plots are drawn (they say which were).
struct report_documents {
  json report;           // report.json
  std::string markdown;  // report.md, rendered to report.html
  std::string title;     // of report.html
  std::string junit;     // report.junit.xml (not written when empty)
  json timing;                  // timing.json (null: not written, as with --no-timing)
  std::string timing_markdown;  // timing.md, rendered to timing.html
  /// Further files by report-relative path, at most one directory deep (certificates/<id>.v).
  std::vector<std::pair<std::string, std::string>> extra_files;
};

/// Checks, before anything runs, that `dir` can take a report: it does not exist yet (its parent
/// can be created and written), or it is empty, or it holds a previous simpson-verify report and
/// nothing else. Creates nothing. Throws std::invalid_argument naming the directory otherwise.
void prepare_output_directory(const std::filesystem::path& dir);

/// True when every entry of `dir` belongs to a simpson-verify report: the files its report.json
/// lists (a directory when every file in it is listed as <directory>/<file>), or for a report written before that list existed, report.* and the section files
/// (.csv, .dat, .gp, .svg, .png).
bool holds_only_a_report(const std::filesystem::path& dir);

/// The files of Debian's KaTeX that write_report_directory copies beside report.html (katex/: the
/// script, its stylesheet, its woff2 fonts), relative to the report directory, sorted; none where
/// libjs-katex is not installed (the page then shows its TeX as code).
std::vector<std::string> katex_file_names();

/// Writes `content` to `path` whole (created or truncated). Throws std::filesystem::filesystem_error
/// with the reason the system gave (ENOSPC: "No space left on device"), from the call that failed.
void write_file(const std::filesystem::path& path, const std::string& content);

/// The version of the cmark-gfm library that renders report.html ("0.29.0.gfm.6").
std::string cmark_gfm_version();

/// Writes the sections' files and plots, then the documents, and swaps the directory into place.
plot_outcome write_report_directory(const std::filesystem::path& dir, const std::vector<section_result>& sections,
                                    const std::function<report_documents(const plot_outcome&)>& documents);

}  // namespace simpson::verify

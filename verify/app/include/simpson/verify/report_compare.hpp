#pragma once
// Comparing two reports (report.json of two report directories), for CI: a run against the
// committed reference. One line per difference, naming the claim (or the section, table, row and
// column), the old and the new value.
//
// Tolerances, by kind of figure (also printed by `simpson-verify compare`):
// - verdicts, expected verdicts, exact values, integers, words and flags: equal;
// - figures computed in floating point (decimal strings, JSON numbers): equal to the digits printed;
// - numeric residuals of the rechecks (max_residual, bound_at_that_sample, max_residual_over_bound):
//   their digits may differ, but within_bound must stay true;
// - figures at round-off level: in a row that names its precision ("precision" or "epsilon"), two
//   figures both at most 1024 ε of that precision are equal (another libm or compiler moves them);
// - what one run chose not to compute is a note, not a difference: Coq certificates exported but
//   not checked by coqc (--no-certify, or no coqc), and what --no-timing leaves out (timing files,
//   plots of run times, the timed section's title);
// - the paper: by its SHA-256; the same bytes named "embedded" in one report and by a path in the
//   other (--paper) are one paper, its name a note;
// - values longer than 120 bytes are shown around where they differ, cut at UTF-8 character
//   boundaries;
// - run times (in timing.json, which is not compared) and the environment: ignored.

#include <simpson/verify/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace simpson::verify {

/// The tolerances above, one line each.
const std::vector<std::string>& comparison_tolerances();

/// One difference: the claim, the section or the report's member that differs ("claim
/// truncation-1440", "section table1", "seed"), and each of its fields that does ("verdict:
/// \"holds\" → \"erratum\""), in the order found.
struct report_difference {
  std::string place;
  std::vector<std::string> changes;
};

/// What a comparison found: differences (exit 1), one per claim, section or member; and notes: on
/// what only one run computed, on a different document (one note, not a difference on every claim
/// that names it), and on the summary and the verdict table, which follow from the claims'
/// differences.
struct report_comparison {
  std::vector<report_difference> differences;
  std::vector<std::string> notes;
  /// Each change as one line, "place: change".
  std::vector<std::string> lines() const;
};

/// Whether a report is of a selection (--claims, --sections: its overrides name them).
bool is_selection(const json& report);

/// The differences between two report.json documents, one line each; empty when they agree.
report_comparison compare_reports(const json& old_report, const json& new_report);

/// The same for a run of a selection against a fuller report (`compare --subset`): only the claims
/// and the sections the new report has are compared, each with the old report's; the run's settings
/// that shape their figures (tool, schema, scene, paper, seed, samples, precisions) must agree. A
/// claim or section of the new report that the old one lacks is a difference; what the new report
/// leaves out is not.
report_comparison compare_report_subset(const json& old_report, const json& new_report);

/// The comparison as JUnit XML, for a CI's test view: a testsuite "compare", a failing testcase per
/// difference (named by its place: "claim phi3-det"; its first change the message, all of them the
/// body), the notes in <system-out>; one passing testcase when the reports agree.
std::string comparison_junit(const report_comparison& found, const std::string& old_name, const std::string& new_name);

/// The comparison as JSON: {"old", "new", "agree", "differences": [{"where", "what": [changes]}], "notes"}.
json comparison_json(const report_comparison& found, const std::string& old_name, const std::string& new_name);

/// report.json of a report directory (or the file itself). Throws std::invalid_argument, "`who`:
/// 'path': why", when it is missing or is not a simpson-verify report (`who` is the command or the
/// flag that read it: "compare", "--baseline").
json load_report(const std::filesystem::path& dir_or_file, const std::string& who = "compare");

}  // namespace simpson::verify

#pragma once
// Scenes: JSON files saying what a run computes. Validated on load; unknown keys are refused.
//
// {
//   "name": "paper",                       required, [a-z0-9_-]+
//   "description": "...",                  optional
//   "claims": "all" | "beyond" | ["phi3-det", ...],  required; "all": the paper's claims,
//                                          "beyond": the part beyond the paper
//   "precisions": ["double", "mpfr:100"],  required, names of the precision list
//   "samples": 16,                         optional, random samples per numeric recheck, 1..10000
//   "seed": 20230830,                      optional, the default seed (--seed overrides)
//   "expected_overrides": {"id": "fails"}, optional, replaces expected verdicts (tests the exit code)
//   "table1": {...}, "work_precision": {...}, "stability": {...}, "long_time": {...}
//                                          optional experiment sections (experiment_section.hpp: the registry the book gives)
// }
// "claims" may be left out when the scene has at least one experiment section.

#include <simpson/precision.hpp>
#include <simpson/verify/claim.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/experiment_section.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace simpson::verify {

inline constexpr std::uint64_t default_seed = 20230830;  // the first day of GSI 2023
inline constexpr unsigned default_samples = 16;

/// What a baseline report (--baseline) judged of one claim: its verdict, an erratum's correction, a
/// remark (its class and text), and the digest of what the claim read there (claim_reads.hpp).
struct baseline_claim {
  std::string correction;
  finding remark_kind = finding::none;
  std::string remark;
  std::string reads;
};

struct scene {
  std::string name;
  std::string description;
  std::vector<std::string> claims;  // ids, in ledger order
  std::vector<precision> precisions;
  unsigned samples = default_samples;
  /// The most decimal digits an interval enclosure of a numeric claim may rise to (from 40, doubling)
  /// before the claim is undecided (--enclosure-budget).
  unsigned enclosure_budget_digits = 640;
  std::uint64_t seed = default_seed;
  std::map<std::string, verdict> expected_overrides;
  /// --accept-fixes: a claim recorded as a finding (erratum, fails) that now holds is a fix, and a
  /// fix passes (an author's pipeline); without it a fix is a change, and the run fails (a guard's).
  bool accept_fixes = false;
  /// --baseline REPORT: each claim the baseline judged is expected to have its verdict there (in
  /// expected_overrides), an erratum its correction there (baseline_corrections), and fixes pass:
  /// nothing may get worse than that report. Empty: no baseline.
  std::string baseline;
  std::map<std::string, baseline_claim> baseline_claims;
  experiment_settings experiments;
  /// The paper's source the formula claims read: empty for the embedded copy, else a file.
  std::string paper_file;
  /// What the command line changed in the scene (report.json "overrides"), and the selection in
  /// words for the title ("claims phi3-det only; no sections"; empty when the scene runs whole).
  json overrides = json::object();
  std::string selection;
  /// The scene's JSON text as read (its SHA-256, with the overrides, is in report.json).
  std::string source_text;
  /// The command line of the run (report.json's environment); empty when run from a test.
  std::vector<std::string> command_line;
  /// False with --no-timing: no run time is measured or written, and every file of the report is
  /// the same from run to run.
  bool timing = true;
};

/// Parses and validates a scene against the claims of `book` (its ids, "all"); `origin` names it in
/// errors. Throws std::invalid_argument with a one-line message naming the field (and, for malformed
/// JSON, the line and column).
scene parse_scene(const std::string& text, const std::string& origin, const claim_book& book);

/// An embedded scene by name ("paper", "quick"), or else a file path.
scene load_scene(const std::string& name_or_path, const claim_book& book);

/// Names and texts of the embedded scenes (the files of scenes/, compiled in).
const std::map<std::string, std::string>& embedded_scenes();

}  // namespace simpson::verify

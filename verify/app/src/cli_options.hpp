#pragma once
// simpson-verify's command line: every option's value, and their declarations with CLI11.

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace simpson::verify {

/// The values of the command line, as given (texts checked by the run that uses them).
struct cli_options {
  std::string scene_name = "paper", out_dir, seed_text, samples_text, enclosure_budget_text, paper_file, timing_runs_text, claims_file;
  std::vector<std::string> claim_ids, section_list, precision_names;
  bool want_claims = false, want_scenes = false, want_precisions = false, want_holes = false, want_core = false,
       want_facts = false, want_sections = false, want_verdicts = false;
  bool allow_expensive = false, long_run = false, quiet = false, no_timing = false, certify = false, no_certify = false, validate = false;
  bool accept_fixes = false;
  std::string baseline;
  std::string list_format = "text";
  CLI::App* compare = nullptr;  // the `compare` subcommand
  std::string compare_old, compare_new, compare_junit, compare_format = "text";
  bool compare_subset = false;
};

/// Declares every option of simpson-verify on `app`, bound to `o`'s members (and the `compare`
/// subcommand, kept in `o.compare`).
void declare_options(CLI::App& app, cli_options& o);

}  // namespace simpson::verify

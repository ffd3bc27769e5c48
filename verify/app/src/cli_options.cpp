// simpson-verify's options (cli_options.hpp).

#include "cli_options.hpp"

#include <simpson/verify/environment.hpp>
#include <simpson/verify/experiment_cost.hpp>
#include <simpson/verify/scene.hpp>

#include <simpson/verify/ledger.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace simpson::verify {

void declare_options(CLI::App& app, cli_options& o) {
  app.set_version_flag("--version", version_line());
  app.footer(
      "Exit codes: 0 every verdict as expected (compare: the reports agree); 1 a verdict differs from the expected one, "
      "coqc rejected a certificate or a section's expectation failed (compare: a difference); 2 bad input (one line on stderr, nothing written); 3 a bug in "
      "the harness; 130 or 143 interrupted by SIGINT or SIGTERM (the previous report left as it was).");
  std::string scene_list;
  for (const auto& [name, text] : embedded_scenes()) scene_list += (scene_list.empty() ? "" : ", ") + name;
  app.add_option("--scene", o.scene_name, "embedded scene name (" + scene_list + ") or a scene JSON file")->capture_default_str();
  app.add_option("--paper", o.paper_file, "the paper's LaTeX source to check (default: the embedded source; the report names the edition it prints and its SHA-256)");
  app.add_option("--claims-file", o.claims_file,
                 "the claims to check, one TOML record each (docs/claims-file.md; default: the embedded claims/paper.toml)");
  app.add_option("--out", o.out_dir,
                 "report directory (default: reports/out/<scene>; with --claims or --sections, a directory named after the "
                 "selection, e.g. reports/out/paper-claims-phi3-det, so that a subset never replaces the full report)");
  app.add_option("--claims", o.claim_ids,
                 "comma-separated claim ids, or all (the scene's); alone, runs these claims and no section (default: the scene's)")
      ->delimiter(',');
  // The sections and what each does to --precisions: the registry's (experiment_section.hpp).
  std::vector<std::string> sections, applied, refused;
  for (const experiment_section* section : experiment_sections()) {
    sections.push_back(section->name());
    if (section->precisions() == experiment_section::precisions_use::applied) applied.push_back(section->name());
    if (section->precisions() == experiment_section::precisions_use::refused) refused.push_back(section->name());
  }
  app.add_option("--sections", o.section_list,
                 fmt::format("comma-separated sections ({}) or none; alone, runs these sections and no claim (default: the scene's)",
                             fmt::join(sections, ", ")))
      ->delimiter(',');
  app.add_flag("--quiet", o.quiet, "print only the summary line and errors");
  o.compare = app.add_subcommand(
      "compare", "compare two report directories (a run against reports/reference/paper): exit 0 when they agree, 1 on a "
                 "difference (one line each), 2 on bad input");
  o.compare->add_option("old", o.compare_old, "the reference report directory (or its report.json)");
  o.compare->add_option("new", o.compare_new, "the report directory to check (or its report.json)");
  o.compare->add_flag("--subset", o.compare_subset,
                    "compare only the claims and sections of NEW (a run of a selection) with those of OLD (a fuller report)");
  o.compare->add_option("--junit", o.compare_junit,
                         "also write the differences as JUnit XML to FILE (a failing testcase each; one passing testcase when the "
                         "reports agree), for a CI's test view");
  o.compare->add_option("--format", o.compare_format, "text (one line per difference) or json (the differences and notes as one JSON document)")
      ->check(CLI::IsMember({"text", "json"}));
  o.compare->fallthrough();
  app.add_option("--precisions", o.precision_names,
                 fmt::format("comma-separated precisions of the claims' rechecks and of the sections {} (the others run in their own; a "
                             "run with {} is refused: they compare double with mpfr by design)",
                             fmt::join(applied, " and "), fmt::join(refused, " or ")))
      ->delimiter(',');
  app.add_option("--seed", o.seed_text, "seed of the random samples (default: the scene's, printed in the report)")->type_name("UINT");
  app.add_option("--samples", o.samples_text, "random samples per numeric recheck and precision, 1..10000")->type_name("UINT");
  app.add_option("--enclosure-budget", o.enclosure_budget_text,
                 "most decimal digits the interval enclosure of a numeric claim may rise to (from 40, doubling) before the "
                 "claim is undecided, 40..20480 (default 640)")
      ->type_name("DIGITS");
  app.add_flag("--allow-expensive", o.allow_expensive,
               fmt::format("run a scene whose estimated cost exceeds the budget ({:.3g} double-step units, about {})", default_cost_budget, seconds_text(default_cost_budget)));
  CLI::Option* certify_flag =
      app.add_flag("--certify", o.certify,
                   "check each claim's Coq certificate (certificates/*.v of the report) with coqc, and fail with exit 2 "
                   "when coqc is not installed; a rejected certificate gives exit code 1. Default: checked wherever coqc is "
                   "installed (one coqc process per core, all certificates at once)");
  app.add_flag("--no-certify", o.no_certify, "export the Coq certificates without checking them (the report says 'exported')")
      ->excludes(certify_flag);
  app.add_flag("--long", o.long_run, "long_time section: 1e9 steps in double instead of the scene's (implies --allow-expensive)");
  app.add_option("--timing-runs", o.timing_runs_text,
                 "work_precision: timed runs per configuration after one warm-up, 1..1000 (default: the scene's, 20)")
      ->type_name("UINT");
  app.add_flag("--no-timing", o.no_timing,
               "measure no run time: no timing.json, timing.md or time plot, and every file is the same from run to run");
  app.add_flag("--list-claims", o.want_claims, "list the claims of the ledger and exit");
  app.add_option("--format", o.list_format,
                 "--list-claims: text (one line each), json (every field of each record, its statement included) or markdown (a table: "
                 "what decides each, what it reads, whose it is, its expected verdict, the core formulas it binds)")
      ->check(CLI::IsMember({"text", "json", "markdown"}));
  app.add_flag("--validate", o.validate,
               "judge every claim by whether it holds, not by the verdict its record expects: exit 0 only when every claim "
               "holds (the recorded errata of the paper then fail)");
  app.add_flag("--accept-fixes", o.accept_fixes,
               "a claim recorded as a finding (erratum, fails) that now holds is a fix, and passes: an author's pipeline (without "
               "it a fix is a change, exit 1: a guard's pipeline)")
      ->excludes("--validate");
  app.add_option("--baseline", o.baseline,
                 "a report directory (or its report.json): nothing may get worse than it. Each claim it judged is expected to "
                 "keep its verdict there, an erratum its correction there; fixes pass (implies --accept-fixes)")
      ->excludes("--validate");
  app.add_flag("--list-scenes", o.want_scenes, "list the embedded scenes and exit");
  app.add_flag("--list-precisions", o.want_precisions, "list the precisions and exit");
  app.add_flag("--list-holes", o.want_holes,
               "list the holes of a sentence's pattern ({order}, {sign}, ...), the shapes that take each and the words each accepts "
               "(a Markdown table), and exit");
  app.add_flag("--list-core", o.want_core,
               "list the formulas of our core a record may bind to the print (core = { function = ... }), the label each "
               "implements and the records that bind it (a Markdown table), and exit");
  app.add_flag("--list-facts", o.want_facts,
               "list the facts the experiments publish that a record may observe (observes = \"table1.printed-orders\"), what "
               "each states and the records that observe it (a Markdown table), and exit");
  app.add_flag("--list-sections", o.want_sections,
               "list the experiment sections of the registry, what each computes, the keys of its scene object and what it does "
               "with --precisions, --timing-runs and --long (a Markdown table), and exit");
  app.add_flag("--list-verdicts", o.want_verdicts,
               "list the verdicts and what each means: whether a finding, whether a record may expect it, how a run's row treats "
               "it, report.json's count (a Markdown table), and exit");
}

}  // namespace simpson::verify

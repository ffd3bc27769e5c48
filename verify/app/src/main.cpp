// simpson-verify: runs a scene of the claims ledger and writes its report.
// Exit codes: 0 every verdict as expected; 1 some verdict differs, or a section's expectation failed (each named on stderr);
// 2 bad input or usage (one line on stderr, nothing written); 3 an internal error (a bug in the
// harness: a check that threw, or an unexpected exception); 128 + n when stopped by signal n.

#include <simpson/verify/environment.hpp>
#include <simpson/verify/experiment_cost.hpp>
#include <simpson/verify/interruption.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/progress.hpp>
#include <simpson/verify/certify.hpp>
#include <simpson/verify/report.hpp>
#include <simpson/verify/output_location.hpp>
#include <simpson/verify/report_compare.hpp>
#include <simpson/verify/scene.hpp>
#include <simpson/verify/selection.hpp>
#include <simpson/verify/sentence_holes.hpp>

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <set>
#include <unistd.h>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <exception>
#include <string>
#include <vector>

namespace {

using namespace simpson::verify;

extern "C" void record_signal(int signal) { interruption_signal().store(signal); }

/// Progress of long sections on stderr, at most two updates a second: on a terminal one line
/// rewritten in place with a percentage, otherwise plain lines.
void install_progress() {
  using clock = std::chrono::steady_clock;
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  auto last = std::make_shared<clock::time_point>(clock::now());
  set_progress_sink([terminal, last](const std::string& section, const std::string& what, double fraction) {
    const auto now = clock::now();
    if (now - *last < std::chrono::milliseconds(500)) return;
    *last = now;
    const std::string percent = fraction >= 0 ? fmt::format(" {:3.0f}%", 100 * fraction) : "";
    if (terminal) {
      fmt::print(stderr, "\r\033[K[{}]{} {}", section, percent, what);
    } else {
      fmt::print(stderr, "[{}]{} {}\n", section, percent, what);
    }
    std::fflush(stderr);
  });
}

/// The exit code of a run stopped by a signal: 128 + its number (130 for SIGINT, 143 for SIGTERM).
int interrupted_exit(const interrupted& e) {
  std::fprintf(stderr, "simpson-verify: interrupted (%s); stopped, no report written\n",
               e.signal() == SIGINT ? "SIGINT" : e.signal() == SIGTERM ? "SIGTERM" : "signal");
  return 128 + e.signal();
}

int list_claims(const claim_book& book, const std::string& format) {
  if (format == "json") {
    json out = json::array();
    for (const claim& c : book.claims) {
      json one{{"id", c.id},           {"section", c.section},   {"equation", c.equation}, {"statement", c.statement},
               {"methods", c.methods}, {"check", c.check_name}, {"expected", to_string(c.expected)}};
      if (c.kind != finding::none) one["finding"] = to_string(c.kind);
      if (!c.follows_from.empty()) one["follows_from"] = c.follows_from;
      out.push_back(std::move(one));
    }
    fmt::print("{}\n", out.dump(2));
    return 0;
  }
  if (format == "markdown") {
    // One row per record: what decides it, what it reads, whose it is, what it is expected to be,
    // and the core formulas it binds to the print (docs/ledger.md's list, generated).
    fmt::print("| id | § | decided by | reads | origin | expected | binds our core |\n|---|---|---|---|---|---|---|\n");
    for (const claim_record& r : book.records) {
      const claim& c = book.find(r.id);
      std::vector<std::string> core;
      for (const core_binding& b : r.core) core.push_back("`" + b.function + "`");
      const std::string expected = to_string(c.expected) + (c.follows_from.empty() ? "" : ", follows from `" + c.follows_from + "`");
      fmt::print("| `{}` | {} | {} | {} | {} | {} | {} |\n", c.id, c.section, r.shape.empty() ? "check `" + r.check + "`" : "shape `" + r.shape + "`",
                 c.equation, to_string(c.origin), expected, core.empty() ? "" : fmt::format("{}", fmt::join(core, ", ")));
    }
    return 0;
  }
  for (const claim& c : book.claims) {
    fmt::print("{:<34} §{:<8} {:<8} {}\n", c.id, c.section, to_string(c.expected), c.equation);
  }
  return 0;
}

int list_scenes() {
  for (const auto& [name, text] : embedded_scenes()) {
    const scene s = parse_scene(text, name);
    fmt::print("{:<8} {} claims, {} precisions: {}\n", name, s.claims.size(), s.precisions.size(), s.description);
  }
  return 0;
}

int list_precisions() {
  fmt::print("double, long double (or long-double), float128, bin50, bin100, mpfr:D ({} <= D <= {}), rational\n",
             simpson::precision::min_mpfr_digits, simpson::precision::max_mpfr_digits);
  for (const simpson::precision& p : simpson::default_precisions()) fmt::print("{:<12} epsilon {}\n", p.name(), p.epsilon());
  return 0;
}

/// `simpson-verify compare OLD NEW`: 0 when the reports agree, 1 on a difference (one line each), 2
/// on bad input.
int compare_report_directories(const std::string& old_dir, const std::string& new_dir, bool quiet, bool subset) {
  json old_report, new_report;
  try {
    old_report = load_report(old_dir);
    new_report = load_report(new_dir);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "simpson-verify: %s\n", e.what());
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
  const std::vector<std::string>& differences = found.differences;
  if (!quiet) {
    fmt::print("compare {} (old) with {} (new){}; tolerances:\n", old_dir, new_dir,
               subset ? fmt::format(", only the new report's {} claims and {} sections", new_report.value("claims", json::array()).size(),
                                    new_report.value("experiments", json::object()).size())
                      : std::string());
    for (const std::string& line : comparison_tolerances()) fmt::print("  - {}\n", line);
  }
  for (const std::string& line : found.notes) fmt::print("note: {}\n", line);
  for (const std::string& line : differences) fmt::print("{}\n", line);
  fmt::print("{}\n", differences.empty() ? std::string("the reports agree")
                                          : fmt::format("{} {}", differences.size(), differences.size() == 1 ? "difference" : "differences"));
  return differences.empty() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"simpson-verify: proves, rechecks and reports every claim of the symplectic Simpson paper"};
  app.set_version_flag("--version", version_line());
  app.footer(
      "Exit codes: 0 every verdict as expected (compare: the reports agree); 1 a verdict differs from the expected one, "
      "coqc rejected a certificate or a section's expectation failed (compare: a difference); 2 bad input (one line on stderr, nothing written); 3 a bug in "
      "the harness; 130 or 143 interrupted by SIGINT or SIGTERM (the previous report left as it was).");
  std::string scene_name = "paper", out_dir, seed_text, samples_text, enclosure_budget_text, paper_file, timing_runs_text,
      claims_file;
  std::vector<std::string> claim_ids, section_list, precision_names;
  bool want_claims = false, want_scenes = false, want_precisions = false, allow_expensive = false, long_run = false,
       quiet = false, no_timing = false, certify = false, no_certify = false;
  std::string scene_list;
  for (const auto& [name, text] : embedded_scenes()) scene_list += (scene_list.empty() ? "" : ", ") + name;
  app.add_option("--scene", scene_name, "embedded scene name (" + scene_list + ") or a scene JSON file")->capture_default_str();
  app.add_option("--paper", paper_file, "the paper's LaTeX source to check (default: the embedded source; the report names the edition it prints and its SHA-256)");
  app.add_option("--claims-file", claims_file,
                 "the claims to check, one TOML record each (docs/claims-file.md; default: the embedded claims/paper.toml)");
  app.add_option("--out", out_dir,
                 "report directory (default: reports/out/<scene>; with --claims or --sections, a directory named after the "
                 "selection, e.g. reports/out/paper-claims-phi3-det, so that a subset never replaces the full report)");
  app.add_option("--claims", claim_ids,
                 "comma-separated claim ids, or all (the scene's); alone, runs these claims and no section (default: the scene's)")
      ->delimiter(',');
  app.add_option("--sections", section_list,
                 "comma-separated sections (table1, work_precision, stability, long_time, nonlinear, floating, family) or none; alone, runs these "
                 "sections and no claim (default: the scene's)")
      ->delimiter(',');
  app.add_flag("--quiet", quiet, "print only the summary line and errors");
  std::string compare_old, compare_new;
  CLI::App* compare = app.add_subcommand(
      "compare", "compare two report directories (a run against reports/reference/paper): exit 0 when they agree, 1 on a "
                 "difference (one line each), 2 on bad input");
  compare->add_option("old", compare_old, "the reference report directory (or its report.json)");
  compare->add_option("new", compare_new, "the report directory to check (or its report.json)");
  bool compare_subset = false;
  compare->add_flag("--subset", compare_subset,
                    "compare only the claims and sections of NEW (a run of a selection) with those of OLD (a fuller report)");
  compare->fallthrough();
  app.add_option("--precisions", precision_names,
                 "comma-separated precisions of the claims' rechecks and of the sections work_precision and stability "
                 "(table1 runs in double; a run with long_time or nonlinear is refused: they compare double with mpfr by design)")
      ->delimiter(',');
  app.add_option("--seed", seed_text, "seed of the random samples (default: the scene's, printed in the report)")->type_name("UINT");
  app.add_option("--samples", samples_text, "random samples per numeric recheck and precision, 1..10000")->type_name("UINT");
  app.add_option("--enclosure-budget", enclosure_budget_text,
                 "most decimal digits the interval enclosure of a numeric claim may rise to (from 40, doubling) before the "
                 "claim is undecided, 40..20480 (default 640)")
      ->type_name("DIGITS");
  app.add_flag("--allow-expensive", allow_expensive,
               fmt::format("run a scene whose estimated cost exceeds the budget ({:.3g} double-step units, about {})", default_cost_budget, seconds_text(default_cost_budget)));
  CLI::Option* certify_flag =
      app.add_flag("--certify", certify,
                   "check each claim's Coq certificate (certificates/*.v of the report) with coqc, and fail with exit 2 "
                   "when coqc is not installed; a rejected certificate gives exit code 1. Default: checked wherever coqc is "
                   "installed (one coqc process per core, all certificates at once)");
  app.add_flag("--no-certify", no_certify, "export the Coq certificates without checking them (the report says 'exported')")
      ->excludes(certify_flag);
  app.add_flag("--long", long_run, "long_time section: 1e9 steps in double instead of the scene's (implies --allow-expensive)");
  app.add_option("--timing-runs", timing_runs_text,
                 "work_precision: timed runs per configuration after one warm-up, 1..1000 (default: the scene's, 20)")
      ->type_name("UINT");
  app.add_flag("--no-timing", no_timing,
               "measure no run time: no timing.json, timing.md or time plot, and every file is the same from run to run");
  app.add_flag("--list-claims", want_claims, "list the claims of the ledger and exit");
  std::string list_format = "text";
  app.add_option("--format", list_format,
                 "--list-claims: text (one line each), json (every field of each record, its statement included) or markdown (a table: "
                 "what decides each, what it reads, whose it is, its expected verdict, the core formulas it binds)")
      ->check(CLI::IsMember({"text", "json", "markdown"}));
  bool validate = false;
  app.add_flag("--validate", validate,
               "judge every claim by whether it holds, not by the verdict its record expects: exit 0 only when every claim "
               "holds (the recorded errata of the paper then fail)");
  app.add_flag("--list-scenes", want_scenes, "list the embedded scenes and exit");
  app.add_flag("--list-precisions", want_precisions, "list the precisions and exit");
  bool want_holes = false;
  app.add_flag("--list-holes", want_holes,
               "list the holes of a sentence's pattern ({order}, {sign}, ...), the shapes that take each and the words each accepts "
               "(a Markdown table), and exit");
  bool want_core = false;
  app.add_flag("--list-core", want_core,
               "list the formulas of our core a record may bind to the print (core = { function = ... }), the label each "
               "implements and the records that bind it (a Markdown table), and exit");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::fprintf(stderr, "simpson-verify: %s\n", e.what());
    return 2;
  }

  if (*compare) {
    if (compare_old.empty() || compare_new.empty()) {
      std::fprintf(stderr, "simpson-verify: compare needs two report directories: OLD, the reference (e.g. reports/reference/paper), "
                   "then NEW, the run to check\n");
      return 2;
    }
    return compare_report_directories(compare_old, compare_new, quiet, compare_subset);
  }

  // From here on a signal is recorded, not acted on: a run started in the background by a shell
  // ignores SIGINT until it installs a handler, so one that came while the scene, the paper and the
  // shape records were read would be lost (the run would finish). It is honoured below, before the run.
  std::signal(SIGINT, record_signal);
  std::signal(SIGTERM, record_signal);
  scene s;
  std::optional<simpson::verify::paper_reading> paper;
  // The run's book: the paper's, or the claims file's; read once, bound to its document once, and
  // passed to the run.
  auto book = std::make_shared<claim_book>(paper_book());
  std::filesystem::path out;
  cost_estimate cost;
  try {
    if (!claims_file.empty()) {
      std::ifstream in(claims_file, std::ios::binary);
      if (!in) throw std::invalid_argument("claims file '" + claims_file + "': cannot be read");
      const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      *book = read_claim_book(text, claims_file);  // a file that does not read is bad input: nothing runs
    }
    if (want_claims) return list_claims(*book, list_format);
    if (want_scenes) return list_scenes();
    if (want_precisions) return list_precisions();
    if (want_holes) {
      fmt::print("{}", simpson::verify::holes_markdown());
      return 0;
    }
    if (want_core) {
      fmt::print("{}", simpson::verify::core_formulas_markdown(*book));
      return 0;
    }
    s = load_scene(scene_name, *book);
    if (!paper_file.empty()) s.paper_file = paper_file;
    if (const claims_document* document = book->checked_document()) {
      // A document's claims file: its claims alone, in a scene named after the file (its report in
      // reports/out/<name>); none of the paper's sections unless --sections asks for them.
      s.name = std::filesystem::path(claims_file).stem().string();
      s.description = fmt::format("The claims of {} on “{}” ({}): formulas read from its LaTeX, decided by proof shapes.", claims_file,
                                  document->title, paper_file.empty() ? std::string("no --paper") : paper_file);
      s.experiments = experiment_settings{};
    }
    scene_selection selection;
    if (app.count("--claims") > 0) selection.claims = claim_ids;
    if (app.count("--sections") > 0) selection.sections = section_list;
    apply_selection(s, selection, *book);
    paper = read_scene_paper(s, *book);  // a paper that is missing or does not parse is bad input: nothing runs
    if (!paper_file.empty()) s.overrides["paper"] = paper_file;
    if (!claims_file.empty()) s.overrides["claims_file"] = claims_file;
    if (validate) {
      for (const std::string& id : s.claims) s.expected_overrides[id] = verdict::holds;
      s.overrides["validate"] = true;
    }
    if (app.count("--precisions") > 0) apply_precisions(s, precision_names);
    const auto parse_count = [](const std::string& flag, const std::string& text, unsigned long long min, unsigned long long max) {
      std::size_t used = 0;
      unsigned long long v = 0;
      try {
        if (text.empty() || text.front() == '-') throw std::invalid_argument("");
        v = std::stoull(text, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != text.size() || used == 0 || v < min || v > max) {
        throw std::invalid_argument(flag + " '" + text + "': expected an integer from " + std::to_string(min) + " to " +
                                    std::to_string(max));
      }
      return v;
    };
    if (!seed_text.empty()) {
      s.seed = parse_count("--seed", seed_text, 0, ~0ULL);
      s.overrides["seed"] = s.seed;
    }
    if (!samples_text.empty()) {
      s.samples = static_cast<unsigned>(parse_count("--samples", samples_text, 1, 10000));
      s.overrides["samples"] = s.samples;
    }
    if (!enclosure_budget_text.empty()) {
      s.enclosure_budget_digits = static_cast<unsigned>(parse_count("--enclosure-budget", enclosure_budget_text, 40, 20480));
      s.overrides["enclosure_budget_digits"] = s.enclosure_budget_digits;
    }
    if (!timing_runs_text.empty() && no_timing) throw std::invalid_argument("--timing-runs and --no-timing exclude each other");
    if (!timing_runs_text.empty()) {
      const auto runs = static_cast<unsigned>(parse_count("--timing-runs", timing_runs_text, 1, 1000));
      if (!s.experiments.work_precision && !s.experiments.nonlinear) {
        throw std::invalid_argument("--timing-runs: the run has no work_precision or nonlinear section, the only ones timed by repeats");
      }
      if (s.experiments.work_precision) s.experiments.work_precision->timing.max_runs = runs;
      if (s.experiments.nonlinear) s.experiments.nonlinear->timing.max_runs = runs;
      s.overrides["timing_runs"] = runs;
    }
    if (no_timing) {
      s.timing = false;
      if (s.experiments.work_precision) s.experiments.work_precision->timing.max_runs = 0;
      if (s.experiments.nonlinear) s.experiments.nonlinear->timing.max_runs = 0;
      s.overrides["timing"] = false;
    }
    s.command_line.assign(argv, argv + argc);
    if (long_run) {
      if (!s.experiments.long_time) s.experiments.long_time = long_time_settings{};
      s.experiments.long_time->steps_double = 1'000'000'000;
      allow_expensive = true;
      s.overrides["long"] = true;
    }
    recheck_load rechecks{0, s.samples, s.precisions};
    for (const std::string& id : s.claims) {
      const std::vector<std::string>& methods = book->find(id).methods;
      if (std::find(methods.begin(), methods.end(), "numeric") != methods.end()) ++rechecks.numeric_claims;
    }
    cost = estimate_cost(s.experiments, rechecks);
    if (cost.units > default_cost_budget && !allow_expensive) {
      std::string parts;
      for (const std::string& line : cost.lines) parts += (parts.empty() ? "" : "; ") + line;
      throw std::invalid_argument(fmt::format("scene '{}': estimated cost {:.3g} units (about {}) exceeds the budget {:.3g} "
                                              "units (about {}) ({}); pass --allow-expensive to run it anyway",
                                              s.name, cost.units, seconds_text(cost.units), default_cost_budget,
                                              seconds_text(default_cost_budget), parts));
    }
    if (certify && coqc_version().empty()) throw std::invalid_argument("--certify: coqc was not found (install Debian's coq)");
    // Checked wherever coqc is installed, unless --no-certify.
    if (!certify && !no_certify) certify = !coqc_version().empty();
    if (s.experiments.floating) s.experiments.floating->check_with_coqc = certify;  // Gappa's proofs and the lifting lemmas
    out = output_directory(s, app.count("--out") > 0 ? std::optional<std::string>(out_dir) : std::nullopt);
    prepare_output_directory(out);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "simpson-verify: %s\n", e.what());
    return 2;
  } catch (const std::domain_error& e) {
    std::fprintf(stderr, "simpson-verify: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "simpson-verify: internal error (a bug in the harness): %s\n", e.what());
    return 3;
  }

  if (s.experiments.any() && !quiet) {
    fmt::print(stderr, "experiments: estimated cost {:.3g} units, about {} (budget {:.3g} units, about {})\n", cost.units,
               seconds_text(cost.units), default_cost_budget, seconds_text(default_cost_budget));
    install_progress();
  }
  try {
    throw_if_interrupted();  // a signal while the run was being set up: nothing was written yet
    const auto start = std::chrono::steady_clock::now();
    run_record record = run(s, book, *paper, [&](std::size_t k, std::size_t n, const claim& c, const claim_outcome* done) {
      if (!done || quiet) return;
      fmt::print(stderr, "[{:>2}/{}] {:<34} {:<8} {:.2f} s\n", k + 1, n, c.id, to_string(done->result.outcome), done->seconds);
    }, [quiet](const std::string& section, double seconds) {
      if (quiet) return;
      if (::isatty(STDERR_FILENO)) fmt::print(stderr, "\r\033[K");
      fmt::print(stderr, "[section] {:<34} {:.2f} s\n", section, seconds);
    });
    throw_if_interrupted();
    if (certify && !record.outcomes.empty()) {
      if (!quiet) fmt::print(stderr, "[coqc] checking the claims' Coq certificates ...\n");
      record_certificates(record, true);
      if (!quiet && record.coq_documents > 0) {
        fmt::print(stderr, "[coqc] {} certificate files checked in {:.1f} s ({} processes side by side)\n", record.coq_documents,
                   record.coq_seconds, record.coq_processes);
      }
    }
    // The verdicts first, then the report: the report is the last thing written, so that a signal
    // at any moment before its directory is swapped into place leaves the previous one as it was.
    // A harness fault first, in its own words: it is no verdict on the paper.
    for (const std::string& error : record.internal_errors) {
      fmt::print(stderr, "simpson-verify: internal error (a bug in the harness) in {}\n", error);
    }
    for (const claim_outcome& o : record.outcomes) {
      const bool faulted = o.result.evidence.contains("error");
      const bool expected_verdict = faulted || as_expected(o.result.outcome, o.expected);
      if (!quiet) {
        fmt::print("  {:<8} {:<34}{}\n", faulted ? "fault" : to_string(o.result.outcome), o.checked->id,
                   faulted            ? "  <- the check threw (a bug in the harness)"
                   : expected_verdict ? ""
                   : record.validation ? (cause_of(o).empty() ? "  <- does not hold" : "  <- follows from " + cause_of(o))
                                       : "  <- expected " + to_string(o.expected));
        if (o.result.outcome == verdict::erratum && !o.result.correction.empty()) {
          fmt::print("           corrected: {}\n", o.result.correction);
        }
      }
      if (!expected_verdict && record.validation) {
        fmt::print(stderr, "simpson-verify: {}: {}{}\n", o.checked->id, to_string(o.result.outcome),
                   cause_of(o).empty() ? "" : ", a consequence of " + cause_of(o));
      } else if (!expected_verdict) {
        fmt::print(stderr, "simpson-verify: {}: verdict {}, expected {}\n", o.checked->id, to_string(o.result.outcome),
                   to_string(o.expected));
      }
    }
    for (const std::string& id : rejected_certificates(record)) fmt::print(stderr, "simpson-verify: {}: coqc rejected its certificate\n", id);
    for (const std::string& key : failed_expectations(record)) {
      fmt::print(stderr, "simpson-verify: expectation {} failed: the run did not show what was predicted (report.md, Failures)\n", key);
    }
    const plot_outcome plots = write_report_files(out, record);
    for (const std::string& failure : plots.failures) fmt::print(stderr, "simpson-verify: warning: plot not drawn: {}\n", failure);
    const std::string scene_text = s.name + (s.selection.empty() ? "" : ": " + s.selection);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const int code = run_exit_code(record);
    if (quiet) {
      fmt::print("{} (scene {}, seed {}, {:.1f} s)\n", summary_line(record), scene_text, s.seed, seconds);
      return code;
    }
    // The Φ₃ table concerns the scene's claims as a whole: a run of a selection does not print it.
    if (s.selection.empty() && !record.outcomes.empty() && record.paper_configuration.is_object()) {
      fmt::print("\nPhi3 at the paper's configuration ({})\n{:<12} {:<10} {:<27} {:<11} {:<13} {}\n",
                 record.paper_configuration["parameters"].get<std::string>(), "precision", "epsilon", "alpha = delta",
                 "det-1", "Delta", "Hd(Phi3 y)-Hd(y)");
      for (const auto& row : record.paper_configuration["rows"]) {
        fmt::print("{:<12} {:<10} {:<27} {:<11} {:<13} {}\n", row["precision"].get<std::string>(),
                   row["epsilon"].get<std::string>(), row["alpha_equals_delta"].get<std::string>(),
                   row["det_minus_one"].get<std::string>(), row["discriminant"].get<std::string>(),
                   row["hd_change_one_step"].get<std::string>());
      }
    }
    fmt::print("\n{} (scene {}, seed {}, {:.1f} s)\n{}\nreport: {}, {}, {}\n", summary_line(record), scene_text, s.seed, seconds,
               expectation_line(record), (out / "report.md").string(), (out / "report.json").string(),
               (out / "report.junit.xml").string());
    if (!record.sections.empty()) {
      fmt::print("sections: ");
      for (std::size_t k = 0; k < record.sections.size(); ++k) fmt::print("{}{}", k ? ", " : "", record.sections[k].name);
      fmt::print(" ({} plots drawn); html: {}\n", plots.drawn.size(), (out / "report.html").string());
    } else {
      fmt::print("html: {}\n", (out / "report.html").string());
    }
    return code;
  } catch (const interrupted& e) {
    return interrupted_exit(e);
  } catch (const std::filesystem::filesystem_error& e) {  // writing the report: the output directory
    fmt::print(stderr, "simpson-verify: --out '{}': cannot write the report ({}); the previous report, if any, is unchanged\n",
               out.string(), e.code().message());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "simpson-verify: internal error (a bug in the harness): %s\n", e.what());
    return 3;
  }
}

// simpson-verify's run of a scene (cli_commands.hpp): the options checked into a scene, a book and
// a paper before anything runs (bad input: exit 2, nothing written), then the run, its lines on
// stdout and stderr, and its report.

#include "cli_commands.hpp"

#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/certify.hpp>
#include <simpson/verify/environment.hpp>
#include <simpson/verify/formula_reference.hpp>
#include <simpson/verify/experiment_cost.hpp>
#include <simpson/verify/interruption.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/output_location.hpp>
#include <simpson/verify/progress.hpp>
#include <simpson/verify/report.hpp>
#include <simpson/verify/report_compare.hpp>
#include <simpson/verify/scene.hpp>
#include <simpson/verify/selection.hpp>
#include <simpson/verify/sentence_holes.hpp>
#include <simpson/verify/verdict_table.hpp>

#include <fmt/core.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <unistd.h>
#include <vector>

namespace simpson::verify {
namespace {

extern "C" void record_signal(int signal) { interruption_signal().store(signal); }

/// Progress of long sections on stderr, at most two updates a second: on a terminal one line
/// rewritten in place with a percentage, otherwise plain lines.
progress_sink progress_on_stderr() {
  using clock = std::chrono::steady_clock;
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  auto last = std::make_shared<clock::time_point>(clock::now());
  return [terminal, last](const std::string& section, const std::string& what, double fraction) {
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
  };
}

/// The exit code of a run stopped by a signal: 128 + its number (130 for SIGINT, 143 for SIGTERM).
int interrupted_exit(const interrupted& e) {
  std::fprintf(stderr, "simpson-verify: interrupted (%s); stopped, no report written\n",
               e.signal() == SIGINT ? "SIGINT" : e.signal() == SIGTERM ? "SIGTERM" : "signal");
  return 128 + e.signal();
}

/// An integer option's value from min to max; bad input otherwise (std::invalid_argument naming it).
unsigned long long parse_count(const std::string& flag, const std::string& text, unsigned long long min, unsigned long long max) {
  std::size_t used = 0;
  unsigned long long v = 0;
  try {
    if (text.empty() || text.front() == '-') throw std::invalid_argument("");
    v = std::stoull(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || used == 0 || v < min || v > max) {
    throw std::invalid_argument(flag + " '" + text + "': expected an integer from " + std::to_string(min) + " to " + std::to_string(max));
  }
  return v;
}

/// A list the command line asks for, printed: its exit code; none when it asks for no list.
std::optional<int> list_asked(const cli_options& o, const claim_book& book) {
  if (o.want_claims) return list_claims(book, o.list_format);
  if (o.want_scenes) return list_scenes();
  if (o.want_precisions) return list_precisions();
  if (o.want_sections) return list_sections();
  if (o.want_verdicts) return list_verdicts();
  if (o.want_holes) fmt::print("{}", simpson::verify::holes_markdown());
  if (o.want_facts) fmt::print("{}", simpson::verify::published_facts_markdown(book));
  if (o.want_core) fmt::print("{}", simpson::verify::core_formulas_markdown(book));
  if (o.want_holes || o.want_facts || o.want_core) return 0;
  return std::nullopt;
}

/// --seed, --samples, --enclosure-budget into the scene (and its overrides).
void apply_run_numbers(const cli_options& o, scene& s) {
  if (!o.seed_text.empty()) {
    s.seed = parse_count("--seed", o.seed_text, 0, ~0ULL);
    s.overrides["seed"] = s.seed;
  }
  if (!o.samples_text.empty()) {
    s.samples = static_cast<unsigned>(parse_count("--samples", o.samples_text, 1, 10000));
    s.overrides["samples"] = s.samples;
  }
  if (!o.enclosure_budget_text.empty()) {
    s.enclosure_budget_digits = static_cast<unsigned>(parse_count("--enclosure-budget", o.enclosure_budget_text, 40, 20480));
    s.overrides["enclosure_budget_digits"] = s.enclosure_budget_digits;
  }
}

/// The run-wide options (--timing-runs, --no-timing, --long) checked against the scene's sections
/// and recorded in its overrides; --long adds the sections that run long. `o.allow_expensive` is set
/// by --long.
section_options run_options(cli_options& o, scene& s, const claim_book& book) {
  if (!o.timing_runs_text.empty() && o.no_timing) throw std::invalid_argument("--timing-runs and --no-timing exclude each other");
  // The run-wide options, each applied by the sections that take it (experiment_section.hpp).
  section_options options;
  if (!o.timing_runs_text.empty()) {
    const auto runs = static_cast<unsigned>(parse_count("--timing-runs", o.timing_runs_text, 1, 1000));
    std::vector<std::string> timed;
    for (const experiment_section* section : book.sections) {
      if (section->times_runs()) timed.push_back(section->name());
    }
    const bool any_timed = std::any_of(s.experiments.entries().begin(), s.experiments.entries().end(),
                                       [](const experiment_settings::entry& e) { return e.section->times_runs(); });
    if (!any_timed) {
      throw std::invalid_argument(fmt::format("--timing-runs: the run has no {} section, the only ones timed by repeats", fmt::join(timed, " or ")));
    }
    options.timing_runs = runs;
    s.overrides["timing_runs"] = runs;
  }
  if (o.no_timing) {
    s.timing = false;
    options.timed = false;
    s.overrides["timing"] = false;
  }
  if (o.long_run) {
    for (const experiment_section* section : book.sections) {
      if (section->runs_long() && !s.experiments.has(section->name())) s.experiments.set(*section, section->defaults({}), book.sections);
    }
    options.long_run = true;
    o.allow_expensive = true;
    s.overrides["long"] = true;
  }
  return options;
}

/// The run's estimated cost; bad input when it exceeds the budget without --allow-expensive.
cost_estimate checked_cost(const scene& s, const claim_book& book, bool allow_expensive) {
  recheck_load rechecks{0, s.samples, s.precisions};
  for (const std::string& id : s.claims) {
    const std::vector<std::string>& methods = book.find(id).methods;
    if (std::find(methods.begin(), methods.end(), "numeric") != methods.end()) ++rechecks.numeric_claims;
  }
  const cost_estimate cost = estimate_cost(s.experiments, rechecks);
  if (cost.units > default_cost_budget && !allow_expensive) {
    std::string parts;
    for (const std::string& line : cost.lines) parts += (parts.empty() ? "" : "; ") + line;
    throw std::invalid_argument(fmt::format("scene '{}': estimated cost {:.3g} units (about {}) exceeds the budget {:.3g} "
                                            "units (about {}) ({}); pass --allow-expensive to run it anyway",
                                            s.name, cost.units, seconds_text(cost.units), default_cost_budget,
                                            seconds_text(default_cost_budget), parts));
  }
  return cost;
}

/// What a run needs, checked: its scene, its book, its paper read, its output directory, its cost.
struct prepared_run {
  scene s;
  std::shared_ptr<claim_book> book;
  std::optional<paper_reading> paper;
  std::filesystem::path out;
  cost_estimate cost;
};

/// Reads and checks everything the run needs into `r`; the exit code when the command ends here (a
/// list asked for: 0; bad input: 2, one line on stderr; a harness fault: 3), none when the run may start.
std::optional<int> prepare_run(cli_options& o, const CLI::App& app, int argc, char** argv, prepared_run& r) {
  // From here on a signal is recorded, not acted on: a run started in the background by a shell
  // ignores SIGINT until it installs a handler, so one that came while the scene, the paper and the
  // shape records were read would be lost (the run would finish). It is honoured below, before the run.
  std::signal(SIGINT, record_signal);
  std::signal(SIGTERM, record_signal);
  scene& s = r.s;
  std::optional<paper_reading>& paper = r.paper;
  // The run's book: the paper's, or the claims file's (read below: a note's run never builds the
  // paper's); read once, bound to its document once, and passed to the run.
  r.book = o.claims_file.empty() ? std::make_shared<claim_book>(paper_book()) : std::make_shared<claim_book>();
  std::shared_ptr<claim_book>& book = r.book;
  std::filesystem::path& out = r.out;
  cost_estimate& cost = r.cost;
  try {
    if (!o.claims_file.empty()) {
      std::ifstream in(o.claims_file, std::ios::binary);
      if (!in) throw std::invalid_argument("claims file '" + o.claims_file + "': cannot be read");
      const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      *book = read_claim_book(text, o.claims_file);  // a file that does not read is bad input: nothing runs
    }
    if (const std::optional<int> listed = list_asked(o, *book)) return listed;
    s = load_scene(o.scene_name, *book);
    if (!o.paper_file.empty()) s.paper_file = o.paper_file;
    if (const claims_document* document = book->checked_document()) {
      // A document's claims file: its claims alone, in a scene named after the file (its report in
      // reports/out/<name>); none of the paper's sections unless --sections asks for them.
      s.name = std::filesystem::path(o.claims_file).stem().string();
      s.description = fmt::format("The claims of {} on “{}” ({}): formulas read from its LaTeX, decided by proof shapes.", o.claims_file,
                                  document->title, o.paper_file.empty() ? std::string("no --paper") : o.paper_file);
      s.experiments = experiment_settings{};
    }
    scene_selection selection;
    if (app.count("--claims") > 0) selection.claims = o.claim_ids;
    if (app.count("--sections") > 0) selection.sections = o.section_list;
    apply_selection(s, selection, *book);
    paper = read_scene_paper(s, *book);  // a paper that is missing or does not parse is bad input: nothing runs
    if (!o.paper_file.empty()) s.overrides["paper"] = o.paper_file;
    if (!o.claims_file.empty()) s.overrides["claims_file"] = o.claims_file;
    if (o.accept_fixes) {
      s.accept_fixes = true;
      s.overrides["accept_fixes"] = true;
    }
    if (!o.baseline.empty()) apply_baseline(s, load_report(o.baseline, "--baseline"), o.baseline);  // a report that does not load: bad input
    if (o.validate) {
      for (const std::string& id : s.claims) s.expected_overrides[id] = verdict::holds;
      s.overrides["validate"] = true;
    }
    if (app.count("--precisions") > 0) apply_precisions(s, o.precision_names);
    apply_run_numbers(o, s);
    section_options options = run_options(o, s, *book);
    s.command_line.assign(argv, argv + argc);
    for (experiment_settings::entry& section : s.experiments.entries()) section.section->apply(section.settings, options);
    cost = checked_cost(s, *book, o.allow_expensive);
    if (o.certify && coqc_version().empty()) throw std::invalid_argument("--certify: coqc was not found (install Debian's coq)");
    // Checked wherever coqc is installed, unless --no-certify.
    if (!o.certify && !o.no_certify) o.certify = !coqc_version().empty();
    options.certify = o.certify;  // Gappa's proofs and the lifting lemmas of the floating section
    for (experiment_settings::entry& section : s.experiments.entries()) section.section->apply(section.settings, options);
    out = output_directory(s, app.count("--out") > 0 ? std::optional<std::string>(o.out_dir) : std::nullopt);
    prepare_output_directory(out);
  } catch (const std::invalid_argument& e) {
    for (const std::string& line : simpson::verify::lines_of(e.what())) std::fprintf(stderr, "simpson-verify: %s\n", line.c_str());  // a claims file's refusals, one a line
    return 2;
  } catch (const std::domain_error& e) {
    std::fprintf(stderr, "simpson-verify: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "simpson-verify: internal error (a bug in the harness): %s\n", e.what());
    return 3;
  }
  return std::nullopt;
}

/// Runs the prepared scene: the verdicts on stdout and stderr, then the report, written last.
/// What a claim's line on stdout points at, from its row of the verdict table: nothing when it is
/// as expected, else why it fails the run, briefly (stderr says it whole).
std::string pointer(const verdict_row& row, const claim_outcome& o, bool validation) {
  if (row.state == verdict_row::status::error) return "  <- the check threw (a bug in the harness)";
  if (!fails_the_run(row)) return "";
  if (row.type == "does-not-hold") return "  <- does not hold";
  if (row.type == "consequence") return "  <- follows from " + cause_of(o);
  if (row.type == "erratum-changed") return "  <- not the recorded erratum";
  if (row.type == "remark-changed") return "  <- not the recorded remark";
  if (row.type == "changed") return cause_of(o).empty() ? "  <- changed: nothing it reads changed" : "  <- changed: follows from " + cause_of(o) + ", not a fix";
  if (row.type == "fixed") return "  <- fixed (recorded " + row.expected + ")";
  if (row.type == "certificate-rejected") return "  <- coqc rejected its certificate";
  return validation ? "  <- no judgment (" + row.type + ")" : "  <- expected " + row.expected;  // unexpected, undecided, unproved, text-changed
}

int execute_run(prepared_run& r, const cli_options& o, const claim_checker& checker) {
  scene& s = r.s;
  const std::shared_ptr<claim_book>& book = r.book;
  const std::optional<paper_reading>& paper = r.paper;
  const std::filesystem::path& out = r.out;
  const cost_estimate& cost = r.cost;
  if (s.experiments.any() && !o.quiet) {
    fmt::print(stderr, "experiments: estimated cost {:.3g} units, about {} (budget {:.3g} units, about {})\n", cost.units,
               seconds_text(cost.units), default_cost_budget, seconds_text(default_cost_budget));
  }
  const progress_sink work = s.experiments.any() && !o.quiet ? progress_on_stderr() : progress_sink{};
  try {
    throw_if_interrupted();  // a signal while the run was being set up: nothing was written yet
    const auto start = std::chrono::steady_clock::now();
    run_record record = run(s, book, *paper, [&](std::size_t k, std::size_t n, const claim& c, const claim_outcome* done) {
      if (!done || o.quiet) return;
      fmt::print(stderr, "[{:>2}/{}] {:<34} {:<8} {:.2f} s\n", k + 1, n, c.id,
                 done->threw ? "threw" : to_string(done->result.outcome), done->seconds);
    }, [quiet = o.quiet](const std::string& section, double seconds) {
      if (quiet) return;
      if (::isatty(STDERR_FILENO)) fmt::print(stderr, "\r\033[K");
      fmt::print(stderr, "[section] {:<34} {:.2f} s\n", section, seconds);
    }, work, checker);
    throw_if_interrupted();
    if (o.certify && !record.outcomes.empty()) {
      if (!o.quiet) fmt::print(stderr, "[coqc] checking the claims' Coq certificates ...\n");
      record_certificates(record, true);
      if (!o.quiet && record.coq_documents > 0) {
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
    // One line per claim on stdout, and what fails the run on stderr, both from the verdict table.
    const std::vector<verdict_row> rows = verdict_table(record);
    if (!o.quiet) {
      for (std::size_t k = 0; k < record.outcomes.size(); ++k) {
        const claim_outcome& c = record.outcomes[k];
        fmt::print("  {:<8} {:<34}{}\n", rows[k].state == verdict_row::status::error ? "fault" : rows[k].verdict, rows[k].name,
                   pointer(rows[k], c, record.validation));
        if (meaning(c.result.outcome).corrected && !c.result.correction.empty()) fmt::print("           corrected: {}\n", c.result.correction);
        if (!c.result.remark.empty()) fmt::print("           remark ({}): {}\n", to_string(c.result.remark_kind), c.result.remark);
      }
    }
    for (const verdict_row& row : rows) {  // an error was named above, in its own words
      if (row.state != verdict_row::status::failed) continue;
      fmt::print(stderr, "simpson-verify: {}{}: {}\n", row.expectation ? "expectation " : "", row.name, row.message);
    }
    const plot_outcome plots = write_report_files(out, record);
    for (const std::string& failure : plots.failures) fmt::print(stderr, "simpson-verify: warning: plot not drawn: {}\n", failure);
    const std::string scene_text = s.name + (s.selection.empty() ? "" : ": " + s.selection);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const int code = run_exit_code(record);
    if (o.quiet) {
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
  } catch (const claims_file_error& e) {  // an argument only its claim's run could judge: bad input, nothing written
    for (const std::string& line : simpson::verify::lines_of(e.what())) std::fprintf(stderr, "simpson-verify: %s\n", line.c_str());
    return 2;
  } catch (const document_error& e) {
    for (const std::string& line : simpson::verify::lines_of(e.what())) std::fprintf(stderr, "simpson-verify: %s\n", line.c_str());
    return 2;
  } catch (const std::filesystem::filesystem_error& e) {  // writing the report: the output directory
    fmt::print(stderr, "simpson-verify: --out '{}': cannot write the report ({}); the previous report, if any, is unchanged\n",
               out.string(), e.code().message());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "simpson-verify: internal error (a bug in the harness): %s\n", e.what());
    return 3;
  }
}

}  // namespace

int run_command(cli_options& o, const CLI::App& app, int argc, char** argv, const claim_checker& checker) {
  prepared_run r;
  if (const std::optional<int> code = prepare_run(o, app, argc, argv, r)) return *code;
  return execute_run(r, o, checker);
}

}  // namespace simpson::verify

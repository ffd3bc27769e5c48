// The floating section (floating_section.hpp).

#include <simpson/verify/floating_section.hpp>
#include <simpson/verify/progress.hpp>

#include <simpson/verify/gappa_run.hpp>
#include <simpson/verify/global_roundoff.hpp>
#include <simpson/verify/stepper_roundoff.hpp>

#include <fmt/format.h>

#include <simpson/verify/command.hpp>
#include <simpson/verify/coq_batch.hpp>

#include <algorithm>
#include <optional>

namespace simpson::verify {
namespace {

constexpr unsigned long long sampling_seed = 20231025;

std::string status_text(const roundoff_proof& proof) {
  switch (proof.status) {
    case proof_status::proved: return "proved";
    case proof_status::unproved: return "unproved: " + proof.reason;
    case proof_status::skipped: return "skipped: " + proof.reason;
  }
  return "?";
}

/// The section's Coq files (Gappa's proofs, the lifting lemmas), checked together once every row is
/// computed (coq_batch.hpp: a few coqc processes, each loading Gappa's and Flocq's libraries once,
/// instead of one process per file). A row keeps the indices of its files and its cells; its Coq cell
/// is written after the check.
class coq_queue {
 public:
  explicit coq_queue(bool check) : check_(check) {}
  std::size_t add(const std::string& name, const std::string& text) {
    documents_.push_back({name + "_" + std::to_string(documents_.size()), text});
    return documents_.size() - 1;
  }
  void run() {
    if (!check_ || documents_.empty()) return;
    if (!program_on_path("coqc")) {
      missing_ = true;
      return;
    }
    verdicts_ = check_with_coqc(documents_);
  }
  /// "checked" when coqc accepted every file, "rejected: …" with the first rejected file's message,
  /// "not checked" without --certify's coqc or without coqc on the machine.
  std::string status(const std::vector<std::size_t>& files) const {
    if (!check_) return "not checked";
    if (missing_) return "not checked: coqc not found (scripts/install-deps installs Debian's coq and libcoq-gappa)";
    for (const std::size_t k : files) {
      if (!verdicts_.at(k).accepted) return "rejected: " + verdicts_.at(k).message;
    }
    return "checked";
  }

 private:
  bool check_;
  bool missing_ = false;
  std::vector<coq_document> documents_;
  std::vector<coq_verdict> verdicts_;
};

/// A row whose last cell, the Coq status of `files`, is written after the queue's check.
struct pending_row {
  table_row cells;
  std::vector<std::size_t> files;
  bool coq_cell = true;  // false: the row has no proof, its last cell is already written
};

void add_rows(table& t, std::vector<pending_row>& rows, const coq_queue& queue) {
  for (pending_row& r : rows) {
    if (r.coq_cell) r.cells.push_back(figure::text(queue.status(r.files)));
    t.add(std::move(r.cells));
  }
}

/// One lifted case: a stepper in a format from y₀ = (p, q) = (0, 1) over the steps `at`, at m = ω = 1
/// or at the paper's configuration (Section 8: m = 1, ω = 2π, h = 1/15).
struct global_case {
  std::string stepper, format;
  rational h;
  std::vector<long long> at;
  bool verinum = false;  // VeriNum's setting: their published bound beside ours
  bool paper = false;    // ω = 2π
};

/// VerifiedLeapfrog's proved bound (Kellison & Appel, NSV 2022) on ‖(p, q)(t_n) − float iterate‖
/// for float32 leapfrog, h = 1/32, ω = 1, (q₀, p₀) = (1, 0), at every n ≤ 1000.
constexpr const char* verinum_bound = "0.0308";
constexpr long long verinum_steps = 1000;

/// The global table's rows into `pending` (their Coq cells written after the queue's check); returns
/// the plot of the bounds against the errors seen.
plot_description add_global(const floating_settings& s, coq_queue& queue, std::vector<pending_row>& pending) {
  const rational box(9, 8);  // room for the orbit of energy 1/2 and the bound's growth
  const rational paper_p_box(7);  // ω = 2π: |p| reaches mω ≈ 6.28 on the orbit from (0, 1)
  const phase_point<rational> y0{rational(0), rational(1)};
  const rational h(1, s.h_denominator), paper_h(1, 15);
  std::vector<global_case> cases{{"leapfrog-verinum", "float32", rational(1, 32), {10, 100, 1000}, true},
                                 {"phi3-matrix", "float32", h, {10, 100, 1000, 10000, 100000}},
                                 {"phi3-matrix", "double", h, {10, 100, 1000, 10000, 100000, 1000000}},
                                 {"phi3-shear", "double", h, {10, 100, 1000, 10000, 100000, 1000000}},
                                 {"newmark-matrix", "double", h, {10, 100, 1000, 10000, 100000}}};
  if (s.paper_configuration) {
    cases.push_back({"phi3-matrix", "float32", paper_h, {15, 150, 1500, 15000, 150000}, false, true});
    cases.push_back({"phi3-matrix", "double", paper_h, {15, 150, 1500, 15000, 150000, 1000000}, false, true});
  }
  panel in_float{"float32", {"n (steps)", true}, {"‖ŷ_n − Φⁿy₀‖₂", true}, {}, "top left"};
  panel in_double{"double", {"n (steps)", true}, {"‖ŷ_n − Φⁿy₀‖₂", true}, {}, "top left"};
  const auto color_of = [&](const std::string& stepper) {
    const auto& names = proved_steppers();
    return static_cast<int>(std::find(names.begin(), names.end(), stepper) - names.begin());
  };
  for (const global_case& c : cases) {
    const rational omega = c.paper ? paper_omega() : rational(1);
    const roundoff_problem problem =
        stepper_roundoff_problem(c.stepper, c.format, rational(1), omega, c.h, c.paper ? paper_p_box : box, box);
    const roundoff_proof proof = prove_roundoff(problem, false);  // coqc after every row: coq_queue
    const std::string name = c.stepper + " " + c.format + (c.paper ? " ω = 2π" : "");
    const figure omega_text = figure::text(c.paper ? "2π" : "1");
    const flow_oscillator flow{rational(1), rational(1), c.paper};
    if (proof.status != proof_status::proved) {
      pending.push_back({{figure::text(c.stepper), figure::text(c.format), omega_text, figure::text(c.h.str()), figure{}, figure{}, figure{},
                          figure{}, figure{}, figure{}, figure{}, figure{}, figure{}, figure{}, figure::text(status_text(proof))},
                         {}, false});
      continue;
    }
    const std::optional<lifting_constants> lifting = lifting_for(problem, proof.bounds, y0);
    if (!lifting) {
      pending.push_back({{figure::text(c.stepper), figure::text(c.format), omega_text, figure::text(c.h.str()), figure{}, figure{}, figure{},
                          figure{}, figure{}, figure{}, figure{}, figure{}, figure{}, figure{},
                          figure::text("no diagonal invariant form: not lifted")},
                         {}, false});
      continue;
    }
    // The row's one-step bound and its lifting: both files must be accepted.
    const std::vector<std::size_t> files{queue.add("gappa", proof.certificate),
                                         queue.add("lifting", lifting_lemma_coq(problem, proof.bounds, *lifting))};
    std::vector<long long> at;
    for (const long long n : c.at) {
      if (n <= lifting->valid_steps) at.push_back(n);
    }
    const std::string label = c.stepper + (c.paper ? " (ω = 2π)" : "");
    const int color = c.paper ? static_cast<int>(proved_steppers().size()) : color_of(c.stepper);
    // A dash type of its own per stepper: two bounds that coincide (the same n ε) both stay visible.
    series bound_curve(label + " bound", line_style::lines, color, 7, 1 + color % 5), seen_curve(label + " seen", line_style::points, color);
    std::vector<global_row> rows = global_comparison(problem, *lifting, c.h, y0, at, flow);
    // VerifiedLeapfrog's bound holds at every n ≤ 1000: it is set beside our bound uniform over
    // n ≤ 1000 and the largest error made over n ≤ 1000, like with like.
    if (c.verinum && verinum_steps <= lifting->valid_steps) rows.push_back(global_uniform(problem, *lifting, c.h, y0, verinum_steps, flow));
    for (const global_row& r : rows) {
      pending.push_back({{figure::text(c.stepper), figure::text(c.format), omega_text, figure::text(c.h.str()),
                          r.uniform ? figure::text("≤ " + std::to_string(r.n)) : figure::integer(r.n),
                          figure::integer(lifting->valid_steps), figure::text(r.roundoff_bound), figure::text(r.roundoff_seen),
                          figure::of(r.roundoff_bound_over_seen), figure::text(r.discretization), figure::text(r.total_bound),
                          figure::text(r.total_seen), figure::of(r.bound_over_seen),
                          c.verinum && r.uniform ? figure::text(verinum_bound) : figure{}},
                         files});
      if (r.uniform) continue;
      bound_curve.add(figure::integer(r.n), figure::of(std::stod(r.roundoff_bound)));
      seen_curve.add(figure::integer(r.n), figure::of(std::stod(r.roundoff_seen)));
      progress_step(s.progress, "floating", name + " n = " + std::to_string(r.n));
    }
    // The proved formula beyond the runs: n = 10^9 where the box still holds the orbit.
    const long long far = 1'000'000'000;
    if (c.format == "double" && far <= lifting->valid_steps) {
      const rational bound = rational(far) * lifting->epsilon * lifting->to_euclidean;
      pending.push_back({{figure::text(c.stepper), figure::text(c.format), omega_text, figure::text(c.h.str()), figure::integer(far),
                          figure::integer(lifting->valid_steps), figure::text(decimal_rounded_up(bound)), figure::text("not run"), figure{},
                          figure{}, figure{}, figure{}, figure{}, figure{}},
                         files});
      // In the table only: on the plot the x axis ends where the runs end.
    }
    panel& into = c.format == "float32" ? in_float : in_double;
    into.curves.push_back(std::move(bound_curve));
    into.curves.push_back(std::move(seen_curve));
  }
  return plot_description{"floating_roundoff",
                           "Proved round-off bound (lines, a dash type per stepper) against the round-off seen (markers) over n "
                           "steps, log-log, per stepper, up to the last n run; each bound is n ε, linear in n (the table also "
                           "gives it at n = 10⁹, not run)",
                           {in_float, in_double}, 2, 1200, 480};
}

/// Which part of the floating results rests on which kernel (issue 29's trust base).
void add_trust_base(section_result& out) {
  table rows{"trust_base", "What each result rests on",
             "Proved: a kernel checked it. Exact: the harness's rational arithmetic (Boost.Multiprecision cpp_rational, GMP "
             "integers), no rounding. Enclosed: MPFI interval arithmetic with outward rounding. Tested: checked on samples, "
             "not proved.",
             {{"part", "part"}, {"rests_on", "rests on"}, {"how", "how"}}};
  const auto row = [&](const char* part, const char* rests_on, const char* how) {
    rows.add({figure::text(part), figure::text(rests_on), figure::text(how)});
  };
  row("the program is the stepper's operation sequence", "tested",
      "rounded_program_test: bit for bit against the stepper on 20 000 random states per format; a reordered program is caught");
  row("the formulas of Φ₃ and Newmark", "GiNaC, Coq", "the ledger's claims derivation-phi3, phi3-explicit and newmark-matrix: exact, symbolic in m, ω, h");
  row("stored coefficients and exact Φ at the run's parameters", "exact", "the core's formulas in the format and in rationals");
  row("one-step bound |fl(step(y)) − Φy| on the box", "Gappa, Coq (Flocq, libcoq-gappa)",
      "Gappa's proof exported with -Bcoq and checked by coqc, including no overflow of any intermediate");
  row("Φ conserves Q = w_p p² + w_q q²", "exact, Coq", "ΦᵀWΦ = W in rationals; again in the lifting lemma (field)");
  row("lifting: ‖ŷ_n − Φⁿy₀‖_Q ≤ n ε while in the box", "Coq (lra, nra)", "the lifting lemma with the harness's constants, checked by coqc");
  row("ε, r₀, the box's ellipse, the steps it holds, the Euclidean factor", "exact", "square roots bounded by rationals, checked by squaring");
  row("discretization ‖Φⁿy₀ − y(t_n)‖₂", "enclosed (MPFI)", "Φⁿ's closed form (a rotation in √W coordinates) and the flow, 40 digits");
  row("round-off and total seen", "enclosed (MPFI)", "the float iterates' exact values against the enclosed Φⁿy₀ and y(t_n)");
  row("total bound = round-off bound + discretization", "exact", "a rational sum; not one Coq theorem (each part is checked on its own)");
  row("the errors seen in one step", "exact", "each float result against Φy in rationals");
  out.add(std::move(rows));
}

}  // namespace

const std::vector<std::string>& floating_stepper_names() { return proved_steppers(); }

section_result run_floating(const floating_settings& s) {
  section_result out;
  out.name = "floating";
  out.title = "Floating-point programs: one-step round-off proved";
  out.conventions = {{"m", 1}, {"omega", 1}, {"h", "1/" + std::to_string(s.h_denominator)}, {"leapfrog_h", "1/32"},
                     {"box", "|p| <= 1, |q| <= 1"}, {"samples", s.samples}, {"seed", sampling_seed}};
  table rows{"one_step", "",
             fmt::format(
                 "Each stepper's operations, in order, as a straight-line program (core/include/simpson/rounded_program.hpp; a "
                 "test checks it against the stepper bit for bit on random states, and that a reordered program is caught). From "
                 "it a Gappa script is written: every operation rounded to nearest-even in the format, the coefficients as the "
                 "stepper stores them (their exact binary values), against the scheme's exact map Φ at the intended parameters "
                 "(m = ω = 1, h = 1/{} for Φ₃ and Newmark; VeriNum's leapfrog at h = 1/32 as its C program writes it), on the box "
                 "|p| ≤ 1, |q| ≤ 1. The bound covers the rounding of the coefficients (Φ̂ against Φ) and of every operation; every "
                 "intermediate is proved below the format's largest finite number (Gappa's formats have no overflow). Gappa's "
                 "proof is exported to Coq (gappa -Bcoq) and checked by coqc with Gappa's Coq library. Bounds are shown rounded "
                 "up. Seen: the largest error of {} random states of the box (seed {}), computed exactly.",
                 s.h_denominator, s.samples, sampling_seed),
             {{"stepper", "stepper"},
              {"format", "format"},
              {"h", "h"},
              {"bound_p", "bound p"},
              {"bound_q", "bound q"},
              {"seen_p", "seen p"},
              {"seen_q", "seen q"},
              {"bound_over_seen", "bound/seen"},
              {"gappa", "Gappa"},
              {"coq", "Coq"}}};
  coq_queue queue(s.check_with_coqc);
  std::vector<pending_row> one_step;
  for (const std::string& stepper : s.steppers) {
    for (const std::string& format : s.formats) {
      const bool leapfrog = stepper == "leapfrog-verinum";
      const rational h = leapfrog ? rational(1, 32) : rational(1, s.h_denominator);
      const roundoff_problem problem = stepper_roundoff_problem(stepper, format, rational(1), rational(1), h, rational(1), rational(1));
      const roundoff_proof proof = prove_roundoff(problem, false);  // coqc after every row: coq_queue
      const claimed_bounds seen = measured_roundoff(problem, s.samples, sampling_seed);
      const bool proved = proof.status == proof_status::proved;
      figure ratio{};
      if (proved && seen.p > 0 && seen.q > 0) {
        const double rp = static_cast<double>(rational(proof.bounds.p / seen.p)), rq = static_cast<double>(rational(proof.bounds.q / seen.q));
        ratio = figure::of(std::max(rp, rq));
      }
      table_row cells{figure::text(stepper), figure::text(format), figure::text(h.str()),
                      proved ? figure::text(decimal_rounded_up(proof.bounds.p)) : figure{},
                      proved ? figure::text(decimal_rounded_up(proof.bounds.q)) : figure{},
                      figure::text(decimal_text(seen.p)), figure::text(decimal_text(seen.q)), ratio,
                      figure::text(status_text(proof))};
      if (proved) {
        one_step.push_back({std::move(cells), {queue.add("gappa", proof.certificate)}});
      } else {
        cells.push_back(figure::text(""));
        one_step.push_back({std::move(cells), {}, false});
      }
      progress_step(s.progress, "floating", stepper + " " + format);
    }
  }
  std::vector<pending_row> global_rows;
  table global{"global", "Over n steps: the one-step bound lifted, and the total error",
             "Each row's one-step bound is proved as in the table above (Gappa, checked by coqc), on the box |p|, |q| ≤ 9/8 "
             "(room for the orbit from y₀ = (p, q) = (0, 1) and the bound's growth); at ω = 2π (the paper's configuration, "
             "Section 8: m = 1, h = 1/15, the same y₀) on |p| ≤ 7, |q| ≤ 9/8, against Φ₃ at ω = 2π rounded to double (the ω "
             "the program holds, exactly), the flow at 2π itself (π enclosed). Φ conserves Q = w_p p² + w_q q² (found from Φ, checked "
             "exactly), so ‖ŷ_n − Φⁿy₀‖_Q ≤ n ε with ε ≥ √(w_p B_p² + w_q B_q²): the lifting lemma, proved in Coq "
             "with these constants (column Coq: this row's one-step Gappa proof and its lifting lemma, both checked by coqc), valid while the iterate stays in the box (the steps column of each stepper says up to "
             "where). Shown in the Euclidean norm (‖z‖₂ ≤ ‖z‖_Q/√min w). Discretization: ‖Φⁿy₀ − y(t_n)‖₂ of the exact scheme "
             "against the exact flow, enclosed in MPFI (40 digits), its upper end. Total: the two bounds added, against the "
             "float iterate's ‖ŷ_n − y(t_n)‖₂ (the lower end of its enclosure). A row n ≤ N holds each figure's largest "
             "value over 1 ≤ n ≤ N: the bound uniform in n (N ε c plus the largest discretization bound) against the largest "
             "error made. VeriNum: VerifiedLeapfrog's proved bound for the same program and setting, which holds at every "
             "n ≤ 1000 (Kellison & Appel, NSV 2022): set beside our row n ≤ 1000, like with like.",
             {{"stepper", "stepper"},
              {"format", "format"},
              {"omega", "ω"},
              {"h", "h"},
              {"n", "n"},
              {"valid_steps", "valid to n"},
              {"roundoff_bound", "round-off bound"},
              {"roundoff_seen", "round-off seen"},
              {"roundoff_bound_over_seen", "ratio"},
              {"discretization", "discretization"},
              {"total_bound", "total bound"},
              {"total_seen", "total seen"},
              {"total_bound_over_seen", "ratio"},
              {"verinum_bound", "VeriNum"},
              {"coq", "Coq (bound, lifting)"}}};
  std::optional<plot_description> plot;
  if (s.global) plot = add_global(s, queue, global_rows);
  progress_step(s.progress, "floating", "coqc on the section's proofs");
  queue.run();
  add_rows(rows, one_step, queue);
  out.add(std::move(rows));
  if (s.global) {
    add_rows(global, global_rows, queue);
    out.add(std::move(global));
    out.add(std::move(*plot));
  }
  add_trust_base(out);
  return out;
}

}  // namespace simpson::verify

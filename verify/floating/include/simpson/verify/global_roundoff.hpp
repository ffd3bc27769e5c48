#pragma once
// From one step to n steps (issue 29): the one-step round-off bound (gappa_run.hpp) lifted over n
// steps in the norm of the exact map's conserved quadratic form, and the total error against the
// exact solution.
//
// The lifting. Φ conserves Q(p, q) = w_p p² + w_q q² (diagonal for every scheme here; found from Φ
// and checked exactly: ΦᵀWΦ = W), so ‖y‖_Q = √Q(y) is a norm in which Φ is an isometry. The float
// iterate is ŷ_{k+1} = Φŷ_k + e_k with |e_k| ≤ (B_p, B_q) while ŷ_k stays in the proved box; then
// d_k = ŷ_k − Φᵏy₀ has d_{k+1} = Φd_k + e_k and ‖d_n‖_Q ≤ n ε, ε ≥ √(w_p B_p² + w_q B_q²): linear
// in n, not geometric. ŷ_k stays in the box while ‖y₀‖_Q + kε ≤ min(P√w_p, Q√w_q) (the ellipse of
// that radius fits in the box): the bound holds up to that n (valid_steps). The lemma, with the
// constants below, is proved in Coq (lifting_lemma_coq, checked by coqc).
//
// The total. ‖ŷ_n − y(t_n)‖₂ ≤ ‖d_n‖_Q/√min(w) + ‖Φⁿy₀ − y(t_n)‖₂, the second term (the exact
// scheme against the exact flow) enclosed in interval arithmetic (MPFI), not estimated.

#include <simpson/verify/gappa_script.hpp>

#include <optional>
#include <string>
#include <vector>

namespace simpson::verify {

/// The lifting's constants, exact rationals.
struct lifting_constants {
  rational w_p, w_q;  // Q = w_p p² + w_q q², Φ-invariant (checked exactly)
  rational epsilon;   // ε ≥ √(w_p B_p² + w_q B_q²), a rational upper bound (checked exactly)
  rational radius0;   // r₀ ≥ ‖y₀‖_Q (checked exactly)
  rational fits;      // ρ ≤ min(P√w_p, Q√w_q): the box holds the ellipse ‖y‖_Q ≤ ρ (checked exactly)
  long long valid_steps = 0;  // the largest n with r₀ + nε ≤ ρ
  rational to_euclidean;      // c ≥ 1/√min(w_p, w_q): ‖z‖₂ ≤ c ‖z‖_Q
};

/// The constants for a proved one-step bound from y₀; none when Φ conserves no diagonal positive
/// form (then nothing is lifted).
std::optional<lifting_constants> lifting_for(const roundoff_problem& problem, const claimed_bounds& one_step,
                                             const phase_point<rational>& y0);

/// One row of the comparison at n steps: every figure as text (bounds rounded up).
struct global_row {
  long long n = 0;
  bool uniform = false;             // every figure is the largest over 1 ≤ k ≤ n (global_uniform), not at n
  std::string roundoff_bound;       // n ε c: ‖ŷ_n − Φⁿy₀‖₂ proved
  std::string roundoff_seen;        // ‖ŷ_n − Φⁿy₀‖₂ of the float iterate (enclosed, shown to 3 digits)
  std::string discretization;       // ‖Φⁿy₀ − y(t_n)‖₂, the upper end of its enclosure (rounded up)
  std::string total_bound;          // the two bounds added
  std::string total_seen;           // ‖ŷ_n − y(t_n)‖₂ of the float iterate, the lower end of its enclosure
  double bound_over_seen = 0;       // total_bound / total_seen
  double roundoff_bound_over_seen = 0;
};

/// The oscillator whose exact flow the iterates are compared with: mass m and ω, or ω = 2π (the
/// paper's, Section 8) when `two_pi`. With ω = 2π, π is enclosed; the problem's exact map is then Φ
/// at 2π rounded to double (stepper_roundoff.hpp's paper_omega), and the scheme's difference
/// from Φ at 2π lies inside the enclosed discretization term.
struct flow_oscillator {
  rational m{1};
  rational omega{1};
  bool two_pi = false;
};

/// Runs the program in its format from y₀ (the problem's h) and compares at each n of `at` (each at
/// most lifting.valid_steps): the float iterate against the exact scheme and the exact solution of
/// `flow`, enclosed at 40 digits.
std::vector<global_row> global_comparison(const roundoff_problem& problem, const lifting_constants& lifting, const rational& h,
                                          const phase_point<rational>& y0, const std::vector<long long>& at,
                                          const flow_oscillator& flow = {});

/// Over every k ≤ n at once (1 ≤ n ≤ lifting.valid_steps): a bound uniform in k, n ε c plus the
/// largest discretization error's upper end, against the largest error made, max_k ‖ŷ_k − y(t_k)‖₂.
/// A published bound that holds at every k ≤ n compares with this row, not with the row at n.
global_row global_uniform(const roundoff_problem& problem, const lifting_constants& lifting, const rational& h,
                          const phase_point<rational>& y0, long long steps, const flow_oscillator& flow = {});

/// The lifting lemma as a Coq file (standard library reals, lra and nra): for the exact Φ and Q,
/// Q(Φz) = Q(z); |e_p| ≤ B_p ∧ |e_q| ≤ B_q ⇒ Q(e) ≤ ε²; and d_{k+1} = Φd_k + e_k with those e_k and
/// d₀ = 0 ⇒ √Q(d_n) ≤ n ε. The constants are the harness's, exactly.
std::string lifting_lemma_coq(const roundoff_problem& problem, const claimed_bounds& one_step, const lifting_constants& lifting);

}  // namespace simpson::verify

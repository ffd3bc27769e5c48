// Section 2: Newmark's map named as one of Newmark's family (the other claims of Section 2 are proof
// shapes' records in claims/paper.toml).

#include "claim_support.hpp"
#include "bespoke_checks.hpp"

#include <simpson/verify/quoted_words.hpp>

#include <simpson/verify/tex_math.hpp>  // canonical_text

#include <ginac/ginac.h>

#include <simpson/newmark_map.hpp>

namespace simpson::verify::detail {
namespace {

/// Newmark's scheme for m q'' + m ω² q = 0 with parameters (β, γ), v = p/m, a = −ω² q:
///   q₁ = q + h v + h² ((1/2 − β) a + β a₁),  v₁ = v + h ((1 − γ) a + γ a₁).
/// Solved for (q₁, v₁) in GiNaC with every symbol free; at β = 1/4, γ = 1/2 the map must be Φ.
claim_result check_newmark_identification(const run_context& ctx) {
  const quoted_sentence said =
      quote(ctx, "the numerical scheme (\\ref{systeme-symplectique-ordre-2}) is one particular inconditionally stable version of the {family} scheme");
  said.choice("family", {{"Newmark", "Newmark (beta, gamma) family"}});
  const GiNaC::symbol m("m"), w("omega"), h("h"), p("p"), q("q"), q1("q1"), v1("v1"), beta("beta"), gamma("gamma");
  const GiNaC::ex v = p / m, a = -w * w * q, a1 = -w * w * q1;
  const GiNaC::ex solution = GiNaC::lsolve(
      GiNaC::lst{q1 == q + h * v + h * h * ((GiNaC::numeric(1, 2) - beta) * a + beta * a1), v1 == v + h * ((1 - gamma) * a + gamma * a1)},
      GiNaC::lst{q1, v1});
  const GiNaC::ex q_next = GiNaC::ex(q1).subs(solution), p_next = m * GiNaC::ex(v1).subs(solution);
  const GiNaC::lst average_acceleration{beta == GiNaC::numeric(1, 4), gamma == GiNaC::numeric(1, 2)};
  const one_step_matrix<GiNaC::ex> phi = newmark_map(oscillator_parameters<GiNaC::ex>{m, w, h});
  const GiNaC::ex dp = GiNaC::normal(p_next.subs(average_acceleration) - (phi.alpha * p + phi.beta * q));
  const GiNaC::ex dq = GiNaC::normal(q_next.subs(average_acceleration) - (phi.gamma * p + phi.delta * q));
  // And the family: det of the Newmark map is 1 exactly when γ = 1/2 (symplectic), for any β.
  const GiNaC::ex a11 = GiNaC::normal(p_next.diff(p)), a12 = GiNaC::normal(p_next.diff(q)), a21 = GiNaC::normal(q_next.diff(p)),
                  a22 = GiNaC::normal(q_next.diff(q));
  const GiNaC::ex det_minus_one = GiNaC::factor(GiNaC::normal(a11 * a22 - a12 * a21 - 1));
  // Canonical text: GiNaC's own printing order depends on symbol serial numbers.
  const std::string det_string = canonical_text(det_minus_one);
  json evidence;
  evidence["exact"] = {{"kernel", "GiNaC"},
                       {"method", "Newmark's two update equations solved for (q_{j+1}, v_{j+1}) with m, omega, h, p, q, beta, "
                                  "gamma symbolic (lsolve), then beta = 1/4, gamma = 1/2 substituted and compared with "
                                  "(matrice-symplectique-ordre-2)"},
                       {"p_next_minus_phi", dp.is_zero() ? "0" : "nonzero"},
                       {"q_next_minus_phi", dq.is_zero() ? "0" : "nonzero"},
                       {"det_minus_one_for_any_beta_gamma", det_string}};
  return confirmed_if(dp.is_zero() && dq.is_zero(), evidence,
                      "Kane et al.'s identification holds: Phi is Newmark's average-acceleration scheme (beta = 1/4, gamma = 1/2). "
                      "Over the whole family det - 1 = " + det_string + ", which vanishes for gamma = 1/2 and any beta.");
}

}  // namespace

void add_section2_checks(check_registry& checks) {
  checks.add("newmark-identification", check_newmark_identification);
}

}  // namespace simpson::verify::detail

// Section 2: Newmark's map named as one of Newmark's family (the other claims of Section 2 are proof
// shapes' records in claims/paper.toml).

#include "claim_support.hpp"
#include "bespoke_checks.hpp"
#include "derivation_support.hpp"

#include <simpson/verify/quoted_words.hpp>

#include <simpson/verify/tex_math.hpp>  // canonical_text

#include <ginac/ginac.h>

#include <simpson/newmark_map.hpp>

namespace simpson::verify::detail {
namespace {

/// Newmark's scheme for m q'' + m ω² q = 0 with parameters (β, γ), v = p/m, a = −ω² q:
///   q₁ = q + h v + h² ((1/2 − β) a + β a₁),  v₁ = v + h ((1 − γ) a + γ a₁),
/// solved for (q₁, v₁) in GiNaC with every symbol free: (p₁, q₁) in p, q, β, γ.
struct newmark_solution {
  GiNaC::symbol p{"p"}, q{"q"}, beta{"beta"}, gamma{"gamma"};
  GiNaC::ex p_next, q_next;
  /// Its matrix on (p, q) at β = 1/4, γ = 1/2 (the average-acceleration scheme).
  GiNaC::matrix average_acceleration() const {
    const GiNaC::lst at{beta == GiNaC::numeric(1, 4), gamma == GiNaC::numeric(1, 2)};
    const GiNaC::ex pn = p_next.subs(at), qn = q_next.subs(at);
    return GiNaC::matrix{{GiNaC::normal(pn.diff(p)), GiNaC::normal(pn.diff(q))}, {GiNaC::normal(qn.diff(p)), GiNaC::normal(qn.diff(q))}};
  }
};

newmark_solution solve_newmark(const GiNaC::ex& m, const GiNaC::ex& w, const GiNaC::ex& h) {
  newmark_solution s;
  const GiNaC::symbol q1("q1"), v1("v1");
  const GiNaC::ex v = s.p / m, a = -w * w * s.q, a1 = -w * w * q1;
  const GiNaC::ex solution = GiNaC::lsolve(
      GiNaC::lst{q1 == s.q + h * v + h * h * ((GiNaC::numeric(1, 2) - s.beta) * a + s.beta * a1), v1 == v + h * ((1 - s.gamma) * a + s.gamma * a1)},
      GiNaC::lst{q1, v1});
  s.q_next = GiNaC::ex(q1).subs(solution);
  s.p_next = m * GiNaC::ex(v1).subs(solution);
  return s;
}

/// Our side: at β = 1/4, γ = 1/2 Newmark's map is the core's newmark_map; over the family, det = 1
/// exactly when γ = 1/2. The printed Φ is judged against the same solution by the printed facet below.
decider_evidence check_newmark_identification(const run_context& ctx) {
  const quoted_sentence said =
      quote(ctx, "the numerical scheme (\\ref{systeme-symplectique-ordre-2}) is one particular inconditionally stable version of the {family} scheme");
  said.choice("family", {{"Newmark", "Newmark (beta, gamma) family"}});
  const GiNaC::symbol m("m"), w("omega"), h("h");
  const newmark_solution s = solve_newmark(m, w, h);
  const GiNaC::matrix newmark = s.average_acceleration();
  const one_step_matrix<GiNaC::ex> phi = newmark_map(oscillator_parameters<GiNaC::ex>{m, w, h});
  const GiNaC::ex dp = GiNaC::normal(newmark(0, 0) - phi.alpha) + GiNaC::normal(newmark(0, 1) - phi.beta);
  const GiNaC::ex dq = GiNaC::normal(newmark(1, 0) - phi.gamma) + GiNaC::normal(newmark(1, 1) - phi.delta);
  // And the family: det of the Newmark map is 1 exactly when γ = 1/2 (symplectic), for any β.
  const GiNaC::ex a11 = GiNaC::normal(s.p_next.diff(s.p)), a12 = GiNaC::normal(s.p_next.diff(s.q)), a21 = GiNaC::normal(s.q_next.diff(s.p)),
                  a22 = GiNaC::normal(s.q_next.diff(s.q));
  const GiNaC::ex det_minus_one = GiNaC::factor(GiNaC::normal(a11 * a22 - a12 * a21 - 1));
  // Canonical text: GiNaC's own printing order depends on symbol serial numbers.
  const std::string det_string = canonical_text(det_minus_one);
  json evidence;
  evidence["exact"] = {{"kernel", "GiNaC"},
                       {"method", "Newmark's two update equations solved for (q_{j+1}, v_{j+1}) with m, omega, h, p, q, beta, "
                                  "gamma symbolic (lsolve), then beta = 1/4, gamma = 1/2 substituted and compared with the core's "
                                  "newmark_map; the printed (matrice-symplectique-ordre-2) is compared with the same solution "
                                  "(kernels, below)"},
                       {"p_next_minus_core", dp.is_zero() ? "0" : "nonzero"},
                       {"q_next_minus_core", dq.is_zero() ? "0" : "nonzero"},
                       {"det_minus_one_for_any_beta_gamma", det_string}};
  return confirmed_if(dp.is_zero() && dq.is_zero(), evidence,
                      "Kane et al.'s identification holds: Phi is Newmark's average-acceleration scheme (beta = 1/4, gamma = 1/2). "
                      "Over the whole family det - 1 = " + det_string + ", which vanishes for gamma = 1/2 and any beta.");
}

/// The printed Φ (matrice-symplectique-ordre-2) against Newmark's map at β = 1/4, γ = 1/2, solved
/// in the paper's symbols: the identification is a property of the printed system (fails, not an
/// erratum, when the print is another map).
printed_outcome newmark_identification_printed(const paper_reading& r) {
  const GiNaC::ex m = sym("m"), w = sym("omega"), h = sym("h");
  printed_outcome o = compare("Phi", printed_side(r, "matrice-symplectique-ordre-2"), solve_newmark(m, w, h).average_acceleration(),
                              as_matrix(newmark_map(oscillator_parameters<GiNaC::ex>{m, w, h})));
  o.property = true;
  return o;
}

}  // namespace

void add_section2_checks(check_registry& checks) {
  checks.add("newmark-identification", check_newmark_identification);
  checks.add_printed("newmark-identification", {"matrice-symplectique-ordre-2"}, newmark_identification_printed);
}

}  // namespace simpson::verify::detail

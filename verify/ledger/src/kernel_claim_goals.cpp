// The Coq goals of the claims our own kernel proves without a printed formula, registered onto their checks (check_registry.hpp):
// the signs of Section 5 (Δ < 0 on the stable bands) and Φ₃'s shear factorization, stated on the
// core's formulas in GiNaC. Our kernel's proofs (Sturm sequences
// on rational functions of θ) stay the claims' exact evidence; these goals are what coqc checks again.

#include "check_registry.hpp"
#include "printed_check_support.hpp"
#include "claims_family.hpp"

#include <simpson/energy.hpp>
#include <simpson/newmark_map.hpp>
#include <simpson/shear_form.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/three_term_scheme.hpp>

namespace simpson::verify::detail {
namespace {

using GiNaC::ex;

GiNaC::matrix core_phi3() { return as_matrix(simpson_map(parameters(derivation()))); }

/// The reduction every exact proof of our kernel uses: with S = diag(mω, 1), Φ(m, ω, h) =
/// S Φ(1, 1, ωh) S⁻¹ for Φ₃ and Newmark's Φ, and H_d(m, ω, h; p, q) = mω² H_d(1, 1, ωh; p/(mω), q).
std::vector<proof_goal> dimensional_scaling() {
  const symbolic_derivation& d = derivation();
  const oscillator_parameters<ex> unit{1, 1, d.omega * d.h};
  const GiNaC::matrix S{{d.m * d.omega, 0}, {0, 1}}, S_inverse{{1 / (d.m * d.omega), 0}, {0, 1}};
  const auto scaled = [&](const one_step_matrix<ex>& at_unit) { return S.mul(as_matrix(at_unit)).mul(S_inverse); };
  return {decided("phi3", scaled(simpson_map(unit)), as_matrix(simpson_map(parameters(d)))),
          decided("newmark", scaled(newmark_map(unit)), as_matrix(newmark_map(parameters(d)))),
          decided("discrete_energy", discrete_energy(parameters(d), phase_point<ex>{d.p, d.q}),
                  d.m * d.omega * d.omega * discrete_energy(unit, phase_point<ex>{d.p / (d.m * d.omega), d.q}))};
}

/// Φ₃ = L(c) U(b) L(c), the core's shears multiplied out, entry by entry (off ω²h² = 12, 24, where
/// the drift's denominator vanishes: hypotheses of the lemmas).
std::vector<proof_goal> phi3_shear_factorization() {
  const symbolic_derivation& d = derivation();
  const auto product = shear_product(simpson::detail::shear_with_step<ex>(d.m, d.omega, d.h));
  return {decided("core", as_matrix(product), core_phi3())};
}

}  // namespace

proof_goal sign_goal(const std::string& name, const ex& lhs, int sign, std::vector<ex> positive, GiNaC::exmap inside) {
  proof_goal g;
  g.name = name;
  g.lhs = lhs;
  g.rhs = 0;
  g.sign = sign;
  g.factored = GiNaC::factor(GiNaC::normal(lhs));
  g.inside = std::move(inside);
  bool in_region = true;
  for (const ex& e : positive) {
    const ex at = GiNaC::normal(e.subs(g.inside));
    in_region = in_region && GiNaC::is_a<GiNaC::numeric>(at) && GiNaC::ex_to<GiNaC::numeric>(at).is_positive();
  }
  const ex at = GiNaC::normal(lhs.subs(g.inside) * sign);
  g.holds = in_region && GiNaC::is_a<GiNaC::numeric>(at) && GiNaC::ex_to<GiNaC::numeric>(at).is_positive();
  g.positive = std::move(positive);
  return g;
}

void add_kernel_claim_goals(check_registry& checks) {
  checks.add_coq_goals("phi3-shear-factorization", phi3_shear_factorization);
  checks.add_coq_goals("scaling", dimensional_scaling);
  checks.add_coq_goals("family-symplectic", family_symplectic_goals);
}

std::string without_coq_statement(const claim& c, const std::string& otherwise) { return c.coq_none.empty() ? otherwise : c.coq_none; }

}  // namespace simpson::verify::detail

// A finding the paper does not print, for round-off over long runs: Φ₃ is a product of three
// shears, drift–kick–drift, with coefficients in closed form (shear_form.hpp). Proved in our kernel
// (rational functions of θ = ωh) and in GiNaC with m, ω, h free; rechecked as a step in every precision.

#include "claim_support.hpp"
#include "bespoke_checks.hpp"
#include "derivation_support.hpp"

#include <simpson/verify/tex_math.hpp>  // canonical_text

#include <simpson/shear_form.hpp>
#include <simpson/simpson_map.hpp>

#include <ginac/ginac.h>

namespace simpson::verify::detail {
namespace {

decider_evidence check_phi3_shear_factorization(const run_context& ctx) {
  // Our kernel: m = ω = 1, h = θ (lemma-dimensional-scaling).
  const oscillator_parameters<symbolic> unit = unit_oscillator_in_theta();
  const one_step_matrix<symbolic> phi = simpson_map(unit);
  const shear_coefficients<symbolic> s = simpson::detail::shear_with_step(unit.m(), unit.omega(), unit.h());
  const one_step_matrix<symbolic> product = shear_product(s);
  const proof ours = prove_zero(std::string(unit_reduction) + "; each entry of L(c) U(b) L(c) - Phi_3, and c - (alpha - 1)/beta",
                                (product.alpha - phi.alpha) * (product.alpha - phi.alpha) +
                                    (product.beta - phi.beta) * (product.beta - phi.beta) +
                                    (product.gamma - phi.gamma) * (product.gamma - phi.gamma) +
                                    (product.delta - phi.delta) * (product.delta - phi.delta) +
                                    (s.drift - (phi.alpha - 1) / phi.beta) * (s.drift - (phi.alpha - 1) / phi.beta));
  // GiNaC: every symbol free.
  const GiNaC::symbol m("m"), omega("omega"), h("h");
  const one_step_matrix<GiNaC::ex> phi_g = simpson::detail::simpson_map_with_step<GiNaC::ex>(m, omega, h);
  const one_step_matrix<GiNaC::ex> product_g = shear_product(simpson::detail::shear_with_step<GiNaC::ex>(m, omega, h));
  json entries = json::array();
  bool ginac_zero = true;
  for (const auto& [name, difference] : {std::pair{"alpha", product_g.alpha - phi_g.alpha}, std::pair{"beta", product_g.beta - phi_g.beta},
                                         std::pair{"gamma", product_g.gamma - phi_g.gamma}, std::pair{"delta", product_g.delta - phi_g.delta}}) {
    const GiNaC::ex normal = GiNaC::normal(difference);
    ginac_zero = ginac_zero && normal.is_zero();
    entries.push_back({{"entry", name}, {"normal_form", canonical_text(normal)}});
  }
  // Where it fails: β = −m ω² h (1 − ω²h²/12)(1 − ω²h²/24)/(1 + ω²h²/24) vanishes for h > 0 exactly at
  // ω²h² = 12 and 24. At 12, c = h/(2m(1 − ω²h²/12)) has its pole and Φ₃'s α is −1, where any product
  // with b = β = 0 has α = 1 + bc = 1: no factorization. At 24, c = −h/(2m) is finite and the identity
  // of rational functions holds there too (both sides evaluated at h = √24/ω).
  const GiNaC::ex x = omega * omega * h * h;
  const GiNaC::ex factored = -h * m * omega * omega * (x - 12) * (x - 24);
  const GiNaC::ex beta_numerator = GiNaC::numer(GiNaC::normal(phi_g.beta));
  const bool beta_zeros = GiNaC::normal(beta_numerator / factored).info(GiNaC::info_flags::rational);
  const GiNaC::exmap at24{{h, GiNaC::sqrt(GiNaC::ex(24)) / omega}}, at12{{h, GiNaC::sqrt(GiNaC::ex(12)) / omega}};
  bool holds_at_24 = true;
  for (const GiNaC::ex& difference : {product_g.alpha - phi_g.alpha, product_g.beta - phi_g.beta, product_g.gamma - phi_g.gamma,
                                      product_g.delta - phi_g.delta}) {
    holds_at_24 = holds_at_24 && GiNaC::normal(GiNaC::expand(difference.subs(at24))).is_zero();
  }
  const GiNaC::ex alpha_at_12 = GiNaC::normal(phi_g.alpha.subs(at12)), beta_at_12 = GiNaC::normal(phi_g.beta.subs(at12));
  const bool none_at_12 = (alpha_at_12 + 1).is_zero() && beta_at_12.is_zero();
  const bool singular_set = beta_zeros && holds_at_24 && none_at_12;
  bool within = false;
  const json numeric = recheck_with(
      ctx, "phi3-shear-factorization",
      [](const auto& par, const auto& y) {
        using Real = std::decay_t<decltype(par.m())>;
        using std::abs;
        const shear_coefficients<Real> c = simpson_shear_coefficients(par);
        const phase_point<Real> expected = simpson_map(par) * y, got = shear_step(c, y);
        // Both are a few roundings of terms up to (1 + |bc|)² times the state (|bc| ≤ 8 for ωh ≤ 2.7):
        // 64 eps (|p| + mω|q|)(1 + |bc|)², with q measured in units of p/(mω).
        const Real mw = par.m() * par.omega(), bc = abs(Real(c.kick * c.drift));
        const Real scale = (abs(y.p) + mw * abs(y.q)) * (1 + bc) * (1 + bc);
        return residual_and_bound<Real>{Real(abs(Real(got.p - expected.p)) + mw * abs(Real(got.q - expected.q))),
                                        Real(64 * eps<Real>() * scale)};
      },
      within);
  json evidence;
  evidence["exact"] = json::array({ours.evidence,
                                   {{"kernel", "GiNaC"},
                                    {"method", "m, omega, h free: normal(L(c) U(b) L(c) - Phi_3) entry by entry"},
                                    {"entries", entries},
                                    {"beta_numerator", canonical_text(beta_numerator)},
                                    {"beta_numerator_over_factored", canonical_text(GiNaC::normal(beta_numerator / factored))},
                                    {"alpha_at_12", canonical_text(alpha_at_12)},
                                    {"holds_at_24", holds_at_24},
                                    {"singular_set", "beta's numerator is a rational multiple of -h m omega^2 (omega^2 h^2 - 12)(omega^2 h^2 - 24): "
                                                     "for h > 0, beta = 0 exactly at omega^2 h^2 = 12 and 24. At 24 the product with b = 0 is Phi_3 "
                                                     "(each entry's difference is 0 at h = sqrt(24)/omega); at 12, Phi_3's alpha is -1 where any "
                                                     "product with b = beta = 0 has alpha = 1 + bc = 1: no factorization"}}});
  evidence["numeric"] = numeric;
  return confirmed_if(ours.proved && ginac_zero && singular_set && within, evidence,
                      "Phi_3 = L(c) U(b) L(c) on (p, q), a drift q += c p, a kick p += b q and the same drift, with "
                      "b = beta and c = h/(2m(1 - omega^2 h^2/12)); for every h but omega^2 h^2 = 12, where c has its pole and no such "
                      "product exists (at 24, b = 0 and Phi_3 = L(2c)). "
                      "Each shear has determinant 1 for any rounded coefficient, so the map computed in floating point "
                      "has no determinant drift (the long_time section compares the forms).");
}

/// Φ₃ = L(c) U(b) L(c), the core's shears multiplied out, entry by entry (off ω²h² = 12, where the
/// drift's denominator vanishes: a hypothesis of the lemmas).
std::vector<proof_goal> phi3_shear_factorization() {
  const symbolic_derivation& d = derivation();
  const auto product = shear_product(simpson::detail::shear_with_step<GiNaC::ex>(d.m, d.omega, d.h));
  return {decided("core", as_matrix(product), as_matrix(simpson_map(parameters(d))))};
}

}  // namespace

void add_shear_checks(check_registry& checks) {
  checks.add("phi3-shear-factorization", check_phi3_shear_factorization);
  checks.add_coq_goals("phi3-shear-factorization", phi3_shear_factorization);
}

}  // namespace simpson::verify::detail

#pragma once
// Section 7: quadratic forms conserved by a linear one-step map of unit determinant.

#include <simpson/one_step_map.hpp>

#include <array>

namespace simpson {

/// (forme-quadratique) Q(p, q) = ξ p²/2 + η p q + ζ q²/2.
template <class Real>
Real quadratic_form(const Real& xi, const Real& eta, const Real& zeta, const phase_point<Real>& y) {
  return xi * y.p * y.p / 2 + eta * y.p * y.q + zeta * y.q * y.q / 2;
}

/// Γ of Section 7: Q(Φy) = Q(y) for all y exactly when Γ (ξ, η, ζ)ᵀ = 0, Φ = ((α, β), (γ, δ)).
/// Rows are the coefficients of p², pq, q² in Q(Φy) − Q(y). The paper prints (γ² − 1)/2 as the
/// last entry; the coefficient of q² is (δ² − 1)/2 (erratum gamma-system).
template <class Real>
std::array<std::array<Real, 3>, 3> invariance_system(const one_step_matrix<Real>& phi) {
  const Real& a = phi.alpha;
  const Real& b = phi.beta;
  const Real& c = phi.gamma;
  const Real& d = phi.delta;
  return {{{(a * a - 1) / 2, a * c, c * c / 2},
           {a * b, a * d + b * c - 1, c * d},
           {b * b / 2, b * d, (d * d - 1) / 2}}};
}

/// det Γ = (αδ − βγ − 1)(1 − α − δ + αδ − βγ)(1 + α + δ + αδ − βγ) / 4. The paper prints the
/// product without the factor 1/4 (erratum gamma-determinant); it vanishes when αδ − βγ = 1.
template <class Real>
Real invariance_system_determinant(const one_step_matrix<Real>& phi) {
  const Real det = determinant(phi);
  const Real trace = phi.alpha + phi.delta;
  return (det - 1) * (1 - trace + det) * (1 + trace + det) / 4;
}

/// Q_c = γ p²/2 − β q²/2 (Section 7): conserved by Φ when α = δ and αδ − βγ = 1; returned as
/// its coefficients (ξ, η, ζ) = (γ, 0, −β).
template <class Real>
std::array<Real, 3> conserved_form_coefficients(const one_step_matrix<Real>& phi) {
  return {phi.gamma, Real(0), Real(-phi.beta)};
}

}  // namespace simpson

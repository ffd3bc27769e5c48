#pragma once
// Section 5: the equation of the internal node q_m, and its solution for the harmonic oscillator.

#include <simpson/oscillator_parameters.hpp>
#include <simpson/residual.hpp>

#include <cmath>

namespace simpson {

/// (equation-milieu-intervalle) m (4/h²)(q_l − 2 q_m + q_r) + V'(q_m); zero where ∂L_h/∂q_m = 0.
template <class Real, class ForceGradient>
Real internal_equation_residual(const Real& m, const Real& h, ForceGradient&& force_gradient, const Real& q_left,
                                const Real& q_mid, const Real& q_right) {
  return m * 4 / (h * h) * (q_left - 2 * q_mid + q_right) + force_gradient(q_mid);
}

/// (qm-oscillateur-harmonique) q_m = (q_l + q_r) / (2 (1 − ω²h²/8)).
/// Throws std::domain_error at ω²h² = 8, where the internal equation has no solution.
template <class Real>
Real harmonic_internal_node(const oscillator_parameters<Real>& par, const Real& q_left, const Real& q_right) {
  const Real internal = 1 - par.omega2_h2() / 8;
  detail::require_nonzero("simpson::harmonic_internal_node", "1 - omega^2 h^2 / 8", internal);
  return (q_left + q_right) / (2 * internal);
}

/// (equation-milieu-intervalle) at the harmonic q_m. Terms of size (4m/h²)(|q_l| + 2|q_m| + |q_r|)
/// cancel (|q_m| carries the 1/(1 − ω²h²/8) growth); ~16 roundings, the potential term adding a
/// relative ω²h²: 32 eps (4m/h²)(|q_l| + 2|q_m| + |q_r|)(1 + ω²h²).
template <class Real>
residual_and_bound<Real> harmonic_internal_node_check(const oscillator_parameters<Real>& par, const Real& q_left,
                                                      const Real& q_right) {
  using std::abs;
  const Real q_mid = harmonic_internal_node(par, q_left, q_right);
  const auto gradient = [&](const Real& v) -> Real { return par.force_gradient(v); };
  const Real scale = 4 * par.m() / (par.h() * par.h()) * (abs(q_left) + 2 * abs(q_mid) + abs(q_right)) * (1 + par.omega2_h2());
  return {internal_equation_residual(par.m(), par.h(), gradient, q_left, q_mid, q_right), Real(32 * eps<Real>() * scale)};
}

}  // namespace simpson

#pragma once
// Section 5: the Simpson Lagrangian of the harmonic oscillator with q_m eliminated.

#include <simpson/internal_node.hpp>
#include <simpson/oscillator_parameters.hpp>
#include <simpson/residual.hpp>
#include <simpson/simpson_lagrangian.hpp>

#include <cmath>

namespace simpson {

/// (Lagrangien-reduit)
/// L_h^r(q_l, q_r) = 1/(1 − ω²h²/8) [ (m h / 2)((q_r − q_l)/h)²
///                   − (h/2) m ω² ( (22 − ω²h²)/48 (q_l² + q_r²) + q_l q_r / 12 ) ].
/// Throws std::domain_error at ω²h² = 8.
template <class Real>
Real reduced_lagrangian(const oscillator_parameters<Real>& par, const Real& q_left, const Real& q_right) {
  const Real& m = par.m();
  const Real& h = par.h();
  const Real x = par.omega2_h2();
  const Real internal = 1 - x / 8;
  detail::require_nonzero("simpson::reduced_lagrangian", "1 - omega^2 h^2 / 8", internal);
  const Real slope = (q_right - q_left) / h;
  const Real potential_part =
      (22 - x) / 48 * (q_left * q_left + q_right * q_right) + q_left * q_right / 12;
  return (m * h / 2 * slope * slope - h / 2 * m * par.omega() * par.omega() * potential_part) / internal;
}

/// (Lagrangien-reduit) − (LLhh) at the harmonic q_m. Both sum terms of size
/// (m/h)(1 + ω²h²)(|q_l| + |q_m| + |q_r|)², the reduced form divided by 1 − ω²h²/8:
/// 64 eps (m/h)(1 + ω²h²)(Σ|q|)²/|1 − ω²h²/8|.
template <class Real>
residual_and_bound<Real> reduced_lagrangian_check(const oscillator_parameters<Real>& par, const Real& q_left,
                                                  const Real& q_right) {
  using std::abs;
  const Real q_mid = harmonic_internal_node(par, q_left, q_right);
  const auto V = [&](const Real& v) -> Real { return par.potential(v); };
  const Real q_sum = abs(q_left) + abs(q_mid) + abs(q_right);
  const Real condition =
      par.m() / par.h() * (1 + par.omega2_h2()) * q_sum * q_sum / abs(Real(1 - par.omega2_h2() / 8));
  return {Real(reduced_lagrangian(par, q_left, q_right) - simpson_lagrangian(par.m(), par.h(), V, q_left, q_mid, q_right)),
          Real(64 * eps<Real>() * condition)};
}

}  // namespace simpson

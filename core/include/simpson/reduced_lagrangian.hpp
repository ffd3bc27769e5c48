#pragma once
// Section 5: the Simpson Lagrangian of the harmonic oscillator with q_m eliminated.

#include <simpson/oscillator_parameters.hpp>

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

}  // namespace simpson

#pragma once
// Section 6: the momentum of the reduced Simpson Lagrangian.

#include <simpson/oscillator_parameters.hpp>

namespace simpson {

/// (moment-ordre-3) p_r = ∂L_h^r/∂q_r (q_l, q_r)
///   = m (q_r − q_l)/h − h (m ω²/6)(q_l + 2 q_r)/(1 − ω²h²/8) + h³ (m ω⁴/48) q_r/(1 − ω²h²/8).
/// With (q_l, q_r) = (q_j, q_{j+1}) it gives p_{j+1}. Throws std::domain_error at ω²h² = 8.
template <class Real>
Real simpson_momentum(const oscillator_parameters<Real>& par, const Real& q_left, const Real& q_right) {
  const Real& m = par.m();
  const Real& h = par.h();
  const Real omega2 = par.omega() * par.omega();
  const Real internal = 1 - par.omega2_h2() / 8;
  detail::require_nonzero("simpson::simpson_momentum", "1 - omega^2 h^2 / 8", internal);
  return m * (q_right - q_left) / h - h * m * omega2 / 6 * (q_left + 2 * q_right) / internal +
         h * h * h * m * omega2 * omega2 / 48 * q_right / internal;
}

}  // namespace simpson

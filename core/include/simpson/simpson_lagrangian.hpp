#pragma once
// Sections 4 and 5: the discrete Lagrangian from Simpson's rule on the quadratic interpolant,
// for a general potential V, and its derivative in the internal node q_m.

#include <simpson/quadratic_interpolation.hpp>

namespace simpson {

/// (LLhh) L_h(q_l, q_m, q_r) = (m h / 12)(g_l² + 4 g_m² + g_r²) − (h/6)(V(q_l) + 4 V(q_m) + V(q_r)).
/// `potential` is a callable V(q).
template <class Real, class Potential>
Real simpson_lagrangian(const Real& m, const Real& h, Potential&& potential, const Real& q_left, const Real& q_mid,
                        const Real& q_right) {
  const Real g_l = gear_left(q_left, q_mid, q_right, h);
  const Real g_m = centred_derivative(q_left, q_right, h);
  const Real g_r = gear_right(q_left, q_mid, q_right, h);
  return m * h / 12 * (g_l * g_l + 4 * g_m * g_m + g_r * g_r) -
         h / 6 * (potential(q_left) + 4 * potential(q_mid) + potential(q_right));
}

/// ∂L_h/∂q_m = (h/12) [(8m/h) g_l − (8m/h) g_r − 8 V'(q_m)] (Section 5, before equation-milieu-intervalle),
/// from ∂g_l/∂q_m = 4/h, ∂g_m/∂q_m = 0, ∂g_r/∂q_m = −4/h. `force_gradient` is a callable V'(q).
template <class Real, class ForceGradient>
Real simpson_lagrangian_dq_mid(const Real& m, const Real& h, ForceGradient&& force_gradient, const Real& q_left,
                               const Real& q_mid, const Real& q_right) {
  const Real g_l = gear_left(q_left, q_mid, q_right, h);
  const Real g_r = gear_right(q_left, q_mid, q_right, h);
  return h / 12 * (8 * m / h * g_l - 8 * m / h * g_r - 8 * force_gradient(q_mid));
}

}  // namespace simpson

#pragma once
// Section 2: the classical discrete Lagrangian (midpoint quadrature, affine interpolation),
// its two-step Euler-Lagrange scheme and its momentum, for a general potential V.

namespace simpson {

/// (lagrangien-discret) L_d(q_l, q_r) = (m h / 2) ((q_r − q_l)/h)² − h V((q_l + q_r)/2).
/// `potential` is a callable V(q).
template <class Real, class Potential>
Real classical_lagrangian(const Real& m, const Real& h, Potential&& potential, const Real& q_left,
                          const Real& q_right) {
  const Real slope = (q_right - q_left) / h;
  return m * h / 2 * slope * slope - h * potential((q_left + q_right) / 2);
}

/// (schema-ordre-deux) m (q_{j+1} − 2 q_j + q_{j−1}) / h² + ½ [V'((q_j + q_{j+1})/2) + V'((q_{j−1} + q_j)/2)]:
/// zero along a solution of the discrete Euler-Lagrange equation (Euler-Lagrange-discret).
/// `force_gradient` is a callable V'(q).
template <class Real, class ForceGradient>
Real classical_scheme_residual(const Real& m, const Real& h, ForceGradient&& force_gradient, const Real& q_prev,
                               const Real& q, const Real& q_next) {
  return m * (q_next - 2 * q + q_prev) / (h * h) +
         (force_gradient((q + q_next) / 2) + force_gradient((q_prev + q) / 2)) / 2;
}

/// (moment) p_r = ∂L_d/∂q_r (q_l, q_r) = m (q_r − q_l)/h − (h/2) V'((q_l + q_r)/2);
/// for V = m ω² q²/2 it is the printed p_{j+1} = m (q_{j+1} − q_j)/h − m ω² h (q_{j+1} + q_j)/4.
template <class Real, class ForceGradient>
Real classical_momentum(const Real& m, const Real& h, ForceGradient&& force_gradient, const Real& q_left,
                        const Real& q_right) {
  return m * (q_right - q_left) / h - h / 2 * force_gradient((q_left + q_right) / 2);
}

}  // namespace simpson

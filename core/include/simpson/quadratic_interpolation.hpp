#pragma once
// Section 3: quadratic finite-element interpolation on one step [0, h], with local coordinate
// s = t/h in [0, 1] (the paper writes θ for s; in this project θ means ωh).

namespace simpson {

/// (fonctions-de-base) φ_0(s) = (1 − s)(1 − 2s)
template <class Real>
Real basis_phi0(const Real& s) {
  return (1 - s) * (1 - 2 * s);
}

/// (fonctions-de-base) φ_{1/2}(s) = 4 s (1 − s)
template <class Real>
Real basis_phi_half(const Real& s) {
  return 4 * s * (1 - s);
}

/// (fonctions-de-base) φ_1(s) = s (2s − 1)
template <class Real>
Real basis_phi1(const Real& s) {
  return s * (2 * s - 1);
}

/// (q2t) q(t) = q_l φ_0(s) + q_m φ_{1/2}(s) + q_r φ_1(s), t = h s.
template <class Real>
Real quadratic_interpolant(const Real& q_left, const Real& q_mid, const Real& q_right, const Real& s) {
  return q_left * basis_phi0(s) + q_mid * basis_phi_half(s) + q_right * basis_phi1(s);
}

/// dq/dt = (1/h) [q_l (4s − 3) + 4 q_m (1 − 2s) + q_r (4s − 1)] (display after q2t).
template <class Real>
Real quadratic_interpolant_derivative(const Real& q_left, const Real& q_mid, const Real& q_right, const Real& h,
                                      const Real& s) {
  return (q_left * (4 * s - 3) + 4 * q_mid * (1 - 2 * s) + q_right * (4 * s - 1)) / h;
}

/// (derivees-gear) g_l = dq/dt(0) = (−3 q_l + 4 q_m − q_r)/h
template <class Real>
Real gear_left(const Real& q_left, const Real& q_mid, const Real& q_right, const Real& h) {
  return (-3 * q_left + 4 * q_mid - q_right) / h;
}

/// (derivees-gear) g_r = dq/dt(h) = (q_l − 4 q_m + 3 q_r)/h
template <class Real>
Real gear_right(const Real& q_left, const Real& q_mid, const Real& q_right, const Real& h) {
  return (q_left - 4 * q_mid + 3 * q_right) / h;
}

/// (derivee-centree) g_m = dq/dt(h/2) = (g_l + g_r)/2 = (q_r − q_l)/h; q_m drops out.
template <class Real>
Real centred_derivative(const Real& q_left, const Real& q_right, const Real& h) {
  return (q_right - q_left) / h;
}

}  // namespace simpson

#pragma once
// Φ₃ as a product of shears (beyond the paper, for round-off over long runs): on (p, q),
//   Φ₃ = L(c) U(b) L(c),  L(c) = [[1, 0], [c, 1]] (a drift q += c p),  U(b) = [[1, b], [0, 1]] (a kick p += b q),
// with b = β = −m ω² h (1 − ω²h²/12)(1 − ω²h²/24)/(1 + ω²h²/24) and c = (α − 1)/β = h/(2m (1 − ω²h²/12)):
// L(c)U(b)L(c) = [[1 + bc, b], [c(2 + bc), 1 + bc]], and 1 + bc = α, c(1 + α) = γ because
// α² − βγ = 1 (claim phi3-shear-factorization). Singular set: ω²h² = 12, the pole of c, where
// Φ₃ = [[−1, 0], [γ, −1]] and no such product exists (β = 0 makes its α = 1). At ω²h² = 24, β = 0 too
// but c = −h/(2m) is finite: Φ₃ = L(2c) = [[1, 0], [−h/m, 1]], the product with b = 0.
// Each shear has determinant 1 whatever its rounded coefficient, so the map computed in floating
// point is symplectic up to the rounding of each update (no drift from a determinant ≠ 1); with
// compensated (Kahan) summation of the updates that rounding shrinks further (Hairer, McLachlan,
// Razakarivony, BIT 48, 2008).

#include <simpson/one_step_map.hpp>
#include <simpson/oscillator_parameters.hpp>

#include <stdexcept>

namespace simpson {

/// The drift c and the kick b of Φ₃ = L(c) U(b) L(c).
template <class Real>
struct shear_coefficients {
  Real drift;  // c
  Real kick;   // b
};

namespace detail {
/// The coefficients for a signed step h (rational functions of h; no validation).
template <class Real>
shear_coefficients<Real> shear_with_step(const Real& m, const Real& omega, const Real& h) {
  const Real x = omega * omega * h * h;
  return {h / (2 * m * (1 - x / 12)), -m * omega * omega * h * (1 - x / 12) * (1 - x / 24) / (1 + x / 24)};
}
}  // namespace detail

/// The shear coefficients of Φ₃. Throws std::domain_error at ω²h² = 12, where the factorization does
/// not exist (at 24 it does, with b = 0).
template <class Real>
shear_coefficients<Real> simpson_shear_coefficients(const oscillator_parameters<Real>& par) {
  const Real x = par.omega2_h2();
  if (x == 12) throw std::domain_error("simpson::simpson_shear_coefficients: no shear factorization at omega^2 h^2 = 12 (Phi_3 = -I + gamma E21)");
  return detail::shear_with_step(par.m(), par.omega(), par.h());
}

/// L(c) U(b) L(c) as a matrix (to compare with Φ₃).
template <class Real>
one_step_matrix<Real> shear_product(const shear_coefficients<Real>& s) {
  const one_step_matrix<Real> drift{Real(1), Real(0), s.drift, Real(1)}, kick{Real(1), s.kick, Real(0), Real(1)};
  return drift * (kick * drift);
}

/// One step in shear form: q += c p, p += b q, q += c p.
template <class Real>
phase_point<Real> shear_step(const shear_coefficients<Real>& s, phase_point<Real> y) {
  y.q += s.drift * y.p;
  y.p += s.kick * y.q;
  y.q += s.drift * y.p;
  return y;
}

/// A state with the compensations of Kahan's summation: the exact state is about y + carry.
template <class Real>
struct compensated_point {
  phase_point<Real> y;
  phase_point<Real> carry{Real(0), Real(0)};
};

namespace detail {
/// sum += increment with compensation: the rounding error of each addition is carried into the next.
template <class Real>
void compensated_add(Real& sum, Real& carry, const Real& increment) {
  const Real a = increment + carry;
  const Real next = sum + a;
  carry = (sum - next) + a;
  sum = next;
}
}  // namespace detail

/// One step in shear form with compensated summation of the three updates.
template <class Real>
void shear_step_compensated(const shear_coefficients<Real>& s, compensated_point<Real>& z) {
  detail::compensated_add(z.y.q, z.carry.q, Real(s.drift * z.y.p));
  detail::compensated_add(z.y.p, z.carry.p, Real(s.kick * z.y.q));
  detail::compensated_add(z.y.q, z.carry.q, Real(s.drift * z.y.p));
}

}  // namespace simpson

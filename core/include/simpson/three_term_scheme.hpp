#pragma once
// Section 5: the three-term scheme of the symplectic Simpson method, its characteristic
// polynomial a r² + b r + c and its discriminant.

#include <simpson/oscillator_parameters.hpp>
#include <simpson/residual.hpp>

#include <array>
#include <cmath>

namespace simpson {

/// (schema-ordre-3)
/// (q_{j+1} − 2 q_j + q_{j−1})/h² + (ω²/24)(q_{j+1} + 22 q_j + q_{j−1}) − (ω⁴ h²/24) q_j;
/// zero along the scheme, the truncation error T_h when the exact solution is put in.
template <class Real>
Real three_term_residual(const oscillator_parameters<Real>& par, const Real& q_prev, const Real& q, const Real& q_next) {
  const Real& h = par.h();
  const Real omega2 = par.omega() * par.omega();
  return (q_next - 2 * q + q_prev) / (h * h) + omega2 / 24 * (q_next + 22 * q + q_prev) - omega2 * omega2 * h * h / 24 * q;
}

/// Coefficients of a r² + b r + c = 0, obtained from (schema-ordre-3) times h² with
/// q_{j−1} = 1, q_j = r, q_{j+1} = r² (Section 5); functions of x = ω²h² alone.
template <class Real>
struct characteristic_coefficients {
  Real a;
  Real b;
  Real c;
};

/// a = 1 + x/24, b = −(48 − 22x + x²)/24 (as printed), c = 1 + x/24 (not printed; the coefficient
/// of q_{j−1}, equal to a, which makes the product of the roots c/a = 1).
template <class Real>
characteristic_coefficients<Real> characteristic_polynomial(const Real& x) {
  const Real a = 1 + x / 24;
  const Real b = -(48 - 22 * x + x * x) / 24;
  return {a, b, a};
}

/// Δ ≡ b² − 4ac (Section 5), as defined.
template <class Real>
Real discriminant(const Real& x) {
  const characteristic_coefficients<Real> k = characteristic_polynomial(x);
  return k.b * k.b - 4 * k.a * k.c;
}

/// The factors of Δ as printed in Section 5: ω²h²/576, (ω²h² − 24), (ω²h² − 12), (ω²h² − 8).
template <class Real>
std::array<Real, 4> discriminant_factors(const Real& x) {
  return {x / 576, x - 24, x - 12, x - 8};
}

/// Δ = (ω²h²/576)(ω²h² − 24)(ω²h² − 12)(ω²h² − 8), the factorisation as printed in Section 5.
template <class Real>
Real discriminant_factorized(const Real& x) {
  const std::array<Real, 4> f = discriminant_factors(x);
  return f[0] * f[1] * f[2] * f[3];
}

/// (b² − 4ac) − the printed factorisation. b² − 4ac cancels terms of size b² + 4|ac|, the factored
/// form has ~8 roundings of its own: 16 eps (b² + 4|ac| + |Δ|).
template <class Real>
residual_and_bound<Real> discriminant_factorization_check(const Real& x) {
  using std::abs;
  const characteristic_coefficients<Real> k = characteristic_polynomial(x);
  const Real factored = discriminant_factorized(x);
  return {Real(discriminant(x) - factored), Real(16 * eps<Real>() * (k.b * k.b + 4 * abs(Real(k.a * k.c)) + abs(factored)))};
}

}  // namespace simpson

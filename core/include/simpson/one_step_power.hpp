#pragma once
// Φⁿ y in closed form for a one-step map of unit determinant, for n far beyond what iterating
// reaches (10⁹ steps in mpfr): by Cayley–Hamilton, Φ² = 2τΦ − I with τ = (α + δ)/2, so
//   Φⁿ = U_{n−1}(τ) Φ − U_{n−2}(τ) I,
// U_k Chebyshev's polynomials of the second kind: U_k(cos φ) = sin((k+1)φ)/sin φ inside the
// unit interval, U_k(±cosh ψ) = (±1)^k sinh((k+1)ψ)/sinh ψ outside it, U_k(±1) = (±1)^k (k+1).
// Outside, the growth e^{nψ} is returned as a logarithm, so that no value leaves Real's range.

#include <simpson/one_step_map.hpp>

#include <cmath>
#include <stdexcept>

namespace simpson {

/// Φⁿ y = e^{log_scale} · direction, with direction of the size of y and Φ y.
template <class Real>
struct scaled_phase_point {
  Real log_scale;
  phase_point<Real> direction;
};

/// Φⁿ y for det Φ = 1 (the identity above needs it; det Φ is not checked here). n ≥ 0.
template <class Real>
scaled_phase_point<Real> power_apply(const one_step_matrix<Real>& phi, const phase_point<Real>& y, long long n) {
  using std::abs;
  using std::acos;
  using std::acosh;
  using std::exp;
  using std::expm1;
  using std::log;
  using std::sin;
  using std::sinh;
  if (n < 0) throw std::invalid_argument("simpson::power_apply: n must be >= 0");
  if (n == 0) return {Real(0), y};
  const phase_point<Real> y1 = phi * y;
  const Real tau = (phi.alpha + phi.delta) / 2;
  const Real N(n), previous(n - 1);
  const auto combine = [&](const Real& a, const Real& b) {  // a Φy − b y
    return phase_point<Real>{Real(a * y1.p - b * y.p), Real(a * y1.q - b * y.q)};
  };
  if (abs(tau) < 1) {
    const Real phase = acos(tau), s = sin(phase);
    return {Real(0), combine(Real(sin(Real(N * phase)) / s), Real(sin(Real(previous * phase)) / s))};
  }
  const Real sign = tau > 0 ? Real(1) : Real(-1);
  const Real parity = n % 2 == 0 ? Real(1) : Real(-1);  // (−1)^n
  const Real sign_n = sign > 0 ? Real(1) : parity;       // sign^n
  if (abs(tau) == 1) return {Real(0), combine(Real(sign_n * sign * N), Real(sign_n * previous))};  // sign^{n−1} n, sign^{n−2} (n−1)
  // |τ| > 1: U_{n−1} = sign^{n−1} e^{nψ}(1 − e^{−2nψ})/(2 sinh ψ), U_{n−2} = sign^{n−2} e^{nψ} e^{−ψ}(1 − e^{−2(n−1)ψ})/(2 sinh ψ).
  const Real psi = acosh(Real(abs(tau)));
  const Real a = -expm1(Real(-2 * N * psi)) * sign_n * sign;
  const Real b = exp(Real(-psi)) * Real(-expm1(Real(-2 * previous * psi))) * sign_n;
  return {Real(N * psi - log(Real(2 * sinh(psi)))), combine(a, b)};
}

}  // namespace simpson

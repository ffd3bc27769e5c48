#pragma once
// The exact solution of the pendulum released from rest (pendulum_exact.hpp) enclosed in MPFI: every
// step of it rounds outward, and the two infinite processes it needs carry a proved remainder.
//   K(k) = π / (2 AGM(1, k')), K(k') = π / (2 AGM(1, k)), k' = √(1 − k²): after each step of the
//     arithmetic-geometric mean, b_n ≤ AGM ≤ a_n, so [b_n, a_n] encloses it.
//   sn and cn by Jacobi's theta functions of the nome q = exp(−π K(k')/K(k)), v = πu/(2K):
//     sn(u, k) = θ₃(0)/θ₂(0) · θ₁(v)/θ₄(v),  cn(u, k) = θ₄(0)/θ₂(0) · θ₂(v)/θ₄(v),
//     θ₁(v) = 2 Σ (−1)ⁿ q^((n+½)²) sin((2n+1)v),  θ₂(v) = 2 Σ q^((n+½)²) cos((2n+1)v),
//     θ₃(v) = 1 + 2 Σ_{n≥1} q^(n²) cos(2nv),        θ₄(v) = 1 + 2 Σ_{n≥1} (−1)ⁿ q^(n²) cos(2nv),
//   each series cut at n = M with its remainder enclosed in ±2 q^(M²)/(1 − q) (every later term is
//   at most 2 q^(n²) in modulus, and Σ_{n≥M} q^(n²) ≤ q^(M²) Σ_j q^j).
// Beyond the paper: the reference against which the nonlinear scheme's errors are enclosed.
// Pulls in MPFI (link simpson::interval).

#include <simpson/interval.hpp>
#include <simpson/one_step_map.hpp>

#include <boost/math/constants/constants.hpp>

#include <stdexcept>

namespace simpson {

namespace detail {

/// AGM(a, b), a ≥ b > 0, enclosed.
inline interval agm_enclosed(interval a, interval b) {
  for (int n = 0; n < 64; ++n) {
    const interval next_a = (a + b) / 2, next_b = sqrt(interval(a * b));
    a = next_a;
    b = next_b;
    if (upper(interval(a - b)) <= lower(interval(eps<interval>() * a))) break;
  }
  return interval(lower(b), upper(a));
}

/// The four theta functions at v for the nome q = exp(log_q), log_q < 0, each enclosed with its remainder.
struct theta_values {
  interval theta1, theta2, theta3, theta4;
};

inline theta_values thetas_enclosed(const interval& log_q, const interval& v) {
  if (!(upper(log_q) < 0)) throw std::domain_error("simpson::detail::thetas_enclosed: the nome must be below 1");
  const auto power = [&](const interval& x) { return interval(exp(interval(x * log_q))); };  // q^x
  // Terms until q^(M²) is below the square of the unit round-off, then the remainder.
  int M = 1;
  while (M < 1000 && !(upper(power(interval(M * M))) < lower(interval(eps<interval>() * eps<interval>())))) ++M;
  theta_values t{interval(0), interval(0), interval(1), interval(1)};
  for (int n = 0; n < M; ++n) {
    const interval half = interval(n) + interval(1) / 2;
    const interval odd = 2 * power(interval(half * half));
    t.theta1 += (n % 2 == 0 ? odd : interval(-odd)) * sin(interval((2 * n + 1) * v));
    t.theta2 += odd * cos(interval((2 * n + 1) * v));
    if (n >= 1) {
      const interval even = 2 * power(interval(n * n)) * cos(interval(2 * n * v));
      t.theta3 += even;
      t.theta4 += n % 2 == 0 ? even : interval(-even);
    }
  }
  const interval tail = 2 * power(interval(M * M)) / (1 - power(interval(1)));
  const interval remainder(lower(interval(-tail)), upper(tail));
  t.theta1 += remainder;
  t.theta2 += remainder;
  t.theta3 += remainder;
  t.theta4 += remainder;
  return t;
}

}  // namespace detail

/// (p, q) at time t of the pendulum V = m ω² (1 − cos q) released from rest at q₀ (0 < q₀ < π),
/// enclosed: q(t) = 2 asin(k sn(K − ωt, k)), p(t) = −2 m ω k cn(K − ωt, k), k = sin(q₀/2).
inline phase_point<interval> pendulum_from_rest_enclosed(const interval& m, const interval& omega, const interval& q0,
                                                         const interval& t) {
  const interval pi = boost::math::constants::pi<interval>();
  if (!(lower(q0) > 0 && upper(q0) < lower(pi))) {
    throw std::domain_error("simpson::pendulum_from_rest_enclosed: q0 must lie in (0, pi)");
  }
  const interval k = sin(interval(q0 / 2)), k_complement = cos(interval(q0 / 2));
  const interval K = pi / (2 * detail::agm_enclosed(interval(1), k_complement));
  const interval K_complement = pi / (2 * detail::agm_enclosed(interval(1), k));
  const interval log_nome = -pi * K_complement / K;
  const interval u = K - omega * t, v = pi * u / (2 * K);
  const detail::theta_values at_zero = detail::thetas_enclosed(log_nome, interval(0)), at_v = detail::thetas_enclosed(log_nome, v);
  const interval sn = at_zero.theta3 / at_zero.theta2 * at_v.theta1 / at_v.theta4;
  const interval cn = at_zero.theta4 / at_zero.theta2 * at_v.theta2 / at_v.theta4;
  return {interval(-2 * m * omega * k * cn), interval(2 * asin(interval(k * sn)))};
}

}  // namespace simpson

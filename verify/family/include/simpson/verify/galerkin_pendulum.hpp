#pragma once
// A member of the family for a general V (issue 30): the implicit step of the discrete
// Euler–Lagrange equations with the rule's own nodes and weights,
//   p_j = −∂L_h/∂q_j,  ∂L_h/∂Q_k = 0,  p_{j+1} = ∂L_h/∂q_{j+1},
//   L_h = h Σ_i w_i [m/2 (q′(c_i)/h)² − V(q(c_i))],
// solved by Newton's method in long double, and its order measured on the pendulum
// (V = m ω² (1 − cos q), m = ω = 1, from rest at q₀ = 1) against the exact solution at t = 5 (not a
// whole period, about 6.7: a map that only returns to its start must not look exact).

#include <simpson/verify/galerkin_member.hpp>

#include <optional>
#include <string>
#include <vector>

namespace simpson::verify {

/// The rule's nodes and weights on [0, 1] in long double: equispaced, Gauss (Boost's Legendre
/// zeros) or Lobatto (the ends and the zeros of P′, by bisection between Legendre zeros); the
/// weights from the exact moments (a Vandermonde system).
struct numeric_rule {
  std::vector<long double> nodes, weights;
};
numeric_rule nodes_and_weights(const quadrature_rule& rule);

struct pendulum_order {
  bool ran = false;
  std::string failure;           // Newton did not converge, or no map
  std::vector<long long> steps;  // to t = 5
  std::vector<long double> errors;  // max(|p − p_exact|, |q − q_exact|) at t = 5
  std::vector<long double> observed;  // log2(e_N / e_2N), one per consecutive pair
  /// The order of the finest pair whose finer error is above long double's round-off floor
  /// (1e-15, about 10⁴ unit round-offs summed over the steps); nothing when none is.
  std::optional<long double> order;
};

/// The order on the pendulum with N = `steps` per period.
pendulum_order measure_pendulum_order(const galerkin_member& member, const std::vector<long long>& steps);

}  // namespace simpson::verify

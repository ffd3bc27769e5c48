#pragma once
// The Simpson variational integrator for any smooth potential V (beyond the paper: §9 leaves the
// nonlinear case open). One step (q_j, p_j) → (q_{j+1}, p_{j+1}) is defined by the discrete
// Euler–Lagrange equations of L_h (LLhh) with its Gear derivatives:
//   p_j = −∂L_h/∂q_l(q_j, q_m, q_{j+1}),  ∂L_h/∂q_m = 0,  p_{j+1} = ∂L_h/∂q_r(q_j, q_m, q_{j+1}).
// Eliminating q_{j+1} from the first two leaves one equation in the internal node x = q_m; the
// claim nonlinear-step-derivation proves in GiNaC, for V uninterpreted, that the forms below are
// these equations.

#include <simpson/one_step_map.hpp>
#include <simpson/scalar_traits.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>

namespace simpson {

/// The internal node's equation, scaled by the mass, given V'(q) and V'(x):
/// F(x) = m (x − q) − (h/2) p + (h²/12) V'(q) + (h²/24) V'(x) = 0.
template <class Real>
Real simpson_internal_residual(const Real& m, const Real& h, const Real& q, const Real& p, const Real& x, const Real& force_q,
                               const Real& force_x) {
  return m * (x - q) - h / 2 * p + h * h / 12 * force_q + h * h / 24 * force_x;
}

/// The step given V' at q and at the internal node x (`force` gives V' at the new position):
/// q_{j+1} = q + (h/m) p − (h²/(6m)) (V'(q) + 2 V'(x)), p_{j+1} = p − (h/6) (V'(q) + 4 V'(x) + V'(q_{j+1})):
/// Simpson's rule for the impulse of the force.
template <class Real, class Force>
phase_point<Real> simpson_update(const Real& m, const Real& h, Force&& force, const Real& q, const Real& p, const Real& force_q,
                                 const Real& force_x) {
  const Real q_next = q + h / m * p - h * h / (6 * m) * (force_q + 2 * force_x);
  return {p - h / 6 * (force_q + 4 * force_x + force(q_next)), q_next};
}

/// The Jacobian ∂(p_{j+1}, q_{j+1})/∂(p_j, q_j) of the step at its internal node x, by the implicit
/// function theorem on F(x) = 0 (differentiating through the Newton solve), as a one-step matrix:
///   x_q = (m − h² V''(q)/12)/F', x_p = (h/2)/F', F' = m + h² V''(x)/24;
///   q'_q = 1 − (h²/(6m))(V''(q) + 2 V''(x) x_q), q'_p = h/m − (h²/(3m)) V''(x) x_p;
///   p'_q = −(h/6)(V''(q) + 4 V''(x) x_q + V''(q') q'_q), p'_p = 1 − (h/6)(4 V''(x) x_p + V''(q') q'_p).
/// Its determinant is 1 for every V (claim nonlinear-symplectic).
/// `c_q`, `c_x`, `c_next` are V'' at q, x and q'.
template <class Real>
one_step_matrix<Real> simpson_step_jacobian(const Real& m, const Real& h, const Real& c_q, const Real& c_x, const Real& c_next) {
  const Real slope = m + h * h / 24 * c_x;
  const Real x_q = (m - h * h / 12 * c_q) / slope, x_p = h / 2 / slope;
  const Real qn_q = 1 - h * h / (6 * m) * (c_q + 2 * c_x * x_q), qn_p = h / m - h * h / (3 * m) * c_x * x_p;
  const Real pn_q = -h / 6 * (c_q + 4 * c_x * x_q + c_next * qn_q), pn_p = 1 - h / 6 * (4 * c_x * x_p + c_next * qn_p);
  return {pn_p, pn_q, qn_p, qn_q};
}

namespace detail {
/// True for a finite value (∞ − ∞ and NaN − NaN are NaN); always true for exact scalars.
template <class Real>
bool finite(const Real& v) {
  return v - v == 0;
}

/// The error of a Newton solve that did not reach its bound: never a silent result.
template <class Real>
[[noreturn]] void throw_newton_failure(const char* who, int iterations, const Real& residual, const Real& bound) {
  std::ostringstream what;
  what << who << ": Newton's method did not converge after " << iterations << " iterations (last residual "
       << std::setprecision(3) << std::scientific << static_cast<double>(residual) << ", bound " << static_cast<double>(bound) << ")";
  throw std::domain_error(what.str());
}
}  // namespace detail

/// What a nonlinear step found: the new state, its internal node, and how Newton's method got there.
template <class Real>
struct nonlinear_step_result {
  phase_point<Real> state;
  Real internal_node;
  int newton_iterations = 0;
  Real residual;        // |F(x)| at the end
  Real residual_bound;  // 16 eps times the sum of the magnitudes of F's terms
};

/// The most Newton iterations a step may take before it is declared failed.
inline constexpr int max_newton_iterations = 100;

/// One step for a potential with derivative() and second_derivative(). Newton's method on F from
/// x₀ = q + h p/(2m), in the working precision, until |F(x)| ≤ 16 eps Σ|terms of F| (each term
/// is a few roundings; V'(x) is computed to about an ulp). Throws std::domain_error, naming the
/// iterations and the last residual, when F' vanishes, a value is not finite, or Newton does not reach
/// that bound in max_newton_iterations: never a silent result.
template <class Real, class Potential>
nonlinear_step_result<Real> simpson_nonlinear_step(const Real& m, const Real& h, const Potential& V, const phase_point<Real>& y) {
  using std::abs;
  const auto force = [&V](const Real& v) { return V.derivative(v); };
  const Real force_q = force(y.q);
  nonlinear_step_result<Real> out{y, Real(y.q + h * y.p / (2 * m)), 0, Real(0), Real(0)};
  Real& x = out.internal_node;
  for (;;) {
    const Real force_x = force(x);
    const Real residual = simpson_internal_residual(m, h, y.q, y.p, x, force_q, force_x);
    out.residual = abs(residual);
    // The condition: the sum of the magnitudes of F's terms.
    out.residual_bound = 16 * eps<Real>() *
                         (m * (abs(x) + abs(y.q)) + abs(h / 2 * y.p) + h * h / 12 * abs(force_q) + h * h / 24 * abs(force_x));
    if (!detail::finite(out.residual) || !detail::finite(out.residual_bound)) break;
    if (out.residual <= out.residual_bound) {
      out.state = simpson_update(m, h, force, y.q, y.p, force_q, force_x);
      return out;
    }
    const Real slope = m + h * h / 24 * V.second_derivative(x);
    if (slope == 0 || out.newton_iterations == max_newton_iterations) break;
    x -= residual / slope;
    ++out.newton_iterations;
  }
  detail::throw_newton_failure("simpson::simpson_nonlinear_step", out.newton_iterations, out.residual, out.residual_bound);
}

}  // namespace simpson

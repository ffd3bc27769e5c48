#pragma once
// Partitioned Runge–Kutta methods on H = p²/(2m) + V(q) for any smooth V, any pair of tableaux
// (runge_kutta_tableaux.hpp), their stage equations solved by Newton's method: Lobatto IIIA–IIIB is
// the Simpson scheme's twin (claim nonlinear-lobatto-equivalence). Beyond the paper.

#include <simpson/nonlinear_simpson_step.hpp>
#include <simpson/partitioned_runge_kutta.hpp>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace simpson {

/// (A Â)_ik and c_i = Σ_j a_ij of a pair of tableaux with the same number of stages.
template <class Real>
struct stage_coupling {
  std::vector<std::vector<Real>> product;  // A Â
  std::vector<Real> nodes;                 // c
};

template <class Real>
stage_coupling<Real> couple(const butcher_tableau<Real>& for_q, const butcher_tableau<Real>& for_p) {
  const std::size_t s = for_q.stages();
  if (for_p.stages() != s) throw std::invalid_argument("simpson::couple: the two tableaux have different stage counts");
  stage_coupling<Real> c{std::vector<std::vector<Real>>(s, std::vector<Real>(s, Real(0))), std::vector<Real>(s, Real(0))};
  for (std::size_t i = 0; i < s; ++i) {
    for (std::size_t j = 0; j < s; ++j) {
      c.nodes[i] += for_q.a[i][j];
      for (std::size_t k = 0; k < s; ++k) c.product[i][k] += for_q.a[i][j] * for_p.a[j][k];
    }
  }
  return c;
}

/// The stage equations in the stage positions, given V'(Q_k), the stage momenta
/// P_j = p − h Σ_k â_jk V'(Q_k) substituted: R_i(Q) = Q_i − q − (h/m) c_i p + (h²/m) Σ_k (A Â)_ik V'(Q_k).
template <class Real>
std::vector<Real> prk_stage_residuals(const stage_coupling<Real>& c, const Real& m, const Real& h, const Real& q, const Real& p,
                                      const std::vector<Real>& stages, const std::vector<Real>& forces) {
  std::vector<Real> r;
  for (std::size_t i = 0; i < stages.size(); ++i) {
    Real coupled(0);
    for (std::size_t k = 0; k < stages.size(); ++k) coupled += c.product[i][k] * forces[k];
    r.push_back(stages[i] - q - h / m * c.nodes[i] * p + h * h / m * coupled);
  }
  return r;
}

/// The step from V' at its stages: q' = q + (h/m) Σ_j b_j P_j, p' = p − h Σ_k b̂_k V'(Q_k).
template <class Real>
phase_point<Real> prk_update(const butcher_tableau<Real>& for_q, const butcher_tableau<Real>& for_p, const Real& m, const Real& h,
                             const Real& q, const Real& p, const std::vector<Real>& forces) {
  const std::size_t s = forces.size();
  Real q_next = q, p_next = p;
  for (std::size_t j = 0; j < s; ++j) {
    Real P = p;
    for (std::size_t k = 0; k < s; ++k) P -= h * for_p.a[j][k] * forces[k];
    q_next += h / m * for_q.b[j] * P;
    p_next -= h * for_p.b[j] * forces[j];
  }
  return {p_next, q_next};
}

/// What a nonlinear partitioned Runge–Kutta step found.
template <class Real>
struct prk_step_result {
  phase_point<Real> state;
  std::vector<Real> stages;
  int newton_iterations = 0;
  Real residual;        // max_i |R_i| at the end
  Real residual_bound;  // 16 eps times the largest sum of magnitudes of an R_i's terms
};

/// One step: Newton's method on R(Q) = 0 from Q_i = q + c_i h p/m (the rule of the Simpson step's
/// x₀ = q + h p/(2m) at c = 1/2), with Jacobian δ_ik + (h²/m)(A Â)_ik V''(Q_k), until
/// max_i |R_i| ≤ 16 eps max_i Σ|terms of R_i|. Throws std::domain_error like simpson_nonlinear_step.
template <class Real, class Potential>
prk_step_result<Real> prk_nonlinear_step(const butcher_tableau<Real>& for_q, const butcher_tableau<Real>& for_p,
                                         const stage_coupling<Real>& c, const Real& m, const Real& h, const Potential& V,
                                         const phase_point<Real>& y) {
  using std::abs;
  const std::size_t s = c.nodes.size();
  prk_step_result<Real> out{y, std::vector<Real>(s), 0, Real(0), Real(0)};
  for (std::size_t i = 0; i < s; ++i) out.stages[i] = y.q + c.nodes[i] * h * y.p / m;
  std::vector<Real> forces(s);
  for (;;) {
    for (std::size_t k = 0; k < s; ++k) forces[k] = V.derivative(out.stages[k]);
    const std::vector<Real> r = prk_stage_residuals(c, m, h, y.q, y.p, out.stages, forces);
    out.residual = Real(0);
    out.residual_bound = Real(0);
    bool finite = true;
    for (std::size_t i = 0; i < s; ++i) {
      // The condition: the sum of the magnitudes of R_i's terms.
      Real terms = abs(out.stages[i]) + abs(y.q) + abs(h / m * c.nodes[i] * y.p);
      for (std::size_t k = 0; k < s; ++k) terms += abs(h * h / m * c.product[i][k] * forces[k]);
      const Real bound = 16 * eps<Real>() * terms;
      finite = finite && detail::finite(r[i]) && detail::finite(bound);
      if (abs(r[i]) > out.residual) out.residual = abs(r[i]);
      if (bound > out.residual_bound) out.residual_bound = bound;
    }
    if (!finite) break;
    // Normwise, as record_residual in nonlinear_ndof_step.hpp: a stage whose own terms vanish
    // (Q₁ = q = 0 in Lobatto IIIA) is solved to the system's round-off, not to zero.
    if (out.residual <= out.residual_bound) {
      out.state = prk_update(for_q, for_p, m, h, y.q, y.p, forces);
      return out;
    }
    if (out.newton_iterations == max_newton_iterations) break;
    std::vector<std::vector<Real>> jacobian(s, std::vector<Real>(s, Real(0)));
    for (std::size_t i = 0; i < s; ++i) {
      for (std::size_t k = 0; k < s; ++k) {
        jacobian[i][k] = (i == k ? Real(1) : Real(0)) + h * h / m * c.product[i][k] * V.second_derivative(out.stages[k]);
      }
    }
    const std::vector<Real> delta = solve_linear(jacobian, r);  // throws on a singular Jacobian
    for (std::size_t i = 0; i < s; ++i) out.stages[i] -= delta[i];
    ++out.newton_iterations;
  }
  detail::throw_newton_failure("simpson::prk_nonlinear_step", out.newton_iterations, out.residual, out.residual_bound);
}

}  // namespace simpson

#pragma once
// Partitioned Runge–Kutta methods on H = p²/(2m) + V(q) for any smooth V, any pair of tableaux
// (runge_kutta_tableaux.hpp), their stage equations solved by Newton's method: Lobatto IIIA–IIIB is
// the Simpson scheme's twin (claim nonlinear-lobatto-equivalence). Beyond the paper.

#include <simpson/nonlinear_simpson_step.hpp>
#include <simpson/partitioned_runge_kutta.hpp>

#include <array>
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

namespace detail {
/// R_i for i < s into r (any indexable storage): see prk_stage_residuals.
template <class Real, class Vector>
void stage_residuals_into(const stage_coupling<Real>& c, const Real& m, const Real& h, const Real& q, const Real& p,
                          const Vector& stages, const Vector& forces, Vector& r, std::size_t s) {
  for (std::size_t i = 0; i < s; ++i) {
    Real coupled(0);
    for (std::size_t k = 0; k < s; ++k) coupled += c.product[i][k] * forces[k];
    r[i] = stages[i] - q - h / m * c.nodes[i] * p + h * h / m * coupled;
  }
}

/// The update from the first s forces (any indexable storage): see prk_update.
template <class Real, class Vector>
phase_point<Real> update_from(const butcher_tableau<Real>& for_q, const butcher_tableau<Real>& for_p, const Real& m, const Real& h,
                              const Real& q, const Real& p, const Vector& forces, std::size_t s) {
  Real q_next = q, p_next = p;
  for (std::size_t j = 0; j < s; ++j) {
    Real P = p;
    for (std::size_t k = 0; k < s; ++k) P -= h * for_p.a[j][k] * forces[k];
    q_next += h / m * for_q.b[j] * P;
    p_next -= h * for_p.b[j] * forces[j];
  }
  return {p_next, q_next};
}
}  // namespace detail

/// The stage equations in the stage positions, given V'(Q_k), the stage momenta
/// P_j = p − h Σ_k â_jk V'(Q_k) substituted: R_i(Q) = Q_i − q − (h/m) c_i p + (h²/m) Σ_k (A Â)_ik V'(Q_k).
template <class Real>
std::vector<Real> prk_stage_residuals(const stage_coupling<Real>& c, const Real& m, const Real& h, const Real& q, const Real& p,
                                      const std::vector<Real>& stages, const std::vector<Real>& forces) {
  std::vector<Real> r(stages.size(), Real(0));
  detail::stage_residuals_into(c, m, h, q, p, stages, forces, r, stages.size());
  return r;
}

/// The step from V' at its stages: q' = q + (h/m) Σ_j b_j P_j, p' = p − h Σ_k b̂_k V'(Q_k).
template <class Real>
phase_point<Real> prk_update(const butcher_tableau<Real>& for_q, const butcher_tableau<Real>& for_p, const Real& m, const Real& h,
                             const Real& q, const Real& p, const std::vector<Real>& forces) {
  return detail::update_from(for_q, for_p, m, h, q, p, forces, forces.size());
}

/// What a nonlinear partitioned Runge–Kutta step found.
template <class Real>
struct prk_step_result {
  phase_point<Real> state;
  int newton_iterations = 0;
  Real residual;        // max_i |R_i| at the end
  Real residual_bound;  // 16 eps times the largest sum of magnitudes of an R_i's terms
};

namespace detail {
/// The step below with its work storage (stage positions, forces, residuals, corrections: at least
/// s entries; the Jacobian at least s × s).
template <class Real, class Potential, class Vector, class Matrix>
prk_step_result<Real> prk_nonlinear_solve(const butcher_tableau<Real>& for_q, const butcher_tableau<Real>& for_p,
                                          const stage_coupling<Real>& c, const Real& m, const Real& h, const Potential& V,
                                          const phase_point<Real>& y, Vector& stages, Vector& forces, Vector& r, Vector& delta,
                                          Matrix& jacobian) {
  using std::abs;
  const std::size_t s = c.nodes.size();
  prk_step_result<Real> out{y, 0, Real(0), Real(0)};
  for (std::size_t i = 0; i < s; ++i) stages[i] = y.q + c.nodes[i] * h * y.p / m;
  for (;;) {
    for (std::size_t k = 0; k < s; ++k) forces[k] = V.derivative(stages[k]);
    stage_residuals_into(c, m, h, y.q, y.p, stages, forces, r, s);
    out.residual = Real(0);
    out.residual_bound = Real(0);
    bool all_finite = true;
    for (std::size_t i = 0; i < s; ++i) {
      // The condition: the sum of the magnitudes of R_i's terms.
      Real terms = abs(stages[i]) + abs(y.q) + abs(h / m * c.nodes[i] * y.p);
      for (std::size_t k = 0; k < s; ++k) terms += abs(h * h / m * c.product[i][k] * forces[k]);
      const Real bound = 16 * eps<Real>() * terms;
      all_finite = all_finite && finite(r[i]) && finite(bound);
      if (abs(r[i]) > out.residual) out.residual = abs(r[i]);
      if (bound > out.residual_bound) out.residual_bound = bound;
    }
    if (!all_finite) break;
    // Normwise, as record_residual in nonlinear_ndof_step.hpp: a stage whose own terms vanish
    // (Q₁ = q = 0 in Lobatto IIIA) is solved to the system's round-off, not to zero.
    if (out.residual <= out.residual_bound) {
      out.state = update_from(for_q, for_p, m, h, y.q, y.p, forces, s);
      return out;
    }
    if (out.newton_iterations == max_newton_iterations) break;
    for (std::size_t i = 0; i < s; ++i) {
      for (std::size_t k = 0; k < s; ++k) {
        jacobian[i][k] = (i == k ? Real(1) : Real(0)) + h * h / m * c.product[i][k] * V.second_derivative(stages[k]);
      }
    }
    eliminate<Real>(jacobian, r, delta, s);  // throws on a singular Jacobian
    for (std::size_t i = 0; i < s; ++i) stages[i] -= delta[i];
    ++out.newton_iterations;
  }
  throw_newton_failure("simpson::prk_nonlinear_step", out.newton_iterations, out.residual, out.residual_bound);
}
}  // namespace detail

/// One step: Newton's method on R(Q) = 0 from Q_i = q + c_i h p/m (the rule of the Simpson step's
/// x₀ = q + h p/(2m) at c = 1/2), with Jacobian δ_ik + (h²/m)(A Â)_ik V''(Q_k), until
/// max_i |R_i| ≤ 16 eps max_i Σ|terms of R_i|. Throws std::domain_error like simpson_nonlinear_step.
/// Its work storage is in fixed-size arrays up to 4 stages (every tableau of the project: no
/// allocation per step in double), in vectors beyond; the same operations in the same order either way.
template <class Real, class Potential>
prk_step_result<Real> prk_nonlinear_step(const butcher_tableau<Real>& for_q, const butcher_tableau<Real>& for_p,
                                         const stage_coupling<Real>& c, const Real& m, const Real& h, const Potential& V,
                                         const phase_point<Real>& y) {
  const std::size_t s = c.nodes.size();
  if (s <= 4) {
    std::array<Real, 4> stages{}, forces{}, r{}, delta{};
    std::array<std::array<Real, 4>, 4> jacobian{};
    return detail::prk_nonlinear_solve(for_q, for_p, c, m, h, V, y, stages, forces, r, delta, jacobian);
  }
  std::vector<Real> stages(s), forces(s), r(s), delta(s);
  std::vector<std::vector<Real>> jacobian(s, std::vector<Real>(s, Real(0)));
  return detail::prk_nonlinear_solve(for_q, for_p, c, m, h, V, y, stages, forces, r, delta, jacobian);
}

}  // namespace simpson

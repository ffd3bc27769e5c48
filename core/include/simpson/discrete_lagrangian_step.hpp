#pragma once
// Beyond the paper: the variational step of a discrete Lagrangian built from a quadrature and a
// polynomial interpolant, for any Lagrangian of lagrangian.hpp. Control points y_0 = q_j, y_1, …,
// y_{m−1} = q_{j+1} at times t_c h; the interpolant's values and derivatives at the quadrature
// nodes are Q_k = Σ_c E_kc y_c and G_k = Σ_c D_kc y_c / h, and
//   L_d(y) = h Σ_k w_k L(Q_k, G_k).
// The step (discrete Euler–Lagrange, position–momentum form): given (q_j, p_j), solve
//   p_j = −∂L_d/∂y_0,   ∂L_d/∂y_c = 0 (0 < c < m−1)
// for y_1, …, y_{m−1} by Newton's method, then p_{j+1} = ∂L_d/∂y_{m−1}. With
// A_k = ∂L/∂q(Q_k, G_k), B_k = ∂L/∂v(Q_k, G_k):
//   ∂L_d/∂y_c = Σ_k w_k (h E_kc A_k + D_kc B_k),
//   ∂²L_d/∂y_c∂y_e = Σ_k w_k (h E_kc E_ke L_qq + E_kc D_ke L_qv + D_kc E_ke L_qvᵀ + D_kc D_ke L_vv / h).
// The schemes are data (discretisation): Simpson's (the paper's L_h, LLhh, for any L), the implicit
// midpoint rule, and the cubic Galerkin Lagrangian with Lobatto quadrature, whose step is the
// Lobatto IIIA–IIIB pair (HLW VI.6.4; hamiltonian_prk_step.hpp). Being data, a test can perturb a
// weight or an interpolant and see what breaks.

#include <simpson/lagrangian.hpp>
#include <simpson/nonlinear_ndof_step.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace simpson {

/// A discrete Lagrangian's discretisation: control-point times t_c (t_0 = 0, t_{m−1} = 1), the
/// quadrature weights w_k (Σ w_k = 1), and the interpolant's evaluation E_kc and derivative D_kc at
/// the quadrature nodes (times 1: D acts on control points, divided by h where used).
template <class Real>
struct discretisation {
  std::vector<Real> times;
  std::vector<Real> weights;
  std::vector<std::vector<Real>> evaluation, derivative;
};

/// The Lagrange basis on control-point times `times`, its values and derivatives at `nodes`:
/// E_kc = ℓ_c(node_k), D_kc = ℓ_c'(node_k), exact in Real (rational in the times).
template <class Real>
std::pair<std::vector<std::vector<Real>>, std::vector<std::vector<Real>>> lagrange_basis(const std::vector<Real>& times,
                                                                                            const std::vector<Real>& nodes) {
  const std::size_t m = times.size();
  std::vector<std::vector<Real>> E(nodes.size(), std::vector<Real>(m, Real(0))), D = E;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    for (std::size_t c = 0; c < m; ++c) {
      Real denominator(1);
      for (std::size_t i = 0; i < m; ++i) {
        if (i != c) denominator *= times[c] - times[i];
      }
      Real value(1), slope(0);  // ℓ_c(t) = Π_{i≠c} (t − t_i) / Π_{i≠c} (t_c − t_i), and its derivative
      for (std::size_t i = 0; i < m; ++i) {
        if (i == c) continue;
        slope = slope * (nodes[k] - times[i]) + value;
        value *= nodes[k] - times[i];
      }
      E[k][c] = value / denominator;
      D[k][c] = slope / denominator;
    }
  }
  return {E, D};
}

/// Simpson's discrete Lagrangian (LLhh): the quadratic interpolant through q_l, q_m, q_r at 0, 1/2, 1
/// (q2t), its derivatives there (derivees-gear, derivee-centree)
///   g_l = (−3q_l + 4q_m − q_r)/h,  g_m = (q_r − q_l)/h,  g_r = (q_l − 4q_m + 3q_r)/h,
/// and Simpson's rule (simpson): L_h = (h/6)[L(q_l, g_l) + 4 L(q_m, g_m) + L(q_r, g_r)].
template <class Real>
discretisation<Real> simpson_discretisation() {
  const Real zero(0), one(1);
  return {{zero, Real(1) / 2, one},
          {Real(1) / 6, Real(4) / 6, Real(1) / 6},  // (simpson)
          {{one, zero, zero}, {zero, one, zero}, {zero, zero, one}},
          {{Real(-3), Real(4), Real(-1)}, {Real(-1), zero, one}, {one, Real(-4), Real(3)}}};  // (derivees-gear), (derivee-centree)
}

/// The implicit midpoint variational integrator: L_d = h L((q_j + q_{j+1})/2, (q_{j+1} − q_j)/h).
template <class Real>
discretisation<Real> midpoint_discretisation() {
  return {{Real(0), Real(1)}, {Real(1)}, {{Real(1) / 2, Real(1) / 2}}, {{Real(-1), Real(1)}}};
}

/// The cubic Galerkin discrete Lagrangian with 3-point Lobatto quadrature: the cubic through control
/// points at 0, 1/3, 2/3, 1, evaluated at 0, 1/2, 1 with weights 1/6, 4/6, 1/6. Its step is the
/// Lobatto IIIA–IIIB pair for any L (HLW, Theorem VI.6.4: degree s with s nodes), which differs
/// from Simpson's (degree s − 1) unless the cubic's bubble, zero at the nodes, leaves L_d unchanged:
/// its stationarity is Σ_k w_k n_k ∂L/∂v(Q_k, G_k) = 0 with n = (2, −1, 2), which holds for
/// Simpson's interpolant when ∂²L/∂v² is constant, not for a configuration-dependent mass.
template <class Real>
discretisation<Real> lobatto_cubic_discretisation() {
  const std::vector<Real> times{Real(0), Real(1) / 3, Real(2) / 3, Real(1)};
  const auto [E, D] = lagrange_basis(times, std::vector<Real>{Real(0), Real(1) / 2, Real(1)});
  return {times, {Real(1) / 6, Real(4) / 6, Real(1) / 6}, E, D};
}

/// What a Lagrangian step found: as ndof_step_result, and for each coordinate k a bound on
/// |p_{j+1,k} − p_{j,k}| that holds when q_k is cyclic (∂L/∂q_k ≡ 0). The exact map conserves that
/// momentum (discrete Noether: L_d is invariant under y_c ↦ y_c + ε e_k since Σ_c E_kc = 1 and
/// Σ_c D_kc = 0, so Σ_c ∂L_d/∂y_{c,k} = 0 and p_{j+1,k} − p_{j,k} = −Σ_{c<m−1} R_{c,k}); what moves
/// it is the Newton residual left at the stated tolerance and the rounding of the update:
///   bound_k = Σ_c |R_{c,k}| + 16 eps (Σ_{c<m−1} T_{c,k} + T_{m−1,k}),
/// T the sums of the magnitudes of the terms (the residual bound's condition).
template <class Real>
struct lagrangian_step_result {
  ndof_state<Real> state;
  int newton_iterations = 0;
  Real residual;        // max over the equations of |R| at the end
  Real residual_bound;  // 16 eps times the largest sum of the magnitudes of an equation's terms
  dense_vector<Real> noether_bound;
};

namespace detail {
/// The node values of one iterate, and the system's residual, terms and Jacobian.
template <class Real>
struct discrete_lagrangian_system {
  std::vector<lagrangian_hessian<Real>> at_nodes;
  std::vector<dense_vector<Real>> gradient, terms;  // ∂L_d/∂y_c and the magnitudes of its terms, for every c
  dense_matrix<Real> jacobian;                      // ∂(∂L_d/∂y_a)/∂y_b, a < m − 1, b > 0
};

/// Evaluates L's derivatives at the quadrature nodes of the control points y and assembles
/// ∂L_d/∂y_c, its terms' magnitudes (each derivative's own magnitude, and its sensitivity to the
/// roundings of its arguments: |L_qq| |Q| + |L_qv| |G's terms| for A, likewise for B) and the
/// Jacobian. Generic over the scalar (intervals included).
template <class Real, class Lag>
discrete_lagrangian_system<Real> assemble(const Lag& L, const discretisation<Real>& d, const Real& h,
                                          const std::vector<dense_vector<Real>>& y, bool with_jacobian) {
  using std::abs;
  const std::size_t nodes = d.weights.size(), m = d.times.size();
  const Eigen::Index n = y[0].size();
  discrete_lagrangian_system<Real> s;
  s.gradient.assign(m, dense_vector<Real>::Zero(n));
  s.terms.assign(m, dense_vector<Real>::Zero(n));
  for (std::size_t k = 0; k < nodes; ++k) {
    dense_vector<Real> Q = dense_vector<Real>::Zero(n), G = Q, Q_size = Q, G_size = Q;
    for (std::size_t c = 0; c < m; ++c) {
      Q += scaled(y[c], d.evaluation[k][c]);
      G += scaled(y[c], Real(d.derivative[k][c] / h));
      Q_size += scaled(dense_vector<Real>(y[c].cwiseAbs()), Real(abs(d.evaluation[k][c])));
      G_size += scaled(dense_vector<Real>(y[c].cwiseAbs()), Real(abs(Real(d.derivative[k][c] / h))));
    }
    lagrangian_hessian<Real> at = lagrangian_hessian_at(L, Q, G);
    const dense_vector<Real> A_size = dense_vector<Real>(at.dq.cwiseAbs()) + at.qq.cwiseAbs() * Q_size + at.qv.cwiseAbs() * G_size;
    const dense_vector<Real> B_size =
        dense_vector<Real>(at.dv.cwiseAbs()) + at.qv.transpose().cwiseAbs() * Q_size + at.vv.cwiseAbs() * G_size;
    for (std::size_t c = 0; c < m; ++c) {
      const Real a = d.weights[k] * h * d.evaluation[k][c], b = d.weights[k] * d.derivative[k][c];
      s.gradient[c] += scaled(at.dq, a) + scaled(at.dv, b);  // ∂L_d/∂y_c = Σ_k w_k (h E_kc A_k + D_kc B_k)
      s.terms[c] += scaled(A_size, Real(abs(a))) + scaled(B_size, Real(abs(b)));
    }
    s.at_nodes.push_back(std::move(at));
  }
  if (with_jacobian) {
    s.jacobian = dense_matrix<Real>::Zero(static_cast<Eigen::Index>(m - 1) * n, static_cast<Eigen::Index>(m - 1) * n);
    for (std::size_t k = 0; k < nodes; ++k) {
      const lagrangian_hessian<Real>& at = s.at_nodes[k];
      const dense_matrix<Real> vq = at.qv.transpose();
      for (std::size_t a = 0; a + 1 < m; ++a) {
        for (std::size_t b = 1; b < m; ++b) {
          const Real& Ea = d.evaluation[k][a];
          const Real& Eb = d.evaluation[k][b];
          const Real& Da = d.derivative[k][a];
          const Real& Db = d.derivative[k][b];
          // w_k (h E_ka E_kb L_qq + E_ka D_kb L_qv + D_ka E_kb L_qvᵀ + D_ka D_kb L_vv / h)
          s.jacobian.block(static_cast<Eigen::Index>(a) * n, static_cast<Eigen::Index>(b - 1) * n, n, n) +=
              scaled(at.qq, Real(d.weights[k] * h * Ea * Eb)) + scaled(at.qv, Real(d.weights[k] * Ea * Db)) +
              scaled(vq, Real(d.weights[k] * Da * Eb)) + scaled(at.vv, Real(d.weights[k] * Da * Db / h));
        }
      }
    }
  }
  return s;
}

/// The velocity whose momentum is p at q, where ∂²L/∂v²(q, 0) is invertible (exact for L quadratic in
/// v): the Newton start's slope. Zero where it is not (a degenerate Lagrangian).
template <class Real, class Lag>
dense_vector<Real> starting_velocity(const Lag& L, const dense_vector<Real>& q, const dense_vector<Real>& p) {
  const dense_vector<Real> zero = dense_vector<Real>::Zero(q.size());
  const lagrangian_hessian<Real> at = lagrangian_hessian_at(L, q, zero);
  const dense_vector<Real> v = at.vv.fullPivLu().solve(dense_vector<Real>(p - at.dv));
  return finite_vector(v) && at.vv.fullPivLu().isInvertible() ? v : zero;
}
}  // namespace detail

/// One step of the discrete Lagrangian `d` from y = (p_j, q_j): Newton's method on
///   R_0 = p_j + ∂L_d/∂y_0,  R_c = ∂L_d/∂y_c (0 < c < m−1)
/// in y_1, …, y_{m−1} from y_c = q_j + t_c h v₀ (v₀ from p_j by the Legendre transform at q_j), with
/// the exact Jacobian from L's Hessian blocks, until max |R| ≤ 16 eps max Σ|terms| (record_residual);
/// then q_{j+1} = y_{m−1}, p_{j+1} = ∂L_d/∂y_{m−1}. Throws std::domain_error naming the function, the
/// iterations and the last residual when Newton does not get there in max_newton_iterations, a value
/// is not finite, or the Jacobian is singular: never a step that did not converge.
template <class Real, class Lag>
lagrangian_step_result<Real> discrete_lagrangian_step(const discretisation<Real>& d, const Lag& L, const Real& h,
                                                      const ndof_state<Real>& y) {
  if (!(h > 0)) throw std::invalid_argument("simpson::discrete_lagrangian_step: h must be positive");
  const std::size_t m = d.times.size();
  const Eigen::Index n = y.q.size();
  if (y.p.size() != n) throw std::invalid_argument("simpson::discrete_lagrangian_step: p and q must have L.dof() entries");
  const dense_vector<Real> v0 = detail::starting_velocity(L, y.q, y.p);
  std::vector<dense_vector<Real>> points(m);
  for (std::size_t c = 0; c < m; ++c) points[c] = y.q + scaled(v0, Real(d.times[c] * h));
  lagrangian_step_result<Real> out{y, 0, Real(0), Real(0), dense_vector<Real>::Zero(n)};
  const Eigen::Index unknowns = static_cast<Eigen::Index>(m - 1) * n;
  for (;;) {
    const detail::discrete_lagrangian_system<Real> s = detail::assemble(L, d, h, points, true);
    dense_vector<Real> residual(unknowns), terms(unknowns);
    for (std::size_t a = 0; a + 1 < m; ++a) {
      const Eigen::Index at = static_cast<Eigen::Index>(a) * n;
      residual.segment(at, n) = s.gradient[a];
      terms.segment(at, n) = s.terms[a];
    }
    residual.head(n) += y.p;  // R_0 = p_j + ∂L_d/∂y_0
    terms.head(n) += y.p.cwiseAbs();
    bool within = false;
    if (!detail::record_residual(residual, terms, out.residual, out.residual_bound, within)) break;
    if (within) {
      out.state.q = points[m - 1];
      out.state.p = s.gradient[m - 1];  // p_{j+1} = ∂L_d/∂y_{m−1}
      dense_vector<Real> moved = s.terms[m - 1];
      for (std::size_t a = 0; a + 1 < m; ++a) moved += terms.segment(static_cast<Eigen::Index>(a) * n, n);
      out.noether_bound = scaled(moved, Real(16 * eps<Real>()));
      for (std::size_t a = 0; a + 1 < m; ++a) out.noether_bound += residual.segment(static_cast<Eigen::Index>(a) * n, n).cwiseAbs();
      return out;
    }
    if (out.newton_iterations == max_newton_iterations) break;
    const auto lu = s.jacobian.fullPivLu();
    if (!lu.isInvertible()) break;
    const dense_vector<Real> delta = lu.solve(residual);
    if (!detail::finite_vector(delta)) break;
    for (std::size_t b = 1; b < m; ++b) points[b] -= delta.segment(static_cast<Eigen::Index>(b - 1) * n, n);
    ++out.newton_iterations;
  }
  detail::throw_newton_failure("simpson::discrete_lagrangian_step", out.newton_iterations, out.residual, out.residual_bound);
}

/// Simpson's variational step for any L (simpson_discretisation).
template <class Real, class Lag>
lagrangian_step_result<Real> simpson_lagrangian_step(const Lag& L, const Real& h, const ndof_state<Real>& y) {
  return discrete_lagrangian_step(simpson_discretisation<Real>(), L, h, y);
}

/// The implicit midpoint variational step (midpoint_discretisation).
template <class Real, class Lag>
lagrangian_step_result<Real> midpoint_lagrangian_step(const Lag& L, const Real& h, const ndof_state<Real>& y) {
  return discrete_lagrangian_step(midpoint_discretisation<Real>(), L, h, y);
}

}  // namespace simpson

#pragma once
// Beyond the paper: partitioned Runge–Kutta steps and RK4 on the Hamiltonian equations of a
// Lagrangian quadratic in v (legendre_hamiltonian.hpp), H not separable. The stage equations of a
// pair (A for q, Â for p; HLW II.2.2)
//   Q_i = q + h Σ_j a_ij ∂H/∂p(Q_j, P_j),   P_i = p − h Σ_j â_ij ∂H/∂q(Q_j, P_j)
// are solved for (Q, P) by Newton's method with the exact Jacobian (H's Hessian blocks), then
//   q' = q + h Σ_j b_j ∂H/∂p(Q_j, P_j),   p' = p − h Σ_j b̂_j ∂H/∂q(Q_j, P_j).
// With Lobatto IIIA–IIIB (runge_kutta_tableaux.hpp) this is the cubic Galerkin variational step
// (discrete_lagrangian_step.hpp's lobatto_cubic_discretisation); Simpson's step when ∂²L/∂v² is
// constant.

#include <simpson/legendre_hamiltonian.hpp>
#include <simpson/partitioned_runge_kutta.hpp>
#include <simpson/runge_kutta_tableaux.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace simpson {

/// One step of the pair (for_q, for_p) on H of L from y. Newton from Q_i = q + c_i h ∂H/∂p(q, p),
/// P_i = p, until max |R| ≤ 16 eps max Σ|terms| (record_residual; the terms include each derivative's
/// sensitivity to its arguments' roundings, |H_pq| |Q| + |H_pp| |P| for ∂H/∂p, likewise for ∂H/∂q).
/// Throws std::domain_error like simpson_ndof_step: never a step that did not converge.
template <class Real, class Lag>
ndof_step_result<Real> hamiltonian_prk_step(const butcher_tableau<Real>& for_q, const butcher_tableau<Real>& for_p, const Lag& L,
                                            const Real& h, const ndof_state<Real>& y) {
  using std::abs;
  const std::size_t s = for_q.stages();
  if (for_p.stages() != s) throw std::invalid_argument("simpson::hamiltonian_prk_step: the two tableaux have different stage counts");
  const Eigen::Index n = y.q.size(), block = 2 * n;
  const dense_vector<Real> v0 = legendre_hamiltonian(L, y.q, y.p, false).dp;
  std::vector<dense_vector<Real>> Q(s), P(s, y.p);
  for (std::size_t i = 0; i < s; ++i) {
    Real c(0);
    for (std::size_t j = 0; j < s; ++j) c += for_q.a[i][j];
    Q[i] = y.q + scaled(v0, Real(c * h));
  }
  ndof_step_result<Real> out{y, 0, Real(0), Real(0)};
  std::vector<hamiltonian_derivatives<Real>> d(s);
  for (;;) {
    for (std::size_t j = 0; j < s; ++j) d[j] = legendre_hamiltonian(L, Q[j], P[j], true);
    dense_vector<Real> residual(static_cast<Eigen::Index>(s) * block), terms(static_cast<Eigen::Index>(s) * block);
    for (std::size_t i = 0; i < s; ++i) {
      dense_vector<Real> rq = Q[i] - y.q, rp = P[i] - y.p;
      dense_vector<Real> tq = dense_vector<Real>(Q[i].cwiseAbs()) + y.q.cwiseAbs(), tp = dense_vector<Real>(P[i].cwiseAbs()) + y.p.cwiseAbs();
      for (std::size_t j = 0; j < s; ++j) {
        const Real a = h * for_q.a[i][j], b = h * for_p.a[i][j];
        rq -= scaled(d[j].dp, a);  // Q_i − q − h Σ_j a_ij H_p(Q_j, P_j)
        rp += scaled(d[j].dq, b);  // P_i − p + h Σ_j â_ij H_q(Q_j, P_j)
        const dense_vector<Real> size_p = dense_vector<Real>(d[j].dp.cwiseAbs()) + d[j].qp.transpose().cwiseAbs() * Q[j].cwiseAbs() +
                                          d[j].pp.cwiseAbs() * P[j].cwiseAbs();
        const dense_vector<Real> size_q =
            dense_vector<Real>(d[j].dq.cwiseAbs()) + d[j].qq.cwiseAbs() * Q[j].cwiseAbs() + d[j].qp.cwiseAbs() * P[j].cwiseAbs();
        tq += scaled(size_p, Real(abs(a)));
        tp += scaled(size_q, Real(abs(b)));
      }
      const Eigen::Index at = static_cast<Eigen::Index>(i) * block;
      residual.segment(at, n) = rq;
      residual.segment(at + n, n) = rp;
      terms.segment(at, n) = tq;
      terms.segment(at + n, n) = tp;
    }
    bool within = false;
    if (!detail::record_residual(residual, terms, out.residual, out.residual_bound, within)) break;
    if (within) {
      out.state = y;
      for (std::size_t j = 0; j < s; ++j) {
        out.state.q += scaled(d[j].dp, Real(h * for_q.b[j]));  // q' = q + h Σ b_j H_p
        out.state.p -= scaled(d[j].dq, Real(h * for_p.b[j]));  // p' = p − h Σ b̂_j H_q
      }
      return out;
    }
    if (out.newton_iterations == max_newton_iterations) break;
    dense_matrix<Real> jacobian = dense_matrix<Real>::Identity(static_cast<Eigen::Index>(s) * block, static_cast<Eigen::Index>(s) * block);
    for (std::size_t i = 0; i < s; ++i) {
      for (std::size_t j = 0; j < s; ++j) {
        const Real a = h * for_q.a[i][j], b = h * for_p.a[i][j];
        const Eigen::Index r = static_cast<Eigen::Index>(i) * block, c = static_cast<Eigen::Index>(j) * block;
        jacobian.block(r, c, n, n) -= scaled(dense_matrix<Real>(d[j].qp.transpose()), a);  // ∂R^Q_i/∂Q_j = δ − h a_ij H_pq
        jacobian.block(r, c + n, n, n) -= scaled(d[j].pp, a);                              // ∂R^Q_i/∂P_j = −h a_ij H_pp
        jacobian.block(r + n, c, n, n) += scaled(d[j].qq, b);                              // ∂R^P_i/∂Q_j = h â_ij H_qq
        jacobian.block(r + n, c + n, n, n) += scaled(d[j].qp, b);                          // ∂R^P_i/∂P_j = δ + h â_ij H_qp
      }
    }
    const dense_vector<Real> delta = jacobian.partialPivLu().solve(residual);
    if (!detail::finite_vector(delta)) break;
    for (std::size_t i = 0; i < s; ++i) {
      Q[i] -= delta.segment(static_cast<Eigen::Index>(i) * block, n);
      P[i] -= delta.segment(static_cast<Eigen::Index>(i) * block + n, n);
    }
    ++out.newton_iterations;
  }
  detail::throw_newton_failure("simpson::hamiltonian_prk_step", out.newton_iterations, out.residual, out.residual_bound);
}

/// The Lobatto IIIA–IIIB pair (3 stages, order 4) on H of L.
template <class Real, class Lag>
ndof_step_result<Real> lobatto_hamiltonian_step(const Lag& L, const Real& h, const ndof_state<Real>& y) {
  return hamiltonian_prk_step(lobatto_iiia3_tableau<Real>(), lobatto_iiib3_tableau<Real>(), L, h, y);
}

/// The classic RK4 step on ṗ = −∂H/∂q, q̇ = ∂H/∂p (explicit: no Newton, no residual).
template <class Real, class Lag>
ndof_step_result<Real> rk4_hamiltonian_step(const Lag& L, const Real& h, const ndof_state<Real>& y) {
  const auto shifted = [](const ndof_state<Real>& z, const ndof_state<Real>& k, const Real& a) {
    return ndof_state<Real>{z.p + scaled(k.p, a), z.q + scaled(k.q, a)};
  };
  const ndof_state<Real> k1 = hamiltonian_field(L, y), k2 = hamiltonian_field(L, shifted(y, k1, Real(h / 2))),
                         k3 = hamiltonian_field(L, shifted(y, k2, Real(h / 2))), k4 = hamiltonian_field(L, shifted(y, k3, h));
  return {{y.p + scaled(dense_vector<Real>(k1.p + 2 * k2.p + 2 * k3.p + k4.p), Real(h / 6)),
           y.q + scaled(dense_vector<Real>(k1.q + 2 * k2.q + 2 * k3.q + k4.q), Real(h / 6))},
          0,
          Real(0),
          Real(0)};
}

}  // namespace simpson

#pragma once
// Beyond the paper: the variational partitioned Runge–Kutta step (VPRK) of GeometricIntegrators.jl,
// the same equations in C++, for a Lagrangian of lagrangian.hpp. Read at
// JuliaGNI/GeometricIntegrators.jl commit 9c299a25544a444220557fee0cc238717d542664
// (src/integrators/vi/vprk_integrator.jl: components!, residual_solution!, residual_correction!,
// update!; src/integrators/vi/vprk_methods.jl: VPRKLobattoIIIAIIIB(s) = TableauLobattoIIIAIIIB(s)
// with nullvector get_lobatto_nullvector(s)), and JuliaGNI/RungeKutta.jl commit
// c27e9a2bb9dd9ef74e284a5c0e4e60971bbd3b7a (src/tableaus/lobatto.jl, prk.jl). Their default runs no
// projection (VPRK, not VPRKpStandard & co.); their a + â and ā + â̄ (coefficients split for
// compensated summation) are the exact coefficients here.
//
// Unknowns: the stage velocities V_1, …, V_s. With (A, b) for q and (Ā, b̄) for p:
//   Q_i = q + h Σ_j a_ij V_j,  P_i = ∂L/∂v(Q_i, V_i),  F_i = ∂L/∂q(Q_i, V_i),
//   r_i = −(P_i − p) + h Σ_j ā_ij F_j                                         (residual_solution!)
// and, with a null vector d (Lobatto: Σ_i d_i V_i = 0 for velocities of a degree s − 1 polynomial),
// the middle stage l = ⌊(s + 1)/2⌋ (1-based) traded for the constraint:
//   μ = (b̄_l / d_l) r_l,  r_l ← Σ_i d_i V_i,  r_i ← r_i − (d_i / b̄_i) μ (i ≠ l)  (residual_correction!)
// that is P_i = p + h Σ_j ā_ij F_j − (d_i / b̄_i) κ for one multiplier κ: the stationarity of the
// degree s − 1 Galerkin Lagrangian, which for s = 3 is Simpson's (discrete_lagrangian_step.hpp).
// Then q' = q + h Σ_i b_i V_i, p' = p + h Σ_i b̄_i F_i (update!). Their solver is Newton's method
// (SimpleSolvers) from a Hermite extrapolation; here Newton with the exact Jacobian from v₀: the same
// zero, reached from another start.

#include <simpson/discrete_lagrangian_step.hpp>
#include <simpson/partitioned_runge_kutta.hpp>
#include <simpson/runge_kutta_tableaux.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace simpson {

/// get_lobatto_nullvector(3) up to its scale (theirs is normalised; the corrected system's zeros do
/// not depend on the scale): Σ_i d_i V_i = 0 for the derivative of a quadratic at 0, 1/2, 1.
template <class Real>
std::vector<Real> lobatto3_null_vector() {
  return {Real(1), Real(-2), Real(1)};
}

/// One VPRK step from y; `null_vector` empty for the uncorrected system (VPRK without one). Newton
/// from V_i = v₀ (the Legendre transform of p at q, zero for a degenerate L) until
/// max |r| ≤ 16 eps max Σ|terms| (record_residual). Throws std::domain_error when it does not converge.
template <class Real, class Lag>
lagrangian_step_result<Real> vprk_lagrangian_step(const butcher_tableau<Real>& for_q, const butcher_tableau<Real>& for_p,
                                                  const std::vector<Real>& null_vector, const Lag& L, const Real& h,
                                                  const ndof_state<Real>& y) {
  using std::abs;
  const std::size_t s = for_q.stages();
  if (for_p.stages() != s || (!null_vector.empty() && null_vector.size() != s)) {
    throw std::invalid_argument("simpson::vprk_lagrangian_step: the tableaux and the null vector must have as many stages");
  }
  const Eigen::Index n = y.q.size(), N = static_cast<Eigen::Index>(s) * n;
  const std::size_t l = (s + 1) / 2 - 1;  // the middle stage, 0-based
  std::vector<dense_vector<Real>> V(s, detail::starting_velocity(L, y.q, y.p)), Q(s);
  std::vector<lagrangian_hessian<Real>> at(s);
  lagrangian_step_result<Real> out{y, 0, Real(0), Real(0), dense_vector<Real>::Zero(n)};
  for (;;) {
    for (std::size_t i = 0; i < s; ++i) {
      Q[i] = y.q;
      for (std::size_t j = 0; j < s; ++j) Q[i] += scaled(V[j], Real(h * for_q.a[i][j]));  // Q_i = q + h Σ_j a_ij V_j
      at[i] = lagrangian_hessian_at(L, Q[i], V[i]);
    }
    dense_vector<Real> r(N), terms(N);
    dense_matrix<Real> J = dense_matrix<Real>::Zero(N, N);
    for (std::size_t i = 0; i < s; ++i) {
      const Eigen::Index ri = static_cast<Eigen::Index>(i) * n;
      dense_vector<Real> ri_value = y.p - at[i].dv;  // −(P_i − p) + h Σ_j ā_ij F_j
      dense_vector<Real> ri_terms = dense_vector<Real>(at[i].dv.cwiseAbs()) + y.p.cwiseAbs() +
                                    at[i].qv.transpose().cwiseAbs() * Q[i].cwiseAbs() + at[i].vv.cwiseAbs() * V[i].cwiseAbs();
      for (std::size_t j = 0; j < s; ++j) {
        const Real w = h * for_p.a[i][j];
        ri_value += scaled(at[j].dq, w);
        ri_terms += scaled(dense_vector<Real>(dense_vector<Real>(at[j].dq.cwiseAbs()) + at[j].qq.cwiseAbs() * Q[j].cwiseAbs() +
                                              at[j].qv.cwiseAbs() * V[j].cwiseAbs()),
                           Real(abs(w)));
      }
      r.segment(ri, n) = ri_value;
      terms.segment(ri, n) = ri_terms;
      for (std::size_t k = 0; k < s; ++k) {
        // ∂r_i/∂V_k = −(h a_ik L_qvᵀ(i) + δ_ik L_vv(i)) + h Σ_j ā_ij (h a_jk L_qq(j) + δ_jk L_qv(j))
        dense_matrix<Real> block = scaled(dense_matrix<Real>(at[i].qv.transpose()), Real(-h * for_q.a[i][k]));
        if (i == k) block -= at[i].vv;
        for (std::size_t j = 0; j < s; ++j) block += scaled(at[j].qq, Real(h * for_p.a[i][j] * h * for_q.a[j][k]));
        block += scaled(at[k].qv, Real(h * for_p.a[i][k]));
        J.block(ri, static_cast<Eigen::Index>(k) * n, n, n) = block;
      }
    }
    const dense_vector<Real> raw_l = r.segment(static_cast<Eigen::Index>(l) * n, n);
    const dense_vector<Real> raw_l_terms = terms.segment(static_cast<Eigen::Index>(l) * n, n);
    const dense_matrix<Real> raw_J_l = J.middleRows(static_cast<Eigen::Index>(l) * n, n);
    if (!null_vector.empty()) {
      dense_vector<Real> constraint = dense_vector<Real>::Zero(n), constraint_terms = constraint;
      for (std::size_t i = 0; i < s; ++i) {
        constraint += scaled(V[i], null_vector[i]);  // Σ_i d_i V_i
        constraint_terms += scaled(dense_vector<Real>(V[i].cwiseAbs()), Real(abs(null_vector[i])));
        const Eigen::Index ri = static_cast<Eigen::Index>(i) * n;
        if (i == l) continue;
        const Real z = null_vector[i] / for_p.b[i] * for_p.b[l] / null_vector[l];  // (d_i / b̄_i) (b̄_l / d_l)
        r.segment(ri, n) -= scaled(raw_l, z);
        terms.segment(ri, n) += scaled(raw_l_terms, Real(abs(z)));
        J.middleRows(ri, n) -= scaled(raw_J_l, z);
      }
      const Eigen::Index rl = static_cast<Eigen::Index>(l) * n;
      r.segment(rl, n) = constraint;
      terms.segment(rl, n) = constraint_terms;
      for (std::size_t k = 0; k < s; ++k) {
        J.block(rl, static_cast<Eigen::Index>(k) * n, n, n) = scaled(dense_matrix<Real>(dense_matrix<Real>::Identity(n, n)), null_vector[k]);
      }
    }
    bool within = false;
    if (!detail::record_residual(r, terms, out.residual, out.residual_bound, within)) break;
    if (within) {
      out.state = y;
      for (std::size_t i = 0; i < s; ++i) {
        out.state.q += scaled(V[i], Real(h * for_q.b[i]));      // q' = q + h Σ b_i V_i
        out.state.p += scaled(at[i].dq, Real(h * for_p.b[i]));  // p' = p + h Σ b̄_i F_i
      }
      return out;
    }
    if (out.newton_iterations == max_newton_iterations) break;
    const auto lu = J.fullPivLu();
    if (!lu.isInvertible()) break;
    const dense_vector<Real> delta = lu.solve(dense_vector<Real>(-r));  // J is ∂r/∂V: V ← V − J⁻¹ r
    if (!detail::finite_vector(delta)) break;
    for (std::size_t i = 0; i < s; ++i) V[i] += delta.segment(static_cast<Eigen::Index>(i) * n, n);
    ++out.newton_iterations;
  }
  detail::throw_newton_failure("simpson::vprk_lagrangian_step", out.newton_iterations, out.residual, out.residual_bound);
}

/// GeometricIntegrators' VPRKLobattoIIIAIIIB(3): Lobatto IIIA for q, IIIB for p, with the null vector.
template <class Real, class Lag>
lagrangian_step_result<Real> vprk_lobatto3_step(const Lag& L, const Real& h, const ndof_state<Real>& y) {
  return vprk_lagrangian_step(lobatto_iiia3_tableau<Real>(), lobatto_iiib3_tableau<Real>(), lobatto3_null_vector<Real>(), L, h, y);
}

}  // namespace simpson

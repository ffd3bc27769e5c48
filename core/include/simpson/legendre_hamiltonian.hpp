#pragma once
// Beyond the paper: the Hamiltonian H(q, p) = p·v − L(q, v) of a Lagrangian of lagrangian.hpp, by
// the Legendre transform, and its derivatives from L's AutoDiff derivatives alone.
//
// Restriction: L quadratic in v, L = ½ vᵀ M(q) v + a(q)ᵀ v − V(q) with M(q) = ∂²L/∂v² invertible.
// Then p = ∂L/∂v = M(q) v + a(q) is solved exactly by one linear solve, v = M(q)⁻¹ (p − a(q)), with
// M and a = ∂L/∂v(q, 0) read at v = 0; every derivative is checked against that: a Lagrangian that is
// not quadratic in v (∂L/∂v(q, v) ≠ p) throws std::domain_error, never a silently wrong H.
// Derivatives (differentiating ∂L/∂v(q, v(q, p)) = p):
//   ∂H/∂p = v,  ∂H/∂q = −∂L/∂q,  ∂²H/∂p² = M⁻¹,  ∂²H/∂p∂q = ∂v/∂q = −M⁻¹ L_qvᵀ,
//   ∂²H/∂q² = −L_qq + L_qv M⁻¹ L_qvᵀ    (L's blocks at (q, v); L_qv(i, j) = ∂²L/∂q_i∂v_j).

#include <simpson/lagrangian.hpp>
#include <simpson/nonlinear_ndof_step.hpp>

#include <cmath>
#include <stdexcept>

namespace simpson {

/// H and its derivatives at (q, p); qp(i, j) = ∂²H/∂q_i∂p_j (the Hessian blocks only when asked).
template <class Real>
struct hamiltonian_derivatives {
  Real value;
  dense_vector<Real> dq, dp;
  dense_matrix<Real> qq, qp, pp;
};

namespace detail {
/// v = M⁻¹ (p − a), with M = ∂²L/∂v² and a = ∂L/∂v at (q, 0). Throws std::domain_error where M is singular.
template <class Real, class Lag>
dense_vector<Real> legendre_velocity(const Lag& L, const dense_vector<Real>& q, const dense_vector<Real>& p, const char* who) {
  const lagrangian_hessian<Real> at_rest = lagrangian_hessian_at(L, q, dense_vector<Real>(dense_vector<Real>::Zero(q.size())));
  const auto lu = at_rest.vv.fullPivLu();
  if (!lu.isInvertible()) throw std::domain_error(std::string(who) + ": d2L/dv2 is singular (a degenerate Lagrangian)");
  return lu.solve(dense_vector<Real>(p - at_rest.dv));
}

/// Throws std::domain_error when ∂L/∂v(q, v) is not p to round-off: L is not quadratic in v.
/// The bound: 64 eps (|p| + |M| |v| + |a|), a few roundings of the solve and of L's derivatives.
template <class Real>
void check_quadratic(const dense_vector<Real>& momentum, const dense_vector<Real>& p, const dense_matrix<Real>& M,
                     const dense_vector<Real>& v, const char* who) {
  const dense_vector<Real> size = dense_vector<Real>(p.cwiseAbs()) + M.cwiseAbs() * v.cwiseAbs() + momentum.cwiseAbs();
  for (Eigen::Index i = 0; i < p.size(); ++i) {
    using std::abs;
    if (!(abs(Real(momentum(i) - p(i))) <= 64 * eps<Real>() * size(i))) {
      throw std::domain_error(std::string(who) + ": L is not quadratic in v (dL/dv(q, M^-1 (p - a)) differs from p)");
    }
  }
}
}  // namespace detail

/// H(q, p) and ∂H/∂q, ∂H/∂p; with `second`, the Hessian blocks too.
template <class Real, class Lag>
hamiltonian_derivatives<Real> legendre_hamiltonian(const Lag& L, const dense_vector<Real>& q, const dense_vector<Real>& p,
                                                   bool second = true) {
  static const char* who = "simpson::legendre_hamiltonian";
  const dense_vector<Real> v = detail::legendre_velocity(L, q, p, who);
  const lagrangian_hessian<Real> at = lagrangian_hessian_at(L, q, v);
  detail::check_quadratic(at.dv, p, at.vv, v, who);
  hamiltonian_derivatives<Real> out{Real(p.dot(v) - at.value), -at.dq, v, {}, {}, {}};  // H = p·v − L, H_q = −L_q, H_p = v
  if (second) {
    const auto lu = at.vv.fullPivLu();
    const dense_matrix<Real> M_inv_vq = lu.solve(dense_matrix<Real>(at.qv.transpose()));                   // M⁻¹ L_qvᵀ
    out.pp = lu.solve(dense_matrix<Real>(dense_matrix<Real>::Identity(q.size(), q.size())));                // M⁻¹
    out.qp = -M_inv_vq.transpose();                                                                         // −L_qv M⁻¹
    out.qq = dense_matrix<Real>(at.qv * M_inv_vq) - at.qq;                                                  // −L_qq + L_qv M⁻¹ L_qvᵀ
  }
  return out;
}

/// The Hamiltonian vector field at y, as a state (momentum first): (−∂H/∂q, ∂H/∂p), from first
/// derivatives of L only (what an explicit method or the reference needs, several times cheaper than
/// the nested AutoDiff): a = ∂L/∂v(q, 0), M's columns M e_k = ∂L/∂v(q, e_k) − a (exact for L quadratic
/// in v; their rounding is eps |a|), v = M⁻¹ (p − a), then ∂L/∂q and the quadratic check at (q, v).
template <class Real, class Lag>
ndof_state<Real> hamiltonian_field(const Lag& L, const ndof_state<Real>& y) {
  static const char* who = "simpson::hamiltonian_field";
  const Eigen::Index n = y.q.size();
  dense_vector<Real> unit = dense_vector<Real>::Zero(n);
  const dense_vector<Real> a = lagrangian_gradient_at(L, y.q, unit).dv;
  dense_matrix<Real> M(n, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    unit(k) = Real(1);
    M.col(k) = lagrangian_gradient_at(L, y.q, unit).dv - a;
    unit(k) = Real(0);
  }
  const auto lu = M.fullPivLu();
  if (!lu.isInvertible()) throw std::domain_error(std::string(who) + ": d2L/dv2 is singular (a degenerate Lagrangian)");
  const dense_vector<Real> v = lu.solve(dense_vector<Real>(y.p - a));
  const lagrangian_gradient<Real> at = lagrangian_gradient_at(L, y.q, v);
  detail::check_quadratic(at.dv, y.p, M, v, who);
  return {at.dq, v};  // ṗ = −∂H/∂q = ∂L/∂q, q̇ = ∂H/∂p = v
}

}  // namespace simpson

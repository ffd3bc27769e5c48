#pragma once
// Beyond the paper: the Simpson scheme for n degrees of freedom with a quadratic Lagrangian
// L = ½ q̇ᵀ M q̇ − ½ qᵀ K q (M symmetric positive definite, K symmetric), as in the authors' 2024
// work on quadratic Lagrangians. The nonlinear step's equations (nonlinear_simpson_step.hpp) with
// the matrix M for m and ∇V = K q are linear, so the step is a 2n × 2n matrix: Φ₃'s block analogue.
// Generic over the floating scalars (Eigen with Boost.Multiprecision numbers). Not with
// `rational`: Eigen 3.4's products do not compile with Boost 1.74's cpp_rational (Eigen's
// scalar-product overload probes is_convertible<Matrix, number>, a hard error in cpp_int's
// byte-container constructor); the exact proofs are GiNaC's (claims ndof-symplectic, ndof-energy).

#include <Eigen/Dense>

#include <stdexcept>

namespace simpson {

template <class Real>
using dense_matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;

/// s A. Written with *= because Boost 1.74's free operators on number<> make `s * A` and `A * s`
/// a hard error when A is an Eigen matrix (is_byte_container in their SFINAE test).
template <class Real>
dense_matrix<Real> scaled(dense_matrix<Real> A, const Real& s) {
  A *= s;
  return A;
}

/// Φ₃ for n degrees of freedom, on y = (p, q) (p first, as phase_point): the step
///   x  = (M + h²K/24)⁻¹ (M q + (h/2) p − (h²/12) K q)                  (internal node)
///   q' = q + h M⁻¹ p − (h²/6) M⁻¹ K (q + 2x)
///   p' = p − (h/6) K (q + 4x + q')                                       (Simpson's rule for the impulse)
/// written as the matrix of (p, q) ↦ (p', q'). Throws std::domain_error when M or M + h²K/24 is
/// singular.
template <class Real>
dense_matrix<Real> ndof_simpson_map(const dense_matrix<Real>& M, const dense_matrix<Real>& K, const Real& h) {
  const Eigen::Index n = M.rows();
  if (M.cols() != n || K.rows() != n || K.cols() != n) throw std::invalid_argument("simpson::ndof_simpson_map: M and K must be n x n");
  const dense_matrix<Real> I = dense_matrix<Real>::Identity(n, n);
  const Real h2 = h * h;
  const Eigen::FullPivLU<dense_matrix<Real>> mass(M), internal(dense_matrix<Real>(M + scaled(K, Real(h2 / 24))));
  if (!mass.isInvertible() || !internal.isInvertible()) {
    throw std::domain_error("simpson::ndof_simpson_map: M or M + h^2 K/24 is singular");
  }
  const dense_matrix<Real> M_inv_K = mass.solve(K), M_inv = mass.solve(I);
  // x = X_p p + X_q q, q' = Q_p p + Q_q q, p' = P_p p + P_q q.
  const dense_matrix<Real> X_p = internal.solve(scaled(I, Real(h / 2)));
  const dense_matrix<Real> X_q = internal.solve(dense_matrix<Real>(M - scaled(K, Real(h2 / 12))));
  const dense_matrix<Real> Q_p = scaled(M_inv, h) - scaled(dense_matrix<Real>(M_inv_K * X_p), Real(h2 / 3));
  const dense_matrix<Real> Q_q = I - scaled(dense_matrix<Real>(M_inv_K * (I + 2 * X_q)), Real(h2 / 6));
  const dense_matrix<Real> P_p = I - scaled(dense_matrix<Real>(K * (4 * X_p + Q_p)), Real(h / 6));
  const dense_matrix<Real> P_q = scaled(dense_matrix<Real>(K * (I + 4 * X_q + Q_q)), Real(-h / 6));
  dense_matrix<Real> phi(2 * n, 2 * n);
  phi << P_p, P_q, Q_p, Q_q;
  return phi;
}

/// The block analogue of (hamiltonien-discret), H_d(p, q) = ½ yᵀ Q y with
/// Q = diag(M⁻¹, K (I − S/12)(I − S/24)(I − S/8)⁻¹), S = h² M⁻¹ K: for n = 1 the printed
/// p²/(2m) + m ω² (1 − ω²h²/12)(1 − ω²h²/24) q²/(2 (1 − ω²h²/8)). Throws std::domain_error where
/// I − S/8 is singular (some ω_k² h² = 8).
template <class Real>
dense_matrix<Real> ndof_discrete_energy_form(const dense_matrix<Real>& M, const dense_matrix<Real>& K, const Real& h) {
  const Eigen::Index n = M.rows();
  const dense_matrix<Real> I = dense_matrix<Real>::Identity(n, n);
  const Eigen::FullPivLU<dense_matrix<Real>> mass(M);
  if (!mass.isInvertible()) throw std::domain_error("simpson::ndof_discrete_energy_form: M is singular");
  const dense_matrix<Real> S = scaled(dense_matrix<Real>(mass.solve(K)), Real(h * h));
  const Eigen::FullPivLU<dense_matrix<Real>> internal(dense_matrix<Real>(I - scaled(S, Real(1) / 8)));
  if (!internal.isInvertible()) throw std::domain_error("simpson::ndof_discrete_energy_form: I - h^2 M^-1 K/8 is singular");
  dense_matrix<Real> form = dense_matrix<Real>::Zero(2 * n, 2 * n);
  form.topLeftCorner(n, n) = mass.solve(I);
  form.bottomRightCorner(n, n) =
      K * (I - scaled(S, Real(1) / 12)) * (I - scaled(S, Real(1) / 24)) * internal.solve(I);
  return form;
}

/// J = [[0, −I], [I, 0]] on (p, q): Φ is symplectic when Φᵀ J Φ = J.
template <class Real>
dense_matrix<Real> symplectic_form(Eigen::Index n) {
  dense_matrix<Real> J = dense_matrix<Real>::Zero(2 * n, 2 * n);
  J.topRightCorner(n, n) = -dense_matrix<Real>::Identity(n, n);
  J.bottomLeftCorner(n, n) = dense_matrix<Real>::Identity(n, n);
  return J;
}

}  // namespace simpson

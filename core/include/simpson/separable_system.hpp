#pragma once
// Beyond the paper: mechanical systems with several degrees of freedom and a separable Hamiltonian
// H(p, q) = ½ pᵀ M⁻¹ p + V(q), M symmetric positive definite, for the nonlinear steps of
// nonlinear_ndof_step.hpp. Each potential gives V, its gradient and its Hessian at a point,
// generically over the floating scalars (Eigen with Boost.Multiprecision numbers, as ndof_linear.hpp).

#include <simpson/ndof_linear.hpp>

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>
#include <utility>

namespace simpson {

template <class Real>
using dense_vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;

/// s v (see scaled for matrices: Boost 1.74's free operators reject `s * v` on Eigen objects).
template <class Real>
dense_vector<Real> scaled(dense_vector<Real> v, const Real& s) {
  v *= s;
  return v;
}

/// A state of n degrees of freedom, momentum first as phase_point.
template <class Real>
struct ndof_state {
  dense_vector<Real> p, q;
};

/// The system: its mass matrix (factored once) and its potential.
template <class Real, class Potential>
class separable_system {
 public:
  separable_system(dense_matrix<Real> mass, Potential potential)
      : mass_(std::move(mass)), factor_(mass_), potential_(std::move(potential)) {
    if (mass_.rows() != mass_.cols() || mass_.rows() == 0) throw std::invalid_argument("simpson::separable_system: M must be n x n, n >= 1");
    if (factor_.info() != Eigen::Success || !factor_.isPositive() || !(factor_.vectorD().minCoeff() > 0)) {
      throw std::invalid_argument("simpson::separable_system: M must be symmetric positive definite");
    }
  }
  Eigen::Index dimension() const { return mass_.rows(); }
  const dense_matrix<Real>& mass() const { return mass_; }
  const Potential& potential() const { return potential_; }
  /// M⁻¹ v.
  dense_vector<Real> mass_solve(const dense_vector<Real>& v) const { return factor_.solve(v); }
  dense_matrix<Real> mass_solve(const dense_matrix<Real>& v) const { return factor_.solve(v); }
  /// H(p, q) = ½ pᵀ M⁻¹ p + V(q).
  Real energy(const ndof_state<Real>& y) const { return Real(y.p.dot(mass_solve(y.p)) / 2 + potential_.value(y.q)); }

 private:
  dense_matrix<Real> mass_;
  Eigen::LDLT<dense_matrix<Real>> factor_;
  Potential potential_;
};

/// The Kepler problem V(q) = −μ/|q| in the plane: ∇V = μ q/|q|³, ∇²V = μ (I/|q|³ − 3 q qᵀ/|q|⁵).
template <class Real>
struct kepler_potential {
  Real mu;
  Real value(const dense_vector<Real>& q) const {
    using std::sqrt;
    return -mu / Real(sqrt(Real(q.squaredNorm())));
  }
  dense_vector<Real> gradient(const dense_vector<Real>& q) const {
    using std::sqrt;
    const Real r2 = q.squaredNorm(), r = sqrt(r2);
    return scaled(q, Real(mu / (r2 * r)));
  }
  dense_matrix<Real> hessian(const dense_vector<Real>& q) const {
    using std::sqrt;
    const Real r2 = q.squaredNorm(), r = sqrt(r2), r3 = r2 * r;
    dense_matrix<Real> out = scaled(dense_matrix<Real>(dense_matrix<Real>::Identity(2, 2)), Real(mu / r3));
    for (Eigen::Index i = 0; i < 2; ++i) {
      for (Eigen::Index j = 0; j < 2; ++j) out(i, j) -= 3 * mu * q(i) * q(j) / (r3 * r2);
    }
    return out;
  }
};

/// Hénon–Heiles: V(x, y) = (x² + y²)/2 + x² y − y³/3; ∇V = (x + 2xy, y + x² − y²),
/// ∇²V = [[1 + 2y, 2x], [2x, 1 − 2y]]. Bounded motion below the escape energy 1/6.
template <class Real>
struct henon_heiles_potential {
  Real value(const dense_vector<Real>& q) const {
    const Real x = q(0), y = q(1);
    return (x * x + y * y) / 2 + x * x * y - y * y * y / 3;
  }
  dense_vector<Real> gradient(const dense_vector<Real>& q) const {
    const Real x = q(0), y = q(1);
    dense_vector<Real> g(2);
    g << Real(x + 2 * x * y), Real(y + x * x - y * y);
    return g;
  }
  dense_matrix<Real> hessian(const dense_vector<Real>& q) const {
    const Real x = q(0), y = q(1);
    dense_matrix<Real> H(2, 2);
    H << Real(1 + 2 * y), Real(2 * x), Real(2 * x), Real(1 - 2 * y);
    return H;
  }
};

/// V(q) = ½ qᵀ K q (the linear n-DOF systems of ndof_linear.hpp).
template <class Real>
struct quadratic_potential {
  dense_matrix<Real> stiffness;
  Real value(const dense_vector<Real>& q) const { return Real(q.dot(stiffness * q) / 2); }
  dense_vector<Real> gradient(const dense_vector<Real>& q) const { return stiffness * q; }
  dense_matrix<Real> hessian(const dense_vector<Real>&) const { return stiffness; }
};

/// A potential of one variable (potential.hpp) as a potential on R¹.
template <class Real, class Scalar>
struct one_dof_potential {
  Scalar scalar;
  Real value(const dense_vector<Real>& q) const { return scalar.value(q(0)); }
  dense_vector<Real> gradient(const dense_vector<Real>& q) const { return dense_vector<Real>::Constant(1, scalar.derivative(q(0))); }
  dense_matrix<Real> hessian(const dense_vector<Real>& q) const {
    return dense_matrix<Real>::Constant(1, 1, scalar.second_derivative(q(0)));
  }
};

}  // namespace simpson

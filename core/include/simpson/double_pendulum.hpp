#pragma once
// Beyond the paper: the nonlinear double pendulum in its two angles, a Lagrangian of lagrangian.hpp
// (a configuration-dependent mass matrix: the Hamiltonian is not separable). Masses m1, m2 on
// massless rods of lengths l1, l2, angles from the downward vertical, gravity g:
//   L = ½ (m1 + m2) l1² θ̇1² + ½ m2 l2² θ̇2² + m2 l1 l2 θ̇1 θ̇2 cos(θ1 − θ2)
//       + (m1 + m2) g l1 cos θ1 + m2 g l2 cos θ2.

#include <simpson/lagrangian.hpp>

#include <cmath>

namespace simpson {

template <class Real>
struct double_pendulum {
  Real m1, m2, l1, l2, g;

  int dof() const { return 2; }

  template <class T>
  T operator()(const Eigen::Matrix<T, Eigen::Dynamic, 1>& q, const Eigen::Matrix<T, Eigen::Dynamic, 1>& v) const {
    using std::cos;
    const T M1(m1), M2(m2), L1(l1), L2(l2), G(g);
    const T kinetic = (M1 + M2) * L1 * L1 * v(0) * v(0) / 2 + M2 * L2 * L2 * v(1) * v(1) / 2 +
                      M2 * L1 * L2 * v(0) * v(1) * cos(T(q(0) - q(1)));
    const T potential = -(M1 + M2) * G * L1 * cos(q(0)) - M2 * G * L2 * cos(q(1));
    return T(kinetic - potential);
  }
};

}  // namespace simpson

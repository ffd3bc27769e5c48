// The Hamiltonian of a Lagrangian quadratic in v (legendre_hamiltonian.hpp): the double pendulum's
// energy in closed form, its Hessian blocks against central differences, a Lagrangian outside the
// restriction refused.

#include <simpson/double_pendulum.hpp>
#include <simpson/legendre_hamiltonian.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace simpson::legendre_hamiltonian_test {
namespace {

dense_vector<double> vec2(double a, double b) {
  dense_vector<double> out(2);
  out << a, b;
  return out;
}

/// L = cosh(v) − q²/2: regular, not quadratic in v.
struct not_quadratic {
  int dof() const { return 1; }
  template <class T>
  T operator()(const Eigen::Matrix<T, Eigen::Dynamic, 1>& q, const Eigen::Matrix<T, Eigen::Dynamic, 1>& v) const {
    using std::cosh;
    return T(cosh(v(0)) - q(0) * q(0) / 2);
  }
};

const double_pendulum<double> L{1, 1, 1, 1, 1};

TEST(HamiltonianOfALagrangian, IsTheDoublePendulumsEnergyAndItsVelocityGivesBackTheMomentum) {
  const dense_vector<double> q = vec2(1.0, -0.5), v = vec2(0.3, 0.2);
  const dense_vector<double> p = lagrangian_gradient_at(L, q, v).dv;
  const hamiltonian_derivatives<double> H = legendre_hamiltonian(L, q, p);
  // T + V in closed form (m = l = g = 1): T = v₁² + v₂²/2 + v₁ v₂ cos(q₁ − q₂), V = −2 cos q₁ − cos q₂.
  const double energy = v(0) * v(0) + v(1) * v(1) / 2 + v(0) * v(1) * std::cos(q(0) - q(1)) - 2 * std::cos(q(0)) - std::cos(q(1));
  EXPECT_NEAR(H.value, energy, 16 * eps<double>());
  EXPECT_NEAR(H.dp(0), v(0), 16 * eps<double>());
  EXPECT_NEAR(H.dp(1), v(1), 16 * eps<double>());
  // The Hessian blocks against central differences of the gradient (step 1e-6: error ~1e-11).
  const double d = 1e-6;
  for (int k = 0; k < 2; ++k) {
    dense_vector<double> up = q, down = q;
    up(k) += d;
    down(k) -= d;
    const auto Hu = legendre_hamiltonian(L, up, p, false), Hd = legendre_hamiltonian(L, down, p, false);
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR((Hu.dq(i) - Hd.dq(i)) / (2 * d), H.qq(i, k), 1e-8);
      EXPECT_NEAR((Hu.dp(i) - Hd.dp(i)) / (2 * d), H.qp(k, i), 1e-8);
    }
  }
  EXPECT_THROW(legendre_hamiltonian(not_quadratic{}, dense_vector<double>(dense_vector<double>::Constant(1, 0.3)),
                                    dense_vector<double>(dense_vector<double>::Constant(1, 0.7))),
               std::domain_error);
}

}  // namespace
}  // namespace simpson::legendre_hamiltonian_test

// The double pendulum (double_pendulum.hpp): its mass matrix and forces against the closed form.

#include <simpson/double_pendulum.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace simpson::double_pendulum_test {
namespace {

template <class Real>
dense_vector<Real> vec2(const Real& a, const Real& b) {
  dense_vector<Real> out(2);
  out << a, b;
  return out;
}

TEST(DoublePendulum, ItsMassMatrixDependsOnTheConfigurationAsTheClosedFormSays) {
  const double_pendulum<double> L{1.5, 0.5, 2, 1, 9.81};
  const dense_vector<double> q = vec2(0.7, -0.4), v = vec2(0.0, 0.0);
  const lagrangian_hessian<double> d = lagrangian_hessian_at(L, q, v);
  // M = [[(m1 + m2) l1², m2 l1 l2 cos(θ1 − θ2)], [·, m2 l2²]]; ∂L/∂θ1 at rest = −(m1 + m2) g l1 sin θ1.
  EXPECT_NEAR(d.vv(0, 0), 8, 1e-14);
  EXPECT_NEAR(d.vv(0, 1), std::cos(1.1), 1e-15);
  EXPECT_NEAR(d.vv(1, 1), 0.5, 1e-15);
  EXPECT_NEAR(d.dq(0), -2 * 9.81 * 2 * std::sin(0.7), 1e-13);
  EXPECT_NEAR(d.dq(1), -0.5 * 9.81 * std::sin(-0.4), 1e-14);
}



}  // namespace
}  // namespace simpson::double_pendulum_test

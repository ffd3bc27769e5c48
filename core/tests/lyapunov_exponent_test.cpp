// The largest Lyapunov exponent (lyapunov_exponent.hpp) of the double pendulum: positive and settled
// from a chaotic start, near zero from small oscillations; the predictability horizon it gives.

#include <simpson/discrete_lagrangian_step.hpp>
#include <simpson/double_pendulum.hpp>
#include <simpson/hamiltonian_prk_step.hpp>
#include <simpson/lyapunov_exponent.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace simpson::lyapunov_exponent_test {
namespace {

template <class Real>
dense_vector<Real> vec2(const Real& a, const Real& b) {
  dense_vector<Real> out(2);
  out << a, b;
  return out;
}

TEST(DoublePendulumLyapunov, ChaoticFromTwoRadiansRegularFromSmallOscillations) {
  const double_pendulum<double> L{1, 1, 1, 1, 1};
  const auto rk4 = [&](const ndof_state<double>& y) { return rk4_hamiltonian_step(L, 0.01, y).state; };
  const ndof_state<double> chaotic{vec2(0.0, 0.0), vec2(2.0, 2.0)}, regular{vec2(0.0, 0.0), vec2(0.1, 0.1)};
  const lyapunov_estimate<double> high = largest_lyapunov_exponent(rk4, chaotic, 0.01, 10, 1000, 1e-8);
  const lyapunov_estimate<double> low = largest_lyapunov_exponent(rk4, regular, 0.01, 10, 1000, 1e-8);
  // Over t = 100: ~0.37 from (2, 2) (settled: its first half within 30%), ~log(t)/t from (0.1, 0.1).
  EXPECT_GT(high.exponent, 0.2);
  EXPECT_LT(high.exponent, 0.6);
  EXPECT_NEAR(high.first_half / high.exponent, 1, 0.3);
  EXPECT_LT(low.exponent, 0.02);
  // The horizon for a double start (ε = 1e-16) and a tolerance of 1e-2: ln(1e14)/λ, some 50–160 units.
  const double horizon = predictability_horizon(high.exponent, 1e-16, 1e-2);
  EXPECT_GT(horizon, 50);
  EXPECT_LT(horizon, 170);
  EXPECT_THROW(predictability_horizon(low.exponent - 1, 1e-16, 1e-2), std::invalid_argument);
}

}  // namespace
}  // namespace simpson::lyapunov_exponent_test

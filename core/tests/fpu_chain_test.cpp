#include <simpson/fpu_chain.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace simpson {
namespace {

TEST(FpuChain, GradientAndHessianAreTheDerivativesOfThePotential) {
  const fpu_potential<double> V{3, 50.0};
  dense_vector<double> q(6);
  q << 0.3, -0.2, 0.5, 0.45, -0.1, 0.7;
  const dense_vector<double> g = V.gradient(q);
  const dense_matrix<double> H = V.hessian(q);
  const double d = 1e-6;
  for (int k = 0; k < 6; ++k) {
    dense_vector<double> up = q, down = q;
    up(k) += d;
    down(k) -= d;
    EXPECT_NEAR(g(k), (V.value(up) - V.value(down)) / (2 * d), 1e-5 * (1 + std::abs(g(k)))) << k;
    const dense_vector<double> dg = (V.gradient(up) - V.gradient(down)) / (2 * d);
    for (int j = 0; j < 6; ++j) EXPECT_NEAR(H(j, k), dg(j), 1e-5 * (1 + std::abs(H(j, k)))) << j << ", " << k;
  }
  EXPECT_TRUE(H.isApprox(H.transpose()));
}

TEST(FpuChain, TheStartIsTheBooksAndItsStiffEnergyIsOne) {
  // x_{0,1} = 1, y_{0,1} = 1, x_{1,1} = 1/ω, y_{1,1} = 1: I₁ = ½ (1 + ω² / ω²) = 1, I₂ = I₃ = 0.
  const ndof_state<double> y = fpu_start(3, 50.0);
  const std::vector<double> I = fpu_oscillatory_energies(y, 50.0);
  ASSERT_EQ(I.size(), 3u);
  EXPECT_NEAR(I[0], 1.0, 1e-15);
  EXPECT_EQ(I[1], 0.0);
  EXPECT_EQ(I[2], 0.0);
  EXPECT_NEAR((y.q(0) + y.q(1)) / std::sqrt(2.0), 1.0, 1e-15);  // x_{0,1}
  // A wrong sign of the stiff elongation would give x_{1,1} = −1/ω: I₁ still 1, so check the sign too.
  EXPECT_NEAR((y.q(1) - y.q(0)) / std::sqrt(2.0), 1 / 50.0, 1e-15);
}

}  // namespace
}  // namespace simpson

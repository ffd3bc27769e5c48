#include <simpson/precision.hpp>
#include <simpson/runge_kutta_tableaux.hpp>

#include <gtest/gtest.h>

namespace simpson {
namespace {

/// The order conditions of a (non-partitioned) tableau up to order 4 that hold for a quadrature
/// b with nodes c = A 1: Σ b c^(k−1) = 1/k for k = 1..4, and Σ b_i a_ij c_j = 1/6.
rational condition(const butcher_tableau<rational>& t, int k) {
  rational sum(0);
  for (std::size_t i = 0; i < t.stages(); ++i) {
    rational c(0);
    for (const rational& a : t.a[i]) c += a;
    rational power(1);
    for (int e = 1; e < k; ++e) power *= c;
    sum += t.b[i] * power;
  }
  return sum;
}

TEST(RungeKuttaTableaux, WeightsIntegratePolynomialsToTheirOrder) {
  for (const auto& t : {lobatto_iiia3_tableau<rational>(), classic_rk4_tableau<rational>()}) {
    for (int k = 1; k <= 4; ++k) EXPECT_EQ(condition(t, k), rational(1, k)) << "k = " << k;
  }
  // Lobatto IIIB's nodes are those of IIIA (c = 0, 1/2, 1): the same weights, the same conditions.
  for (int k = 1; k <= 4; ++k) EXPECT_EQ(condition(lobatto_iiib3_tableau<rational>(), k), rational(1, k)) << "k = " << k;
  EXPECT_EQ(condition(implicit_midpoint_tableau<rational>(), 1), rational(1));
  EXPECT_EQ(condition(implicit_midpoint_tableau<rational>(), 2), rational(1, 2));
}

TEST(RungeKuttaTableaux, LobattoPairSatisfiesTheSymplecticCondition) {
  // b_i â_ij + b̂_j a_ji = b_i b̂_j (Sun 1993), exactly.
  const auto a = lobatto_iiia3_tableau<rational>(), b = lobatto_iiib3_tableau<rational>();
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) EXPECT_EQ(a.b[i] * b.a[i][j] + b.b[j] * a.a[j][i], a.b[i] * b.b[j]);
  }
}

TEST(RungeKuttaTableaux, GaussLegendreNodesAreTheGaussPoints) {
  const auto t = gauss_legendre2_tableau<double>();
  const double c1 = t.a[0][0] + t.a[0][1], c2 = t.a[1][0] + t.a[1][1];
  EXPECT_NEAR(c1, 0.5 - std::sqrt(3.0) / 6, 4e-16);
  EXPECT_NEAR(c2, 0.5 + std::sqrt(3.0) / 6, 4e-16);
  // Symplectic: b_i a_ij + b_j a_ji = b_i b_j.
  for (std::size_t i = 0; i < 2; ++i) {
    for (std::size_t j = 0; j < 2; ++j) EXPECT_NEAR(t.b[i] * t.a[i][j] + t.b[j] * t.a[j][i], t.b[i] * t.b[j], 4e-16);
  }
}

}  // namespace
}  // namespace simpson

#include <simpson/three_term_scheme.hpp>

#include <simpson/reduced_lagrangian.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

namespace simpson {
namespace {

using R = rational;

TEST(ThreeTermScheme, CharacteristicPolynomialIsTheSchemeOnPowers) {
  // q_{j−1} = 1, q_j = r, q_{j+1} = r²: h² × (schema-ordre-3) = a r² + b r + c, for any r.
  for (const auto& par : test::parameter_cases<R>()) {
    const characteristic_coefficients<R> k = characteristic_polynomial(par.omega2_h2());
    for (const R& r : {R(0), R(1), R(-3, 2), R(7, 5)}) {
      EXPECT_EQ(par.h() * par.h() * three_term_residual(par, R(1), r, R(r * r)), k.a * r * r + k.b * r + k.c);
    }
  }
}

TEST(ThreeTermScheme, IsTheDiscreteEulerLagrangeEquationOfTheReducedLagrangian) {
  // ∂L_h^r/∂q_r(q_{j−1}, q_j) + ∂L_h^r/∂q_l(q_j, q_{j+1}) = −(m h/(1 − x/8)) × (schema-ordre-3),
  // the derivatives by exact differences of (Lagrangien-reduit), which is quadratic.
  for (const auto& par : test::parameter_cases<R>()) {
    const R q_prev(-2, 3), q(5, 4), q_next(9, 5);
    const auto L_right = [&](const R& v) -> R { return reduced_lagrangian(par, q_prev, v); };
    const auto L_left = [&](const R& v) -> R { return reduced_lagrangian(par, v, q_next); };
    const R euler_lagrange = test::exact_derivative_quartic<R>(L_right, q) + test::exact_derivative_quartic<R>(L_left, q);
    EXPECT_EQ(euler_lagrange, -par.m() * par.h() / (1 - par.omega2_h2() / 8) * three_term_residual(par, q_prev, q, q_next));
  }
}

TEST(ThreeTermScheme, KnownCoefficientsAndDiscriminant) {
  // x = 4: a = c = 7/6, b = −(48 − 88 + 16)/24 = 1, Δ = 1 − 4·49/36 = −40/9.
  const characteristic_coefficients<R> k = characteristic_polynomial(R(4));
  EXPECT_EQ(k.a, R(7, 6));
  EXPECT_EQ(k.b, R(1));
  EXPECT_EQ(k.c, R(7, 6));
  EXPECT_EQ(discriminant(R(4)), R(-40, 9));
}

TEST(ThreeTermScheme, FactorizedDiscriminantAgreesAtSamplePoints) {
  // Pointwise only; the polynomial identity is proved in the claims ledger.
  for (const R& x : {R(1, 3), R(4), R(8), R(10), R(12), R(16), R(24), R(30)}) {
    EXPECT_EQ(discriminant(x), discriminant_factorized(x)) << to_string(x);
  }
}

TEST(ThreeTermScheme, DiscriminantSignAlternatesAcrossTheBands) {
  // Negative on (0, 8) and (12, 24): complex roots of product 1; positive on (8, 12) and beyond 24.
  EXPECT_LT(discriminant(R(1, 1000)), 0);
  EXPECT_LT(discriminant(R(79, 10)), 0);
  EXPECT_GT(discriminant(R(81, 10)), 0);
  EXPECT_GT(discriminant(R(119, 10)), 0);
  EXPECT_LT(discriminant(R(121, 10)), 0);
  EXPECT_LT(discriminant(R(239, 10)), 0);
  EXPECT_GT(discriminant(R(241, 10)), 0);
}

}  // namespace
}  // namespace simpson

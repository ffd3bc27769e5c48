#include <simpson/quadratic_interpolation.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

namespace simpson {
namespace {

using R = rational;

TEST(QuadraticInterpolation, BasisIsNodalAndSumsToOne) {
  const R nodes[] = {R(0), R(1, 2), R(1)};
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(basis_phi0(nodes[i]), R(i == 0 ? 1 : 0));
    EXPECT_EQ(basis_phi_half(nodes[i]), R(i == 1 ? 1 : 0));
    EXPECT_EQ(basis_phi1(nodes[i]), R(i == 2 ? 1 : 0));
  }
  for (const R& s : {R(1, 3), R(-2, 7), R(5, 4)}) {
    EXPECT_EQ(basis_phi0(s) + basis_phi_half(s) + basis_phi1(s), R(1));
  }
}

TEST(QuadraticInterpolation, InterpolantTakesTheNodalValues) {
  const R q_l(2, 3), q_m(-1, 5), q_r(7, 2);
  EXPECT_EQ(quadratic_interpolant(q_l, q_m, q_r, R(0)), q_l);
  EXPECT_EQ(quadratic_interpolant(q_l, q_m, q_r, R(1, 2)), q_m);
  EXPECT_EQ(quadratic_interpolant(q_l, q_m, q_r, R(1)), q_r);
}

TEST(QuadraticInterpolation, DerivativeIsThatOfTheInterpolant) {
  // q(t) is quadratic in t = h s; its exact derivative by Richardson differences in s, divided by h.
  const R q_l(2, 3), q_m(-1, 5), q_r(7, 2), h(1, 9);
  for (const R& s : {R(0), R(1, 3), R(1, 2), R(1)}) {
    const auto q_of_s = [&](const R& v) -> R { return quadratic_interpolant(q_l, q_m, q_r, v); };
    EXPECT_EQ(quadratic_interpolant_derivative(q_l, q_m, q_r, h, s), test::exact_derivative_quartic<R>(q_of_s, s) / h);
  }
}

TEST(QuadraticInterpolation, GearDerivativesAreTheEndSlopesAndAverageToTheCentredOne) {
  // (derivees-gear) at s = 0 and s = 1; (derivee-centree) g_m = (g_l + g_r)/2 = (q_r − q_l)/h = q'(h/2).
  const R q_l(2, 3), q_m(-1, 5), q_r(7, 2), h(1, 9);
  const R g_l = gear_left(q_l, q_m, q_r, h);
  const R g_r = gear_right(q_l, q_m, q_r, h);
  EXPECT_EQ(g_l, quadratic_interpolant_derivative(q_l, q_m, q_r, h, R(0)));
  EXPECT_EQ(g_r, quadratic_interpolant_derivative(q_l, q_m, q_r, h, R(1)));
  EXPECT_EQ(centred_derivative(q_l, q_r, h), (g_l + g_r) / 2);
  EXPECT_EQ(centred_derivative(q_l, q_r, h), quadratic_interpolant_derivative(q_l, q_m, q_r, h, R(1, 2)));
  // The derivative is affine in s: g_l (1 − s) + g_r s (display after q2t).
  const R s(2, 7);
  EXPECT_EQ(quadratic_interpolant_derivative(q_l, q_m, q_r, h, s), g_l * (1 - s) + g_r * s);
}

}  // namespace
}  // namespace simpson

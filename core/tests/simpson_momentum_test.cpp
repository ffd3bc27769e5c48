#include <simpson/simpson_momentum.hpp>

#include <simpson/reduced_lagrangian.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

namespace simpson {
namespace {

using R = rational;

TEST(SimpsonMomentum, IsTheDerivativeOfTheReducedLagrangianInTheRightNode) {
  // (moment-ordre-3) against its definition p_r = ∂L_h^r/∂q_r, by exact differences.
  for (const auto& par : test::parameter_cases<R>()) {
    const R q_l(-2, 3), q_r(5, 4);
    const auto L_of_right = [&](const R& v) -> R { return reduced_lagrangian(par, q_l, v); };
    EXPECT_EQ(simpson_momentum(par, q_l, q_r), test::exact_derivative_quartic<R>(L_of_right, q_r));
  }
}

TEST(SimpsonMomentum, KnownValue) {
  // m = 1, ω = 1, h = 2 (x = 4, 1 − x/8 = 1/2), q_l = 0, q_r = 1:
  // p_r = 1/2 − 2·(1/6)·2/(1/2) + 8·(1/48)·1/(1/2) = 1/2 − 4/3 + 1/3 = −1/2.
  EXPECT_EQ(simpson_momentum(oscillator_parameters<R>(R(1), R(1), R(2)), R(0), R(1)), R(-1, 2));
}

}  // namespace
}  // namespace simpson

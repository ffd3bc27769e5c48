#include <simpson/classical_lagrangian.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

namespace simpson {
namespace {

using R = rational;

// A quartic potential with a linear term: the general-V formulas must not rely on V being quadratic.
const auto tilted_quartic_potential = [](const R& q) -> R { return q * q * q * q / 4 - q * q / 3 + q / 5; };
const auto tilted_quartic_gradient = [](const R& q) -> R { return q * q * q - 2 * q / 3 + R(1, 5); };

TEST(ClassicalLagrangian, KnownValue) {
  // m = 2, h = 1/2, q_l = 1, q_r = 2, V(q) = q²: L_d = (2·(1/2)/2)·2² − (1/2)·(3/2)² = 2 − 9/8.
  const auto V = [](const R& q) -> R { return q * q; };
  EXPECT_EQ(classical_lagrangian(R(2), R(1, 2), V, R(1), R(2)), R(7, 8));
}

TEST(ClassicalLagrangian, MomentumIsDerivativeInRightNode) {
  // (moment) p_r = ∂L_d/∂q_r; L_d is a quartic in q_r, so the Richardson difference is exact.
  const R m(3, 2), h(1, 7), q_l(-2, 3), q_r(5, 4);
  const auto L_of_right = [&](const R& v) -> R { return classical_lagrangian(m, h, tilted_quartic_potential, q_l, v); };
  EXPECT_EQ(classical_momentum(m, h, tilted_quartic_gradient, q_l, q_r), test::exact_derivative_quartic<R>(L_of_right, q_r));
}

TEST(ClassicalLagrangian, SchemeResidualIsTheDiscreteEulerLagrangeEquation) {
  // (Euler-Lagrange-discret) ∂L_d/∂q_r(q_{j−1}, q_j) + ∂L_d/∂q_l(q_j, q_{j+1}) = −h × (schema-ordre-deux),
  // with both partial derivatives taken by exact differences, not by the momentum formula.
  const R m(3, 2), h(1, 7), q_prev(-2, 3), q(5, 4), q_next(9, 5);
  const auto L_right = [&](const R& v) -> R { return classical_lagrangian(m, h, tilted_quartic_potential, q_prev, v); };
  const auto L_left = [&](const R& v) -> R { return classical_lagrangian(m, h, tilted_quartic_potential, v, q_next); };
  const R euler_lagrange = test::exact_derivative_quartic<R>(L_right, q) + test::exact_derivative_quartic<R>(L_left, q);
  EXPECT_EQ(euler_lagrange, -h * classical_scheme_residual(m, h, tilted_quartic_gradient, q_prev, q, q_next));
}

TEST(ClassicalLagrangian, HarmonicMomentumIsThePrintedFormula) {
  // p_{j+1} = m (q_{j+1} − q_j)/h − m ω² h (q_{j+1} + q_j)/4 as printed in Section 2.
  for (const auto& par : test::parameter_cases<R>()) {
    const R q_j(2, 3), q_next(-1, 4);
    const auto gradient = [&](const R& v) -> R { return par.force_gradient(v); };
    const R printed = par.m() * (q_next - q_j) / par.h() -
                      par.m() * par.omega() * par.omega() * par.h() / 4 * (q_next + q_j);
    EXPECT_EQ(classical_momentum(par.m(), par.h(), gradient, q_j, q_next), printed);
  }
}

}  // namespace
}  // namespace simpson

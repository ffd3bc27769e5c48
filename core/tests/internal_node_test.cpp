#include <simpson/internal_node.hpp>

#include <simpson/simpson_lagrangian.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

namespace simpson {
namespace {

template <class Real>
class InternalNode : public test::precision_fixture<Real> {};
TYPED_TEST_SUITE(InternalNode, test::all_scalars, test::scalar_names);

TYPED_TEST(InternalNode, HarmonicNodeSolvesTheInternalEquation) {
  using Real = TypeParam;
  for (const auto& par : test::parameter_cases<Real>()) {
    const Real q_l = test::ratio<Real>(2, 3), q_r = test::ratio<Real>(-5, 4);
    const Real q_m = harmonic_internal_node(par, q_l, q_r);
    const auto gradient = [&](const Real& v) -> Real { return par.force_gradient(v); };
    // (equation-milieu-intervalle): terms of size (4m/h²)(|q_l| + 2|q_m| + |q_r|) cancel; their
    // sum bounds the round-off (~16 operations with the rounding of q_m itself).
    const Real scale = 4 * par.m() / (par.h() * par.h()) *
                       (test::magnitude(q_l) + 2 * test::magnitude(q_m) + test::magnitude(q_r));
    EXPECT_TRUE(test::within(internal_equation_residual(par.m(), par.h(), gradient, q_l, q_m, q_r), Real(0),
                             Real(32 * eps<Real>() * scale)));
  }
}

TEST(InternalNodeExact, ResidualIsTheMidNodeDerivativeOfTheLagrangian) {
  // ∂L_h/∂q_m = −(2h/3) × (equation-milieu-intervalle), for any V: the two vanish together.
  using R = rational;
  const R m(3, 2), h(1, 7), q_l(-2, 3), q_m(1, 4), q_r(5, 4);
  const auto gradient = [](const R& q) -> R { return q * q * q - 2 * q / 3; };
  EXPECT_EQ(simpson_lagrangian_dq_mid(m, h, gradient, q_l, q_m, q_r),
            -2 * h / 3 * internal_equation_residual(m, h, gradient, q_l, q_m, q_r));
}

TEST(InternalNodeExact, KnownValue) {
  // x = 4: q_m = (q_l + q_r)/(2 · 1/2) = q_l + q_r.
  using R = rational;
  EXPECT_EQ(harmonic_internal_node(oscillator_parameters<R>(R(1), R(1), R(2)), R(2, 3), R(1, 6)), R(5, 6));
}

}  // namespace
}  // namespace simpson

#include <simpson/reduced_lagrangian.hpp>

#include <simpson/internal_node.hpp>
#include <simpson/simpson_lagrangian.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

namespace simpson {
namespace {

template <class Real>
class ReducedLagrangian : public test::precision_fixture<Real> {};
TYPED_TEST_SUITE(ReducedLagrangian, test::all_scalars, test::scalar_names);

TYPED_TEST(ReducedLagrangian, EqualsSimpsonLagrangianWithInternalNodeSubstituted) {
  using Real = TypeParam;
  for (const auto& par : test::parameter_cases<Real>()) {
    const Real q_l = test::ratio<Real>(2, 3), q_r = test::ratio<Real>(-5, 4);
    const auto V = [&](const Real& v) -> Real { return par.potential(v); };
    const Real q_m = harmonic_internal_node(par, q_l, q_r);
    const Real direct = simpson_lagrangian(par.m(), par.h(), V, q_l, q_m, q_r);
    // Round-off: both sides are sums of terms of size (m/h)(|q_l| + |q_m| + |q_r|)² (kinetic) and
    // m ω² h (q_l² + q_m² + q_r²) (potential), with a 1/|1 − x/8| amplification in the reduced form.
    const Real q_sum = test::magnitude(q_l) + test::magnitude(q_m) + test::magnitude(q_r);
    const Real condition = (par.m() / par.h() + par.m() * par.omega() * par.omega() * par.h()) * q_sum * q_sum /
                           test::magnitude(Real(1 - par.omega2_h2() / 8));
    EXPECT_TRUE(test::within(reduced_lagrangian(par, q_l, q_r), direct, Real(64 * eps<Real>() * condition)));
  }
}

}  // namespace
}  // namespace simpson

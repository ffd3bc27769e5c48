#include <simpson/simpson_elimination.hpp>

#include <simpson/simpson_map.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

namespace simpson {
namespace {

template <class Real>
class SimpsonElimination : public test::precision_fixture<Real> {};
TYPED_TEST_SUITE(SimpsonElimination, test::all_scalars, test::scalar_names);

TYPED_TEST(SimpsonElimination, EqualsTheMapObtainedByEliminatingThePreviousState) {
  using Real = TypeParam;
  for (const auto& par : test::parameter_cases<Real>()) {
    const phase_point<Real> y{test::ratio<Real>(-3, 2), test::ratio<Real>(5, 7)};
    const phase_point<Real> by_formula = simpson_map(par) * y;
    const phase_point<Real> by_elimination = simpson_step_by_elimination(par, y);
    // The elimination sums terms of size (|q| + h|p|/m)(1 + x/|1 − x/8|) in q and m/h times that in p,
    // then divides by slopes of size m/h; 128 covers its ~40 roundings twice over.
    const Real x = par.omega2_h2();
    const Real amplification = 1 + x / test::magnitude(Real(1 - x / 8));
    const Real q_scale = (test::magnitude(y.q) + test::magnitude(by_formula.q) + par.h() * test::magnitude(y.p) / par.m()) *
                         amplification;
    const Real p_scale = q_scale * par.m() / par.h();
    EXPECT_TRUE(test::within(by_elimination.q, by_formula.q, Real(128 * eps<Real>() * q_scale)));
    EXPECT_TRUE(test::within(by_elimination.p, by_formula.p, Real(128 * eps<Real>() * p_scale)));
  }
}

}  // namespace
}  // namespace simpson

namespace simpson {
namespace {

TEST(SimpsonEliminationRegression, StateLargeAgainstMomentumKeepsItsAccuracy) {
  // Found by the property EqualsTheMapObtainedByElimination (seed 20230830): with a unit probe the
  // slopes were differences of values of size |q| m/h and lost a factor |q| = 6456 of accuracy.
  using Real = long double;
  const oscillator_parameters<Real> par(1, 1, 1);
  const phase_point<Real> y{1, 6456.542290346556L};
  const phase_point<Real> by_formula = simpson_map(par) * y, by_elimination = simpson_step_by_elimination(par, y);
  // Same scale as the property: (|q| + |q'| + h|p|/m)(1 + x/|1 − x/8|), 256 eps.
  const Real scale = (6456.542290346556L + std::abs(by_formula.q) + 1) * (1 + 1 / 0.875L);
  EXPECT_TRUE(test::within(by_elimination.q, by_formula.q, Real(256 * eps<Real>() * scale)));
}

}  // namespace
}  // namespace simpson

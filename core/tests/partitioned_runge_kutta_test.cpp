#include <simpson/partitioned_runge_kutta.hpp>

#include <simpson/explicit_runge_kutta.hpp>

#include <simpson/newmark_map.hpp>
#include <simpson/runge_kutta_tableaux.hpp>
#include <simpson/scheme.hpp>
#include <simpson/stormer_verlet.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <random>

namespace simpson {
namespace {

template <class Real>
class PartitionedRungeKutta : public test::precision_fixture<Real> {};
TYPED_TEST_SUITE(PartitionedRungeKutta, test::all_scalars, test::scalar_names);

/// |a − b| entrywise against k eps (|a| + |b|) (each entry a sum of O(k) rounded terms of that size).
template <class Real>
::testing::AssertionResult same_map(const one_step_matrix<Real>& a, const one_step_matrix<Real>& b, int k) {
  for (const auto& [x, y] : {std::pair{a.alpha, b.alpha}, std::pair{a.beta, b.beta}, std::pair{a.gamma, b.gamma},
                             std::pair{a.delta, b.delta}}) {
    const ::testing::AssertionResult r =
        test::within(x, y, Real(k * eps<Real>() * (test::magnitude(x) + test::magnitude(y))));
    if (!r) return r;
  }
  return ::testing::AssertionSuccess();
}

TYPED_TEST(PartitionedRungeKutta, ImplicitMidpointIsTheNewmarkMap) {
  using Real = TypeParam;
  for (const auto& par : test::parameter_cases<Real>()) {
    EXPECT_TRUE(same_map(partitioned_runge_kutta_map(par, implicit_midpoint_tableau<Real>(), implicit_midpoint_tableau<Real>()),
                         newmark_map(par), 32));
  }
}

TYPED_TEST(PartitionedRungeKutta, TwoStageLobattoPairIsStormerVerlet) {
  using Real = TypeParam;
  for (const auto& par : test::parameter_cases<Real>()) {
    EXPECT_TRUE(same_map(partitioned_runge_kutta_map(par, lobatto_iiia2_tableau<Real>(), lobatto_iiib2_tableau<Real>()),
                         stormer_verlet_map(par), 32));
  }
}

TYPED_TEST(PartitionedRungeKutta, ClassicRk4IsTheTaylorPolynomialOfTheFlow) {
  // On y' = L y, RK4 gives I + hL + (hL)²/2 + (hL)³/6 + (hL)⁴/24; with L² = −ω² I:
  // α = δ = 1 − x/2 + x²/24, β = −mω²h (1 − x/6), γ = h/m (1 − x/6), x = ω²h².
  using Real = TypeParam;
  for (const auto& par : test::parameter_cases<Real>()) {
    const Real x = par.omega2_h2();
    const Real w2 = par.omega() * par.omega();
    const one_step_matrix<Real> expected{Real(1 - x / 2 + x * x / 24), Real(-par.m() * w2 * par.h() * (1 - x / 6)),
                                         Real(par.h() / par.m() * (1 - x / 6)), Real(1 - x / 2 + x * x / 24)};
    EXPECT_TRUE(same_map(partitioned_runge_kutta_map(par, classic_rk4_tableau<Real>(), classic_rk4_tableau<Real>()), expected, 64));
  }
}

// The forms the work-precision comparison runs: RK4 by its explicit stages, and the implicit
// peers with their stage matrix factored once, are the same maps as the stage system solved at
// every step (exactly, for exact scalars; to a few ulps in floating point). A weaker check (the
// step applied once to one state) would miss a swapped u and v: both unit states are stepped.
TYPED_TEST(PartitionedRungeKutta, ExplicitStagesAndFactoredStagesAreTheSameMaps) {
  using Real = TypeParam;
  const auto from_steps = [](const auto& step) {
    const phase_point<Real> a = step(phase_point<Real>{Real(1), Real(0)}), b = step(phase_point<Real>{Real(0), Real(1)});
    return one_step_matrix<Real>{a.p, b.p, a.q, b.q};
  };
  for (const auto& par : test::parameter_cases<Real>()) {
    const butcher_tableau<Real> rk4 = classic_rk4_tableau<Real>();
    EXPECT_TRUE(is_explicit(rk4));
    const explicit_tableau<Real> stages(rk4);
    EXPECT_TRUE(same_map(from_steps([&](const phase_point<Real>& y) { return explicit_runge_kutta_step(par, stages, y); }),
                         partitioned_runge_kutta_map(par, rk4, rk4), 64));
    const std::vector<std::pair<butcher_tableau<Real>, butcher_tableau<Real>>> implicit{
        {implicit_midpoint_tableau<Real>(), implicit_midpoint_tableau<Real>()},
        // Gauss–Legendre's shape with 17/10 for √3: the two algorithms agree for any tableau, and
        // the exact scalars have no √3.
        {gauss_legendre2_tableau<Real>(Real(17) / 10), gauss_legendre2_tableau<Real>(Real(17) / 10)},
        {lobatto_iiia3_tableau<Real>(), lobatto_iiib3_tableau<Real>()}};
    for (const auto& pair : implicit) {
      const butcher_tableau<Real>& for_q = pair.first;  // named, not a structured binding: C++17 lambdas cannot capture one
      const butcher_tableau<Real>& for_p = pair.second;
      EXPECT_FALSE(is_explicit(for_q));
      const factored_linear_stages<Real> f = factor_linear_stages(par, for_q, for_p);
      EXPECT_TRUE(same_map(from_steps([&](const phase_point<Real>& y) { return factored_prk_step(par, for_q, for_p, f, y); }),
                           partitioned_runge_kutta_map(par, for_q, for_p), 64));
    }
  }
  EXPECT_THROW(explicit_tableau<Real>(implicit_midpoint_tableau<Real>()), std::invalid_argument);
}

TEST(PartitionedRungeKutta, TheComparisonsRk4StepSolvesNoLinearSystem) {
  // What the work-precision comparison times as RK4 (stepper, scheme.hpp) is its explicit stages, bit
  // for bit, on random states and parameters; the stage system solved by Gaussian elimination rounds
  // otherwise on some of them (the control), so a stepper that solved it would fail the first check.
  std::mt19937_64 rng(20230830);
  std::uniform_real_distribution<double> unit(-1, 1), positive(0.1, 2);
  const explicit_tableau<double> stages(classic_rk4_tableau<double>());
  int solved_differs = 0;
  for (int k = 0; k < 1000; ++k) {
    const oscillator_parameters<double> par{positive(rng), positive(rng), positive(rng) / 4};
    const phase_point<double> y{unit(rng), unit(rng)};
    const phase_point<double> timed = stepper<double>(scheme_id::rk4, par).step(y), by_stages = explicit_runge_kutta_step(par, stages, y);
    ASSERT_EQ(timed.p, by_stages.p);
    ASSERT_EQ(timed.q, by_stages.q);
    const phase_point<double> solved = partitioned_runge_kutta_step(par, classic_rk4_tableau<double>(), classic_rk4_tableau<double>(), y);
    solved_differs += solved.p != by_stages.p || solved.q != by_stages.q;
  }
  EXPECT_GT(solved_differs, 0);
}

TEST(PartitionedRungeKutta, SolveLinearPivotsAndRefusesSingularSystems) {
  // A zero leading entry needs a row exchange.
  const std::vector<double> x = solve_linear<double>({{0, 1}, {2, 0}}, {3, 4});
  EXPECT_EQ(x[0], 2);
  EXPECT_EQ(x[1], 3);
  EXPECT_THROW(solve_linear<double>({{1, 2}, {2, 4}}, {1, 1}), std::domain_error);
  EXPECT_THROW(partitioned_runge_kutta_step(oscillator_parameters<double>{1, 1, 1}, implicit_midpoint_tableau<double>(),
                                            classic_rk4_tableau<double>(), phase_point<double>{1, 0}),
               std::invalid_argument);
}

}  // namespace
}  // namespace simpson

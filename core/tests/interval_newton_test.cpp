// Krawczyk's test proves a unique zero in a box or proves nothing; the nonlinear Simpson step
// enclosed by it contains the mpfr:100 step.

#include <simpson/interval_newton.hpp>

#include <simpson/enclosed_prk_step.hpp>
#include <simpson/runge_kutta_tableaux.hpp>

#include <simpson/potential.hpp>
#include <simpson/precision.hpp>

#include <gtest/gtest.h>

namespace simpson {
namespace {

TEST(Krawczyk, ProvesTheUniqueRootOfTwoInABoxAndEnclosesItTightly) {
  const scoped_interval_digits digits(50);
  const auto f = [](const interval& x) { return interval(x * x - 2); };
  const auto df = [](const interval& x) { return interval(2 * x); };
  using real = boost::multiprecision::mpfr_float;
  const krawczyk_result r = krawczyk(f, df, interval(real("1.3"), real("1.5")));
  ASSERT_TRUE(r.proved);
  EXPECT_TRUE(zero_in(interval(r.enclosure * r.enclosure - 2)));
  EXPECT_LT(width(r.enclosure), 1e-45) << enclosure_text(r.enclosure);
}

TEST(Krawczyk, ProvesNothingOnABoxWithoutARootOrWithTwo) {
  const scoped_interval_digits digits(50);
  const auto f = [](const interval& x) { return interval(x * x - 2); };
  const auto df = [](const interval& x) { return interval(2 * x); };
  using real = boost::multiprecision::mpfr_float;
  EXPECT_FALSE(krawczyk(f, df, interval(real(2), real(3))).proved) << "no root in [2, 3]";
  EXPECT_FALSE(krawczyk(f, df, interval(real(-2), real(2))).proved) << "two roots in [-2, 2]";
}

TEST(Krawczyk, TheEnclosedPendulumStepContainsTheMpfrStep) {
  using real = boost::multiprecision::mpfr_float;
  phase_point<real> reference;
  {
    const scoped_mpfr_digits digits(100);
    const pendulum_potential<mpfr> V{mpfr(1), mpfr(2)};
    reference = simpson_nonlinear_step(mpfr(1), mpfr("0.3"), V, phase_point<mpfr>{mpfr("0.4"), mpfr(1)}).state;
  }
  const scoped_interval_digits digits(40);
  const pendulum_potential<interval> V{interval(1), interval(2)};
  const enclosed_simpson_step step = simpson_enclosed_step(interval(1), interval("0.3"), V, phase_point<interval>{interval("0.4"), interval(1)});
  ASSERT_TRUE(step.node.proved);
  EXPECT_TRUE(in(reference.q, step.state.q)) << enclosure_text(step.state.q);
  EXPECT_TRUE(in(reference.p, step.state.p)) << enclosure_text(step.state.p);
  EXPECT_LT(width(step.state.q), 1e-35);
}

TEST(Krawczyk, ProvesNothingWhereItCannotAndNeverAborts) {
  // A derivative enclosure that is the whole line: the test proves nothing. It compares points, never
  // intervals: an uncertain interval comparison throws from Boost's noexcept operator==, and aborts.
  const scoped_interval_digits digits(30);
  const auto f = [](const interval& x) { return interval(x * x - 2); };
  const auto df = [](const interval&) { return entire_line(); };
  using real = boost::multiprecision::mpfr_float;
  EXPECT_FALSE(krawczyk(f, df, interval(real("1.3"), real("1.5"))).proved);
  // The pendulum stepped in 6 digits with h = 1/2 (V = 1 − cos q, q(0) = 1, p(0) = 0): the state
  // widens step by step until a node is not proved. Comparing the Newton midpoints as intervals
  // aborted on the way.
  const scoped_interval_digits few(6);
  const pendulum_potential<interval> V{interval(1), interval(1)};
  phase_point<interval> y{interval(0), interval(1)};
  bool proved = true;
  int steps = 0;
  for (; steps < 10000 && proved; ++steps) {
    const enclosed_simpson_step step = simpson_enclosed_step(interval(1), interval(interval(1) / 2), V, y);
    proved = step.node.proved;
    if (proved) y = step.state;
  }
  EXPECT_FALSE(proved) << steps;
}

TEST(KrawczykSystem, ProvesTheUniqueRootOfACircleAndALineAndNothingWhereThereIsNone) {
  const scoped_interval_digits digits(50);
  // x² + y² = 4, x = y: one root (√2, √2) in the positive quadrant.
  const auto f = [](const interval_vector& v) { return interval_vector{v[0] * v[0] + v[1] * v[1] - 4, v[0] - v[1]}; };
  const auto df = [](const interval_vector& v) {
    return interval_matrix{{interval(2 * v[0]), interval(2 * v[1])}, {interval(1), interval(-1)}};
  };
  using real = boost::multiprecision::mpfr_float;
  const interval near(real("1.3"), real("1.5"));
  const krawczyk_system_result r = krawczyk_system(f, df, {near, near});
  ASSERT_TRUE(r.proved);
  const interval root2 = sqrt(interval(2));
  EXPECT_TRUE(overlap(r.enclosure[0], root2) && overlap(r.enclosure[1], root2));
  EXPECT_LT(width(r.enclosure[0]), 1e-45) << enclosure_text(r.enclosure[0]);
  const interval far(real(2), real(3));
  EXPECT_FALSE(krawczyk_system(f, df, {far, far}).proved) << "no root in [2, 3]²";
  const interval both(real(-2), real(2));
  EXPECT_FALSE(krawczyk_system(f, df, {both, both}).proved) << "two roots in [-2, 2]²";
}

TEST(KrawczykSystem, TheEnclosedLobattoStepContainsTheMpfrStepAndTheSimpsonStep) {
  phase_point<mpfr> reference;
  {
    const scoped_mpfr_digits digits(100);
    const pendulum_potential<mpfr> V{mpfr(1), mpfr(2)};
    const auto for_q = lobatto_iiia3_tableau<mpfr>(), for_p = lobatto_iiib3_tableau<mpfr>();
    reference = prk_nonlinear_step(for_q, for_p, couple(for_q, for_p), mpfr(1), mpfr("0.3"), V,
                                   phase_point<mpfr>{mpfr("0.4"), mpfr(1)}).state;
  }
  const scoped_interval_digits digits(40);
  const pendulum_potential<interval> V{interval(1), interval(2)};
  const auto for_q = lobatto_iiia3_tableau<interval>(), for_p = lobatto_iiib3_tableau<interval>();
  const phase_point<interval> y{interval("0.4"), interval(1)};
  const enclosed_prk_step lobatto = prk_enclosed_step(for_q, for_p, couple(for_q, for_p), interval(1), interval("0.3"), V, y);
  ASSERT_TRUE(lobatto.stages.proved);
  EXPECT_TRUE(in(reference.q, lobatto.state.q)) << enclosure_text(lobatto.state.q);
  EXPECT_TRUE(in(reference.p, lobatto.state.p)) << enclosure_text(lobatto.state.p);
  EXPECT_LT(width(lobatto.state.q), 1e-35);
  const enclosed_simpson_step simpson = simpson_enclosed_step(interval(1), interval("0.3"), V, y);
  ASSERT_TRUE(simpson.node.proved);
  EXPECT_TRUE(overlap(simpson.state.q, lobatto.state.q) && overlap(simpson.state.p, lobatto.state.p));
}


TEST(KrawczykSystem, ALobattoPairOffBy1e30SeparatesFromTheSimpsonStep) {
  const scoped_interval_digits digits(40);
  const pendulum_potential<interval> V{interval(1), interval(2)};
  auto for_q = lobatto_iiia3_tableau<interval>(), for_p = lobatto_iiib3_tableau<interval>();
  for_p.b[1] += interval("1e-30");  // a wrong weight: the enclosures must tell the two steps apart
  const phase_point<interval> y{interval("0.4"), interval(1)};
  const enclosed_prk_step lobatto = prk_enclosed_step(for_q, for_p, couple(for_q, for_p), interval(1), interval("0.3"), V, y);
  const enclosed_simpson_step simpson = simpson_enclosed_step(interval(1), interval("0.3"), V, y);
  ASSERT_TRUE(lobatto.stages.proved && simpson.node.proved);
  EXPECT_FALSE(overlap(simpson.state.p, lobatto.state.p)) << enclosure_text(simpson.state.p) << " against " << enclosure_text(lobatto.state.p);
}

}  // namespace
}  // namespace simpson

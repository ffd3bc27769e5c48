// Krawczyk's test proves a unique zero in a box or proves nothing; the nonlinear Simpson step
// enclosed by it contains the mpfr:100 step.

#include <simpson/interval_newton.hpp>

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

}  // namespace
}  // namespace simpson

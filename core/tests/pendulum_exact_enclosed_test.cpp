// The pendulum's exact solution enclosed (pendulum_exact_enclosed.hpp): it contains Boost.Math's
// Jacobi-function value computed with more digits, is tight, passes through q = 0 at t = K/ω and
// conserves the energy; a nome, a series or a remainder taken wrongly moves it off those values.

#include <simpson/pendulum_exact_enclosed.hpp>

#include <simpson/pendulum_exact.hpp>
#include <simpson/precision.hpp>

#include <gtest/gtest.h>

namespace simpson {
namespace {

using real = boost::multiprecision::mpfr_float;

TEST(PendulumExactEnclosed, ContainsTheJacobiValueAndIsTight) {
  for (const char* t_text : {"0", "0.3", "2.5", "10", "37.25"}) {
    phase_point<real> reference;
    {
      const scoped_mpfr_digits digits(140);
      const pendulum_from_rest<real> exact{real(1), real(1), real(1)};
      reference = exact.at(real(t_text));
    }
    const scoped_interval_digits digits(100);
    const phase_point<interval> y = pendulum_from_rest_enclosed(interval(1), interval(1), interval(1), interval(t_text));
    EXPECT_TRUE(encloses(y.q, interval(reference.q))) << "t = " << t_text << ": " << enclosure_text(y.q);
    EXPECT_TRUE(encloses(y.p, interval(reference.p))) << "t = " << t_text << ": " << enclosure_text(y.p);
    EXPECT_LT(width(y.q), 1e-90) << enclosure_text(y.q);
    EXPECT_LT(width(y.p), 1e-90) << enclosure_text(y.p);
  }
}

TEST(PendulumExactEnclosed, StartsAtRestCrossesZeroAtAQuarterPeriodAndConservesTheEnergy) {
  const scoped_interval_digits digits(60);
  const interval m(2), omega(3), q0("2.5");
  const phase_point<interval> start = pendulum_from_rest_enclosed(m, omega, q0, interval(0));
  EXPECT_TRUE(encloses(start.q, q0)) << enclosure_text(start.q);
  EXPECT_TRUE(zero_in(start.p)) << enclosure_text(start.p);
  // A quarter period: t = K(k)/ω with K from Boost.Math in more digits, where q = 0.
  real quarter;
  {
    const scoped_mpfr_digits more(90);
    quarter = boost::math::ellint_1(real(sin(real("1.25")))) / 3;
  }
  const phase_point<interval> crossing = pendulum_from_rest_enclosed(m, omega, q0, interval(quarter));
  EXPECT_LT(abs(real(median(crossing.q))), 1e-50) << enclosure_text(crossing.q);
  const interval H0 = m * omega * omega * (1 - cos(q0));
  for (const char* t : {"0.1", "1.7", "4"}) {
    const phase_point<interval> y = pendulum_from_rest_enclosed(m, omega, q0, interval(t));
    const interval H = y.p * y.p / (2 * m) + m * omega * omega * (1 - cos(y.q));
    EXPECT_TRUE(zero_in(interval(H - H0))) << "t = " << t << ": H - H0 = " << enclosure_text(interval(H - H0));
    EXPECT_LT(width(interval(H - H0)), 1e-50);
  }
}

TEST(PendulumExactEnclosed, RejectsAStartOutsideTheLibration) {
  const scoped_interval_digits digits(30);
  EXPECT_THROW(pendulum_from_rest_enclosed(interval(1), interval(1), interval(4), interval(0)), std::domain_error);
  EXPECT_THROW(pendulum_from_rest_enclosed(interval(1), interval(1), interval(0), interval(0)), std::domain_error);
}

}  // namespace
}  // namespace simpson

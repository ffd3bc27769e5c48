// Simpson's variational step enclosed by Krawczyk's test (enclosed_lagrangian_step.hpp): the
// enclosure contains the mpfr:100 step and is narrow; a box of starts is covered; a step too large
// proves nothing (and never aborts).

#include <simpson/double_pendulum.hpp>
#include <simpson/enclosed_lagrangian_step.hpp>
#include <simpson/precision.hpp>

#include <gtest/gtest.h>

namespace simpson::enclosed_lagrangian_step_test {
namespace {

template <class Real>
dense_vector<Real> vec2(const Real& a, const Real& b) {
  dense_vector<Real> out(2);
  out << a, b;
  return out;
}

template <class Real>
ndof_state<Real> start_of(const double_pendulum<Real>& L) {
  const dense_vector<Real> q = vec2(Real(1), Real(Real(-1) / 2)), v = vec2(Real(Real(3) / 10), Real(Real(1) / 5));
  return {lagrangian_gradient_at(L, q, v).dv, q};
}

TEST(EnclosedLagrangianStep, ContainsTheMpfrStepOfTheDoublePendulumTightly) {
  ndof_state<mpfr> reference;
  {
    const scoped_mpfr_digits digits(100);
    const double_pendulum<mpfr> L{mpfr(1), mpfr(1), mpfr(1), mpfr(1), mpfr(1)};
    reference = simpson_lagrangian_step(L, mpfr(1) / 10, start_of(L)).state;
  }
  const scoped_interval_digits digits(40);
  const double_pendulum<interval> L{interval(1), interval(1), interval(1), interval(1), interval(1)};
  const enclosed_lagrangian_step step = simpson_enclosed_lagrangian_step(L, interval(interval(1) / 10), start_of(L));
  ASSERT_TRUE(step.proved);
  for (int i = 0; i < 2; ++i) {
    EXPECT_TRUE(in(reference.q(i), step.state.q(i))) << enclosure_text(step.state.q(i));
    EXPECT_TRUE(in(reference.p(i), step.state.p(i))) << enclosure_text(step.state.p(i));
    EXPECT_LT(width(step.state.q(i)), 1e-30);
    EXPECT_LT(width(step.state.p(i)), 1e-30);
  }
}

TEST(EnclosedLagrangianStep, ABoxOfStartsIsCoveredAndAStepTooLargeProvesNothing) {
  const scoped_interval_digits digits(30);
  const double_pendulum<interval> L{interval(1), interval(1), interval(1), interval(1), interval(1)};
  ndof_state<interval> box = start_of(L);
  using real = boost::multiprecision::mpfr_float;
  for (int i = 0; i < 2; ++i) box.q(i) = interval(real(lower(box.q(i))) - real("1e-12"), real(upper(box.q(i))) + real("1e-12"));
  const enclosed_lagrangian_step step = simpson_enclosed_lagrangian_step(L, interval(interval(1) / 10), box);
  ASSERT_TRUE(step.proved);
  EXPECT_GT(width(step.state.q(0)), 1e-13);  // the start's width carried through
  EXPECT_LT(width(step.state.q(0)), 1e-10);
  EXPECT_FALSE(simpson_enclosed_lagrangian_step(L, interval(40), start_of(L)).proved);
}

}  // namespace
}  // namespace simpson::enclosed_lagrangian_step_test

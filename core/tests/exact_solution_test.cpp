#include <simpson/exact_solution.hpp>

#include <simpson/energy.hpp>

#include "test_support.hpp"

#include <boost/math/constants/constants.hpp>
#include <gtest/gtest.h>

namespace simpson {
namespace {

template <class Real>
class ExactSolution : public test::precision_fixture<Real> {};
TYPED_TEST_SUITE(ExactSolution, test::floating_scalars, test::scalar_names);

template <class Real>
oscillator_parameters<Real> sample_parameters() {
  return {test::ratio<Real>(3, 2), test::ratio<Real>(7, 3), test::ratio<Real>(1, 5)};
}

TYPED_TEST(ExactSolution, StartsAtTheInitialStateAndReturnsAfterOnePeriod) {
  using Real = TypeParam;
  const oscillator_parameters<Real> par = sample_parameters<Real>();
  const phase_point<Real> y0{test::ratio<Real>(-3, 2), test::ratio<Real>(5, 7)};
  const phase_point<Real> at_zero = exact_solution(par, y0, Real(0));
  EXPECT_TRUE(test::within(at_zero.p, y0.p, Real(0)));
  EXPECT_TRUE(test::within(at_zero.q, y0.q, Real(0)));
  // After T = 2π/ω the phase ωT = 2π carries ~3 roundings: the state errs by about
  // 3·2π·eps times the amplitude (|p0| + mω|q0| for p, |q0| + |p0|/(mω) for q), plus ~6 roundings.
  const Real period = boost::math::constants::two_pi<Real>() / par.omega();
  const phase_point<Real> after = exact_solution(par, y0, period);
  const Real m_omega = par.m() * par.omega();
  const Real p_amplitude = test::magnitude(y0.p) + m_omega * test::magnitude(y0.q);
  EXPECT_TRUE(test::within(after.p, y0.p, Real(32 * eps<Real>() * p_amplitude)));
  EXPECT_TRUE(test::within(after.q, y0.q, Real(32 * eps<Real>() * p_amplitude / m_omega)));
}

TYPED_TEST(ExactSolution, ConservesTheEnergyAndComposesInTime) {
  using Real = TypeParam;
  const oscillator_parameters<Real> par = sample_parameters<Real>();
  const phase_point<Real> y0{test::ratio<Real>(-3, 2), test::ratio<Real>(5, 7)};
  const Real t1 = test::ratio<Real>(3, 10), t2 = test::ratio<Real>(11, 7);
  const phase_point<Real> direct = exact_solution(par, y0, Real(t1 + t2));
  const phase_point<Real> composed = exact_solution(par, exact_solution(par, y0, t1), t2);
  const Real H = energy(par, y0);
  EXPECT_TRUE(test::within(energy(par, direct), H, Real(32 * eps<Real>() * H)));
  // Phases ω t of size ≤ 5 with ~3 roundings each, amplitude-relative: 32 eps (1 + ω(t1 + t2)) amplitude.
  const Real m_omega = par.m() * par.omega();
  const Real p_amplitude = test::magnitude(y0.p) + m_omega * test::magnitude(y0.q);
  const Real growth = 1 + par.omega() * (t1 + t2);
  EXPECT_TRUE(test::within(composed.p, direct.p, Real(32 * eps<Real>() * growth * p_amplitude)));
  EXPECT_TRUE(test::within(composed.q, direct.q, Real(32 * eps<Real>() * growth * p_amplitude / m_omega)));
}

TEST(ExactSolutionHighPrecision, SatisfiesHamiltonsEquations) {
  // q' = p/m and p' = −m ω² q, by central differences in mpfr:200 with step e = 1e-50:
  // truncation e²/6 max|y'''| ≤ e² ω³ amplitude, round-off ~4 eps amplitude/e.
  const scoped_mpfr_digits digits(200);
  const oscillator_parameters<mpfr> par = sample_parameters<mpfr>();
  const phase_point<mpfr> y0{mpfr(-3) / 2, mpfr(5) / 7};
  const mpfr t = mpfr(2) / 3, e("1e-50");
  const phase_point<mpfr> ahead = exact_solution(par, y0, mpfr(t + e));
  const phase_point<mpfr> behind = exact_solution(par, y0, mpfr(t - e));
  const phase_point<mpfr> now = exact_solution(par, y0, t);
  const mpfr m_omega = par.m() * par.omega();
  const mpfr q_amplitude = test::magnitude(y0.q) + test::magnitude(y0.p) / m_omega;
  const mpfr omega3 = par.omega() * par.omega() * par.omega();
  const mpfr q_bound = e * e * omega3 * q_amplitude + 4 * eps<mpfr>() * q_amplitude / e;
  EXPECT_TRUE(test::within(mpfr((ahead.q - behind.q) / (2 * e)), mpfr(now.p / par.m()), q_bound));
  EXPECT_TRUE(test::within(mpfr((ahead.p - behind.p) / (2 * e)), mpfr(-par.m() * par.omega() * par.omega() * now.q),
                           mpfr(q_bound * m_omega * par.omega())));
}

}  // namespace
}  // namespace simpson

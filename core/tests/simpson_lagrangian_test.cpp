#include <simpson/simpson_lagrangian.hpp>

#include <simpson/quadratic_interpolation.hpp>
#include <simpson/simpson_rule.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

namespace simpson {
namespace {

using R = rational;

template <class Real>
Real double_well_potential(const Real& q) {
  return q * q * q * q / 4 - q * q / 3;
}
template <class Real>
Real quartic_gradient(const Real& q) {
  return q * q * q - 2 * q / 3;
}

TEST(SimpsonLagrangian, IsSimpsonsRuleOfTheLagrangianAlongTheInterpolant) {
  // (LLhh) against its definition: h ∫_0^1 [m/2 q'(s)² − V(q(s))] ds by (simpson), with q from (q2t).
  const R m(3, 2), h(1, 7), q_l(-2, 3), q_m(1, 4), q_r(5, 4);
  const auto integrand = [&](const R& s) -> R {
    const R velocity = quadratic_interpolant_derivative(q_l, q_m, q_r, h, s);
    return m / 2 * velocity * velocity - double_well_potential<R>(quadratic_interpolant(q_l, q_m, q_r, s));
  };
  EXPECT_EQ(simpson_lagrangian(m, h, double_well_potential<R>, q_l, q_m, q_r), h * simpson_rule<R>(integrand));
}

TEST(SimpsonLagrangian, KineticPartIsTheExactIntegral) {
  // q'(t)² is quadratic in s, so Simpson integrates it exactly: with V = 0, L_h = (m/2) ∫_0^h q'² dt.
  // ∫_0^1 (g_l (1−s) + g_r s)² ds = (g_l² + g_l g_r + g_r²)/3.
  const R m(3, 2), h(1, 7), q_l(-2, 3), q_m(1, 4), q_r(5, 4);
  const R g_l = gear_left(q_l, q_m, q_r, h), g_r = gear_right(q_l, q_m, q_r, h);
  const auto no_potential = [](const R&) { return R(0); };
  EXPECT_EQ(simpson_lagrangian(m, h, no_potential, q_l, q_m, q_r), m / 2 * h * (g_l * g_l + g_l * g_r + g_r * g_r) / 3);
}

TEST(SimpsonLagrangian, DerivativeInMidNodeMatchesExactDifference) {
  // L_h is a quartic in q_m for this V, so the Richardson difference is its exact derivative.
  const R m(3, 2), h(1, 7), q_l(-2, 3), q_m(1, 4), q_r(5, 4);
  const auto L_of_mid = [&](const R& v) -> R { return simpson_lagrangian(m, h, double_well_potential<R>, q_l, v, q_r); };
  EXPECT_EQ(simpson_lagrangian_dq_mid(m, h, quartic_gradient<R>, q_l, q_m, q_r),
            test::exact_derivative_quartic<R>(L_of_mid, q_m));
}

TEST(SimpsonLagrangian, DerivativeInMidNodeMatchesHighPrecisionFiniteDifference) {
  // In mpfr:200 a central difference with step e = 1e-50 errs by e²/6 max|∂³L_h/∂q_m³| (truncation;
  // ∂³L_h/∂q_m³ = −(2h/3) V'''(q_m) = −4 h q_m here) plus about 4 eps |L_h|/e (round-off).
  const scoped_mpfr_digits digits(200);
  const mpfr m = mpfr(3) / 2, h = mpfr(1) / 7, q_l = mpfr(-2) / 3, q_m = mpfr(1) / 4, q_r = mpfr(5) / 4;
  const mpfr e("1e-50");
  const auto L_of_mid = [&](const mpfr& v) -> mpfr { return simpson_lagrangian(m, h, double_well_potential<mpfr>, q_l, v, q_r); };
  const mpfr difference = (L_of_mid(mpfr(q_m + e)) - L_of_mid(mpfr(q_m - e))) / (2 * e);
  using std::abs;
  const mpfr truncation = e * e / 6 * 4 * h * (abs(q_m) + e);
  const mpfr round_off = 4 * eps<mpfr>() * abs(L_of_mid(q_m)) / e;
  EXPECT_TRUE(test::within(mpfr(simpson_lagrangian_dq_mid(m, h, quartic_gradient<mpfr>, q_l, q_m, q_r)), difference,
                           mpfr(truncation + round_off)));
}

}  // namespace
}  // namespace simpson

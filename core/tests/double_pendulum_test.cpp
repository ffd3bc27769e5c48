// The double pendulum (double_pendulum.hpp), its mpfr reference (reference_flow.hpp) and its
// largest Lyapunov exponent (lyapunov_exponent.hpp): the reference's digits agree between halvings
// and with a double Simpson run to its truncation error; the exponent is positive from a chaotic
// start, near zero from small oscillations, and the same whichever stepper estimates it.

#include <simpson/discrete_lagrangian_step.hpp>
#include <simpson/double_pendulum.hpp>
#include <simpson/hamiltonian_prk_step.hpp>
#include <simpson/lyapunov_exponent.hpp>
#include <simpson/reference_flow.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace simpson::double_pendulum_test {
namespace {

template <class Real>
dense_vector<Real> vec2(const Real& a, const Real& b) {
  dense_vector<Real> out(2);
  out << a, b;
  return out;
}

TEST(DoublePendulum, ItsMassMatrixDependsOnTheConfigurationAsTheClosedFormSays) {
  const double_pendulum<double> L{1.5, 0.5, 2, 1, 9.81};
  const dense_vector<double> q = vec2(0.7, -0.4), v = vec2(0.0, 0.0);
  const lagrangian_hessian<double> d = lagrangian_hessian_at(L, q, v);
  // M = [[(m1 + m2) l1², m2 l1 l2 cos(θ1 − θ2)], [·, m2 l2²]]; ∂L/∂θ1 at rest = −(m1 + m2) g l1 sin θ1.
  EXPECT_NEAR(d.vv(0, 0), 8, 1e-14);
  EXPECT_NEAR(d.vv(0, 1), std::cos(1.1), 1e-15);
  EXPECT_NEAR(d.vv(1, 1), 0.5, 1e-15);
  EXPECT_NEAR(d.dq(0), -2 * 9.81 * 2 * std::sin(0.7), 1e-13);
  EXPECT_NEAR(d.dq(1), -0.5 * 9.81 * std::sin(-0.4), 1e-14);
}

TEST(DoublePendulumReference, HalvingAgreesTo20DigitsAndASimpsonRunIsWithinItsTruncationError) {
  ndof_state<double> y0, at_T;
  {
    const scoped_mpfr_digits digits(40);
    const double_pendulum<mpfr> L{mpfr(1), mpfr(1), mpfr(1), mpfr(1), mpfr(1)};
    const dense_vector<mpfr> q0 = vec2(mpfr(1), mpfr(-1) / 2), v0 = vec2(mpfr(3) / 10, mpfr(1) / 5);
    const ndof_state<mpfr> start{lagrangian_gradient_at(L, q0, v0).dv, q0};
    const reference_state r = lagrangian_reference(L, start, mpfr(1), 20, 32, 3);
    EXPECT_GE(r.agreed_digits, 20) << r.steps << " steps";
    EXPECT_LE(r.steps, 256);
    y0 = {vec2(static_cast<double>(start.p(0)), static_cast<double>(start.p(1))), vec2(1.0, -0.5)};
    at_T = {vec2(static_cast<double>(r.state.p(0)), static_cast<double>(r.state.p(1))),
            vec2(static_cast<double>(r.state.q(0)), static_cast<double>(r.state.q(1)))};
  }
  const double_pendulum<double> L{1, 1, 1, 1, 1};
  ndof_state<double> y = y0;
  for (int j = 0; j < 64; ++j) y = simpson_lagrangian_step(L, 1.0 / 64, y).state;
  const double error = std::max((y.q - at_T.q).cwiseAbs().maxCoeff(), (y.p - at_T.p).cwiseAbs().maxCoeff());
  EXPECT_LT(error, 1e-8);   // C h⁴ with C ~ 0.04 (discrete_lagrangian_step_test's orders)
  EXPECT_GT(error, 1e-12);  // and not round-off: the reference is not Simpson's own run
}

TEST(DoublePendulumLyapunov, ChaoticFromTwoRadiansRegularFromSmallOscillations) {
  const double_pendulum<double> L{1, 1, 1, 1, 1};
  const auto rk4 = [&](const ndof_state<double>& y) { return rk4_hamiltonian_step(L, 0.01, y).state; };
  const ndof_state<double> chaotic{vec2(0.0, 0.0), vec2(2.0, 2.0)}, regular{vec2(0.0, 0.0), vec2(0.1, 0.1)};
  const lyapunov_estimate<double> high = largest_lyapunov_exponent(rk4, chaotic, 0.01, 10, 1000, 1e-8);
  const lyapunov_estimate<double> low = largest_lyapunov_exponent(rk4, regular, 0.01, 10, 1000, 1e-8);
  // Over t = 100: ~0.37 from (2, 2) (settled: its first half within 30%), ~log(t)/t from (0.1, 0.1).
  EXPECT_GT(high.exponent, 0.2);
  EXPECT_LT(high.exponent, 0.6);
  EXPECT_NEAR(high.first_half / high.exponent, 1, 0.3);
  EXPECT_LT(low.exponent, 0.02);
  // The horizon for a double start (ε = 1e-16) and a tolerance of 1e-2: ln(1e14)/λ, some 50–160 units.
  const double horizon = predictability_horizon(high.exponent, 1e-16, 1e-2);
  EXPECT_GT(horizon, 50);
  EXPECT_LT(horizon, 170);
  EXPECT_THROW(predictability_horizon(low.exponent - 1, 1e-16, 1e-2), std::invalid_argument);
}

}  // namespace
}  // namespace simpson::double_pendulum_test

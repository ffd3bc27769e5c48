// The mpfr reference (reference_flow.hpp) on the double pendulum: two halvings agree to 20 digits,
// and a double Simpson run lands within its truncation error of it, not on it.

#include <simpson/discrete_lagrangian_step.hpp>
#include <simpson/double_pendulum.hpp>
#include <simpson/hamiltonian_prk_step.hpp>
#include <simpson/reference_flow.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace simpson::reference_flow_test {
namespace {

template <class Real>
dense_vector<Real> vec2(const Real& a, const Real& b) {
  dense_vector<Real> out(2);
  out << a, b;
  return out;
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

}  // namespace
}  // namespace simpson::reference_flow_test

// The Simpson step for any V (nonlinear_simpson_step.hpp), its twin Lobatto IIIA–IIIB with Newton
// (nonlinear_partitioned_rk.hpp), the potentials and the pendulum's exact solution.

#include <simpson/nonlinear_partitioned_rk.hpp>
#include <simpson/nonlinear_simpson_step.hpp>
#include <simpson/pendulum_exact.hpp>
#include <simpson/potential.hpp>

#include <simpson/runge_kutta_tableaux.hpp>
#include <simpson/simpson_map.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace simpson {
namespace {

template <class Real>
class NonlinearStep : public test::precision_fixture<Real> {};
TYPED_TEST_SUITE(NonlinearStep, test::all_scalars, test::scalar_names);

template <class Real>
class NonlinearPendulum : public test::precision_fixture<Real> {};
TYPED_TEST_SUITE(NonlinearPendulum, test::floating_scalars, test::scalar_names);

TYPED_TEST(NonlinearStep, QuarticIsThePolynomialWithItsCoefficients) {
  using Real = TypeParam;
  const quartic_potential<Real> quartic{Real(3), Real(2), test::ratio<Real>(1, 5)};
  const polynomial_potential<Real> poly({Real(0), Real(0), Real(6), Real(0), test::ratio<Real>(1, 20)});
  for (const Real& q : {test::ratio<Real>(-7, 3), Real(0), test::ratio<Real>(5, 4)}) {
    // Horner and the closed forms round differently: a few eps of the largest term (~ 30 at |q| = 7/3).
    const Real bound = 64 * eps<Real>() * 100;
    EXPECT_TRUE(test::within(poly.value(q), quartic.value(q), bound));
    EXPECT_TRUE(test::within(poly.derivative(q), quartic.derivative(q), bound));
    EXPECT_TRUE(test::within(poly.second_derivative(q), quartic.second_derivative(q), bound));
    // V' is the derivative of V (exact for a quartic, test_support.hpp).
    if constexpr (is_exact_v<Real>) {
      EXPECT_EQ(test::exact_derivative_quartic([&](const Real& v) { return poly.value(v); }, q), poly.derivative(q));
    }
  }
}

TYPED_TEST(NonlinearStep, OnTheHarmonicPotentialItIsPhi3) {
  using Real = TypeParam;
  // V = m ω² q²/2 as a polynomial: the step's equation is linear, Newton ends after one iteration
  // (none in exact arithmetic beyond it), and the step is Φ₃ (exactly in rationals).
  for (const auto& par : test::parameter_cases<Real>()) {
    if (par.omega2_h2() >= 8) continue;  // the first stable band, where the comparison is well conditioned
    const polynomial_potential<Real> V({Real(0), Real(0), Real(par.m() * par.omega() * par.omega() / 2)});
    const phase_point<Real> y{test::ratio<Real>(3, 7), test::ratio<Real>(-2, 5)};
    const auto step = simpson_nonlinear_step(par.m(), par.h(), V, y);
    const phase_point<Real> expected = simpson_map(par) * y;
    EXPECT_LE(step.newton_iterations, 2);
    const Real scale = test::magnitude(y.p) + par.m() * par.omega() * test::magnitude(y.q);
    EXPECT_TRUE(test::within(step.state.p, expected.p, Real(64 * eps<Real>() * scale)));
    EXPECT_TRUE(test::within(Real(par.m() * par.omega() * step.state.q), Real(par.m() * par.omega() * expected.q),
                             Real(64 * eps<Real>() * scale)));
  }
}

TYPED_TEST(NonlinearStep, ANewtonFailureThrowsNeverASilentResult) {
  using Real = TypeParam;
  if constexpr (!is_exact_v<Real> && std::numeric_limits<Real>::has_infinity) {
    // λ q⁴ overflows: the residual is not finite and the step says so.
    const quartic_potential<Real> V{Real(1), Real(1), Real(std::numeric_limits<Real>::max() / 4)};
    EXPECT_THROW(simpson_nonlinear_step(Real(1), Real(1), V, phase_point<Real>{Real(0), Real(1e10)}), std::domain_error);
  }
  // F'(x) = m + h² V''(x)/24 = 0 at the first iterate: V'' = −24 m/h² everywhere.
  const polynomial_potential<Real> flat({Real(0), Real(0), Real(-12)});
  EXPECT_THROW(simpson_nonlinear_step(Real(1), Real(1), flat, phase_point<Real>{Real(1), Real(1)}), std::domain_error);
}

TYPED_TEST(NonlinearPendulum, SimpsonAndLobattoIIIAIIIBAgreeToRoundOff) {
  using Real = TypeParam;
  const pendulum_potential<Real> V{Real(1), Real(1)};
  const Real h = test::ratio<Real>(1, 4);
  const auto lobatto_q = lobatto_iiia3_tableau<Real>(), lobatto_p = lobatto_iiib3_tableau<Real>();
  const auto coupling = couple(lobatto_q, lobatto_p);
  phase_point<Real> s{Real(0), Real(1)}, l = s;
  Real largest(0);
  for (int j = 0; j < 40; ++j) {
    s = simpson_nonlinear_step(Real(1), h, V, s).state;
    l = prk_nonlinear_step(lobatto_q, lobatto_p, coupling, Real(1), h, V, l).state;
    using std::abs;
    largest = std::max(largest, Real(abs(Real(s.q - l.q)) + abs(Real(s.p - l.p))));
  }
  // Two solves to 16 eps each, their round-off accumulating over 40 steps of a map of norm ~1.
  EXPECT_LE(largest, Real(40 * 64 * eps<Real>())) << to_string(largest, 3);
}

TYPED_TEST(NonlinearPendulum, FourthOrderAgainstTheExactSolution) {
  using Real = TypeParam;
  const pendulum_from_rest<Real> exact{Real(1), Real(1), Real(1)};
  const pendulum_potential<Real> V{Real(1), Real(1)};
  // The exact solution: starts at rest at q₀, conserves H, returns after a period.
  const phase_point<Real> start = exact.at(Real(0)), later = exact.at(Real(3));
  using std::abs;
  using std::cos;
  EXPECT_LE(abs(Real(start.q - 1)) + abs(start.p), Real(64 * eps<Real>()));
  const auto H = [&](const phase_point<Real>& y) { return y.p * y.p / 2 + V.value(y.q); };
  EXPECT_LE(abs(Real(H(later) - H(start))), Real(64 * eps<Real>()));
  EXPECT_LE(abs(Real(exact.at(exact.period()).q - 1)), Real(1024 * eps<Real>()));
  // Global error at T = 10 with N = 20 and 40: divided by about 2⁴.
  const auto error = [&](int N) {
    const Real h = Real(10) / N;
    phase_point<Real> y = start;
    for (int j = 0; j < N; ++j) y = simpson_nonlinear_step(Real(1), h, V, y).state;
    return Real(abs(Real(y.q - exact.at(Real(10)).q)));
  };
  const double ratio = static_cast<double>(Real(error(20) / error(40)));
  EXPECT_GT(ratio, 12.0);
  EXPECT_LT(ratio, 20.0);
}

}  // namespace
}  // namespace simpson

#include <simpson/oscillator_parameters.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace simpson {
namespace {

template <class Real>
class OscillatorParameters : public test::precision_fixture<Real> {};
TYPED_TEST_SUITE(OscillatorParameters, test::all_scalars, test::scalar_names);

TYPED_TEST(OscillatorParameters, DimensionlessStepIsOmegaTimesH) {
  using Real = TypeParam;
  const oscillator_parameters<Real> par(test::ratio<Real>(3, 2), test::ratio<Real>(7, 3), test::ratio<Real>(1, 5));
  // θ = 7/15 and x = 49/225, each up to two roundings of operands below 1 in magnitude.
  EXPECT_TRUE(test::within(par.omega_h(), test::ratio<Real>(7, 15), Real(4 * eps<Real>())));
  EXPECT_TRUE(test::within(par.omega2_h2(), test::ratio<Real>(49, 225), Real(8 * eps<Real>())));
}

TEST(OscillatorParametersExact, ForceGradientIsTheDerivativeOfThePotential) {
  // V is quadratic, so the Richardson difference is exact in rationals: an independent route.
  using R = rational;
  for (const auto& par : test::parameter_cases<R>()) {
    const R q(-5, 3);
    const auto V = [&](const R& v) -> R { return par.potential(v); };
    EXPECT_EQ(test::exact_derivative_quartic<R>(V, q), par.force_gradient(q));
  }
}

TYPED_TEST(OscillatorParameters, RejectsNonPositiveParametersNamingThem) {
  using Real = TypeParam;
  const Real one(1);
  for (const Real& bad : {Real(0), Real(-1), test::ratio<Real>(-1, 3)}) {
    for (const char* name : {"m", "omega", "h"}) {
      const std::string label(name);
      try {
        oscillator_parameters<Real>(label == "m" ? bad : one, label == "omega" ? bad : one, label == "h" ? bad : one);
        ADD_FAILURE() << "accepted " << name << " = " << to_string(bad);
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(": " + label + " must be positive and finite, got "), std::string::npos)
            << e.what();
      }
    }
  }
}

template <class Real>
class FloatingOscillatorParameters : public test::precision_fixture<Real> {};
TYPED_TEST_SUITE(FloatingOscillatorParameters, test::floating_scalars, test::scalar_names);

TYPED_TEST(FloatingOscillatorParameters, RejectsNanAndInfinity) {
  using Real = TypeParam;
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  const Real inf = std::numeric_limits<Real>::infinity();
  EXPECT_THROW(oscillator_parameters<Real>(nan, Real(1), Real(1)), std::invalid_argument);
  EXPECT_THROW(oscillator_parameters<Real>(Real(1), inf, Real(1)), std::invalid_argument);
  EXPECT_THROW(oscillator_parameters<Real>(Real(1), Real(1), Real(-inf)), std::invalid_argument);
  try {
    oscillator_parameters<Real>(Real(1), Real(1), nan);
    ADD_FAILURE() << "accepted h = nan";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("h must be positive and finite, got "), std::string::npos) << e.what();
  }
}

TEST(StepSize, IsTOverN) {
  EXPECT_EQ(step_size(rational(1), 15), rational(1, 15));
  EXPECT_EQ(step_size(3.0, 4), 0.75);
}

TEST(StepSize, RejectsNBelowOneAndBadT) {
  try {
    step_size(1.0, 0);
    ADD_FAILURE() << "accepted N = 0";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("N must be at least 1, got 0"), std::string::npos) << e.what();
  }
  EXPECT_THROW(step_size(1.0, -3), std::invalid_argument);
  EXPECT_THROW(step_size(0.0, 10), std::invalid_argument);
  EXPECT_THROW(step_size(std::numeric_limits<double>::infinity(), 10), std::invalid_argument);
}

}  // namespace
}  // namespace simpson

// The integration driver and its observers (integration_driver.hpp), and the sections' method list
// (integration_methods.hpp): each observer against a run whose answer is known exactly (states that
// double at every step, a reference offset by a known amount, a ramp), so a wrong energy, a wrong
// reference step or a wrong scale shows as a wrong number, not as a tolerance missed.

#include <simpson/verify/integration_driver.hpp>
#include <simpson/verify/integration_methods.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace simpson::verify {
namespace {

using point = phase_point<double>;

/// The energy of a unit oscillator, p²/2 + q²/2.
double oscillator_energy(const point& y) { return y.p * y.p / 2 + y.q * y.q / 2; }

/// Records the steps and samples it sees.
struct recorder : observer {
  std::vector<long long> steps, samples;
  long long starts = 0;
  void start(const point&) { ++starts; }
  void step(long long j, const point&) { steps.push_back(j); }
  void sample(long long j, const point&) { samples.push_back(j); }
};

TEST(IntegrationDriver, SamplesTheStartEveryKthStepAndTheLast) {
  point y{1, 0};
  recorder r;
  const run_end end = integrate_n_steps([](const point& z) { return z; }, y, 10, 4, never_stop{}, r);
  EXPECT_TRUE(end.ok());
  EXPECT_EQ(end.steps, 10);
  EXPECT_EQ(r.starts, 1);
  EXPECT_EQ(r.steps, (std::vector<long long>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
  EXPECT_EQ(r.samples, (std::vector<long long>{0, 4, 8, 10}));
}

TEST(IntegrationDriver, RelativeChangeIsAgainstTheStartAndItsWindowsCloseAtSamples) {
  // Each step doubles the state, so E(y_j) = 4^j E(y_0): the relative change after j steps is 4^j − 1,
  // exactly in double. An observer that measured against the previous step (3 at every step) or
  // divided by E(y_j) (1 − 4^−j) would give other numbers.
  point y{1, 0};
  auto energy = relative_change_of<double>(oscillator_energy, observed_at::every_step, true);
  std::vector<double> windows;  // each window's maximum, read at its end before the window closes
  auto window_ends = at_samples_of([&](long long j, const point&) {
    if (j > 0) windows.push_back(energy.window_maximum);
  });
  const run_end end =
      integrate_n_steps([](const point& z) { return point{2 * z.p, 2 * z.q}; }, y, 5, 2, never_stop{}, window_ends, energy);
  EXPECT_EQ(end.steps, 5);
  EXPECT_EQ(energy.initial, 0.5);
  EXPECT_EQ(energy.maximum, 1023.0);  // 4⁵ − 1
  EXPECT_EQ(energy.last, 1023.0);
  EXPECT_EQ(windows, (std::vector<double>{15.0, 255.0, 1023.0}));                // steps 1–2, 3–4, 5
  EXPECT_EQ(energy.at_samples, (std::vector<double>{0.0, 15.0, 255.0, 1023.0}));  // j = 0, 2, 4, 5
}

TEST(IntegrationDriver, RelativeChangeAtSamplesSeesOnlyTheSamples) {
  // The state halves and doubles in turn: after every odd step the energy's relative change is 3/4,
  // after every even step 0; sampled at even steps only, it never changes.
  point y{1, 0};
  long long j = 0;
  auto energy = relative_change_of<double>(oscillator_energy, observed_at::samples);
  integrate_n_steps(
      [&j](const point& z) {
        const double f = ++j % 2 == 1 ? 0.5 : 2.0;
        return point{f * z.p, f * z.q};
      },
      y, 6, 2, never_stop{}, energy);
  EXPECT_EQ(energy.maximum, 0.0);
}

TEST(IntegrationDriver, ReferenceErrorIsTheOffsetInPositionAndInMomentum) {
  // The state stays at (p, q) = (2, 1); the reference moves away by (j/2, j/4) a step. The errors after
  // 8 steps: |Δq| = 2, |Δp|/p_scale = 4/2 = 2; their largest, at the last step.
  point y{2, 1};
  const auto reference = [](long long j) { return point{2 + 0.5 * static_cast<double>(j), 1 + 0.25 * static_cast<double>(j)}; };
  auto errors = reference_error_of<double>(reference, 2.0);
  integrate_n_steps([](const point& z) { return z; }, y, 8, 8, never_stop{}, errors);
  EXPECT_EQ(errors.q_max, 2.0);
  EXPECT_EQ(errors.p_max, 2.0);
  EXPECT_EQ(errors.q_last, 2.0);
  // A reference taken one step late (j − 1) would give 1.75 for both.
}

TEST(IntegrationDriver, MeanDriftComparesTheLastTenthWithTheFirst) {
  // q = j after step j: the mean over steps 1..10 is 5.5, over 91..100 it is 95.5; the drift 90, over
  // a scale of 3, is 30.
  point y{0, 0};
  auto drift = mean_drift_of([](const point& z) { return z.q; }, 100);
  integrate_n_steps([](const point& z) { return point{z.p, z.q + 1}; }, y, 100, 100, never_stop{}, drift);
  EXPECT_EQ(drift.tenth, 10);
  EXPECT_DOUBLE_EQ(drift.drift(3), 30.0);
}

TEST(IntegrationDriver, AStopEndsTheRunBeforeAnyObserverSeesTheState) {
  point y{0, 0};
  recorder r;
  const stop_when_unstable stop([](const point& z) { return z.q > 5; });
  const run_end end = integrate_n_steps([](const point& z) { return point{z.p, z.q + 1}; }, y, 100, 1, stop, r);
  EXPECT_FALSE(end.ok());
  EXPECT_EQ(end.status.value(), "unstable (step 6)");
  EXPECT_EQ(end.steps, 5);
  EXPECT_EQ(r.steps.back(), 5);
  EXPECT_EQ(r.samples.back(), 5);
  EXPECT_EQ(y.q, 6);  // the state that stopped the run
}

TEST(IntegrationDriver, AStepThatThrowsIsAFailedRun) {
  point y{0, 0};
  const run_end end = integrate_n_steps(
      [](const point& z) {
        if (z.q >= 2) throw std::domain_error("no convergence");
        return point{z.p, z.q + 1};
      },
      y, 10, 1, never_stop{});
  EXPECT_EQ(end.status.value(), "failed: no convergence");
  EXPECT_EQ(end.steps, 2);
  EXPECT_EQ(y.q, 2);  // left as it was before the failed step
}

TEST(IntegrationDriver, UnwrappedAngleCountsTurns) {
  // A rotation of (q, p) by 1 rad a step: after 100 steps the unwrapped angle is 100 rad (16 turns and
  // 100 − 32π), to round-off.
  const double c = std::cos(1.0), s = std::sin(1.0);
  point y{1, 0};
  unwrapped_angle<double> angle(2 * M_PI);
  integrate_n_steps([&](const point& z) { return point{c * z.p - s * z.q, s * z.p + c * z.q}; }, y, 100, 100, never_stop{}, angle);
  EXPECT_EQ(angle.turns, 16);
  EXPECT_NEAR(2 * M_PI * static_cast<double>(angle.turns) + angle.angle, 100.0, 1e-11);
}

TEST(IntegrationMethods, AreNamedOnceWithTheSchemeTheyAreOnTheOscillator) {
  EXPECT_EQ(find_method("implicit-midpoint").on_oscillator, scheme_id::newmark);
  EXPECT_FALSE(find_method("trigonometric").on_oscillator.has_value());
  EXPECT_THROW(find_method("euler"), std::invalid_argument);
  const scheme_style midpoint = style_of(find_method("implicit-midpoint")), newmark = style_of(scheme_id::newmark);
  EXPECT_EQ(midpoint.color, newmark.color);
  EXPECT_EQ(midpoint.point, newmark.point);
  for (const integration_method& m : integration_methods) {
    EXPECT_EQ(&find_method(m.name), &method_of(m.id)) << m.name;
    const std::string_view expected = m.name == "implicit-midpoint" ? std::string_view("newmark") : m.name;
    if (m.on_oscillator) {
      EXPECT_EQ(expected, traits_of(*m.on_oscillator).name);
    }
  }
}

TEST(IntegrationMethods, EachStepIsItsSchemesMapOnTheOscillator) {
  // V = q²/2, m = 1, h = 0.3: each method's n-DOF step (Newton to 16 eps for the implicit ones) is the
  // one-step matrix of the scheme it is on the oscillator.
  const double h = 0.3;
  const separable_system<double, quadratic_potential<double>> oscillator(dense_matrix<double>::Identity(1, 1),
                                                                         quadratic_potential<double>{dense_matrix<double>::Identity(1, 1)});
  const oscillator_parameters<double> par{1, 1, h};
  for (const integration_method& m : integration_methods) {
    if (!m.on_oscillator) continue;
    ndof_stepper<double, quadratic_potential<double>> stepper_on(m, oscillator);
    const one_step_matrix<double> phi = stepper<double>(*m.on_oscillator, par).matrix();
    ndof_state<double> y{dense_vector<double>::Constant(1, 0.6), dense_vector<double>::Constant(1, 0.8)};
    point z{0.6, 0.8};
    long long iterations = 0;
    for (int j = 0; j < 5; ++j) {
      y = stepper_on.step(h, y, iterations);
      z = phi * z;
    }
    EXPECT_NEAR(y.p(0), z.p, 1e-13) << m.name;
    EXPECT_NEAR(y.q(0), z.q, 1e-13) << m.name;
    EXPECT_EQ(iterations > 0, m.implicit) << m.name;
  }
}

}  // namespace
}  // namespace simpson::verify

#pragma once
// One integration driver for every experiment section, and the observers they share (after
// Boost.Odeint's integrate_n_steps and its observers): a method is a step, data the sections choose
// (integration_methods.hpp, core's scheme list); the loop that runs it, stops it and samples it is
// written here once.
//
// integrate_n_steps(step, y, n, every, stop, observers...) advances y by n steps of `step`, unless
// `stop` ends the run first, and calls each observer
//   - start(y) once, before the first step,
//   - step(j, y) after every step j = 1..n,
//   - sample(j, y) at j = 0 and after each step j that is a multiple of `every`, and after the last.
// An observer derives from `observer` and defines the hooks it needs. `stop` decides, after each step
// and before any observer sees it, whether the state ends the run (stop.check(j, y) returns the fault,
// e.g. unstable_at(j)), and names a step that threw std::domain_error (stop.failed(j, e)): no observer
// sees a state that ended the run.
//
// The observers written here are the quantities the sections report: the relative change of an
// energy (its largest, and its largest since the last sample), its drift (the mean over the last
// tenth of the run against the first), and the error against a reference solution, in position and in
// momentum. Each evaluates its formula in the run's own Real, in the order the sections' figures
// have always been computed, so moving a section onto the driver changes no digit.

#include <simpson/verify/figure.hpp>
#include <simpson/verify/interruption.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace simpson::verify {

/// How a run ended: the steps it completed (the states the observers saw) and "ok" or its fault.
struct run_end {
  long long steps = 0;
  figure status = figure::text("ok");
  bool ok() const { return !status.is_fault(); }
};

/// The no-op hooks an observer overrides (by name: each hook it defines hides the one here).
struct observer {
  template <class State>
  void start(const State&) {}
  template <class State>
  void step(long long, const State&) {}
  template <class State>
  void sample(long long, const State&) {}
};

/// A stop rule that never stops, and names a failed step "failed: <what>".
struct never_stop {
  template <class State>
  std::optional<figure> check(long long, const State&) const {
    return std::nullopt;
  }
  figure failed(long long, const std::domain_error& e) const { return figure::fault(std::string("failed: ") + e.what()); }
};

/// A stop rule from a predicate on the state: `unstable(y)` true ends the run as unstable_at(j); a
/// failed step is "failed: <what>".
template <class Unstable>
struct stop_when_unstable : never_stop {
  Unstable unstable;
  explicit stop_when_unstable(Unstable u) : unstable(std::move(u)) {}
  template <class State>
  std::optional<figure> check(long long j, const State& y) const {
    if (unstable(y)) return unstable_at(j);
    return std::nullopt;
  }
};

/// Advances y by n steps of step(y) (a new state), with the stop rule and the observers above; y is
/// left at the last state computed (the one that stopped the run, if one did; a step that threw leaves
/// y as it was). Checks for an interruption every 1024 steps.
template <class State, class Step, class Stop, class... Observers>
run_end integrate_n_steps(Step&& step, State& y, long long n, long long every, const Stop& stop, Observers&... observers) {
  run_end end;
  every = std::max(1LL, every);
  (observers.start(static_cast<const State&>(y)), ...);
  (observers.sample(0LL, static_cast<const State&>(y)), ...);
  for (long long j = 1; j <= n; ++j) {
    if ((j & 1023) == 0) throw_if_interrupted();
    try {
      y = step(static_cast<const State&>(y));
    } catch (const std::domain_error& e) {
      end.status = stop.failed(j, e);
      return end;
    }
    if (std::optional<figure> fault = stop.check(j, static_cast<const State&>(y))) {
      end.status = std::move(*fault);
      return end;
    }
    end.steps = j;
    (observers.step(j, static_cast<const State&>(y)), ...);
    if (j % every == 0 || j == n) (observers.sample(j, static_cast<const State&>(y)), ...);
  }
  return end;
}

/// When an observer evaluates its quantity: after every step, or at the sample points only.
enum class observed_at { every_step, samples };

/// The relative change |E(y) − E(y₀)| / |E(y₀)| of a quantity E (an energy, an invariant): its
/// largest over the run, its largest since the last sample (a window's), its last value, and its
/// value at each sample when `keep_samples`. E returns the run's Real.
template <class Real, class Quantity>
struct relative_change : observer {
  Quantity quantity;
  observed_at at = observed_at::every_step;
  bool keep_samples = false;
  Real initial{0}, maximum{0}, window_maximum{0}, last{0};
  std::vector<Real> at_samples;

  explicit relative_change(Quantity q, observed_at when = observed_at::every_step, bool keep = false)
      : quantity(std::move(q)), at(when), keep_samples(keep) {}

  template <class State>
  void start(const State& y) {
    initial = quantity(y);
  }
  template <class State>
  void step(long long, const State& y) {
    if (at == observed_at::every_step) take(y);
  }
  template <class State>
  void sample(long long j, const State& y) {
    if (at == observed_at::samples) take(y);
    if (keep_samples) at_samples.push_back(j == 0 ? Real(0) : last);
    if (j > 0) window_maximum = Real(0);
  }
  /// The relative change at y, the run's largest and the window's largest updated. The window closes
  /// in this observer's sample hook: an observer that reads window_maximum at a sample is passed to
  /// integrate_n_steps before this one, so that its hook runs first.
  template <class State>
  void take(const State& y) {
    using std::abs;
    last = Real(abs(Real(quantity(y) - initial)) / abs(initial));
    maximum = std::max(maximum, last);
    window_maximum = std::max(window_maximum, last);
  }
};

template <class Real, class Quantity>
relative_change<Real, Quantity> relative_change_of(Quantity q, observed_at when = observed_at::every_step, bool keep = false) {
  return relative_change<Real, Quantity>(std::move(q), when, keep);
}

/// The drift of a quantity Q: its mean over every step of the last tenth of the run minus its mean
/// over the first tenth (every step: a quantity that oscillates with a fast phase would alias if
/// sampled far apart), over `scale`. `n` is the run's length in steps.
template <class Quantity>
struct mean_drift : observer {
  Quantity quantity;
  long long n, tenth;
  double first_sum = 0, last_sum = 0;

  mean_drift(Quantity q, long long steps) : quantity(std::move(q)), n(steps), tenth(std::max(1LL, steps / 10)) {}

  template <class State>
  void step(long long j, const State& y) {
    if (j <= tenth) first_sum += quantity(y);
    if (j > n - tenth) last_sum += quantity(y);
  }
  double drift(double scale) const { return (last_sum - first_sum) / static_cast<double>(tenth) / scale; }
};

template <class Quantity>
mean_drift<Quantity> mean_drift_of(Quantity q, long long steps) {
  return mean_drift<Quantity>(std::move(q), steps);
}

/// The error against a reference solution, after every step j: |q_j − q_ref(j)| and the momentum's
/// |p_j − p_ref(j)| / p_scale, their largest over the run. `reference(j)` returns the reference state
/// at step j (a phase point of Real).
template <class Real, class Reference>
struct reference_error : observer {
  Reference reference;
  Real p_scale;
  Real q_max{0}, p_max{0}, q_last{0}, p_last{0};

  reference_error(Reference r, Real scale) : reference(std::move(r)), p_scale(std::move(scale)) {}

  template <class State>
  void step(long long j, const State& y) {
    using std::abs;
    const auto& at = reference(j);
    q_last = abs(Real(y.q - at.q));
    p_last = abs(Real(y.p - at.p)) / p_scale;
    q_max = std::max(q_max, q_last);
    p_max = std::max(p_max, p_last);
  }
};

template <class Real, class Reference>
reference_error<Real, Reference> reference_error_of(Reference r, Real p_scale) {
  return reference_error<Real, Reference>(std::move(r), std::move(p_scale));
}

/// The unwrapped angle of (q, p) after every step: 2π·turns + angle, an integer count of branch
/// crossings beside the angle in (−π, π] (a running sum of about θ per step would err by up to n
/// ulp(nθ)/2 over n steps). A step advances the angle by less than π, so a crossing of the branch
/// cut is a jump by about ∓2π.
template <class Real>
struct unwrapped_angle : observer {
  Real two_pi, angle{0};
  long long turns = 0;

  explicit unwrapped_angle(Real two_pi_value) : two_pi(std::move(two_pi_value)) {}

  template <class State>
  void step(long long, const State& z) {
    using std::atan2;
    const Real next_angle = atan2(z.q, z.p);
    if (next_angle - angle < -two_pi / 2) ++turns;
    if (next_angle - angle > two_pi / 2) --turns;
    angle = next_angle;
  }
};

/// An observer of the samples alone, from a callable f(j, y): what a section does at its sample
/// points (a window's end, a row of its table) beside the shared observers.
template <class F>
struct at_samples : observer {
  F f;
  explicit at_samples(F callable) : f(std::move(callable)) {}
  template <class State>
  void sample(long long j, const State& y) {
    f(j, y);
  }
};

template <class F>
at_samples<F> at_samples_of(F f) {
  return at_samples<F>(std::move(f));
}

/// An observer of every step alone, from a callable f(j, y).
template <class F>
struct at_steps : observer {
  F f;
  explicit at_steps(F callable) : f(std::move(callable)) {}
  template <class State>
  void step(long long j, const State& y) {
    f(j, y);
  }
};

template <class F>
at_steps<F> at_steps_of(F f) {
  return at_steps<F>(std::move(f));
}

}  // namespace simpson::verify

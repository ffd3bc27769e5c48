// The cost estimate that guards a scene against running for days: steps times the cost of a step
// in each precision, in units of one step of Φ₃ in double. Calibrated on the 2-core machine:
// the paper scene's experiments, estimated at ~3e9 units, take ~13 s (about 5 ns per unit).

#include <simpson/verify/experiment_cost.hpp>


#include <fmt/format.h>

#include <algorithm>

namespace simpson::verify {
namespace {

/// Cost of one arithmetic-heavy step in a precision relative to double, measured on the 2-core
/// machine (Φ₃ iteration with the energy monitor): software float128 and multiprecision are slower.
double precision_factor(const precision& p) {
  switch (p.kind()) {
    case precision_kind::float64: return 1;
    case precision_kind::extended: return 2;
    case precision_kind::float128: return 20;
    case precision_kind::bin50: return 60;
    case precision_kind::bin100: return 120;
    case precision_kind::mpfr: return 30 + static_cast<double>(p.digits10()) / 5;
    case precision_kind::rational: return 1e6;
  }
  return 1;
}

}  // namespace

cost_estimate estimate_cost(const experiment_settings& e, const recheck_load& rechecks) {
  cost_estimate c;
  if (rechecks.numeric_claims > 0 && rechecks.samples > 0) {
    // Measured on the 2-core machine, one sample of one claim: ~1 µs in double, 2.6 ms in mpfr:10000,
    // 8 ms in mpfr:30000 (cos, sin and the checks at that precision): 200 units times the precision's
    // factor bounds these (within 2x at 10000 digits and more, generously below).
    // Exact rationals, which no experiment runs, take ~0.13 ms a sample here (small numerators): factor 150.
    double units = 0;
    for (const precision& p : rechecks.precisions) {
      const double factor = p.exact() ? 150 : precision_factor(p);
      units += 200 * factor * static_cast<double>(rechecks.numeric_claims) * static_cast<double>(rechecks.samples);
    }
    c.units += units;
    const auto count = [](std::size_t n, const char* what) { return fmt::format("{} {}{}", n, what, n == 1 ? "" : "s"); };
    c.lines.push_back(fmt::format("numeric rechecks: {:.3g} units ({} x {} x {})", units, count(rechecks.numeric_claims, "claim"),
                                  count(rechecks.samples, "sample"), count(rechecks.precisions.size(), "precision")));
  }
  if (e.table1) {
    double steps = 0;
    for (const long long N : e.table1->meshes) steps += 2.0 * static_cast<double>(N);
    c.units += steps;
    c.lines.push_back(fmt::format("table1: {:.3g} steps in double", steps));
  }
  if (e.work_precision) {
    const work_precision_settings& w = *e.work_precision;
    double units = 0;
    for (const precision& p : w.precisions) {
      for (const scheme_id scheme : w.schemes) {
        for (const long long N : w.meshes) {
          // The error run and the exact solution (cos, sin: ~10 steps' worth), then up to max_runs + 1
          // timed runs; each step of a step algorithm costs ~10 matrix steps per stage.
          const double steps = static_cast<double>(N) * static_cast<double>(w.periods);
          units += steps * precision_factor(p) * (10 + 10 * traits_of(scheme).stages * (1 + (w.timing.max_runs > 0 ? 1 + w.timing.max_runs : 0)));
        }
      }
    }
    c.units += units;
    c.lines.push_back(w.timing.max_runs > 0 ? fmt::format("work_precision: {:.3g} units (timing capped at {} s per configuration)",
                                                          units, w.timing.max_seconds)
                                            : fmt::format("work_precision: {:.3g} units (no timing)", units));
  }
  if (e.stability) {
    const stability_settings& s = *e.stability;
    // The endpoints' closed form and the stiff chain's squarings (an 8 x 8 product, ~500 units, per
    // doubling and band) cost the same at any n: both in mpfr:50.
    double units = (9 * 100 + 500.0 * 4 * static_cast<double>(s.stiff_ratios.size() * static_cast<std::size_t>(s.stiff_doublings))) *
                   precision_factor(precision::mpfr_digits(50));
    for (const precision& p : s.precisions) {
      units += static_cast<double>(s.omega_h.size() + s.masses.size()) * static_cast<double>(s.steps) * precision_factor(p) * 2;
    }
    c.units += units;
    c.lines.push_back(fmt::format("stability: {:.3g} units", units));
  }
  if (e.long_time) {
    const long_time_settings& l = *e.long_time;
    // Each step also evaluates an energy and an angle (atan2): about 12 units in double (measured:
    // 1e7 steps of the three schemes take ~2 s).
    // Φ₃'s three forms in double: about 2 units a step each.
    const double units = 3 * 12 * static_cast<double>(l.steps_double) + 3 * 2 * static_cast<double>(l.steps_double) +
                         3 * 12 * static_cast<double>(l.steps_mpfr) * precision_factor(precision::mpfr_digits(l.mpfr_digits));
    c.units += units;
    c.lines.push_back(fmt::format("long_time: {:.3g} units", units));
  }
  if (e.nonlinear) {
    const nonlinear_settings& n = *e.nonlinear;
    // Measured on the 2-core machine: a Newton step of the pendulum in mpfr:50 beside its Lobatto
    // run ~3e4 units; a step of a nonlinear problem in double (Eigen, dynamic sizes) ~200 units for
    // the implicit methods, with up to max_runs + 1 timed runs; Hénon–Heiles' reference, 24 times the
    // finest N of Gauss–Legendre steps in mpfr:32, ~2e4 units each (scaled by the precision's factor);
    // a step of the Brouwer part (three forms in double and the reference in long double) ~400 units.
    double pendulum = 0, problems = 0, finest = 0, double_pendulum = 0;
    const double mpfr_factor = precision_factor(precision::mpfr_digits(n.mpfr_digits)) / precision_factor(precision::mpfr_digits(50));
    for (const long long N : n.pendulum_N) pendulum += 3e4 * mpfr_factor * static_cast<double>(N) + 100 * static_cast<double>(n.energy_steps);
    for (const long long N : n.N) {
      problems += 200 * 5 * static_cast<double>(N) * static_cast<double>(n.problems.size()) * (2 + n.timing.max_runs);
      finest = std::max(finest, static_cast<double>(N));
    }
    for (const long long N : n.double_pendulum_N) double_pendulum += 300 * mpfr_factor * static_cast<double>(N) + 50 * static_cast<double>(n.energy_steps);
    const bool henon_heiles = std::find(n.problems.begin(), n.problems.end(), "henon-heiles") != n.problems.end();
    const double reference_factor =
        precision_factor(precision::mpfr_digits(n.reference_digits)) / precision_factor(precision::mpfr_digits(32));
    const double brouwer = 400 * static_cast<double>(n.brouwer_steps);
    // The FPU chain's reference: 24 times the finest N of Gauss–Legendre steps in long double, 2m = 6
    // degrees of freedom, ~2e3 units each (measured 12 µs a step: 1.2 s for 16 + 8 times N = 4096).
    const bool chain = std::find(n.problems.begin(), n.problems.end(), "fpu") != n.problems.end();
    const double units = pendulum + brouwer + problems + double_pendulum + (henon_heiles ? 2e4 * reference_factor * 24 * finest : 0) +
                         (chain ? 2e3 * 24 * finest : 0);
    c.units += units;
    c.lines.push_back(fmt::format("nonlinear: {:.3g} units", units));
  }
  if (e.fpu) {
    const fpu_settings& f = *e.fpu;
    // A step of the chain in double: ~700 units for the implicit methods (6 to 12 unknowns, a few
    // Newton iterations; measured: the default size, 20 s), ~30 for Störmer–Verlet.
    const double per_time = f.omega * (3 * 700 + 30);
    double units = 0;
    for (const double omega_h : f.omega_h) units += per_time * f.end_time / omega_h;
    for (double omega_h = f.scan_from; omega_h <= f.scan_to + 1e-9; omega_h += f.scan_step) units += per_time * f.scan_end_time / omega_h;
    units += f.omega * 700 * f.exchange_time / f.reference_omega_h;
    c.units += units;
    c.lines.push_back(fmt::format("fpu: {:.3g} units", units));
  }
  return c;
}

std::string seconds_text(double units) {
  const double seconds = units * seconds_per_cost_unit;
  if (seconds < 120) return fmt::format("{:.2g} s", seconds);
  if (seconds < 7200) return fmt::format("{:.2g} min", seconds / 60);
  return fmt::format("{:.2g} h", seconds / 3600);
}

}  // namespace simpson::verify

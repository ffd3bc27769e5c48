// The cost estimate that guards a scene against running for days: steps times the cost of a step
// in each precision, in units of one step of Φ₃ in double. Calibrated on the 2-core machine:
// the paper scene's experiments, estimated at ~3e9 units, take ~13 s (about 5 ns per unit).

#include <simpson/verify/experiment_cost.hpp>

#include "precision_cost.hpp"


#include <fmt/format.h>

#include <algorithm>

namespace simpson::verify {

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
  for (const experiment_settings::entry& section : e.entries()) {
    const section_cost cost = section.section->cost(section.settings);
    c.units += cost.units;
    c.lines.push_back(cost.line);
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

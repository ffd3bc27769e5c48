#pragma once
// The cost estimate that guards a scene against running for days, checked before anything runs.

#include <simpson/verify/experiment_section.hpp>

#include <string>
#include <vector>

namespace simpson::verify {

/// Estimated cost of a scene's experiments in double-step equivalents (one step of Φ₃ in double
/// = 1), with a line per section; compared with the budget before anything runs.
struct cost_estimate {
  double units = 0;
  std::vector<std::string> lines;
};
inline constexpr double default_cost_budget = 2.5e10;  // about 2 minutes on the 2-core machine (~5 ns per unit)

/// The claims' numeric rechecks a run makes: each claim with a numeric method draws `samples`
/// samples in each precision.
struct recheck_load {
  std::size_t numeric_claims = 0;
  unsigned samples = 0;
  std::vector<precision> precisions;
};

cost_estimate estimate_cost(const experiment_settings& e, const recheck_load& rechecks = {});

/// Seconds one cost unit takes on the 2-core machine the costs were calibrated on.
inline constexpr double seconds_per_cost_unit = 5e-9;
/// "about 15 s", "about 2.1 min", "about 3.5 h": an estimate in calibrated wall time.
std::string seconds_text(double units);


}  // namespace simpson::verify

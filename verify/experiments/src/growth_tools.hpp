#pragma once
// Round-off growth over long runs (Brouwer's law), shared by long_time's forms of Φ₃ and the
// nonlinear section's forms of the step: where a run is sampled, the growth exponent fitted to a
// running maximum, and the t and √t guides of its plot.

#include <simpson/verify/floating_tools.hpp>
#include <simpson/verify/result_model.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace simpson::verify::detail {

/// Step counts at which a run is sampled: 10 per decade from 100, and the last step.
inline std::vector<long long> log_spaced_checkpoints(long long steps) {
  std::vector<long long> out;
  for (double d = 2; d <= std::log10(static_cast<double>(steps)) + 1e-9; d += 0.1) {
    const long long k = std::llround(std::pow(10.0, d));
    if (k <= steps && (out.empty() || k > out.back())) out.push_back(k);
  }
  if (out.empty() || out.back() != steps) out.push_back(steps);
  return out;
}

/// True for 10^k steps: the rows a table keeps.
inline bool is_decade(long long steps) {
  const double d = std::log10(static_cast<double>(steps));
  return std::abs(d - std::round(d)) < 1e-9;
}

/// Where the growth fit starts: 1e5 steps, or the last two decades of a shorter run.
inline long long growth_fit_start(long long steps) {
  return static_cast<long long>(std::min(1e5, static_cast<double>(steps) / 100));
}

/// The least-squares slope of log(running maximum) against log(steps) from growth_fit_start to the
/// end: 1 for a drift, 1/2 for a random walk.
template <class Real>
Real growth_exponent(const std::vector<long long>& steps, const std::vector<Real>& running_max) {
  const long long from = growth_fit_start(steps.empty() ? 0 : steps.back());
  std::vector<Real> xs;
  std::vector<bool> use;
  for (const long long k : steps) {
    xs.push_back(Real(k));
    use.push_back(k >= from);
  }
  return log_log_slope(xs, running_max, use);
}

/// A dashed guide of slope `exponent` (log-log) through a curve's value at the fit's first step,
/// a factor 4 below it, to the end; none when that value is not positive.
template <class Real>
void add_slope_guide(panel& p, const std::string& title, double exponent, const std::vector<long long>& steps,
                     const std::vector<Real>& values, int color = 8, int dash = 2) {
  if (steps.empty()) return;
  std::size_t anchor = 0;
  while (anchor + 1 < steps.size() && steps[anchor] < growth_fit_start(steps.back())) ++anchor;
  if (!(values[anchor] > 0)) return;
  series guide(title, line_style::dashed, color, 7, dash);
  guide.reference = true;
  for (std::size_t i = anchor; i < steps.size(); ++i) {
    using std::pow;
    guide.add(figure::integer(steps[i]),
              figure::of(Real(values[anchor] / 4 * pow(Real(steps[i]) / Real(steps[anchor]), Real(exponent)))));
  }
  p.curves.push_back(guide);
}

}  // namespace simpson::verify::detail

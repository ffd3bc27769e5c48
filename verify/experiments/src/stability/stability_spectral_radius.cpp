// The stability section's plot of the spectral radius ρ(Φ) of each scheme's one-step matrix on the
// oscillator against ωh, with Φ₃'s band ends from the exact region on the axis.

#include "stability_parts.hpp"

#include <simpson/verify/readable_math.hpp>
#include <simpson/verify/scheme_style.hpp>

#include <simpson/scheme.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

namespace simpson::verify::detail {
namespace {

/// max |λ| of a 2 × 2 matrix: λ = τ ± sqrt(τ² − det), τ = trace/2.
double spectral_radius(const one_step_matrix<double>& phi) {
  const double tau = (phi.alpha + phi.delta) / 2, det = phi.alpha * phi.delta - phi.beta * phi.gamma, d = tau * tau - det;
  return d >= 0 ? std::abs(tau) + std::sqrt(d) : std::sqrt(det);
}

}  // namespace

std::vector<std::pair<double, std::string>> band_end_tics(const stability_report& region, double last) {
  std::vector<std::pair<double, std::string>> tics;
  std::vector<double> ends;
  for (const positive_root& root : region.roots) {
    const double at = std::sqrt(root.low.convert_to<double>());
    if (at >= last) continue;
    ends.push_back(at);
    tics.emplace_back(at, readable_math(omega_h_text(root)));  // "2 sqrt(2)" as "2√2", narrow enough for neighbouring tics
  }
  for (int k = 0; k <= static_cast<int>(last); ++k) {
    if (std::none_of(ends.begin(), ends.end(), [&](double at) { return std::abs(at - k) < 0.6; })) tics.emplace_back(k, std::to_string(k));
  }
  return tics;
}

void add_spectral_radius(const stability_report& region, section_result& out) {
  constexpr double last = 7;
  constexpr int points = 1400;
  panel p{"spectral radius of each scheme's one-step matrix", {"ωh (dimensionless)"}, {"ρ(Φ) = max |λ|", true}, {}, "top left"};  // the corner the curves leave empty
  // The x tics: the integers, and Φ₃'s band ends where they fall (2√2, 2√3, 2√6), read from the exact region.
  p.x.tics = band_end_tics(region, last);
  std::vector<std::string> leaves;  // where each scheme's ρ first exceeds 1 on the grid
  for (const scheme_traits& s : scheme_list) {
    // Φ₃ = Lobatto IIIA–IIIB and Φ₃ by elimination: the same matrix as simpson (the peer-schemes claim).
    if (s.id == scheme_id::simpson_elimination || s.id == scheme_id::lobatto_iiia_iiib_3) continue;
    const scheme_style style = style_of(s.id);
    series curve(std::string(s.name), line_style::lines, style.color, style.point, style.dash);
    std::string first_above;
    for (int k = 1; k <= points; ++k) {
      const double omega_h = last * k / points;
      const double rho = spectral_radius(stepper<double>(s.id, oscillator_parameters<double>{1, 1, omega_h}).matrix());
      curve.add(figure::of(omega_h), figure::of(rho));
      if (first_above.empty() && rho > 1 + 1e-9) first_above = fmt::format("{:.3f}", omega_h);
    }
    leaves.push_back(fmt::format("{} {}", s.name, first_above.empty() ? "nowhere" : "at " + first_above));
    p.curves.push_back(std::move(curve));
  }
  series unit("ρ = 1", line_style::dashed, 8, 7, 2);
  unit.reference = true;
  unit.add(figure::of(last / points), figure::of(1.0));
  unit.add(figure::of(last), figure::of(1.0));
  p.curves.push_back(std::move(unit));
  std::string bands;
  for (const stability_band& b : region.bands) {
    if (b.stable) bands += fmt::format("{}({}, {})", bands.empty() ? "" : " ∪ ", b.omega_h_from, b.omega_h_to);
  }
  out.add(plot_description{"stability_spectral_radius",
                           fmt::format("Spectral radius ρ(Φ) of each scheme's one-step matrix on the oscillator against ωh (m = ω = 1, "
                                       "computed in double). Φ₃ (simpson, the same matrix as Lobatto IIIA–IIIB and the elimination "
                                       "route) has ρ = 1 on its exact stable set {} and ρ > 1 in the gap and beyond; the x tics mark "
                                       "its band ends. Curves on ρ = 1 lie on one another. The first ωh of the grid (step {}) "
                                       "where ρ exceeds 1 + 10⁻⁹: {}. RK4 lies below 1 before it: it damps.",
                                       bands, last / points, fmt::format("{}", fmt::join(leaves, "; "))),
                           {p}, 1, 900, 520});
}

}  // namespace simpson::verify::detail

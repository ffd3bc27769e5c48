// The fpu section: the Fermi–Pasta–Ulam–Tsingou chain (fpu_chain.hpp) in double, for Simpson's
// scheme (the implicit step for a general potential), Störmer–Verlet, the implicit midpoint rule,
// Gauss–Legendre 2 and a trigonometric integrator (trigonometric_step.hpp, the peer at large ωh).
// Every implicit step is solved by the same Newton rule (16 eps of the terms); the explicit ones keep
// the force a step ends with for the next (first same as last). Force evaluations are counted.

#include <simpson/verify/fpu_section.hpp>
#include <simpson/verify/stability_section.hpp>

#include "fpu_runs.hpp"
#include "stability_parts.hpp"

#include <simpson/verify/integration_methods.hpp>
#include <simpson/verify/interruption.hpp>
#include <simpson/verify/progress.hpp>
#include <simpson/verify/scheme_style.hpp>

#include <simpson/fpu_chain.hpp>

#include <simpson/scheme.hpp>

#include <boost/math/constants/constants.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace simpson::verify {
namespace {

using detail::chain_methods;
using detail::chain_run;
using detail::run_chain;
using detail::system_type;
/// A step-size resonance: an ωh at which a method's rotation angle on the stiff springs is θ = 2π/k.
struct resonance {
  double omega_h;
  int k;
};

/// Where in (0, last] a method's rotation angle θ on the oscillator (eigenvalues e^{±iθ}, cos θ = tr Φ/2,
/// det Φ = 1 for all four) is 2π/k: the step-size resonances of Hairer, Lubich and Wanner's analysis of
/// the oscillatory energy (chapter XIII: near-conservation of I asks |sin(jθ/2)| bounded away from 0
/// for small j). Sign changes of tr Φ/2 − cos(2π/k) on a grid of 0.001, each refined by bisection in
/// double; a sign change across a pole of tr Φ (not a root) is recognised and left out.
std::vector<resonance> resonant_steps(const integration_method& m, const std::vector<int>& orders, double last) {
  const auto cos_theta = [&m](double omega_h) {
    if (!m.on_oscillator) return std::cos(omega_h);  // the trigonometric method, exact on the stiff springs: θ = ωh
    // The scheme it is on the oscillator: the implicit midpoint rule is Newmark's average acceleration.
    const one_step_matrix<double> phi = stepper<double>(*m.on_oscillator, oscillator_parameters<double>{1, 1, omega_h}).matrix();
    return (phi.alpha + phi.delta) / 2;
  };
  std::vector<resonance> out;
  for (const int k : orders) {
    const double target = std::cos(2 * boost::math::constants::pi<double>() / k);
    const auto f = [&](double omega_h) { return cos_theta(omega_h) - target; };
    const int points = static_cast<int>(std::ceil(last / 0.001));
    for (int i = 1; i < points; ++i) {
      double a = last * i / points, b = last * (i + 1) / points;
      if (!(f(a) * f(b) < 0)) continue;
      for (int it = 0; it < 80 && b - a > 0; ++it) {
        const double c = (a + b) / 2;
        if (c <= a || c >= b) break;
        (f(a) * f(c) <= 0 ? b : a) = c;
      }
      const double at = (a + b) / 2;
      if (std::abs(f(at)) < 1e-9) out.push_back({at, k});
    }
  }
  std::sort(out.begin(), out.end(), [](const resonance& x, const resonance& y) { return x.omega_h < y.omega_h; });
  return out;
}

/// θ = 2π/k in lowest terms: π/2 for k = 4, 2π/3 for k = 3.
std::string resonance_text(int k) { return k % 2 == 0 ? fmt::format("θ = π/{}", k / 2) : fmt::format("θ = 2π/{}", k); }

/// The linear stability of a method on the stiff springs alone (the soft ones are slow): Φ₃'s exact
/// region for Simpson, ωh < 2 for Störmer–Verlet, every ωh for the A-stable two. Nothing within 0.05
/// of an endpoint is predicted: the soft springs' curvature 12 d² (d, their elongation, of order 1)
/// beside the stiff springs' ω² = 2500 shifts the stiff frequency by about half a percent, so ωh by
/// at most 0.025 up to ωh = 5; 0.05 is twice that.
std::optional<bool> predicted_stable(const integration_method& m, const stability_report& region, double omega_h) {
  switch (m.id) {
    case method_id::implicit_midpoint:
    case method_id::gauss_legendre_2:
    case method_id::trigonometric: return true;
    case method_id::stormer_verlet:
      if (std::abs(omega_h - 2) < 0.05) return std::nullopt;
      return omega_h < 2;
    case method_id::simpson:
      for (const positive_root& root : region.roots) {
        if (std::abs(std::sqrt(root.low.convert_to<double>()) - omega_h) < 0.05) return std::nullopt;
      }
      for (const stability_band& band : region.bands) {
        const double from = std::sqrt(band.x_from.convert_to<double>());
        const double to = band.to ? std::sqrt(band.to->low.convert_to<double>()) : INFINITY;
        if (omega_h > from && omega_h < to) return band.stable;
      }
      break;
    case method_id::yoshida:
    case method_id::rk4: break;  // not run on the chain
  }
  return std::nullopt;
}

/// max over j and the samples of |I_j − I_j of the reference|, the reference interpolated linearly
/// at each sample's t: how far a method's exchange is from the reference's.
double exchange_gap(const chain_run& r, const chain_run& reference) {
  double gap = 0;
  const std::array<const std::vector<double>*, 3> mine{&r.I1, &r.I2, &r.I3}, theirs{&reference.I1, &reference.I2, &reference.I3};
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    const auto above = std::lower_bound(reference.t.begin(), reference.t.end(), r.t[i]);
    if (above == reference.t.end()) break;
    const std::size_t b = static_cast<std::size_t>(above - reference.t.begin()), a = b == 0 ? 0 : b - 1;
    const double w = b == a ? 0 : (r.t[i] - reference.t[a]) / (reference.t[b] - reference.t[a]);
    for (std::size_t j = 0; j < 3; ++j) {
      gap = std::max(gap, std::abs((*mine[j])[i] - ((1 - w) * (*theirs[j])[a] + w * (*theirs[j])[b])));
    }
  }
  return gap;
}

/// I₁, I₂, I₃ and I of a run against t.
panel exchange_panel(const std::string& title, const chain_run& r) {
  panel exchange{title + (r.ok() ? "" : " (" + r.status.value() + ")"), {"t"}, {"oscillatory energy"}};
  const std::array<const std::vector<double>*, 4> parts{&r.I1, &r.I2, &r.I3, &r.I};
  const std::array<const char*, 4> names{"I₁", "I₂", "I₃", "I = I₁ + I₂ + I₃"};
  for (std::size_t j = 0; j < parts.size(); ++j) {
    series c(names[j], line_style::lines, static_cast<int>(4 + j), 7, 1);
    for (std::size_t i = 0; i < r.t.size(); ++i) c.add(figure::of(r.t[i]), figure::of((*parts[j])[i]));
    exchange.curves.push_back(std::move(c));
  }
  return exchange;
}

/// A method's force evaluations per step at one scanned ωh (a stable run).
struct scanned_cost {
  double omega_h, per_step;
};

/// The ωh at which a method spends as many force evaluations per unit time as Störmer–Verlet at ωh =
/// `at` (one a step: ωh = at × per_step), from its scan: the first root of at × per_step(ωh) − ωh
/// between two scanned points, per_step interpolated linearly (so a method of one evaluation a step
/// runs at ωh = at exactly); nothing when no scanned stable step is that cheap.
std::optional<double> equal_cost_step(const std::vector<scanned_cost>& scanned, double at) {
  for (std::size_t i = 0; i + 1 < scanned.size(); ++i) {
    const double a = at * scanned[i].per_step - scanned[i].omega_h, b = at * scanned[i + 1].per_step - scanned[i + 1].omega_h;
    if (a == 0) return scanned[i].omega_h;
    if (a > 0 && b <= 0) return scanned[i].omega_h + (scanned[i + 1].omega_h - scanned[i].omega_h) * a / (a - b);
  }
  return std::nullopt;
}

/// The section's title, conventions and the chain described.
section_result fpu_intro(const fpu_settings& s) {
  section_result out;
  out.name = "fpu";
  out.title = fmt::format("A stiff problem: the Fermi–Pasta–Ulam–Tsingou chain (m = {}, ω = {})", s.m, s.omega);
  out.conventions = {{"m", s.m},
                     {"omega", s.omega},
                     {"omega_h", s.omega_h},
                     {"end_time", s.end_time},
                     {"scan", {s.scan_from, s.scan_to, s.scan_step}},
                     {"scan_end_time", s.scan_end_time},
                     {"resonances", s.resonances},
                     {"samples", s.samples}};
  out.text(fmt::format(
      "Hairer, Lubich and Wanner's chain (Geometric Numerical Integration, §I.5.1): {} unit masses, stiff linear springs "
      "of frequency ω = {} inside each pair, soft cubic springs between the pairs and to the walls, their start "
      "(x₀,₁ = 1, ẋ₀,₁ = 1, x₁,₁ = 1/ω, ẋ₁,₁ = 1). I_j = ½(ẋ₁,ⱼ² + ω² x₁,ⱼ²) is the energy of the j-th stiff spring, "
      "I = I₁ + I₂ + I₃; for the exact flow I(t) = I(0) + O(1/ω) over exponentially long times, while the I_j exchange "
      "energy on the slow time scale. The step is set by ωh of the stiff springs (the slow motion has periods of order "
      "1, so every h here resolves it). Computed in double; each implicit step is solved by Newton's method to 16 eps of "
      "its terms, from the same start.",
      2 * s.m, s.omega));
  return out;
}

/// The reference for the exchange: Gauss–Legendre 2 (order 4) at ωh = reference_omega_h over the
/// exchange's time, with its own error estimated as its gap to the same method at half its step.
struct exchange_reference {
  double time;
  chain_run run;
  double error;
};

exchange_reference reference_run(const fpu_settings& s, const system_type& chain) {
  const integration_method& gl2 = method_of(method_id::gauss_legendre_2);
  const double exchange_time = std::min(s.exchange_time, s.end_time);
  chain_run reference = run_chain(gl2, chain, s, s.reference_omega_h, exchange_time, s.samples);
  // The reference's own error, estimated as its gap to the same method at half its step.
  const double reference_error = exchange_gap(reference, run_chain(gl2, chain, s, s.reference_omega_h / 2, exchange_time, s.samples));
  return {exchange_time, std::move(reference), reference_error};
}

/// The runs followed over time, each method at each ωh: the runs and exchange tables, their panels,
/// and Simpson's runs (its second band is read from them).
struct runs_over_time {
  table runs, exchange;
  std::vector<panel> exchange_panels, error_panels;
  std::vector<chain_run> simpson_runs;
};

runs_over_time runs_over_time_tables(const fpu_settings& s, const exchange_reference& reference) {
  const double exchange_time = reference.time, reference_error = reference.error;
  table runs{"runs", fmt::format("Each method at each ωh, t up to {}", s.end_time),
             "Relative errors: max |H − H(0)|/H(0) and max |I − I(0)|/I(0) over the samples; the drift of I is its mean over "
             "the last tenth of the run minus its mean over the first tenth, over every step. I_d is I with each stiff spring's ω²x² weighted "
             "as (hamiltonien-discret) weights ω²q², by (1 − x/12)(1 − x/24)/(1 − x/8), x = (ωh)²: the form Φ₃ conserves "
             "for a spring alone, shown for Simpson. Newton: iterations per step.",
             {{"method", "method"},
              {"omega_h", "ωh", "", 0},
              {"steps", "steps"},
              {"max_energy_error", "max |ΔH|/H₀"},
              {"max_invariant_error", "max |ΔI|/I₀"},
              {"invariant_drift", "drift of I"},
              {"max_discrete_invariant_error", "max |ΔI_d|/I_d(0), Simpson's"},
              column::fixed_point("newton_per_step", "Newton / step", 2),
              {"status", "status"}}};
  table exchange{"exchange", fmt::format("The exchange against the reference, t ≤ {}", exchange_time),
                 fmt::format("max over j and t of |I_j − I_j of the reference| (Gauss–Legendre 2 at ωh = {}, interpolated at each "
                             "method's samples): 0 is the reference's exchange, about 1 an exchange out of phase. The reference's own "
                             "error, its gap to Gauss–Legendre 2 at half its step: {:.2g}.",
                             s.reference_omega_h, reference_error),
                 {{"method", "method"}, {"omega_h", "ωh", "", 0}, {"exchange_gap", "max |I_j − I_j ref|"}, {"status", "status"}}};
  return {std::move(runs), std::move(exchange), {}, {}, {}};
}

/// One method at each ωh over time: its rows, its panel of errors, its exchange against the reference.
void run_method_over_time(const integration_method& m, const fpu_settings& s, const system_type& chain, const exchange_reference& ref,
                          runs_over_time& out) {
  const std::string name(m.name);
  const double exchange_time = ref.time;
  const chain_run& reference = ref.run;
  panel errors{name, {"t"}, {"relative error", true}};
  for (std::size_t k = 0; k < s.omega_h.size(); ++k) {
    const double omega_h = s.omega_h[k];
    const chain_run r = run_chain(m, chain, s, omega_h, s.end_time, s.samples);
    progress_step(s.progress, "fpu", fmt::format("{} at ωh = {}", name, omega_h));
    // An unstable run's largest errors are those of the few samples before it stopped: left blank.
    out.runs.add({figure::text(name), figure::of(omega_h), figure::integer(r.steps), r.ok() ? figure::of(r.max_energy_error) : figure{},
                  r.ok() ? figure::of(r.max_invariant_error) : figure{}, r.ok() ? figure::of(r.invariant_drift) : figure{},
                  m.id == method_id::simpson && r.ok() ? figure::of(r.max_discrete_invariant_error) : figure::text("n/a"),
                  figure::of(static_cast<double>(r.newton_iterations) / static_cast<double>(std::max(1LL, r.steps))), r.status});
    if (m.id == method_id::simpson) out.simpson_runs.push_back(r);
    const int color = static_cast<int>(k);
    series energy(fmt::format("ωh = {}: H", omega_h), line_style::lines, color, 7, 1), invariant(fmt::format("ωh = {}: I", omega_h), line_style::lines, color, 7, 2);
    for (std::size_t i = 1; i < r.t.size(); ++i) {  // t = 0: both errors are 0
      energy.add(figure::of(r.t[i]), figure::of(r.energy_error[i]));
      invariant.add(figure::of(r.t[i]), figure::of(std::abs(r.I[i] - 1)));
    }
    errors.curves.push_back(std::move(energy));
    errors.curves.push_back(std::move(invariant));
    // The exchange: I₁, I₂, I₃ and I over the first exchange_time at the second ωh (the book's
    // hω = 1.5 when it is given), sampled densely.
    // The run itself when it ends where the exchange does (a quick scene), else a shorter one.
    const chain_run early = exchange_time < s.end_time ? run_chain(m, chain, s, omega_h, exchange_time, s.samples) : r;
    out.exchange.add({figure::text(name), figure::of(omega_h), early.ok() ? figure::of(exchange_gap(early, reference)) : figure{}, early.status});
    if (k == std::min<std::size_t>(1, s.omega_h.size() - 1)) out.exchange_panels.push_back(exchange_panel(fmt::format("{}, ωh = {}", name, omega_h), early));
  }
  out.error_panels.push_back(std::move(errors));
}

/// Which method's exchange is nearest the reference at each ωh, from the exchange table.
std::string nearest_exchange(const fpu_settings& s, const table& exchange) {
  std::vector<std::string> nearest;
  for (const double omega_h : s.omega_h) {
    std::string best;
    double best_gap = INFINITY;
    for (std::size_t r = 0; r < exchange.rows.size(); ++r) {
      if (exchange.rows[r][1].value() != figure::of(omega_h).value() || !exchange.rows[r][2].is_number()) continue;
      const double gap = std::stod(exchange.rows[r][2].value());  // computed in double
      if (gap < best_gap) {
        best_gap = gap;
        best = exchange.rows[r][0].value();
      }
    }
    if (!best.empty()) nearest.push_back(fmt::format("at ωh = {} {} ({:.2g})", omega_h, best, best_gap));
  }
  return nearest.empty() ? std::string("none") : fmt::format("{}", fmt::join(nearest, "; "));
}

/// The runs over time, their tables, the exchange and the plots of both.
runs_over_time add_runs_over_time(const fpu_settings& s, const system_type& chain, const exchange_reference& reference, section_result& out) {
  runs_over_time r = runs_over_time_tables(s, reference);
  r.exchange_panels.push_back(exchange_panel(fmt::format("reference: gauss-legendre-2, ωh = {}", s.reference_omega_h), reference.run));
  progress_step(s.progress, "fpu", "reference for the exchange");
  for (const integration_method* m : chain_methods) run_method_over_time(*m, s, chain, reference, r);
  const std::string nearest = nearest_exchange(s, r.exchange);
  out.add(std::move(r.runs));
  out.add(std::move(r.exchange));
  out.text(fmt::format(
      "Nearest the reference's exchange: {}. Against the book: its description of this problem (the stiff energy passes "
      "from I₁ to I₂ and I₃ over t ≈ 0..200 while I stays nearly constant; Störmer–Verlet is stable only for ωh < 2, the "
      "implicit midpoint rule for every ωh) is what the reference and the runs here show. The book's figures per method "
      "and step are not at hand in this project; its theory of step-size resonances is, and the scan below runs each "
      "method at its own.",
      nearest));
  out.add(plot_description{"fpu_exchange",
                           fmt::format("The stiff springs' energies I₁, I₂, I₃ and their sum I against t ≤ {}, a reference and each "
                                       "method at one ωh: the energy passes from the first spring to the others on the slow time "
                                       "scale while I stays within O(1/ω) of 1",
                                       std::min(s.exchange_time, s.end_time)),
                           r.exchange_panels, 2, 900, 900});
  out.add(plot_description{"fpu_errors",
                           "Relative energy error |H − H(0)|/H(0) (solid) and |I − I(0)| (dashed) against t, a panel per "
                           "method, a colour per ωh; a run that became unstable ends where it stopped",
                           r.error_panels, 2, 900, 620});
  return r;
}

/// The scan's table, its two panels, the resonances' points, each method's text at its resonances and
/// each method's stable grid points with their cost.
struct scan_figures {
  table scan;
  panel energy, invariant;
  series resonant_points, resonant_invariant;
  std::vector<std::string> at_resonances;  // each method's error in I at its resonances beside its scanned neighbours'
  std::vector<std::vector<scanned_cost>> costs;  // each method's stable grid points
};

scan_figures scan_tables(const fpu_settings& s, const stability_report& region) {
  table scan{"scan", fmt::format("The largest errors over t ≤ {} against ωh", s.scan_end_time), "",
             {{"method", "method"}, {"omega_h", "ωh", "", 0}, {"max_energy_error", "max |ΔH|/H₀"}, {"max_invariant_error", "max |ΔI|/I₀"},
              {"predicted", "linear theory"}, {"resonance", "resonance"}, {"status", "status"}}};
  scan.markdown = false;
  scan.csv_file = "fpu_scan.csv";
  panel scan_energy{"max |H − H(0)|/H(0)", {"ωh of the stiff springs"}, {"relative error", true}};
  panel scan_invariant{"max |I − I(0)|/I(0)", {"ωh of the stiff springs"}, {"relative error", true}};
  scan_energy.x.tics = scan_invariant.x.tics = detail::band_end_tics(region, s.scan_to);
  series resonant_points("resonance θ = 2π/k", line_style::points, 8, 6, 1);
  series resonant_invariant = resonant_points;
  return {std::move(scan), std::move(scan_energy), std::move(scan_invariant), resonant_points, std::move(resonant_invariant), {},
          std::vector<std::vector<scanned_cost>>(chain_methods.size())};
}

/// The grid, and the method's resonant ωh within it, in increasing order: ωh, and k for a resonance (0
/// for a grid point).
std::vector<std::pair<double, int>> scan_steps(const integration_method& m, const fpu_settings& s) {
  const int points = static_cast<int>(std::floor((s.scan_to - s.scan_from) / s.scan_step + 1e-9)) + 1;
  std::vector<std::pair<double, int>> steps;  // ωh, and k for a resonance (0 for a grid point)
  for (int k = 0; k < points; ++k) steps.emplace_back(std::round((s.scan_from + k * s.scan_step) * 1e9) / 1e9, 0);
  for (const resonance& r : resonant_steps(m, s.resonances, s.scan_to)) {
    if (r.omega_h < s.scan_from) continue;
    // A resonance on a grid point (Störmer–Verlet's θ = π/3 is ωh = 1) marks that point.
    const auto same = std::find_if(steps.begin(), steps.end(), [&](const auto& p) { return std::abs(p.first - r.omega_h) < 1e-9 * p.first; });
    if (same != steps.end()) same->second = r.k;
    else steps.emplace_back(r.omega_h, r.k);
  }
  std::stable_sort(steps.begin(), steps.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return steps;
}

/// Each resonance of a method against the grid points beside it (the nearest ok one on each side).
void describe_resonances(const std::string& name, const std::vector<std::pair<double, int>>& steps, const std::vector<double>& grid_invariant,
                         std::vector<std::string>& at_resonances) {
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (!steps[i].second || std::isnan(grid_invariant[i])) continue;
    std::vector<std::string> beside;
    for (const int dir : {-1, 1}) {
      for (std::size_t j = i + dir; j < steps.size(); j += dir) {
        if (steps[j].second) continue;
        if (!std::isnan(grid_invariant[j])) beside.push_back(fmt::format("{:.2g} at {}", grid_invariant[j], steps[j].first));
        break;
      }
    }
    at_resonances.push_back(fmt::format("{} {} at ωh = {:.4f}: {:.2g}{}", name, resonance_text(steps[i].second), steps[i].first,
                                        grid_invariant[i], beside.empty() ? std::string() : fmt::format(" (beside it {})", fmt::join(beside, ", "))));
  }
}

/// One method's scan: its runs at each step of its grid, its curves, and the expectation that it is
/// stable where the linear theory of its stiff springs says so.
void scan_method(std::size_t index, const integration_method& m, const fpu_settings& s, const system_type& chain,
                 const stability_report& region, scan_figures& f, section_result& out) {
  const std::string name(m.name);
  const scheme_style style = style_of(m);
  // A curve per run of stable points: a line never bridges a stretch of unstable runs (Simpson's gap).
  const series blank(name, line_style::lines_points, style.color, style.point, style.dash);
  series energy = blank, invariant = blank;
  const auto close_curve = [&] {
    if (!energy.x.empty()) {
      f.energy.curves.push_back(std::move(energy));
      f.invariant.curves.push_back(std::move(invariant));
    }
    energy = blank;
    invariant = blank;
  };
  std::size_t agree = 0, predicted_count = 0;
  std::vector<std::string> disagree;
  const std::vector<std::pair<double, int>> steps = scan_steps(m, s);
  std::vector<double> grid_invariant;  // max |ΔI|/I₀ at each step (NaN where not ok)
  for (const auto& [omega_h, order] : steps) {
    const chain_run r = run_chain(m, chain, s, omega_h, s.scan_end_time, 200);
    const std::optional<bool> stable = predicted_stable(m, region, omega_h);
    f.scan.add({figure::text(name), figure::of(omega_h), r.ok() ? figure::of(r.max_energy_error) : figure{},
                r.ok() ? figure::of(r.max_invariant_error) : figure{},
                figure::text(stable ? (*stable ? "stable" : "unstable") : "endpoint: not predicted"),
                order ? figure::text(resonance_text(order)) : figure::text(""), r.status});
    grid_invariant.push_back(r.ok() ? r.max_invariant_error : NAN);
    if (r.ok() && r.steps > 0) {
      f.costs[index].push_back({omega_h, r.gradients_per_step()});
    }
    if (r.ok()) {
      energy.add(figure::of(omega_h), figure::of(r.max_energy_error));
      invariant.add(figure::of(omega_h), figure::of(r.max_invariant_error));
      if (order) {
        f.resonant_points.add(figure::of(omega_h), figure::of(r.max_energy_error));
        f.resonant_invariant.add(figure::of(omega_h), figure::of(r.max_invariant_error));
      }
    } else {
      close_curve();
    }
    const bool unstable_run = r.status.value().rfind("unstable", 0) == 0;
    if (stable) {
      ++predicted_count;
      if (*stable == !unstable_run) ++agree;
      else disagree.push_back(fmt::format("{} ({})", omega_h, r.status.value()));
    }
  }
  progress_step(s.progress, "fpu", "scan of " + name);
  close_curve();
  describe_resonances(name, steps, grid_invariant, f.at_resonances);
  out.expect({"scan-stability-" + name,
              fmt::format("On the FPU chain, {} is stable at each scanned ωh where the linear theory of its stiff springs says so, "
                          "and unstable where it says not.",
                          name),
              m.id == method_id::simpson          ? "Φ₃'s exact region on the stiff springs' ωh (the stability section)"
              : m.id == method_id::stormer_verlet ? "ωh < 2 (Störmer–Verlet's linear stability)"
              : m.id == method_id::trigonometric  ? "stable at every ωh (the stiff springs' flow is exact)"
                                                : "stable at every ωh (A-stable)",
              fmt::format("{} of {} scanned ωh off the endpoints as predicted{}", agree, predicted_count,
                          disagree.empty() ? std::string() : "; not: " + fmt::format("{}", fmt::join(disagree, ", "))),
              agree == predicted_count});
}

/// The scan: the largest errors over a shorter run at each ωh of a grid, and the stability each
/// method's linear theory predicts for the stiff springs; returns each method's stable grid points
/// with their cost.
std::vector<std::vector<scanned_cost>> add_scan(const fpu_settings& s, const system_type& chain, const stability_report& region,
                                                section_result& out) {
  scan_figures f = scan_tables(s, region);
  for (std::size_t k = 0; k < chain_methods.size(); ++k) scan_method(k, *chain_methods[k], s, chain, region, f, out);
  out.add(std::move(f.scan));
  if (!f.resonant_points.x.empty()) {
    f.energy.curves.push_back(std::move(f.resonant_points));
    f.invariant.curves.push_back(std::move(f.resonant_invariant));
  }
  out.text(fmt::format(
      "Step-size resonances: the scan adds, for each method, the ωh where its rotation angle θ on the stiff springs (its "
      "oscillator matrix's eigenvalues e^(±iθ)) is 2π/k, k = {} (θ = π, k = 2, is Φ₃'s band end 2√2). Hairer, Lubich and "
      "Wanner's near-conservation of I asks |sin(jθ/2)| to stay away from 0 for small j; at these θ it vanishes for j = k. "
      "max |ΔI|/I₀ there, beside the scanned ωh on either side: {}.",
      fmt::join(s.resonances, ", "), f.at_resonances.empty() ? std::string("none in the scanned range") : fmt::format("{}", fmt::join(f.at_resonances, "; "))));
  out.add(plot_description{"fpu_scan",
                           fmt::format("The largest relative errors in H and in I over t ≤ {} against the stiff springs' ωh, each "
                                       "method; a method's unstable runs are left out (the scan table has them); grey circles: "
                                       "runs at a step-size resonance. The x tics mark Φ₃'s band ends.",
                                       s.scan_end_time),
                           {f.energy, f.invariant}, 2, 1000, 420});
  return std::move(f.costs);
}

/// Every method at equal cost: the force evaluations per unit time of Störmer–Verlet at each ωh of
/// equal_cost_omega_h, spent by each method on its own step.
void add_equal_cost(const fpu_settings& s, const system_type& chain, const exchange_reference& ref,
                    const std::vector<std::vector<scanned_cost>>& scanned_costs, section_result& out) {
  const double exchange_time = ref.time, reference_error = ref.error;
  const chain_run& reference = ref.run;
  table costs{"equal_cost", fmt::format("At equal cost, t ≤ {}", exchange_time),
              fmt::format("Each method's step set so that it spends as many force evaluations per unit time as Störmer–Verlet at the "
                          "ωh of the first column (one a step: ω/ωh per unit time); an implicit method's evaluations per step (its Newton "
                          "iterations' ∇V, counted as its step makes them) from the scan below, interpolated in ωh between two scanned stable steps. The trigonometric method's evaluation is of the "
                          "soft springs' ∇U alone; its stiff springs are integrated exactly, by cos and sin of ωh. ∇²V: the Newton steps' "
                          "Hessians, apart. The exchange is against the reference above, whose own error (its gap to a run at half its "
                          "step) is {:.2g}.{}",
                          reference_error, s.timed ? " The runs' seconds are in the run-time report's table \"At equal cost: run times\"." : ""),
              {{"budget", "cost of Störmer–Verlet at ωh", "", 0},
               {"method", "method"},
               {"omega_h", "ωh", "", 3},
               column::fixed_point("gradients_per_step", "∇V / step", 2),
               column::fixed_point("hessians_per_step", "∇²V / step", 2),
               {"max_energy_error", "max |ΔH|/H₀"},
               {"exchange_gap", "max |I_j − I_j ref|"},
               {"status", "status"}}};
  table cost_times{"equal_cost_seconds", "At equal cost: run times",
                   "Each run of the table \"At equal cost\" (t up to the exchange's end), its wall time on this machine, once.",
                   {{"budget", "cost of Störmer–Verlet at ωh", "", 0}, {"method", "method"}, {"seconds", "seconds", "s"}}};
  cost_times.timing = true;
  std::vector<std::string> cheapest;  // at each budget, the method nearest the reference's exchange
  for (const double at : s.equal_cost_omega_h) {
    std::string best;
    double best_gap = INFINITY, best_energy = INFINITY;
    std::string best_energy_method;
    for (std::size_t k = 0; k < chain_methods.size(); ++k) {
      const integration_method& m = *chain_methods[k];
      const std::string name(m.name);
      const std::optional<double> omega_h = equal_cost_step(scanned_costs[k], at);
      if (!omega_h) {
        const auto cheapest_step = std::min_element(scanned_costs[k].begin(), scanned_costs[k].end(), [](const scanned_cost& x, const scanned_cost& y) {
          return x.per_step / x.omega_h < y.per_step / y.omega_h;
        });
        const bool below = !scanned_costs[k].empty() && at * scanned_costs[k].front().per_step < scanned_costs[k].front().omega_h;
        costs.add({figure::of(at), figure::text(name), figure{}, figure{}, figure{}, figure{}, figure{},
                   figure::text(cheapest_step == scanned_costs[k].end() ? std::string("no stable step scanned")
                                : below ? fmt::format("its step at this cost is below the scan's first stable ωh ({})", scanned_costs[k].front().omega_h)
                                        : fmt::format("no scanned stable step this cheap: its cheapest, ωh = {}, costs {:.3g} times as much",
                                                      cheapest_step->omega_h, cheapest_step->per_step / cheapest_step->omega_h * at))});
        continue;
      }
      const chain_run r = run_chain(m, chain, s, *omega_h, exchange_time, s.samples);
      progress_step(s.progress, "fpu", fmt::format("{} at the cost of Störmer–Verlet at ωh = {}", name, at));
      const double per_step = r.gradients_per_step();
      const double gap = r.ok() ? exchange_gap(r, reference) : INFINITY;
      costs.add({figure::of(at), figure::text(name), figure::of(*omega_h), figure::of(per_step),
                 figure::of(static_cast<double>(r.hessians) / static_cast<double>(std::max(1LL, r.steps))),
                 r.ok() ? figure::of(r.max_energy_error) : figure{}, r.ok() ? figure::of(gap) : figure{}, r.status});
      cost_times.add({figure::of(at), figure::text(name), figure::of(r.seconds)});
      if (gap < best_gap) {
        best_gap = gap;
        best = name;
      }
      if (r.ok() && r.max_energy_error < best_energy) {
        best_energy = r.max_energy_error;
        best_energy_method = name;
      }
    }
    if (!best.empty()) {
      cheapest.push_back(fmt::format("at the cost of Störmer–Verlet at ωh = {}, the exchange nearest the reference's is {}'s ({:.2g}) and "
                                     "the smallest energy error {}'s ({:.2g})",
                                     at, best, best_gap, best_energy_method, best_energy));
    }
  }
  out.add(std::move(costs));
  if (s.timed) out.add(std::move(cost_times));
  if (!cheapest.empty()) out.text(fmt::format("At equal cost: {}.", fmt::join(cheapest, "; ")));
}

/// Simpson in its second band: does it keep the adiabatic invariant? Decided by the runs over time.
void add_second_band(const fpu_settings& s, const std::vector<chain_run>& simpson_runs, section_result& out) {
  std::vector<std::string> second_band;
  for (std::size_t k = 0; k < s.omega_h.size() && k < simpson_runs.size(); ++k) {
    const double x = s.omega_h[k] * s.omega_h[k];
    if (x > 12 && x < 24) {
      const chain_run& r = simpson_runs[k];
      second_band.push_back(r.ok() ? fmt::format("at ωh = {} (second band) max |ΔI|/I₀ = {:.3g} and the drift of I over the run is "
                                                 "{:.3g}; its own I_d keeps to {:.3g} relative, with a drift of {:.3g}; max |ΔH|/H₀ = {:.3g}",
                                                 s.omega_h[k], r.max_invariant_error, r.invariant_drift, r.max_discrete_invariant_error,
                                                 r.discrete_invariant_drift, r.max_energy_error)
                                   : fmt::format("at ωh = {} (second band) the run stopped: {}", s.omega_h[k], r.status.value()));
    }
  }
  if (!second_band.empty()) out.text("Simpson's scheme in its second stable band, from the runs above: " + fmt::format("{}", fmt::join(second_band, "; ")) + ".");
}

}  // namespace

fpu_run_summary run_fpu_chain(const fpu_settings& s, const std::string& method, double omega_h, double end_time) {
  const auto m = std::find_if(chain_methods.begin(), chain_methods.end(), [&](const integration_method* k) { return k->name == method; });
  if (m == chain_methods.end()) throw std::invalid_argument("run_fpu_chain: unknown method '" + method + "'");
  const system_type chain = fpu_system(s.m, s.omega);
  const chain_run r = run_chain(**m, chain, s, omega_h, end_time, 100);
  return {r.max_energy_error, r.max_invariant_error, r.invariant_drift, r.max_discrete_invariant_error, r.discrete_invariant_drift,
          r.steps, r.status.value()};
}

section_result run_fpu(const fpu_settings& s) {
  section_result out = fpu_intro(s);
  const system_type chain = fpu_system(s.m, s.omega);
  const stability_report region = simpson_exact_region();
  const exchange_reference reference = reference_run(s, chain);
  const runs_over_time over_time = add_runs_over_time(s, chain, reference, out);
  const std::vector<std::vector<scanned_cost>> costs = add_scan(s, chain, region, out);
  add_equal_cost(s, chain, reference, costs, out);
  add_second_band(s, over_time.simpson_runs, out);
  return out;
}

}  // namespace simpson::verify

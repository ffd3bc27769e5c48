// The long_time section: energy drift over 1e7 steps in double (1e5 in mpfr), bounded oscillation
// against drift, and the phase error against the frequency predicted by the exact characteristic roots.
// Every figure, including the fitted slope, is computed in the run's precision; above double the
// energy changes and phase errors are enclosed (MPFI) and carry only guaranteed digits.

#include <simpson/verify/long_time_section.hpp>
#include <simpson/verify/interruption.hpp>
#include <simpson/verify/progress.hpp>
#include <simpson/verify/scheme_style.hpp>

#include <simpson/verify/floating_tools.hpp>
#include "enclosed_figures.hpp"
#include "guarded_run.hpp"  // growth_limit
#include "long_time_parts.hpp"
#include <simpson/verify/integration_driver.hpp>

#include <simpson/energy.hpp>

#include <boost/math/constants/constants.hpp>
#include <fmt/format.h>

#include <cmath>
#include <optional>

namespace simpson::verify {
namespace {

enum class monitored_energy { hamiltonian, discrete };

struct long_run_case {
  scheme_id scheme;
  monitored_energy monitored;
};

/// Simpson watched through H_d (hamiltonien-discret), which it conserves; Newmark through H
/// (HH-exact), which it conserves; RK4 through H, which it does not.
constexpr std::array<long_run_case, 3> long_run_cases{{{scheme_id::simpson, monitored_energy::discrete},
                                                       {scheme_id::newmark, monitored_energy::hamiltonian},
                                                       {scheme_id::rk4, monitored_energy::hamiltonian}}};

const char* energy_name(monitored_energy e) { return e == monitored_energy::discrete ? "H_d" : "H"; }


struct long_run {
  table_row row;
  series drift, phase_measured, phase_predicted;  // against t, one point per window
  std::optional<expectation> drift_law;            // where the section predicts the energy's change
};

/// Above double, the run's figures enclosed: every iterate (an exact binary value) enters an interval
/// exactly, and the monitored energy, its change and the phase errors are evaluated on it in MPFI at
/// the run's own m, ω, h and matrix entries (exact values of Real), so no digit shown is a round-off
/// of the evaluation. The angle's branch crossings are the floating run's count.
struct enclosed_long_run {
  oscillator_parameters<interval> par;
  monitored_energy monitored;
  interval E0, window_max{0}, overall{0}, phase_per_step, measured_phase_error{0}, predicted_phase_error{0};

  template <class Real>
  enclosed_long_run(const oscillator_parameters<Real>& p, monitored_energy e, const one_step_matrix<Real>& phi,
                    const phase_point<Real>& y0)
      : par{detail::exact_interval(p.m()), detail::exact_interval(p.omega()), detail::exact_interval(p.h())}, monitored(e) {
    E0 = monitor(y0);
    const interval tr = detail::exact_interval(phi.alpha) + detail::exact_interval(phi.delta);
    const interval det = detail::exact_interval(phi.alpha) * detail::exact_interval(phi.delta) -
                         detail::exact_interval(phi.beta) * detail::exact_interval(phi.gamma);
    phase_per_step = atan2(interval(sqrt(interval(4 * det - tr * tr))), tr);
  }
  template <class Real>
  interval monitor(const phase_point<Real>& y) const {
    const phase_point<interval> at{detail::exact_interval(y.p), detail::exact_interval(y.q)};
    return monitored == monitored_energy::discrete ? discrete_energy(par, at) : energy(par, at);
  }
  template <class Real>
  void step(const phase_point<Real>& y) {
    window_max = enclosed_max(window_max, interval(abs(interval(monitor(y) - E0)) / E0));
  }
  /// At a window's end (j steps, `turns` branch crossings): the phase errors, and the window closed.
  template <class Real>
  void window_end(const phase_point<Real>& y, long long j, long long turns) {
    const interval two_pi = 2 * boost::math::constants::pi<interval>();
    const interval omega_t = par.omega() * par.h() * interval(j);
    const interval angle = atan2(detail::exact_interval(y.q), interval(detail::exact_interval(y.p) / (par.m() * par.omega())));
    measured_phase_error = two_pi * interval(turns) - omega_t + angle;
    predicted_phase_error = interval(j) * phase_per_step - omega_t;
    overall = enclosed_max(overall, window_max);
  }
  void window_start() { window_max = interval(0); }
};

/// Runs `steps` steps of a scheme's matrix from y_0 = (mω, 0), m = 1, ω = 1, h = θ, in windows:
/// per window the largest relative change of the monitored energy, and at each window end the phase
/// error (unwrapped angle of (q, p/(mω)) minus t) against the prediction j (φ − θ) with φ the
/// argument of the eigenvalue of Φ (the exact characteristic roots).
template <class Real>
long_run run_long(const long_run_case& c, const precision& prec, long long steps, long long windows, double theta, const progress_sink& progress) {
  using std::abs;
  using std::atan2;
  using std::sqrt;
  const oscillator_parameters<Real> par{Real(1), Real(1), Real(theta)};
  const one_step_matrix<Real> phi = stepper<Real>(c.scheme, par).matrix();
  const auto monitor = [&](const phase_point<Real>& y) -> Real {
    return c.monitored == monitored_energy::discrete ? discrete_energy(par, y) : energy(par, y);
  };
  // Eigenvalues of Φ: (tr ± sqrt(tr² − 4 det))/2; on the oscillator, complex with argument φ.
  const Real tr = phi.alpha + phi.delta, det = determinant(phi);
  const Real phase_per_step = atan2(Real(sqrt(Real(4 * det - tr * tr))), tr);
  // det Φ of the matrix as rounded in Real, exactly: each step then scales every quadratic
  // invariant by det, so rounding alone makes the energy drift linearly by about |det − 1| per step.
  const rational exact_det_minus_one = to_rational(phi.alpha) * to_rational(phi.delta) -
                                       to_rational(phi.beta) * to_rational(phi.gamma) - 1;
  const Real det_minus_one = to_real<Real>(exact_det_minus_one);
  const phase_point<Real> y0{Real(1), Real(0)};
  const long long window = std::max<long long>(1, steps / windows);
  const std::string name = fmt::format("{}-{}", traits_of(c.scheme).name, energy_name(c.monitored));
  const scheme_style style = style_of(c.scheme);
  long_run out{{}, series(name, line_style::lines, style.color, style.point, style.dash),
               // Measured as markers, predicted as a line drawn over them: where they agree, both show.
               // A phase error is the scheme's, whatever energy the run monitors: named after the scheme.
               series(fmt::format("{} measured", traits_of(c.scheme).name), line_style::points, style.color, style.point),
               series(fmt::format("{} predicted", traits_of(c.scheme).name), line_style::lines, style.color, style.point),
               std::nullopt};
  phase_point<Real> y = y0;
  Real overall(0), measured_phase_error(0), predicted_phase_error(0);
  std::vector<Real> times, maxima;
  std::optional<scoped_interval_digits> interval_digits;
  std::optional<enclosed_long_run> enclosed;
  if constexpr (detail::enclosed_above_double_v<Real>) {
    interval_digits.emplace(detail::enclosure_digits_for<Real>());
    enclosed.emplace(par, c.monitored, phi, y0);
  }
  // Every step: the energy's largest change against E(y_0) in the window, and the unwrapped angle.
  // A state past growth_limit times the amplitude (|q| + |p|/(mω) = 1 at y_0) stops the run.
  auto energy_change = relative_change_of<Real>(monitor);
  unwrapped_angle<Real> angle(2 * boost::math::constants::pi<Real>());
  bool window_closed = false;  // the enclosed window opens at the next window's first step (the last one stays read)
  auto enclosed_steps = at_steps_of([&](long long, const phase_point<Real>& z) {
    if (!enclosed) return;
    if (window_closed) enclosed->window_start();
    window_closed = false;
    enclosed->step(z);
  });
  // At each window's end (j steps): the phase errors, the window's figures, and the window closed.
  auto window_ends = at_samples_of([&](long long j, const phase_point<Real>& z) {
    if (j == 0) return;
    const Real t = Real(theta) * Real(j);
    measured_phase_error = Real(angle.two_pi * Real(angle.turns) - t) + angle.angle;
    predicted_phase_error = Real(j) * phase_per_step - t;
    const Real window_max = energy_change.window_maximum;
    overall = std::max(overall, window_max);
    times.push_back(t);
    maxima.push_back(window_max);
    if (enclosed) {
      enclosed->window_end(z, j, angle.turns);
      out.drift.add(figure::of(t), detail::enclosed_figure(enclosed->window_max));
      out.phase_measured.add(figure::of(t), detail::enclosed_figure(interval(abs(enclosed->measured_phase_error))));
      out.phase_predicted.add(figure::of(t), detail::enclosed_figure(interval(abs(enclosed->predicted_phase_error))));
      window_closed = true;
    } else {
      out.drift.add(figure::of(t), figure::of(window_max));
      out.phase_measured.add(figure::of(t), figure::of(Real(abs(measured_phase_error))));
      out.phase_predicted.add(figure::of(t), figure::of(Real(abs(predicted_phase_error))));
    }
    progress_step(progress, "long_time", fmt::format("{} {} step {}", name, prec.name(), j), static_cast<double>(j) / static_cast<double>(steps));
  });
  const stop_when_unstable stop([](const phase_point<Real>& z) { return abs(z.q) + abs(z.p) > detail::growth_limit; });
  // window_ends reads the window's maximum before energy_change's own sample hook closes the window.
  const run_end end = integrate_n_steps([&phi](const phase_point<Real>& z) { return phase_point<Real>(phi * z); }, y, steps, window,
                                        stop, window_ends, energy_change, angle, enclosed_steps);
  const figure status = end.status;
  // Drift: log-log slope of the per-window maxima against time over the second half (0: bounded,
  // 1: linear drift, 0.5: a random walk of round-off).
  std::vector<bool> use(times.size(), false);
  for (std::size_t k = times.size() / 2; k < times.size(); ++k) use[k] = true;
  const bool ran = !status.is_fault();
  // The figures of the energy change and the phase: enclosed above double, the run's own in double.
  figure largest = figure::of(overall), last = figure::of(maxima.empty() ? Real(0) : maxima.back()),
         measured = figure::of(measured_phase_error), predicted = figure::of(predicted_phase_error),
         ratio = figure::of(Real(measured_phase_error / predicted_phase_error));
  if (enclosed) {
    largest = detail::enclosed_figure(enclosed->overall);
    last = detail::enclosed_figure(enclosed->window_max);
    measured = detail::enclosed_figure(enclosed->measured_phase_error);
    predicted = detail::enclosed_figure(enclosed->predicted_phase_error);
    ratio = detail::enclosed_figure(interval(enclosed->measured_phase_error / enclosed->predicted_phase_error));
  }
  // The drift law, for the runs whose exact map conserves the energy watched (Simpson's H_d,
  // Newmark's H): each step of the rounded matrix multiplies its own invariant quadratic form, within
  // O(eps) of the watched energy, by det Φ, so the energy drifts linearly, by |detⁿ − 1| after n steps
  // (here n d (1 + (n − 1) d / 2), d = det Φ − 1; the next term is (n d)²/6 relative, and the law is
  // used where |n d| < 1e-3). Beside it the round-off of each step moves the energy like a random walk,
  // typically eps √n. The law is predicted where it is at least 100 times that walk, and the run's
  // drift slope must then be linear's. Its size is shown beside the measured change, not judged: the
  // remainder is the rounding's bias, which no bound here makes small (measured 0.15% of the law).
  const Real slope = log_log_slope(times, maxima, use);
  const Real n(steps), root_n = sqrt(n), unit = eps<Real>();
  const Real nd = n * det_minus_one, law = abs(Real(nd * (1 + (n - 1) * det_minus_one / 2)));
  if (ran && c.scheme != scheme_id::rk4 && abs(nd) < Real(1e-3) && law >= 100 * unit * root_n) {
    const std::string measured_class = energy_drift_class(static_cast<double>(slope));
    out.drift_law = expectation{
        fmt::format("drift-law-{}-{}", traits_of(c.scheme).name, prec.name()),
        fmt::format("In {}, {}'s {} drifts linearly in t, by the rounded matrix's |detⁿ − 1|, above the round-off's random walk.",
                    prec.name(), traits_of(c.scheme).name, energy_name(c.monitored)),
        fmt::format("linear: |detⁿ − 1| = {} (det Φ − 1 = {}, from the rounded entries exactly; n = {}) is at least 100 times the "
                    "random walk's eps √n = {}",
                    simpson::to_string(law, 4), simpson::to_string(det_minus_one, 4), steps, simpson::to_string(Real(unit * root_n), 2)),
        fmt::format("{}: drift slope {} (log-log, second half); largest relative change {} against the law's {}", measured_class,
                    simpson::to_string(slope, 3), simpson::to_string(overall, 4), simpson::to_string(law, 4)),
        measured_class == "linear"};
  }
  out.row = {figure::text(std::string(traits_of(c.scheme).name)),
             figure::text(energy_name(c.monitored)),
             figure::text(prec.name()),
             figure::integer(steps),
             ran ? largest : status,
             ran ? last : figure{},
             ran ? figure::of(slope) : figure{},
             figure::of(det_minus_one),
             figure::of(Real(abs(det_minus_one) * Real(steps))),
             figure::of(Real(phase_per_step / Real(theta))),
             ran ? measured : figure{},
             ran ? predicted : figure{},
             ran ? ratio : figure{},
             status};
  return out;
}

}  // namespace

std::string energy_drift_class(double slope) {
  return slope < 0.25 ? "bounded" : slope < 0.75 ? "random walk" : slope < 1.5 ? "linear" : "faster than linear";
}

section_result run_long_time(const long_time_settings& s) {
  section_result out;
  out.name = "long_time";
  out.title = "Long runs: energy drift and phase error";
  out.conventions = {{"m", 1}, {"omega", 1}, {"omega_h", s.omega_h}, {"windows", s.windows}};
  table rows{"rows", "",
             fmt::format(
                 "m = ω = 1, ωh = {}, y₀ = (mω, 0), steps of each scheme's one-step matrix; {} windows. Drift slope: "
                 "least-squares slope of log(per-window maximum of |E(y_j) − E(y₀)|/E(y₀)) against log t over the second "
                 "half (≈ 0 bounded oscillation, 1 linear drift, 0.5 round-off random walk). Phase error: the unwrapped "
                 "angle of (q, p/(mω)) minus ωt at the end, against (φ/h − ω)t with φ the argument of the exact "
                 "characteristic root of Φ. Above double the energy changes and the phase errors are enclosures (MPFI): each "
                 "iterate, an exact binary value, with the energy evaluated on it at the run's own m, ω, h and the phase "
                 "from the rounded matrix's exact entries, so every digit shown is guaranteed (report.json gives each "
                 "radius); the drift slope is a least-squares statistic of the run's own values.\n\n"
                 "The matrices are rounded to the working precision, so det Φ (computed exactly from the rounded entries, "
                 "then shown in the run's precision) is 1 only to within round-off: each step multiplies every quadratic "
                 "invariant by det Φ, a drift of about |det Φ − 1| per step that the table compares with the measured one. "
                 "RK4's own det is 1 − θ⁶/72 + …",
                 simpson::to_string(s.omega_h, 3), s.windows),
             {{"scheme", "scheme"},
              {"monitored", "energy"},
              {"precision", "precision"},
              {"steps", "steps"},
              {"max_relative_energy_change", "max rel. change"},
              {"last_window_max", "last window max"},
              {"drift_slope_log_log", "drift slope"},
              {"rounded_matrix_det_minus_one", "det Φ − 1 (rounded Φ, exact)"},
              {"drift_predicted_by_rounded_det", "drift from det"},
              {"numerical_frequency_over_omega", "ω_h/ω", "", 8},
              {"phase_error_measured", "phase error"},
              {"phase_error_predicted", "predicted"},
              {"measured_over_predicted", "ratio"},
              {"status", "status"}}};
  std::vector<panel> energy_panels, phase_panels;
  // No structured bindings here: clang 14 cannot capture them in the lambdas below.
  for (const std::pair<precision, long long>& run : {std::pair{precision::parse("double"), s.steps_double},
                                                      std::pair{precision::mpfr_digits(s.mpfr_digits), s.steps_mpfr}}) {
    const precision& prec = run.first;
    const long long steps = run.second;
    panel energy_panel{"Energy drift, " + prec.name(), {"t (units of 1/ω)", true}, {"per-window max |E - E_0|/E_0", true}, {},
                       "bottom right"};
    panel phase_panel{"Phase error, " + prec.name(), {"t (units of 1/ω)", true}, {"|phase error| (rad)", true}, {},
                      "top left"};
    for (const long_run_case& c : long_run_cases) {
      long_run r = visit_floating(prec, [&](auto tag) {
        using Real = typename decltype(tag)::type;
        return run_long<Real>(c, prec, steps, s.windows, s.omega_h, s.progress);
      });
      rows.add(std::move(r.row));
      if (r.drift_law) out.expect(std::move(*r.drift_law));
      energy_panel.curves.push_back(std::move(r.drift));
      phase_panel.curves.push_back(std::move(r.phase_measured));
      phase_panel.curves.push_back(std::move(r.phase_predicted));
    }
    energy_panels.push_back(std::move(energy_panel));
    phase_panels.push_back(std::move(phase_panel));
  }
  out.add(std::move(rows));
  out.add(plot_description{"long_time_energy", "Per-window maximum relative energy change against time (log-log)",
                           energy_panels, 2, 1100, 450});
  out.add(plot_description{"long_time_phase",
                           "|Phase error| against time (log-log), measured (markers) and predicted by the characteristic roots (lines)",
                           phase_panels, 2, 1100, 450});
  detail::add_long_time_forms(s, out);
  return out;
}

}  // namespace simpson::verify

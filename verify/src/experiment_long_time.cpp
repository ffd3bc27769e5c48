// The long_time section: energy drift over 1e7 steps in double (1e5 in mpfr), bounded oscillation
// against drift, and the phase error against the frequency predicted by the exact characteristic roots.

#include <simpson/verify/experiments.hpp>
#include <simpson/verify/interruption.hpp>

#include "figures.hpp"
#include "schemes.hpp"

#include <simpson/energy.hpp>

#include <boost/math/constants/constants.hpp>
#include <fmt/format.h>

#include <cmath>

namespace simpson::verify {
namespace {

using detail::figure;
using detail::figure_text;

struct long_run {
  json row;
  std::string data;  // window end time, window max drift, phase error measured, phase error predicted
};

/// Runs `steps` steps of a scheme's matrix from y_0 = (mω, 0), m = 1, ω = 1, h = θ, in windows:
/// per window the largest relative change of the monitored energy, and at each window end the phase
/// error (unwrapped angle of (q, p/(mω)) minus t) against the prediction j (φ − θ) with φ the
/// argument of the eigenvalue of Φ (the exact characteristic roots).
template <class Real>
long_run run_long(const std::string& scheme, const std::string& monitored, const precision& prec, long long steps,
                  long long windows, double theta) {
  using std::abs;
  using std::atan2;
  using std::log;
  using std::sqrt;
  const oscillator_parameters<Real> par{Real(1), Real(1), Real(theta)};
  const one_step_matrix<Real> phi = detail::scheme_runner<Real>(scheme, par).matrix();
  const auto monitor = [&](const phase_point<Real>& y) -> Real {
    return monitored == "H_d" ? discrete_energy(par, y) : energy(par, y);
  };
  // Eigenvalues of Φ: (tr ± sqrt(tr² − 4 det))/2; on the oscillator, complex with argument φ.
  const Real tr = phi.alpha + phi.delta, det = determinant(phi);
  const Real phase_per_step = atan2(Real(sqrt(Real(4 * det - tr * tr))), tr);
  // det Φ of the matrix as rounded in Real, exactly: each step then scales every quadratic
  // invariant by det, so rounding alone makes the energy drift linearly by about |det − 1| per step.
  const rational exact_det_minus_one = detail::to_rational(phi.alpha) * detail::to_rational(phi.delta) -
                                       detail::to_rational(phi.beta) * detail::to_rational(phi.gamma) - 1;
  const phase_point<Real> y0{Real(1), Real(0)};
  const Real E0 = monitor(y0);
  const long long window = std::max<long long>(1, steps / windows);
  phase_point<Real> y = y0;
  Real window_max(0), overall(0), angle_previous(0), unwrapped(0);
  const Real two_pi = 2 * boost::math::constants::pi<Real>();
  std::vector<double> times, maxima;
  std::string data;
  Real measured_phase_error(0), predicted_phase_error(0);
  for (long long j = 1; j <= steps; ++j) {
    if ((j & 0xFFFFF) == 0) throw_if_interrupted();  // every ~1e6 steps: a few ms in double
    y = phi * y;
    window_max = std::max(window_max, Real(abs(Real(monitor(y) - E0)) / E0));
    // Unwrap the angle of (q, p): it advances by about θ per step (< π), so steps of the branch are detected.
    const Real angle = atan2(y.q, y.p);
    Real delta = angle - angle_previous;
    while (delta > two_pi / 2) delta -= two_pi;
    while (delta < -two_pi / 2) delta += two_pi;
    unwrapped += delta;
    angle_previous = angle;
    if (j % window == 0 || j == steps) {
      const Real t = Real(theta) * Real(j);
      measured_phase_error = unwrapped - t;
      predicted_phase_error = Real(j) * phase_per_step - t;
      overall = std::max(overall, window_max);
      times.push_back(static_cast<double>(t));
      maxima.push_back(static_cast<double>(window_max));
      data += fmt::format("{} {} {} {}\n", simpson::to_string(static_cast<double>(t), 6),
                          detail::plot_value(figure(window_max)), detail::plot_value(figure(measured_phase_error)),
                          detail::plot_value(figure(predicted_phase_error)));
      window_max = 0;
    }
  }
  // Drift: log-log slope of the per-window maxima against time over the second half (0: bounded,
  // 1: linear drift, 0.5: a random walk of round-off).
  std::vector<bool> use(times.size(), false);
  for (std::size_t k = times.size() / 2; k < times.size(); ++k) use[k] = true;
  const double slope = detail::log_log_slope(times, maxima, use);
  const double ratio = static_cast<double>(measured_phase_error / predicted_phase_error);
  long_run out;
  out.row = {{"scheme", scheme},
             {"monitored", monitored},
             {"precision", prec.name()},
             {"steps", steps},
             {"omega_h", theta},
             {"max_relative_energy_change", figure(overall)},
             {"last_window_max", figure(Real(maxima.empty() ? 0.0 : maxima.back()))},
             {"drift_slope_log_log", figure(slope)},
             {"rounded_matrix_det_minus_one", figure(static_cast<double>(exact_det_minus_one))},
             {"drift_predicted_by_rounded_det", figure(std::abs(static_cast<double>(exact_det_minus_one)) * static_cast<double>(steps))},
             {"numerical_frequency_over_omega", figure(Real(phase_per_step / Real(theta)))},
             {"phase_error_measured", figure(measured_phase_error)},
             {"phase_error_predicted", figure(predicted_phase_error)},
             {"measured_over_predicted", figure(ratio)}};
  out.data = data;
  return out;
}

}  // namespace

section_output run_long_time(const long_time_settings& s) {
  section_output out;
  out.name = "long_time";
  std::string md = fmt::format(
      "## Long runs: energy drift and phase error\n\nm = ω = 1, ωh = {}, y₀ = (mω, 0), steps of each scheme's one-step "
      "matrix; {} windows. Drift slope: least-squares slope of log(per-window maximum of |E(y_j) − E(y₀)|/E(y₀)) against "
      "log t over the second half (≈ 0 bounded oscillation, 1 linear drift, 0.5 round-off random walk). Phase error: the "
      "unwrapped angle of (q, p/(mω)) minus ωt at the end, against (φ/h − ω)t with φ the argument of the exact "
      "characteristic root of Φ.\n\n"
      "The matrices are rounded to the working precision, so det Φ (computed exactly from the rounded entries) is 1 "
      "only to within round-off: each step multiplies every quadratic invariant by det Φ, a drift of about "
      "|det Φ − 1| per step that the table compares with the measured one. RK4's own det is 1 − θ⁶/72 + …\n\n"
      "| scheme | energy | precision | steps | max rel. change | drift slope | det Φ − 1 (rounded Φ, exact) | "
      "drift from det | ω_h/ω | phase error | predicted | ratio |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n",
      simpson::to_string(s.omega_h, 3), s.windows);
  json rows = json::array();
  const std::vector<std::pair<std::string, std::string>> runs{{"simpson", "H_d"}, {"newmark", "H"}, {"rk4", "H"}};
  std::vector<std::string> blocks;
  // No structured bindings here: clang 14 cannot capture them in the lambdas below.
  for (const std::pair<precision, long long>& run : {std::pair{precision::parse("double"), s.steps_double},
                                                      std::pair{precision::mpfr_digits(s.mpfr_digits), s.steps_mpfr}}) {
    const precision& prec = run.first;
    const long long steps = run.second;
    std::string data = "# blocks: " + prec.name() + " simpson H_d, newmark H, rk4 H; columns t max_drift phase_measured phase_predicted\n";
    for (const auto& scheme_and_energy : runs) {
      const std::string& scheme = scheme_and_energy.first;
      const std::string& monitored = scheme_and_energy.second;
      const long_run r = detail::visit_floating(prec, [&](auto tag) {
        using Real = typename decltype(tag)::type;
        return run_long<Real>(scheme, monitored, prec, steps, s.windows, s.omega_h);
      });
      rows.push_back(r.row);
      data += r.data + "\n\n";
      const json& w = r.row;
      md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", scheme, monitored, prec.name(), steps,
                        figure_text(w["max_relative_energy_change"]), figure_text(w["drift_slope_log_log"]),
                        figure_text(w["rounded_matrix_det_minus_one"]), figure_text(w["drift_predicted_by_rounded_det"]), figure_text(w["numerical_frequency_over_omega"]),
                        figure_text(w["phase_error_measured"]), figure_text(w["phase_error_predicted"]),
                        figure_text(w["measured_over_predicted"]));
    }
    std::string tag = prec.name();
    tag.erase(std::remove(tag.begin(), tag.end(), ':'), tag.end());
    out.files.push_back({"long_time_" + tag + ".dat", data});
    blocks.push_back(tag);
  }
  out.data["conventions"] = {{"m", 1}, {"omega", 1}, {"omega_h", s.omega_h}, {"windows", s.windows}};
  out.data["rows"] = rows;
  const std::string names = "'Simpson-H_d Newmark-H RK4-H'";
  std::string energy_plot = "names = " + names +
                            "\nset multiplot layout 1,2\nset logscale xy\nset format y '10^{%L}'\nset format x '10^{%L}'\n"
                            "set xlabel 't (units of 1/omega)'\nset ylabel 'per-window max |E - E_0|/E_0'\nset key bottom right\n";
  std::string phase_plot = "names = " + names +
                           "\nset multiplot layout 1,2\nset logscale x\nset format x '10^{%L}'\nset xlabel 't (units of 1/omega)'\n"
                           "set ylabel 'phase error (rad)'\nset key top left\n";
  for (const std::string& b : blocks) {
    energy_plot += fmt::format("set title 'Energy drift, {}'\nplot for [i=0:2] 'long_time_{}.dat' index i u 1:($2 > 0 ? $2 : NaN) "
                               "w l lc i+1 t word(names, i+1)\n", b, b);
    phase_plot += fmt::format("set title 'Phase error, {}'\nplot for [i=0:2] 'long_time_{}.dat' index i u 1:3 w l lc i+1 "
                              "t word(names, i+1).' measured', for [i=0:2] '' index i u 1:4 w l dt 2 lc i+1 "
                              "t word(names, i+1).' predicted'\n", b, b);
  }
  out.plots.push_back({"long_time_energy", "Per-window maximum relative energy change against time (log-log)",
                       energy_plot + "unset multiplot\n", 1100, 450});
  out.plots.push_back({"long_time_phase", "Phase error against time, measured (solid) and predicted by the characteristic roots (dashed)",
                       phase_plot + "unset multiplot\n", 1100, 450});
  out.markdown = md + "\n![energy drift](long_time_energy.svg)\n\n![phase error](long_time_phase.svg)\n\n";
  return out;
}

}  // namespace simpson::verify

// The work_precision section: error against run time for the Simpson scheme and its peers, in
// several precisions, each scheme advancing by its own step algorithm.

#include <simpson/verify/work_precision_section.hpp>
#include <simpson/verify/interruption.hpp>
#include <simpson/verify/progress.hpp>
#include <simpson/verify/scheme_style.hpp>

#include <simpson/verify/floating_tools.hpp>
#include "enclosed_figures.hpp"
#include "timed_runs.hpp"

#include <simpson/energy.hpp>
#include <simpson/exact_solution.hpp>
#include <simpson/iterate.hpp>

#include <boost/math/constants/constants.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>

namespace simpson::verify {
namespace {

struct measured_run {
  table_row row;         // the figures of the error run
  table_row timing_row;  // runs, minimum and median time (empty when nothing is timed)
  figure error;          // max of the q error and the scaled p error (a fault when the run has one)
  figure seconds;        // minimum run time
};

/// The exact solution at t_j = j/N (ω = 2π, y₀ = (mω, 0) exactly): q(t_j) = sin(2π t_j) and
/// p(t_j)/(mω) = cos(2π t_j), enclosed (p holds p/(mω)). Empty in double.
using enclosed_solution = std::vector<phase_point<interval>>;

enclosed_solution enclose_exact_solution(long long N, long long periods) {
  enclosed_solution out;
  const interval two_pi = 2 * boost::math::constants::pi<interval>();
  const long long steps = N * periods;
  out.reserve(static_cast<std::size_t>(steps) + 1);
  for (long long j = 0; j <= steps; ++j) {
    if ((j & 1023) == 0) throw_if_interrupted();  // minutes in high precision at large N
    const interval angle = two_pi * interval(j * periods) / interval(steps);
    out.push_back({interval(cos(angle)), interval(sin(angle))});
  }
  return out;
}

/// The row's error and energy figures: the largest errors in q and p/(mω), the relative change of H
/// at the end, and of H_d for the Simpson family (else empty); in Scalar, the run's own precision or
/// intervals above double (figure_of makes the figure).
template <class Scalar, class FigureOf>
void add_error_figures(measured_run& out, bool simpson_family, const Scalar& error_q, const Scalar& error_p,
                       const oscillator_parameters<Scalar>& par, const phase_point<Scalar>& first, const phase_point<Scalar>& last,
                       FigureOf&& figure_of) {
  using std::abs;
  out.row.push_back(figure_of(error_q));
  out.row.push_back(figure_of(error_p));
  const Scalar E0 = energy(par, first);
  out.row.push_back(figure_of(Scalar(abs(Scalar(energy(par, last) - E0)) / E0)));
  if (simpson_family) {
    const Scalar Ed0 = discrete_energy(par, first);
    out.row.push_back(figure_of(Scalar(abs(Scalar(discrete_energy(par, last) - Ed0)) / abs(Ed0))));
  } else {
    out.row.push_back(figure{});
  }
}

template <class Real>
measured_run measure(scheme_id scheme, const precision& prec, long long N, long long periods,
                     const timing_policy& timing, bool benchmark, const std::vector<phase_point<Real>>& exact,
                     const enclosed_solution& enclosed_exact) {
  using std::abs;
  const Real omega = 2 * boost::math::constants::pi<Real>();
  const long long steps = N * periods;
  const oscillator_parameters<Real> par{Real(1), omega, step_size(Real(periods), steps)};
  const phase_point<Real> y0{Real(par.m() * omega), Real(0)};
  const stepper<Real> runner(scheme, par);

  // The error run (not timed): maxima over every t_j against the exact solution.
  Real error_q(0), error_p(0);
  phase_point<Real> y = y0;
  figure status = figure::text("ok");
  const Real amplitude = abs(y0.p) / (par.m() * omega);
  // Above double, the same maxima enclosed: each iterate (an exact binary value) against the
  // enclosed exact solution, so the figures carry only guaranteed digits.
  const bool enclosed = !enclosed_exact.empty();
  interval enclosed_q(0), enclosed_p(0);
  const interval m_omega = enclosed ? interval(2 * boost::math::constants::pi<interval>() * detail::exact_interval(par.m())) : interval(0);
  try {
    for (long long j = 1; j <= steps; ++j) {
      if ((j & 1023) == 0) throw_if_interrupted();
      y = runner.step(y);
      const Real eq = abs(Real(y.q - exact[static_cast<std::size_t>(j)].q));
      const Real ep = abs(Real(y.p - exact[static_cast<std::size_t>(j)].p)) / (par.m() * omega);
      if (!(eq == eq) || !(ep == ep)) {
        status = figure::fault("non-finite");
        break;
      }
      if (eq > 1000000 * amplitude) {
        status = unstable_at(j);
        break;
      }
      error_q = std::max(error_q, eq);
      error_p = std::max(error_p, ep);
      if constexpr (detail::enclosed_above_double_v<Real>) {
        if (enclosed) {
          const phase_point<interval>& e = enclosed_exact[static_cast<std::size_t>(j)];
          enclosed_q = enclosed_max(enclosed_q, abs(interval(detail::exact_interval(y.q) - e.q)));
          enclosed_p = enclosed_max(enclosed_p, abs(interval(detail::exact_interval(y.p) / m_omega - e.p)));
        }
      }
    }
  } catch (const std::domain_error& e) {
    status = figure::fault(std::string("failed: ") + e.what());
  }
  // At the round-off floor: within 100 N eps of zero (N steps, each rounding a few times).
  const Real floor_level = 100 * Real(steps) * eps<Real>();
  const table_row key{figure::text(std::string(traits_of(scheme).name)), figure::text(prec.name()), figure::integer(N)};
  measured_run out{key, {}, status, status};
  out.row.push_back(figure::integer(steps));
  out.row.push_back(status);
  if (status.is_fault()) {
    for (int k = 0; k < 5; ++k) out.row.push_back(figure{});
    if (timing.max_runs > 0) out.timing_row = {key[0], key[1], key[2], figure{}, figure{}, figure{}};
    if (timing.max_runs > 0 && benchmark) out.timing_row.push_back(figure{});
    return out;
  }
  const bool simpson_family = scheme == scheme_id::simpson || scheme == scheme_id::simpson_elimination;
  if (enclosed) {
    if constexpr (detail::enclosed_above_double_v<Real>) {
      // The energies at the run's own parameters (m, ω and h as rounded in Real, exact values).
      const oscillator_parameters<interval> at{detail::exact_interval(par.m()), detail::exact_interval(par.omega()),
                                               detail::exact_interval(par.h())};
      add_error_figures(out, simpson_family, enclosed_q, enclosed_p, at, {detail::exact_interval(y0.p), detail::exact_interval(y0.q)},
                        {detail::exact_interval(y.p), detail::exact_interval(y.q)}, detail::enclosed_figure);
      const interval error_both = enclosed_max(enclosed_q, enclosed_p);
      out.row.push_back(figure::flag(upper(error_both) <= lower(detail::exact_interval(floor_level))));
      out.error = detail::enclosed_figure(error_both);
    }
  } else {
    add_error_figures(out, simpson_family, error_q, error_p, par, y0, y, [](const Real& v) { return figure::of(v); });
    const Real error = std::max(error_q, error_p);
    out.row.push_back(figure::flag(error <= floor_level));
    out.error = figure::of(error);
  }
  if (timing.max_runs == 0) return out;

  // Timing: one warm-up run, then runs until max_runs or max_seconds; each run is `steps` steps.
  const detail::run_times times = detail::time_runs(timing, [&] {
    phase_point<Real> z = y0;
    for (long long j = 0; j < steps; ++j) z = runner.step(z);
    return static_cast<double>(z.q);
  });
  out.timing_row = {key[0], key[1], key[2], figure::integer(times.runs), figure::of(times.minimum), figure::of(times.median)};
  if (benchmark) out.timing_row.push_back(figure::of(static_cast<double>(steps) / times.minimum));
  out.seconds = figure::of(times.minimum);
  return out;
}

}  // namespace

section_result run_work_precision(const work_precision_settings& s) {
  section_result out;
  out.name = "work_precision";
  const bool timed = s.timing.max_runs > 0;
  out.title = timed ? "Work against precision: error and run time" : "Work against precision: error (not timed)";
  out.conventions = {{"m", 1}, {"omega", "2 pi"}, {"periods", s.periods}, {"start", "y_0 = (m omega, 0)"}};
  out.timing_conventions = {{"warm_up_runs", 1}, {"max_runs", s.timing.max_runs}, {"max_seconds", s.timing.max_seconds}};
  table rows{"rows", "",
             fmt::format(
                 "m = 1, ω = 2π, {} period(s), y₀ = (mω, 0); N steps per period. Each scheme advances by its own step "
                 "algorithm: Simpson by its explicit map Φ₃ (the paper's form for the oscillator: one 2 × 2 product per "
                 "step), simpson-elimination by Section 6's elimination of the internal node at every step, Newmark as the "
                 "implicit midpoint rule, Gauss–Legendre and Lobatto IIIA–IIIB by solving their (linear) stage equations at "
                 "every step, Störmer–Verlet, Yoshida and RK4 explicitly. Errors: maxima over all t_j of |q_j − q(t_j)| and "
                 "|p_j − p(t_j)|/(mω), computed in the run's precision; the relative error of H (and of H_d for Simpson) at "
                 "the end. Above double the error and energy figures are enclosures (MPFI): each iterate, an exact binary "
                 "value, against the exact solution at t_j = j/N with 2π enclosed, and the energies at the run's own "
                 "rounded m, ω, h; only guaranteed digits are shown, with the radius where fewer than three are. {} "
                 "A run whose state is not finite, grows past 10⁶ times the amplitude (unstable, with the step), or throws "
                 "is recorded with its status. At the round-off floor: error ≤ 100 N eps. On this linear problem every "
                 "scheme could be reduced to a 2 × 2 matrix and cost the same per step; the peers run their general "
                 "algorithms, as for any force.",
                 s.periods,
                 timed ? "Run times, and how they are measured, are in timing.md." : "Not timed (--no-timing)."),
             {{"scheme", "scheme"},
              {"precision", "precision"},
              {"N_per_period", "N"},
              {"steps", "steps"},
              {"status", "status"},
              {"error_q_max", "error q"},
              {"error_p_max_over_m_omega", "error p/(mω)"},
              {"error_H_end_relative", "H rel. (end)"},
              {"error_Hd_end_relative", "H_d rel. (end)"},
              {"at_round_off_floor", "at floor"}}};
  rows.csv_file = "work_precision.csv";
  table times{"timing_rows", "Run time of each configuration",
              fmt::format("One warm-up run, then runs until {} runs or {} s (steady_clock); each run is the N × periods steps "
                          "of the error run, without the error computation.",
                          s.timing.max_runs, simpson::to_string(s.timing.max_seconds, 3)),
              {{"scheme", "scheme"}, {"precision", "precision"}, {"N_per_period", "N"}, {"runs", "runs"},
               {"min_seconds", "min time", "s"}, {"median_seconds", "median time", "s"}}};
  if (s.benchmark) times.columns.push_back({"steps_per_second", "steps/s"});
  times.csv_file = "work_precision_time.csv";
  times.timing = true;
  std::vector<panel> by_time, by_n;
  for (const precision& prec : s.precisions) {
    const std::string error_label = "max error of q and p/(mω)";  // error_max: the larger of the two
    panel time_panel{prec.name(), {"run time (s, minimum of repeats)", true}, {error_label, true}, {}, "bottom left"};
    panel n_panel{prec.name(), {"N (steps per period)", true}, {error_label, true}, {}, "bottom left"};
    visit_floating(prec, [&](auto precision_tag) {
      using Real = typename decltype(precision_tag)::type;
      // The exact solution at every t_j of each N, shared by the schemes; above double, enclosed too
      // (in enough digits to hold Real's values exactly).
      std::map<long long, std::vector<phase_point<Real>>> exact_by_N;
      std::map<long long, enclosed_solution> enclosed_by_N;
      std::optional<scoped_interval_digits> interval_digits;
      if constexpr (detail::enclosed_above_double_v<Real>) interval_digits.emplace(detail::enclosure_digits_for<Real>());
      for (const long long N : s.meshes) {
        if constexpr (detail::enclosed_above_double_v<Real>) enclosed_by_N[N] = enclose_exact_solution(N, s.periods);
        const Real omega = 2 * boost::math::constants::pi<Real>();
        const long long steps = N * s.periods;
        const oscillator_parameters<Real> par{Real(1), omega, step_size(Real(s.periods), steps)};
        const phase_point<Real> y0{omega, Real(0)};
        std::vector<phase_point<Real>>& exact = exact_by_N[N];
        exact.reserve(static_cast<std::size_t>(steps) + 1);
        for (long long j = 0; j <= steps; ++j) {
          if ((j & 1023) == 0) throw_if_interrupted();
          exact.push_back(exact_solution(par, y0, Real(par.h() * Real(j))));
        }
      }
      for (std::size_t k = 0; k < s.schemes.size(); ++k) {
        const scheme_id scheme = s.schemes[k];
        const scheme_style style = style_of(scheme);
        series by_seconds{std::string(traits_of(scheme).name), style.line, style.color, style.point, style.dash};
        series by_mesh = by_seconds;
        for (const long long N : s.meshes) {
          measured_run m = measure<Real>(scheme, prec, N, s.periods, s.timing, s.benchmark, exact_by_N[N], enclosed_by_N[N]);
          progress_step("work_precision", fmt::format("{} {} N = {}", traits_of(scheme).name, prec.name(), N));
          if (timed) by_seconds.add(m.seconds, m.error);
          by_mesh.add(figure::integer(N), m.error);
          rows.add(std::move(m.row));
          if (timed) times.add(std::move(m.timing_row));
        }
        time_panel.curves.push_back(by_seconds);
        n_panel.curves.push_back(by_mesh);
      }
      // Guides: slopes N^-2 and N^-4, a factor 4 below the first Newmark and Simpson errors (so that
      // they run beside the curves, not on them), and the round-off floor.
      for (const auto& [order, anchor_scheme] : {std::pair{2, scheme_id::newmark}, std::pair{4, scheme_id::simpson}}) {
        const auto anchor = std::find(s.schemes.begin(), s.schemes.end(), anchor_scheme);
        if (anchor == s.schemes.end() || s.meshes.empty()) continue;
        const series& anchored = n_panel.curves[static_cast<std::size_t>(anchor - s.schemes.begin())];
        const auto e0 = anchored.y.front().plottable();
        if (!e0 || !(*e0 > 0)) continue;
        const series slope = slope_guide(fmt::format("slope N^{{-{}}}", order), order == 2 ? 8 : 9,
                                         static_cast<double>(s.meshes.front()), *e0 / 4, s.meshes, order);
        n_panel.curves.push_back(slope);
      }
      series floor_line{"round-off floor 100 N eps", line_style::dashed, 8, 7, 3};  // short dashes: not a slope
      floor_line.reference = true;
      for (const long long N : s.meshes) {
        floor_line.add(figure::integer(N), figure::of(Real(100 * Real(N * s.periods) * eps<Real>())));
      }
      n_panel.curves.push_back(floor_line);
    });
    by_time.push_back(time_panel);
    by_n.push_back(n_panel);
  }
  out.add(std::move(rows));
  if (timed) out.add(std::move(times));
  const int columns = static_cast<int>(std::min<std::size_t>(3, s.precisions.size()));
  const int panel_rows = static_cast<int>((s.precisions.size() + static_cast<std::size_t>(columns) - 1) / static_cast<std::size_t>(columns));
  if (timed) {
    plot_description time_plot{"work_precision_time", "Maximum error of q and p/(mω) against run time (log-log), one panel per precision",
                               by_time, columns, 460 * columns, 400 * panel_rows};
    time_plot.timing = true;
    out.add(std::move(time_plot));
  }
  out.add(plot_description{"work_precision_n",
                           "Maximum error of q and p/(mω) against N, one panel per precision; dashed guides: slopes N⁻² (grey) "
                           "and N⁻⁴ (black); short dashes: the round-off floor 100 N eps",
                           by_n,
                           columns, 460 * columns, 400 * panel_rows});
  return out;
}

}  // namespace simpson::verify

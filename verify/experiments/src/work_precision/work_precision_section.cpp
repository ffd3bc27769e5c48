// The work_precision section: error against run time for the Simpson scheme and its peers, in
// several precisions, each scheme run two ways: by its general step (what it runs for any force) and
// as its own exact 2 × 2 matrix (what Φ₃ is in the paper), so that the plot compares methods, and
// separately implementations.

#include <simpson/verify/work_precision_section.hpp>
#include <simpson/verify/interruption.hpp>
#include <simpson/verify/progress.hpp>
#include <simpson/verify/scheme_style.hpp>

#include <simpson/verify/floating_tools.hpp>
#include "enclosed_figures.hpp"
#include "timed_runs.hpp"
#include <simpson/verify/integration_driver.hpp>

#include <simpson/energy.hpp>
#include <simpson/exact_solution.hpp>
#include <simpson/iterate.hpp>
#include <simpson/nonlinear_simpson_step.hpp>
#include <simpson/potential.hpp>

#include <boost/math/constants/constants.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <optional>

namespace simpson::verify {
namespace {

struct measured_run {
  table_row row;         // the figures of the error run
  table_row timing_row;  // runs, minimum, median and maximum time (empty when nothing is timed)
  figure error;          // max of the q error and the scaled p error (a fault when the run has one)
  figure seconds;        // median run time
};

/// One scheme's measured points in the first precision's general step, N increasing: what the cost
/// to reach a given error is read from.
struct measured_point {
  double N = 0, error = 0, seconds = 0;
};

/// Where a log-log line through the measured points reaches `target` (the first pair of neighbours
/// that brackets it, interpolated in log N and log seconds): none when no pair does.
std::optional<measured_point> reaching(const std::vector<measured_point>& points, double target) {
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const measured_point &a = points[k], &b = points[k + 1];
    if (!(a.error > target && b.error <= target && a.error > 0 && b.error > 0)) continue;
    const double f = std::log(a.error / target) / std::log(a.error / b.error);  // 0 at a, 1 at b
    const auto between = [f](double x, double y) { return std::exp(std::log(x) + f * (std::log(y) - std::log(x))); };
    return measured_point{between(a.N, b.N), target, between(a.seconds, b.seconds)};
  }
  return std::nullopt;
}

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

/// The error run's stop rule: a state whose error against the exact solution is not finite, or whose
/// q is off by more than 10⁶ times the amplitude (unstable); a step that throws, "failed: <why>".
template <class Real, class Exact>
struct error_stop : never_stop {
  Exact exact;
  Real m_omega, amplitude;
  std::optional<figure> check(long long j, const phase_point<Real>& y) const {
    using std::abs;
    const Real eq = abs(Real(y.q - exact(j).q));
    const Real ep = abs(Real(y.p - exact(j).p)) / m_omega;
    if (!(eq == eq) || !(ep == ep)) return figure::fault("non-finite");
    if (eq > 1000000 * amplitude) return unstable_at(j);
    return std::nullopt;
  }
};

template <class Real>
measured_run measure(scheme_id scheme, const std::string& form, const precision& prec, long long N, long long periods,
                     const timing_policy& timing, bool benchmark, const std::vector<phase_point<Real>>& exact,
                     const enclosed_solution& enclosed_exact) {
  using std::abs;
  const Real omega = 2 * boost::math::constants::pi<Real>();
  const long long steps = N * periods;
  const oscillator_parameters<Real> par{Real(1), omega, step_size(Real(periods), steps)};
  const phase_point<Real> y0{Real(par.m() * omega), Real(0)};
  const stepper<Real> runner(scheme, par);
  // The form: the scheme's own 2 × 2 matrix, or its general step. Simpson's general step is its
  // nonlinear step (Newton on the internal node to 16 eps of the terms) with V = mω²q²/2; the
  // others' is stepper::step (stage equations, kicks and drifts, Section 6's elimination).
  const bool as_matrix = form == "matrix";
  const one_step_matrix<Real> own = runner.matrix();
  const quartic_potential<Real> harmonic{par.m(), omega, Real(0)};
  const auto advance = [&](const phase_point<Real>& z) {
    if (as_matrix) return own * z;
    if (scheme == scheme_id::simpson) return simpson_nonlinear_step(par.m(), par.h(), harmonic, z).state;
    return runner.step(z);
  };

  // The error run (not timed): maxima over every t_j against the exact solution, of the errors in q
  // and p/(mω) and of the relative changes of H and H_d.
  const Real m_omega_real = par.m() * omega;
  const auto exact_at = [&exact](long long j) -> const phase_point<Real>& { return exact[static_cast<std::size_t>(j)]; };
  auto errors = reference_error_of<Real>(exact_at, m_omega_real);
  auto energy_change = relative_change_of<Real>([&par](const phase_point<Real>& z) { return Real(energy(par, z)); });
  auto discrete_energy_change = relative_change_of<Real>([&par](const phase_point<Real>& z) { return Real(discrete_energy(par, z)); });
  phase_point<Real> y = y0;
  // A state not finite, or whose q is off by 10⁶ times the amplitude, ends the run.
  const error_stop<Real, decltype(exact_at)> stop{{}, exact_at, m_omega_real, Real(abs(y0.p) / m_omega_real)};
  // Above double, the same maxima enclosed: each iterate (an exact binary value) against the
  // enclosed exact solution, so the figures carry only guaranteed digits.
  const bool enclosed = !enclosed_exact.empty();
  interval enclosed_q(0), enclosed_p(0);
  const interval m_omega = enclosed ? interval(2 * boost::math::constants::pi<interval>() * detail::exact_interval(par.m())) : interval(0);
  auto enclosed_errors = at_steps_of([&](long long j, const phase_point<Real>& z) {
    if constexpr (detail::enclosed_above_double_v<Real>) {
      if (enclosed) {
        const phase_point<interval>& e = enclosed_exact[static_cast<std::size_t>(j)];
        enclosed_q = enclosed_max(enclosed_q, abs(interval(detail::exact_interval(z.q) - e.q)));
        enclosed_p = enclosed_max(enclosed_p, abs(interval(detail::exact_interval(z.p) / m_omega - e.p)));
      }
    }
  });
  const figure status = integrate_n_steps(advance, y, steps, steps, stop, errors, energy_change, discrete_energy_change, enclosed_errors).status;
  const Real &error_q = errors.q_max, &error_p = errors.p_max;
  // At the round-off floor: within 100 N eps of zero (N steps, each rounding a few times).
  const Real floor_level = 100 * Real(steps) * eps<Real>();
  const table_row key{figure::text(std::string(traits_of(scheme).name)), figure::text(form), figure::text(prec.name()), figure::integer(N)};
  measured_run out{key, {}, status, status};
  out.row.push_back(figure::integer(steps));
  out.row.push_back(status);
  if (status.is_fault()) {
    for (int k = 0; k < 7; ++k) out.row.push_back(figure{});
    if (timing.max_runs > 0) out.timing_row = {key[0], key[1], key[2], key[3], figure{}, figure{}, figure{}, figure{}};
    if (timing.max_runs > 0 && benchmark) out.timing_row.push_back(figure{});
    return out;
  }
  const bool simpson_family = scheme == scheme_id::simpson || scheme == scheme_id::simpson_elimination;
  // The energies' largest changes over the run, computed in Real (the end values below are enclosed
  // above double): at the end of whole periods the state is back near y₀, and the end value
  // understates the oscillation.
  const auto with_maxima = [&] {
    out.row.push_back(figure::of(energy_change.maximum));
    out.row.push_back(simpson_family ? figure::of(discrete_energy_change.maximum) : figure{});
  };
  if (enclosed) {
    if constexpr (detail::enclosed_above_double_v<Real>) {
      // The energies at the run's own parameters (m, ω and h as rounded in Real, exact values).
      const oscillator_parameters<interval> at{detail::exact_interval(par.m()), detail::exact_interval(par.omega()),
                                               detail::exact_interval(par.h())};
      add_error_figures(out, simpson_family, enclosed_q, enclosed_p, at, {detail::exact_interval(y0.p), detail::exact_interval(y0.q)},
                        {detail::exact_interval(y.p), detail::exact_interval(y.q)}, detail::enclosed_figure);
      const interval error_both = enclosed_max(enclosed_q, enclosed_p);
      with_maxima();
      out.row.push_back(figure::flag(upper(error_both) <= lower(detail::exact_interval(floor_level))));
      out.error = detail::enclosed_figure(error_both);
    }
  } else {
    add_error_figures(out, simpson_family, error_q, error_p, par, y0, y, [](const Real& v) { return figure::of(v); });
    const Real error = std::max(error_q, error_p);
    with_maxima();
    out.row.push_back(figure::flag(error <= floor_level));
    out.error = figure::of(error);
  }
  if (timing.max_runs == 0) return out;

  // Timing: one warm-up run, then runs until max_runs or max_seconds; each run is `steps` steps.
  const detail::run_times times = detail::time_runs(timing, [&] {
    phase_point<Real> z = y0;
    for (long long j = 0; j < steps; ++j) z = advance(z);
    return static_cast<double>(z.q);
  });
  out.timing_row = {key[0],
                    key[1],
                    key[2],
                    key[3],
                    figure::integer(times.runs),
                    figure::of(times.minimum),
                    figure::of(times.median),
                    figure::of(times.maximum)};
  if (benchmark) out.timing_row.push_back(figure::of(static_cast<double>(steps) / times.median));
  out.seconds = figure::of(times.median);
  return out;
}
/// The rows of every run: the errors, the energies' changes and the status (work_precision.csv).
table rows_table(const work_precision_settings& s) {
  const bool timed = s.timing.max_runs > 0;
  table rows{"rows", "",
             fmt::format(
                 "m = 1, ω = 2π, {} period(s), y₀ = (mω, 0); N steps per period. Each scheme runs in the forms {}: "
                 "`step` is its general algorithm, what it runs for any force (Simpson its nonlinear step, Newton's method on "
                 "the internal node to 16 eps of the terms, with V = mω²q²/2; simpson-elimination Section 6's elimination of "
                 "the internal node at every step; Newmark the implicit midpoint rule, Gauss–Legendre (and Lobatto IIIA–IIIB) "
                 "by their stage equations, whose matrix, constant for this linear force, is factored once; Störmer–Verlet "
                 "and Yoshida their kicks and drifts, RK4 its four explicit stages: each peer as its users write it); "
                 "`matrix` is its own exact 2 × 2 one-step matrix, one product a step, the form the paper gives Φ₃ in. In "
                 "the matrix form every scheme costs the same per step, so it is drawn against N only; against run time the "
                 "general steps are compared (the plot work_precision_time, in timing.md with the run times: the median of the "
                 "timed runs, with their minimum and maximum). Errors: maxima over all t_j of |q_j − q(t_j)| and "
                 "|p_j − p(t_j)|/(mω), computed in the run's precision; the relative error of H (and of H_d for Simpson) at "
                 "the end, and its largest over the run (at the end of whole periods the state is back near y₀). Above double the error and energy figures are enclosures (MPFI): each iterate, an exact binary "
                 "value, against the exact solution at t_j = j/N with 2π enclosed, and the energies at the run's own "
                 "rounded m, ω, h; only guaranteed digits are shown, with the radius where fewer than three are. {} "
                 "A run whose state is not finite, grows past 10⁶ times the amplitude (unstable, with the step), or throws "
                 "is recorded with its status. At the round-off floor: error ≤ 100 N eps.{}",
                 s.periods, fmt::format("{}", fmt::join(s.forms, " and ")),
                 timed ? "Run times, and how they are measured, are in [timing.md](timing.md)." : "Not timed (--no-timing).",
                 std::find(s.schemes.begin(), s.schemes.end(), scheme_id::lobatto_iiia_iiib_3) == s.schemes.end()
                     ? ""
                     : " Lobatto IIIA–IIIB(3) is Simpson's map (claim nonlinear-lobatto-equivalence): its rows are a second "
                       "implementation of the same method, not another method."),
             {{"scheme", "scheme"},
              {"form", "form"},
              {"precision", "precision"},
              {"N_per_period", "N"},
              {"steps", "steps"},
              {"status", "status"},
              {"error_q_max", "error q"},
              {"error_p_max_over_m_omega", "error p/(mω)"},
              {"error_H_end_relative", "H rel. (end)"},
              {"error_Hd_end_relative", "H_d rel. (end)"},
              {"error_H_max_relative", "H rel. (max)"},
              {"error_Hd_max_relative", "H_d rel. (max)"},
              {"at_round_off_floor", "at floor"}}};
  rows.csv_file = "work_precision.csv";
  return rows;
}

/// The run time of each configuration (timing.md).
table timing_table(const work_precision_settings& s) {
  table times{"timing_rows", "Run time of each configuration",
              fmt::format("One warm-up run, then runs until {} runs or {} s (steady_clock); each run is the N × periods steps "
                          "of the error run, without the error computation.",
                          s.timing.max_runs, simpson::to_string(s.timing.max_seconds, 3)),
              {{"scheme", "scheme"}, {"form", "form"}, {"precision", "precision"}, {"N_per_period", "N"}, {"runs", "runs"},
               {"min_seconds", "min time", "s"}, {"median_seconds", "median time", "s"}, {"max_seconds", "max time", "s"}}};
  if (s.benchmark) times.columns.push_back({"steps_per_second", "steps/s"});
  times.csv_file = "work_precision_time.csv";
  times.timing = true;
  return times;
}

/// What the runs of every precision add to: the tables, each scheme's measured points in double's
/// general step (for the cost to an error), and the panels drawn.
struct work_precision_runs {
  table rows, times;
  std::map<scheme_id, std::vector<measured_point>> general_steps;  // double's step form (when it is the first precision), for the cost to an error
  std::vector<panel> by_time, by_n;
};

/// The exact solution at every t_j of each N, shared by the schemes; above double, enclosed too (in
/// the interval digits the caller has set, enough to hold Real's values exactly).
template <class Real>
struct exact_solutions {
  std::map<long long, std::vector<phase_point<Real>>> exact_by_N;
  std::map<long long, enclosed_solution> enclosed_by_N;
};

template <class Real>
exact_solutions<Real> exact_solutions_of(const work_precision_settings& s) {
  exact_solutions<Real> out;
  auto& exact_by_N = out.exact_by_N;
  [[maybe_unused]] auto& enclosed_by_N = out.enclosed_by_N;
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
  return out;
}

/// One scheme in each form at every N in Real: its rows, its curves against run time and N, and its
/// first error for the guides.
template <class Real>
void measure_scheme(scheme_id scheme, const precision& prec, bool first, const work_precision_settings& s, exact_solutions<Real>& solutions,
                    const std::string& shown_form, std::map<std::string, panel>& time_panels, panel& n_panel,
                    std::map<int, double>& lowest_first_error, work_precision_runs& runs) {
  const bool timed = s.timing.max_runs > 0;
    const scheme_style style = style_of(scheme);
    for (const std::string& form : s.forms) {
      series by_seconds{std::string(traits_of(scheme).name), style.line, style.color, style.point, style.dash};
      series by_mesh = by_seconds;
      for (const long long N : s.meshes) {
        measured_run m = measure<Real>(scheme, form, prec, N, s.periods, s.timing, s.benchmark, solutions.exact_by_N[N], solutions.enclosed_by_N[N]);
        progress_step(s.progress, "work_precision", fmt::format("{} ({}) {} N = {}", traits_of(scheme).name, form, prec.name(), N));
        if (timed) by_seconds.add(m.seconds, m.error);
        const auto e = m.error.plottable(), t = m.seconds.plottable();
        // In double only: its errors are doubles, so the interpolation passes no enclosure through double.
        if (timed && first && prec.kind() == precision_kind::float64 && form != "matrix" && e && t) {
          runs.general_steps[scheme].push_back({static_cast<double>(N), *e, *t});
        }
        by_mesh.add(figure::integer(N), m.error);
        runs.rows.add(std::move(m.row));
        if (timed) runs.times.add(std::move(m.timing_row));
      }
      time_panels.at(form).curves.push_back(by_seconds);
      if (form != shown_form) continue;
      if (const auto e0 = by_mesh.y.front().plottable(); e0 && *e0 > 0) {
        const int order = traits_of(scheme).order;
        lowest_first_error[order] = lowest_first_error.count(order) ? std::min(lowest_first_error[order], *e0) : *e0;
      }
      n_panel.curves.push_back(by_mesh);
    }
}

/// Guides: slopes N^-2 and N^-4, a factor 4 below the lowest first error among the schemes of that
/// order, so that each runs beside its schemes' curves and under them, never on one; and the round-off
/// floor.
template <class Real>
void add_guides(const work_precision_settings& s, const std::map<int, double>& lowest_first_error, panel& n_panel) {
  for (const int order : {2, 4}) {
    const auto anchor = lowest_first_error.find(order);
    if (anchor == lowest_first_error.end() || s.meshes.empty()) continue;
    n_panel.curves.push_back(slope_guide(fmt::format("slope N^{{-{}}}", order), order == 2 ? 8 : 9, static_cast<double>(s.meshes.front()),
                                         anchor->second / 4, s.meshes, order));
  }
  series floor_line{"round-off floor 100 N eps", line_style::dashed, 8, 7, 3};  // short dashes: not a slope
  floor_line.reference = true;
  for (const long long N : s.meshes) {
    floor_line.add(figure::integer(N), figure::of(Real(100 * Real(N * s.periods) * eps<Real>())));
  }
  n_panel.curves.push_back(floor_line);
}

/// Every scheme in one precision: the tables' rows, and the panels drawn (the first precision large,
/// in every form against run time; the last precision, the highest, where round-off is far below the
/// schemes' errors, in the step form).
void measure_precision(std::size_t pk, const work_precision_settings& s, const std::string& shown_form, work_precision_runs& runs) {
  const precision& prec = s.precisions[pk];
  const bool first = pk == 0, last = pk + 1 == s.precisions.size();
  const std::string error_label = "max error of q and p/(mω)";  // error_max: the larger of the two
  // Against run time, the general step only: as its own 2 × 2 matrix every scheme costs the same per
  // step, so that error against time would be error against N (work_precision_n) relabelled.
  std::map<std::string, panel> time_panels;
  for (const std::string& form : s.forms) {
    time_panels.emplace(form, panel{fmt::format("{}, each scheme by its general step", prec.name()),
                                    {"run time (s, median of repeats)", true}, {error_label, true}, {}, "bottom left"});
  }
  panel n_panel{fmt::format("{}, {} form", prec.name(), shown_form), {"N (steps per period)", true}, {error_label, true}, {}, "bottom left"};
  visit_floating(prec, [&](auto precision_tag) {
    using Real = typename decltype(precision_tag)::type;
    std::optional<scoped_interval_digits> interval_digits;
    if constexpr (detail::enclosed_above_double_v<Real>) interval_digits.emplace(detail::enclosure_digits_for<Real>());
    exact_solutions<Real> solutions = exact_solutions_of<Real>(s);
    // The first error of each order's schemes at the coarsest N, for the guides.
    std::map<int, double> lowest_first_error;
    for (const scheme_id scheme : s.schemes) {
      measure_scheme<Real>(scheme, prec, first, s, solutions, shown_form, time_panels, n_panel, lowest_first_error, runs);
    }
    add_guides<Real>(s, lowest_first_error, n_panel);
  });
  for (const std::string& form : s.forms) {
    if (form != "matrix" && (first || (last && form == shown_form))) runs.by_time.push_back(time_panels.at(form));
  }
  if (first || last) runs.by_n.push_back(n_panel);
}

/// The measured ratios: to reach one error, the steps and the seconds each general step needs,
/// against Simpson's (log-log interpolation between the two measured N that bracket it).
table cost_to_error_table(const work_precision_settings& s, std::map<scheme_id, std::vector<measured_point>>& general_steps) {
  const double target = 1e-8;
  const auto simpson = general_steps.count(scheme_id::simpson) ? reaching(general_steps[scheme_id::simpson], target) : std::nullopt;
  table cost{"cost_to_error", fmt::format("The cost of an error of {:.0e}", target),
             fmt::format("In {}, each scheme by its general step: the steps per period and the run time at which its max error of q and "
                         "p/(mω) reaches {:.0e}, interpolated log-log between the two measured N that bracket it (none: not reached "
                         "within the measured N), and both against Simpson's.",
                         s.precisions.front().name(), target),
             {{"scheme", "scheme"}, column::fixed_point("N_at_error", "N", 1), {"seconds_at_error", "time", "s"},
              column::fixed_point("N_over_simpson", "N / Simpson's", 2), column::fixed_point("seconds_over_simpson", "time / Simpson's", 2)}};
  cost.timing = true;
  for (const scheme_id scheme : s.schemes) {
    if (!general_steps.count(scheme)) continue;
    const std::optional<measured_point> at = reaching(general_steps[scheme], target);
    if (!at) {
      cost.add({figure::text(std::string(traits_of(scheme).name)), figure::text("not reached"), figure{}, figure{}, figure{}});
      continue;
    }
    cost.add({figure::text(std::string(traits_of(scheme).name)), figure::of(at->N), figure::of(at->seconds),
              simpson ? figure::of(at->N / simpson->N) : figure{}, simpson ? figure::of(at->seconds / simpson->seconds) : figure{}});
  }
  return cost;
}

/// The plots: error against run time (timed runs only) and against N.
void add_plots(const work_precision_settings& s, const std::string& shown_form, const std::vector<panel>& by_time,
               const std::vector<panel>& by_n, section_result& out) {
  const bool timed = s.timing.max_runs > 0;
  if (timed) {
    plot_description time_plot{"work_precision_time",
                               fmt::format("Maximum error of q and p/(mω) against run time (log-log; the median of the timed runs, their "
                                           "minimum and maximum in timing.md), each scheme by its general step, what it runs for any "
                                           "force: Simpson's nonlinear step with its Newton solve, the implicit peers' stage equations "
                                           "(their matrix factored once for this linear force), the explicit peers' stages. As its own "
                                           "2 × 2 matrix every scheme costs the same per step, so that form is drawn against N only "
                                           "(work_precision_n). {}",
                                           by_time.size() > 1 ? "The last panel is the highest precision of the run." : ""),
                               by_time, 2, 1000, 440 * static_cast<int>((by_time.size() + 1) / 2)};
    time_plot.timing = true;
    out.add(std::move(time_plot));
  }
  out.add(plot_description{"work_precision_n",
                           fmt::format("Maximum error of q and p/(mω) against N ({} form), the run's first and last precision; dashed "
                                       "guides: slopes N⁻² (grey) and N⁻⁴ (black), a factor 4 below the lowest curve of their order; "
                                       "short dashes: the round-off floor 100 N eps. The other precisions are in work_precision.csv",
                                       shown_form),
                           by_n, 2, 1000, 460});
}

}  // namespace

section_result run_work_precision(const work_precision_settings& s) {
  section_result out;
  out.name = "work_precision";
  const bool timed = s.timing.max_runs > 0;
  out.title = timed ? "Work against precision: error and run time" : "Work against precision: error (not timed)";
  out.conventions = {{"m", 1}, {"omega", "2 pi"}, {"periods", s.periods}, {"start", "y_0 = (m omega, 0)"}};
  out.timing_conventions = {{"warm_up_runs", 1}, {"max_runs", s.timing.max_runs}, {"max_seconds", s.timing.max_seconds}};
  // The panels drawn: the first precision large, in every form against run time; the last precision
  // (the highest, where round-off is far below the schemes' errors) in the step form. Every other
  // precision's figures are in the tables and work_precision.csv (above double they match double's
  // to its round-off, and a panel each would show the same curves again).
  const std::string shown_form = s.forms.front() == "matrix" && s.forms.size() > 1 ? s.forms[1] : s.forms.front();
  work_precision_runs runs{rows_table(s), timing_table(s), {}, {}, {}};
  for (std::size_t pk = 0; pk < s.precisions.size(); ++pk) measure_precision(pk, s, shown_form, runs);
  out.add(std::move(runs.rows));
  if (timed) out.add(std::move(runs.times));
  if (timed && !runs.general_steps.empty()) out.add(cost_to_error_table(s, runs.general_steps));
  add_plots(s, shown_form, runs.by_time, runs.by_n, out);
  return out;
}

}  // namespace simpson::verify

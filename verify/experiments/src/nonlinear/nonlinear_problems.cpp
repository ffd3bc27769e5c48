// The nonlinear section's error against N, work and run time: the paper's oscillator through the
// general steps, the pendulum, the Kepler problem, Hénon–Heiles and the FPU chain, for Simpson and its peers in double. Work is counted in ∇V and ∇²V
// evaluations (counting_potential.hpp), beside the seconds. The implicit methods (Simpson,
// Gauss–Legendre) solve their stage equations by the same rule: Newton's method to 16 eps
// of the terms, from the same starting guess (each stage at q + c_i h M⁻¹ p), Jacobians solved
// by Eigen's partial-pivoting LU; the explicit ones (Störmer–Verlet, Yoshida, RK4) evaluate forces.

#include "counting_potential.hpp"
#include "nonlinear_parts.hpp"
#include "timed_runs.hpp"

#include <simpson/verify/integration_driver.hpp>
#include <simpson/verify/integration_methods.hpp>

#include <simpson/verify/floating_tools.hpp>
#include <simpson/verify/fpu_section.hpp>
#include <simpson/verify/interruption.hpp>
#include <simpson/verify/progress.hpp>
#include <simpson/verify/scheme_style.hpp>

#include <simpson/fpu_chain.hpp>
#include <simpson/kepler_exact.hpp>
#include <simpson/nonlinear_ndof_step.hpp>
#include <simpson/pendulum_exact.hpp>
#include <simpson/potential.hpp>
#include <simpson/runge_kutta_tableaux.hpp>
#include <simpson/scheme.hpp>
#include <simpson/stormer_verlet.hpp>

#include <boost/math/constants/constants.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace simpson::verify::detail {
namespace {

// Simpson is drawn once, as the method: Lobatto IIIA–IIIB(3) is the same map (claim
// nonlinear-lobatto-equivalence), and comparing its stage solve with Simpson's Newton step compares two
// implementations, which bench/nonlinear_step_bench.cpp measures apart.
constexpr std::array<const integration_method*, 5> methods{&method_of(method_id::simpson), &method_of(method_id::gauss_legendre_2),
                                                       &method_of(method_id::stormer_verlet), &method_of(method_id::yoshida),
                                                       &method_of(method_id::rk4)};

/// A problem: its system, start, end time and the state at T (rounded to double from a computation
/// in mpfr), with a sentence saying where that state comes from.
template <class Potential>
struct problem {
  std::string name;
  separable_system<double, Potential> system;
  ndof_state<double> start;
  double T;
  ndof_state<double> at_T;
  std::string reference;
  long long steps_per_N = 1;  // the runs take N times this many steps (Kepler: N a period, over its periods)
};

template <class Real>
ndof_state<double> rounded(const ndof_state<Real>& y) {
  ndof_state<double> out{dense_vector<double>(y.p.size()), dense_vector<double>(y.q.size())};
  for (Eigen::Index i = 0; i < y.p.size(); ++i) {
    out.p(i) = static_cast<double>(y.p(i));
    out.q(i) = static_cast<double>(y.q(i));
  }
  return out;
}

ndof_state<mpfr> widened(const ndof_state<double>& y) {
  ndof_state<mpfr> out{dense_vector<mpfr>(y.p.size()), dense_vector<mpfr>(y.q.size())};
  for (Eigen::Index i = 0; i < y.p.size(); ++i) {
    out.p(i) = y.p(i);
    out.q(i) = y.q(i);
  }
  return out;
}

/// The paper's oscillator (m = 1, ω = 2π, y₀ = (mω, 0), one period) through the general steps, V =
/// ½ ω² q² with ω² as the runs hold it in double; the state at T is that system's exact flow, in mpfr.
problem<quadratic_potential<double>> oscillator_problem(const nonlinear_settings& s) {
  const double omega = 2 * boost::math::constants::pi<double>(), T = 1;
  const double stiffness = omega * omega;
  const scoped_mpfr_digits digits(s.reference_digits);
  const mpfr w = sqrt(mpfr(stiffness)), p0(omega);
  const auto one = [](const mpfr& p, const mpfr& q) {
    return ndof_state<double>{dense_vector<double>::Constant(1, static_cast<double>(p)),
                              dense_vector<double>::Constant(1, static_cast<double>(q))};
  };
  return {"oscillator", {dense_matrix<double>::Identity(1, 1), quadratic_potential<double>{dense_matrix<double>::Constant(1, 1, stiffness)}},
          one(p0, mpfr(0)), T, one(p0 * cos(w * T), p0 / w * sin(w * T)),
          fmt::format("the paper's: m = 1, ω = 2π, q(0) = 0, p(0) = mω, T = 1 (one period), V = ω²q²/2 (the work_precision section's "
                      "problem, here through each method's general step, as for any force); exact solution with the double ω² the runs "
                      "use, in mpfr:{}",
                      s.reference_digits)};
}

using pendulum_1d = one_dof_potential<double, pendulum_potential<double>>;

problem<pendulum_1d> pendulum_problem(const nonlinear_settings& s) {
  const scoped_mpfr_digits digits(s.reference_digits);
  const pendulum_from_rest<mpfr> exact{mpfr(1), mpfr(1), mpfr(s.pendulum_q0)};
  const phase_point<mpfr> start = exact.at(mpfr(0)), end = exact.at(mpfr(s.pendulum_T));
  const auto one = [](const phase_point<mpfr>& y) {
    return ndof_state<double>{dense_vector<double>::Constant(1, static_cast<double>(y.p)),
                              dense_vector<double>::Constant(1, static_cast<double>(y.q))};
  };
  return {"pendulum", {dense_matrix<double>::Identity(1, 1), pendulum_1d{pendulum_potential<double>{1, 1}}}, one(start),
          s.pendulum_T, one(end),
          fmt::format("q(0) = {} rad, p(0) = 0, T = {}; exact solution by Jacobi functions in mpfr:{}",
                      fmt::format("{:g}", s.pendulum_q0), fmt::format("{:g}", s.pendulum_T), s.reference_digits)};
}

problem<kepler_potential<double>> kepler_problem(const nonlinear_settings& s) {
  const double T = 2 * boost::math::constants::pi<double>() * s.kepler_periods;
  const scoped_mpfr_digits digits(s.reference_digits);
  const kepler_orbit<mpfr> orbit{mpfr(s.eccentricity)};
  return {"kepler", {dense_matrix<double>::Identity(2, 2), kepler_potential<double>{1}}, rounded(orbit.initial()), T,
          rounded(orbit.at(mpfr(T))),
          fmt::format("e = {}, q(0) = (1 − e, 0), p(0) = (0, √((1 + e)/(1 − e))), H = −1/2, T = {} periods of 2π (GeometricProblems.jl's "
                      "set-up; T rounded to double; N is the scene's N times the periods, so that each period has as many steps as "
                      "the other problems' runs); exact solution from Kepler's equation in mpfr:{}",
                      fmt::format("{:g}", s.eccentricity), s.kepler_periods, s.reference_digits), s.kepler_periods};
}

problem<henon_heiles_potential<double>> henon_heiles_problem(const nonlinear_settings& s, long long finest) {
  const double T = 20;
  ndof_state<double> start{dense_vector<double>(2), dense_vector<double>(2)};
  start.q << 0.1, 0;
  start.p << 0, 0.5;
  // The reference: the classical Runge–Kutta method (order 4, explicit, a method independent of
  // Simpson's) in mpfr with 8 and 16 times the finest N; the difference of the two bounds its error
  // (Richardson: e(N_ref) ≈ |y(N_ref) − y(N_ref/2)|/15). Explicit: four gradients a step and no
  // Newton solve: 1.3 s where Gauss–Legendre 2 took 6.5 s in the paper scene (docs/beyond.md).
  const scoped_mpfr_digits digits(s.reference_digits);
  const separable_system<mpfr, henon_heiles_potential<mpfr>> exact_system(dense_matrix<mpfr>::Identity(2, 2), {});
  ndof_stepper<mpfr, henon_heiles_potential<mpfr>> rk4(method_of(method_id::rk4), exact_system);
  const auto run = [&](long long N) {
    ndof_state<mpfr> y = widened(start);
    long long iterations = 0;
    const mpfr h = mpfr(T) / N;
    for (long long j = 1; j <= N; ++j) {
      if ((j & 255) == 0) throw_if_interrupted();
      y = rk4.step(h, y, iterations);
    }
    return y;
  };
  const long long N_ref = 16 * finest;
  const ndof_state<mpfr> fine = run(N_ref), coarse = run(N_ref / 2);
  const mpfr estimate = std::max(mpfr(dense_vector<mpfr>(fine.q - coarse.q).norm()), mpfr(dense_vector<mpfr>(fine.p - coarse.p).norm())) / 15;
  const separable_system<double, henon_heiles_potential<double>> system(dense_matrix<double>::Identity(2, 2), {});
  return {"henon-heiles", system, start, T, rounded(fine),
          fmt::format("q(0) = (0.1, 0), p(0) = (0, 0.5), H = {} (below the escape energy 1/6), T = 20; reference: the classical Runge–Kutta method in mpfr:{} with N = {} "
                      "(error estimated {} from the run with N/2)",
                      fmt::format("{:g}", system.energy(start)), s.reference_digits, N_ref, simpson::to_string(estimate, 2))};
}

problem<fpu_potential<double>> fpu_problem(const nonlinear_settings& s, long long finest) {
  // The chain of the fpu section (its m, ω and start: Hairer, Lubich and Wanner's). The reference:
  // Gauss–Legendre 2 in long double with 16 and 8 times the finest N, the difference bounding its
  // error as for Hénon–Heiles (mpfr would take minutes for 2m = 6 degrees of freedom; long double's
  // round-off, about 1e-19 a step, stays far below the estimate).
  const fpu_settings chain;
  const double T = s.fpu_T;
  const separable_system<long double, fpu_potential<long double>> exact_system = fpu_system<long double>(chain.m, chain.omega);
  ndof_stepper<long double, fpu_potential<long double>> gl2(method_of(method_id::gauss_legendre_2), exact_system);
  const auto run = [&](long long N) {
    ndof_state<long double> y = fpu_start<long double>(chain.m, chain.omega);
    long long iterations = 0;
    const long double h = static_cast<long double>(T) / static_cast<long double>(N);
    for (long long j = 1; j <= N; ++j) {
      if ((j & 255) == 0) throw_if_interrupted();
      y = gl2.step(h, y, iterations);
    }
    return y;
  };
  const long long N_ref = 16 * finest;
  const ndof_state<long double> fine = run(N_ref), coarse = run(N_ref / 2);
  const long double estimate =
      std::max(dense_vector<long double>(fine.q - coarse.q).norm(), dense_vector<long double>(fine.p - coarse.p).norm()) / 15;
  return {"fpu", fpu_system<double>(chain.m, chain.omega), fpu_start<double>(chain.m, chain.omega), T, rounded(fine),
          fmt::format("the fpu section's chain, m = {}, ω = {}, its start (Hairer, Lubich and Wanner's), T = {} (ωh of the stiff "
                      "springs from {} at the coarsest N to {} at the finest); reference: Gauss–Legendre 2 in long double with "
                      "N = {} (error estimated {} from the run with N/2)",
                      chain.m, fmt::format("{:g}", chain.omega), fmt::format("{:g}", T),
                      fmt::format("{:.3g}", chain.omega * T / static_cast<double>(*std::min_element(s.N.begin(), s.N.end()))),
                      fmt::format("{:.3g}", chain.omega * T / static_cast<double>(finest)), N_ref,
                      fmt::format("{:.2g}", static_cast<double>(estimate)))};
}

/// One (method, N) run: the error run, then timed runs without the error computation.
struct problem_run {
  table_row row, timing_row;
  figure state_error, energy_error, seconds, gradients;
  double error_q = 0, energy = 0, iterations = 0, gradients_per_step = 0;  // when the run is ok
  bool ok = false;
};

/// The error run's stop rule: an energy error that is not finite ends the run; a step that throws is
/// "failed: <why>".
template <class Potential>
struct finite_energy_stop : never_stop {
  const separable_system<double, Potential>* system;
  double H0;
  std::optional<figure> check(long long, const ndof_state<double>& y) const {
    if (!std::isfinite(std::abs(system->energy(y) - H0) / std::abs(H0))) return figure::fault("non-finite");
    return std::nullopt;
  }
};

template <class Potential>
problem_run run_one(const problem<Potential>& p, const integration_method& m, long long N, const timing_policy& timing) {
  ndof_stepper<double, Potential> method(m, p.system);
  // The error run counts its ∇V and ∇²V calls; the timed runs below do not.
  evaluation_count count;
  const separable_system<double, counting_potential<Potential>> counted_system(p.system.mass(), {p.system.potential(), count});
  ndof_stepper<double, counting_potential<Potential>> counted(m, counted_system);
  const double h = p.T / static_cast<double>(N), H0 = p.system.energy(p.start);
  const table_row key{figure::text(p.name), figure::text(std::string(m.name)), figure::integer(N)};
  problem_run out{key, key, figure{}, figure{}, figure{}, figure{}};
  ndof_state<double> y = p.start;
  long long iterations = 0;
  // The largest relative change of H over the run.
  auto energy = relative_change_of<double>([&p](const ndof_state<double>& z) { return p.system.energy(z); });
  const figure status = integrate_n_steps([&](const ndof_state<double>& z) { return counted.step(h, z, iterations); }, y, N, N,
                                          finite_energy_stop<Potential>{{}, &p.system, H0}, energy)
                            .status;
  const double energy_error = energy.maximum;
  out.row.push_back(status);
  if (status.is_fault()) {
    for (int k = 0; k < 6; ++k) out.row.push_back(figure{});
    if (timing.max_runs > 0) out.timing_row.insert(out.timing_row.end(), {figure{}, figure{}, figure{}, figure{}});
    return out;
  }
  out.ok = true;
  out.error_q = dense_vector<double>(y.q - p.at_T.q).norm();
  out.energy = energy_error;
  out.iterations = static_cast<double>(iterations) / static_cast<double>(N);
  out.gradients_per_step = static_cast<double>(count.gradients) / static_cast<double>(N);
  out.state_error = figure::of(out.error_q);
  out.energy_error = figure::of(energy_error);
  out.gradients = figure::integer(count.gradients);
  out.row.insert(out.row.end(), {out.state_error, figure::of(dense_vector<double>(y.p - p.at_T.p).norm()), out.energy_error,
                                 m.implicit ? figure::of(out.iterations) : figure{}, figure::of(out.gradients_per_step),
                                 figure::of(static_cast<double>(count.hessians) / static_cast<double>(N))});
  if (timing.max_runs == 0) return out;
  const run_times times = time_runs(timing, [&] {
    ndof_state<double> z = p.start;
    long long ignored = 0;
    for (long long j = 0; j < N; ++j) z = method.step(h, z, ignored);
    return z.q(0);
  });
  out.timing_row.insert(out.timing_row.end(),
                        {figure::integer(times.runs), figure::of(times.minimum), figure::of(times.median), figure::of(times.maximum)});
  out.seconds = figure::of(times.median);
  return out;
}

struct problem_panels {
  std::string name;
  panel state, energy, work, time;
  std::vector<std::pair<const integration_method*, std::vector<std::pair<double, double>>>> work_error;  // each method's (∇V, ‖q_N − q(T)‖), runs ok
};

/// The ∇V evaluations at which a method's error reaches `target`: log-log interpolation between the
/// two runs around it (the first crossing, in the order of work); nothing when its runs do not cross it.
std::optional<double> work_for(std::vector<std::pair<double, double>> points, double target) {
  std::sort(points.begin(), points.end());
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const auto [w0, e0] = points[i];
    const auto [w1, e1] = points[i + 1];
    if (e0 >= target && e1 <= target && e0 > 0 && e1 > 0 && e0 != e1) {
      const double t = (std::log(e0) - std::log(target)) / (std::log(e0) - std::log(e1));
      return std::exp(std::log(w0) + t * (std::log(w1) - std::log(w0)));
    }
  }
  return std::nullopt;
}

template <class Potential>
problem_panels run_problem(const problem<Potential>& p, const nonlinear_settings& s, table& rows, table& summary, table& times,
                           std::vector<std::string>& references) {
  references.push_back("**" + p.name + "**: " + p.reference);
  problem_panels out{p.name,
                     {p.name + ": state error", {"N", true}, {"|q_N - q(T)|", true}, {}, "bottom left"},
                     {p.name + ": energy error", {"N", true}, {"max |H - H_0|/|H_0|", true}, {}, "bottom left"},
                     {p.name, {"∇V evaluations in the run", true}, {"|q_N - q(T)|", true}, {}, "bottom left"},
                     {p.name, {"run time (s, median of repeats)", true}, {"|q_N - q(T)|", true}, {}, "bottom left"},
                     {}};
  for (const integration_method* m : methods) {
    const integration_method& id = *m;
    const scheme_style style = style_of(id);
    series by_n(std::string(id.name), style.line, style.color, style.point, style.dash);
    series energy = by_n, by_work = by_n, by_time = by_n;
    std::vector<double> ok_N, ok_errors;
    std::vector<std::pair<double, double>> work_error;
    std::vector<bool> use;
    problem_run finest;
    long long finest_N = 0, failed = 0;
    for (const long long per : s.N) {
      const long long N = per * p.steps_per_N;
      problem_run r = run_one(p, id, N, s.timing);
      if (r.ok) {
        ok_N.push_back(static_cast<double>(N));
        ok_errors.push_back(r.error_q);
        work_error.emplace_back(r.gradients_per_step * static_cast<double>(N), r.error_q);
        use.push_back(true);
        if (N > finest_N) {
          finest_N = N;
          finest = r;
        }
      } else {
        ++failed;
      }
      progress_step(s.progress, "nonlinear", fmt::format("{} {} N = {}", p.name, id.name, N));
      by_n.add(figure::integer(N), r.state_error);
      energy.add(figure::integer(N), r.energy_error);
      by_work.add(r.gradients, r.state_error);
      if (s.timing.max_runs > 0) {
        by_time.add(r.seconds, r.state_error);
        times.add(std::move(r.timing_row));
      }
      rows.add(std::move(r.row));
    }
    const double order = -log_log_slope(ok_N, ok_errors, use);
    summary.add({figure::text(p.name), figure::text(std::string(id.name)), figure::integer(static_cast<long long>(ok_N.size())),
                 figure::integer(failed), ok_N.size() >= 2 ? figure::of(order) : figure{}, finest_N ? figure::integer(finest_N) : figure{},
                 finest_N ? figure::of(finest.error_q) : figure{}, finest_N ? figure::of(finest.energy) : figure{},
                 finest_N && id.implicit ? figure::of(finest.iterations) : figure{},
                 finest_N ? figure::of(finest.gradients_per_step) : figure{}});
    out.state.curves.push_back(by_n);
    out.energy.curves.push_back(energy);
    out.work.curves.push_back(by_work);
    out.time.curves.push_back(by_time);
    out.work_error.emplace_back(m, std::move(work_error));
  }
  return out;
}

}  // namespace

void add_nonlinear_problems(const nonlinear_settings& s, section_result& out) {
  if (s.problems.empty()) return;
  const bool timed = s.timing.max_runs > 0;
  table summary{"problems_summary", "Error against N: the nonlinear problems (double)", "",
                {{"problem", "problem"},
                 {"method", "method"},
                 {"runs_ok", "runs ok"},
                 {"runs_failed", "failed"},
                 column::fixed_point("order_q_least_squares", "order (q)", 2),
                 {"finest_N", "finest N"},
                 {"error_q_finest", "‖q_N − q(T)‖ there"},
                 {"energy_error_finest", "max rel. H error there"},
                 column::fixed_point("newton_iterations_finest", "Newton it./step there", 2),
                 column::fixed_point("gradients_per_step_finest", "∇V / step there", 2)}};
  table rows{"problems", "", "",
             {{"problem", "problem"},
              {"method", "method"},
              {"N", "N"},
              {"status", "status"},
              {"error_q", "‖q_N − q(T)‖"},
              {"error_p", "‖p_N − p(T)‖"},
              {"energy_error_max_relative", "max rel. H error"},
              column::fixed_point("newton_iterations_mean", "Newton it./step", 2),
              column::fixed_point("gradients_per_step", "∇V / step", 2),
              column::fixed_point("hessians_per_step", "∇²V / step", 2)}};
  rows.csv_file = "nonlinear_problems.csv";
  rows.markdown = false;  // every run in report.json and the CSV; the summary in report.md
  table times{"problems_timing", "Run time of each configuration (nonlinear problems)",
              fmt::format("One warm-up run, then runs until {} runs or {} s (steady_clock); each run is the N steps of the "
                          "error run, without the error computation.",
                          s.timing.max_runs, simpson::to_string(s.timing.max_seconds, 3)),
              {{"problem", "problem"}, {"method", "method"}, {"N", "N"}, {"runs", "runs"}, {"min_seconds", "min time", "s"},
               {"median_seconds", "median time", "s"}, {"max_seconds", "max time", "s"}}};
  times.csv_file = "nonlinear_problems_time.csv";
  times.timing = true;
  std::vector<std::string> references;
  std::vector<panel> state_panels, energy_panels, work_panels, time_panels;
  table costs{"problems_cost", "The cost of an error: ∇V evaluations against Simpson's",
              "For each problem, the ∇V evaluations at which ‖q_N − q(T)‖ reaches the target, interpolated log-log between the two "
              "runs around it, and their ratio to Simpson's. The target is 1e-8, or, where Simpson's runs do not reach it, the decade "
              "above Simpson's smallest error. Counts, not seconds: they are the same on every machine (the run times, which also "
              "pay for the implicit methods' ∇²V and LU solves, are in the run-time report).",
              {{"problem", "problem"}, {"target", "target ‖q_N − q(T)‖"}, {"method", "method"}, {"work", "∇V evaluations"},
               column::fixed_point("ratio", "against Simpson's", 2), {"status", "status"}}};
  const auto add_costs = [&](const std::string& name, const problem_panels& p) {
    const auto simpson = std::find_if(p.work_error.begin(), p.work_error.end(), [](const auto& m) { return m.first->id == method_id::simpson; });
    if (simpson == p.work_error.end() || simpson->second.empty()) return;
    double best = INFINITY;
    for (const auto& [work, error] : simpson->second) best = std::min(best, error);
    const double target = best <= 1e-8 ? 1e-8 : std::pow(10.0, std::ceil(std::log10(best)));
    const std::optional<double> own = work_for(simpson->second, target);
    for (const auto& [id, points] : p.work_error) {
      const std::optional<double> work = work_for(points, target);
      double smallest = INFINITY;
      for (const auto& [w, e] : points) smallest = std::min(smallest, e);
      costs.add({figure::text(name), figure::of(target), figure::text(std::string(id->name)), work ? figure::of(*work) : figure{},
                 work && own ? figure::of(*work / *own) : figure{},
                 work ? figure::text("ok")
                      : figure::text(points.empty() ? std::string("no run ok")
                                     : smallest > target ? fmt::format("not reached: its smallest error {:.3g}", smallest)
                                                         : std::string("below the target at its coarsest run"))});
    }
  };
  const auto collect = [&](const problem_panels& p) {
    add_costs(p.name, p);
    state_panels.push_back(p.state);
    energy_panels.push_back(p.energy);
    work_panels.push_back(p.work);
    time_panels.push_back(p.time);
  };
  const long long finest = *std::max_element(s.N.begin(), s.N.end());
  for (const std::string& name : s.problems) {
    if (name == "oscillator") collect(run_problem(oscillator_problem(s), s, rows, summary, times, references));
    if (name == "pendulum") collect(run_problem(pendulum_problem(s), s, rows, summary, times, references));
    if (name == "kepler") collect(run_problem(kepler_problem(s), s, rows, summary, times, references));
    if (name == "henon-heiles") collect(run_problem(henon_heiles_problem(s, finest), s, rows, summary, times, references));
    if (name == "fpu") collect(run_problem(fpu_problem(s, finest), s, rows, summary, times, references));
  }
  std::string intro =
      "In double, h = T/N, m = 1 (M = I). Errors: the Euclidean norms ‖q_N − q(T)‖ and ‖p_N − p(T)‖ at T against the "
      "state below (rounded to double), and the largest relative change of H over the run. Simpson "
      "and Gauss–Legendre 2 solve their stage equations by the same rule: Newton's method until every residual is within "
      "16 eps of the sum of its terms' magnitudes, from each stage at q + c_i h M⁻¹p, the Jacobian solved by Eigen's "
      "partial-pivoting LU (Simpson has n unknowns, Gauss–Legendre 2n). Störmer–Verlet, Yoshida and RK4 are "
      "explicit. Work: every call of ∇V and of ∇²V that the steps make as they are written, counted in the error run: "
      "Störmer–Verlet 1 ∇V a step and Yoshida 3 (each keeps the force a kick ends with for the next, first same as last, "
      "and evaluates one more at the run's start), RK4 4; Simpson 2 + its Newton iterations (one at the internal node per "
      "Newton pass and one at the step's end, which it keeps for the next step's start), Gauss–Legendre 2 two per "
      "Newton pass, with one ∇²V per stage and Newton iteration (Simpson: one; the LU solves are not counted: "
      "they are in the run time). Simpson is drawn once, as the method: Lobatto IIIA–IIIB(3) is the same map "
      "(claim nonlinear-lobatto-equivalence), and its stage solve against Simpson's Newton step compares two implementations, "
      "not two methods (measured apart by make bench, bench/nonlinear_step_bench.cpp). Order: least-squares slope "
      "of log ‖q_N − q(T)‖ against log N over the runs that are ok (round-off flattens it where the errors reach it). "
      "Every run is in nonlinear_problems.csv and report.json (`problems`).";
  for (const std::string& r : references) intro += "\n\n- " + r;
  intro += timed ? "\n\nRun times are in timing.md." : "\n\nNot timed (--no-timing).";
  summary.intro = intro;
  out.add(std::move(summary));
  out.add(std::move(costs));
  out.add(std::move(rows));
  if (timed) out.add(std::move(times));
  const int columns = static_cast<int>(state_panels.size());
  std::vector<panel> panels = state_panels;
  panels.insert(panels.end(), energy_panels.begin(), energy_panels.end());
  out.add(plot_description{"nonlinear_problems_n",
                           "Nonlinear problems in double: state error at T (top) and the largest relative energy error (bottom) "
                           "against N, log-log",
                           panels, columns, 440 * columns, 720});
  out.add(plot_description{"nonlinear_problems_work",
                           "Nonlinear problems in double: state error at T against work, the ∇V evaluations of the run as the "
                           "steps are written (log-log; Störmer–Verlet and Yoshida keep the force a kick ends with for the next, "
                           "first same as last; the Newton solves' ∇²V and LU are not counted, the run time plot has them)",
                           work_panels, columns, 440 * columns, 380});
  if (timed) {
    plot_description time_plot{"nonlinear_problems_time", "Nonlinear problems in double: state error at T against run time (log-log)",
                               time_panels, columns, 440 * columns, 380};
    time_plot.timing = true;
    out.add(std::move(time_plot));
  }
}

}  // namespace simpson::verify::detail

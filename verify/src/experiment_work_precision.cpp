// The work_precision section: error against run time for the Simpson scheme and its peers, in
// several precisions, each scheme advancing by its own step algorithm.

#include <simpson/verify/experiments.hpp>
#include <simpson/verify/interruption.hpp>

#include "figures.hpp"
#include "schemes.hpp"

#include <simpson/energy.hpp>
#include <simpson/exact_solution.hpp>
#include <simpson/iterate.hpp>

#include <boost/math/constants/constants.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <map>

namespace simpson::verify {
namespace {

using detail::figure;
using detail::figure_text;

/// A file-name form of a precision: "long double" → "long-double", "mpfr:50" → "mpfr50".
std::string file_tag(const precision& p) {
  std::string name;
  for (const char c : p.name()) {
    if (c == ' ') name += '-';
    else if (c != ':') name += c;
  }
  return name;
}

struct measured_run {
  json row;
  double error = 0;   // max of the q error and the scaled p error, for the plots (NaN on a fault)
  double seconds = 0; // minimum run time
};

template <class Real>
measured_run measure(const std::string& scheme, const precision& prec, long long N, long long periods,
                     const timing_policy& timing, const std::vector<phase_point<Real>>& exact) {
  using std::abs;
  using clock = std::chrono::steady_clock;
  const Real omega = 2 * boost::math::constants::pi<Real>();
  const long long steps = N * periods;
  const oscillator_parameters<Real> par{Real(1), omega, step_size(Real(periods), steps)};
  const phase_point<Real> y0{Real(par.m() * omega), Real(0)};
  const detail::scheme_runner<Real> runner(scheme, par);
  json row{{"scheme", scheme}, {"precision", prec.name()}, {"N_per_period", N}, {"steps", steps}};
  measured_run out;
  out.error = std::numeric_limits<double>::quiet_NaN();
  out.seconds = std::numeric_limits<double>::quiet_NaN();

  // The error run (not timed): maxima over every t_j against the exact solution.
  Real error_q(0), error_p(0);
  phase_point<Real> y = y0;
  std::string status = "ok";
  const Real amplitude = abs(y0.p) / (par.m() * omega);
  try {
    for (long long j = 1; j <= steps; ++j) {
      if ((j & 1023) == 0) throw_if_interrupted();
      y = runner.step(y);
      const Real eq = abs(Real(y.q - exact[static_cast<std::size_t>(j)].q));
      const Real ep = abs(Real(y.p - exact[static_cast<std::size_t>(j)].p)) / (par.m() * omega);
      if (!(eq == eq) || !(ep == ep)) {
        status = "non-finite";
        break;
      }
      if (eq > 1e6 * amplitude) {
        status = "unstable";
        break;
      }
      error_q = std::max(error_q, eq);
      error_p = std::max(error_p, ep);
    }
  } catch (const std::domain_error& e) {
    status = std::string("failed: ") + e.what();
  }
  row["status"] = status;
  if (status != "ok") {
    out.row = row;
    return out;
  }
  const Real H0 = energy(par, y0);
  row["error_q_max"] = figure(error_q);
  row["error_p_max_over_m_omega"] = figure(error_p);
  row["error_H_end_relative"] = figure(Real(abs(Real(energy(par, y) - H0)) / H0));
  if (scheme == "simpson" || scheme == "simpson-elimination") {
    const Real Hd0 = discrete_energy(par, y0);
    row["error_Hd_end_relative"] = figure(Real(abs(Real(discrete_energy(par, y) - Hd0)) / abs(Hd0)));
  }
  out.error = static_cast<double>(std::max(error_q, error_p));

  // Timing: one warm-up run, then runs until max_runs or max_seconds; each run is `steps` steps.
  const auto one_run = [&] {
    phase_point<Real> z = y0;
    for (long long j = 0; j < steps; ++j) z = runner.step(z);
    return z;
  };
  volatile double sink = static_cast<double>(one_run().q);
  std::vector<double> seconds;
  const auto start = clock::now();
  while (seconds.size() < timing.max_runs &&
         (seconds.empty() || std::chrono::duration<double>(clock::now() - start).count() < timing.max_seconds)) {
    throw_if_interrupted();
    const auto t0 = clock::now();
    sink = sink + static_cast<double>(one_run().q);
    seconds.push_back(std::chrono::duration<double>(clock::now() - t0).count());
  }
  std::sort(seconds.begin(), seconds.end());
  const double median = seconds.size() % 2 ? seconds[seconds.size() / 2]
                                           : (seconds[seconds.size() / 2 - 1] + seconds[seconds.size() / 2]) / 2;
  row["timing"] = {{"runs", seconds.size()}, {"min_seconds", seconds.front()}, {"median_seconds", median}};
  out.seconds = seconds.front();
  out.row = row;
  return out;
}

}  // namespace

section_output run_work_precision(const work_precision_settings& s) {
  section_output out;
  out.name = "work_precision";
  json rows = json::array();
  std::string csv =
      "scheme,precision,N_per_period,steps,status,error_q_max,error_p_max_over_m_omega,error_H_end_relative,"
      "error_Hd_end_relative,runs,min_seconds,median_seconds\n";
  std::string md = "## Work against precision: error and run time\n\n";
  md += fmt::format(
      "m = 1, ω = 2π, {} period(s), y₀ = (mω, 0); N steps per period. Each scheme advances by its own step algorithm: "
      "Simpson by its explicit map Φ₃ (the paper's form for the oscillator: one 2 × 2 product per step), "
      "simpson-elimination by Section 6's elimination of the internal node at every step, Newmark as the implicit midpoint rule, "
      "Gauss–Legendre and Lobatto IIIA–IIIB by solving their (linear) stage equations at every step, Störmer–Verlet, "
      "Yoshida and RK4 explicitly. Errors: maxima over all t_j of |q_j − q(t_j)| and |p_j − p(t_j)|/(mω); the relative "
      "error of H (and of H_d for Simpson) at the end. Time: one warm-up run, then runs until {} runs or {} s, "
      "steady_clock; minimum and median per run. A run whose state is not finite, grows past 10⁶ times the amplitude, "
      "or throws is recorded with its status. On this linear problem every scheme could be reduced to a 2 × 2 "
      "matrix and cost the same per step; the peers run their general algorithms, as for any force.\n\n",
      s.periods, s.timing.max_runs, simpson::to_string(s.timing.max_seconds, 3));
  md += "| scheme | precision | N | error q | error p/(mω) | H rel. (end) | H_d rel. (end) | status | min time | median time |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
  std::vector<std::string> panels_time, panels_n;
  for (const precision& prec : s.precisions) {
    const std::string tag = file_tag(prec);
    std::string data = fmt::format("# {}: one block per scheme ({}); columns N min_seconds error\n", prec.name(),
                                   fmt::join(s.schemes, ", "));
    detail::visit_floating(prec, [&](auto precision_tag) {
      using Real = typename decltype(precision_tag)::type;
      // The exact solution at every t_j of each N, shared by the schemes.
      std::map<long long, std::vector<phase_point<Real>>> exact_by_N;
      for (const long long N : s.meshes) {
        const Real omega = 2 * boost::math::constants::pi<Real>();
        const long long steps = N * s.periods;
        const oscillator_parameters<Real> par{Real(1), omega, step_size(Real(s.periods), steps)};
        const phase_point<Real> y0{omega, Real(0)};
        std::vector<phase_point<Real>>& exact = exact_by_N[N];
        exact.reserve(static_cast<std::size_t>(steps) + 1);
        for (long long j = 0; j <= steps; ++j) exact.push_back(exact_solution(par, y0, Real(par.h() * Real(j))));
      }
      for (const std::string& scheme : s.schemes) {
        for (const long long N : s.meshes) {
          const long long steps = N * s.periods;
          const std::vector<phase_point<Real>>& exact = exact_by_N[N];
          const measured_run m =
              measure<Real>(scheme, prec, N, s.periods, s.timing, exact);
          const json& r = m.row;
          const auto get = [&](const char* key) { return r.contains(key) ? r[key] : json(""); };
          const json t = r.contains("timing") ? r["timing"] : json::object();
          csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{}\n", scheme, prec.name(), N, r["steps"].get<long long>(),
                             r["status"].get<std::string>(), detail::figure_text(get("error_q_max")),
                             detail::figure_text(get("error_p_max_over_m_omega")), detail::figure_text(get("error_H_end_relative")),
                             detail::figure_text(get("error_Hd_end_relative")), t.value("runs", 0),
                             t.contains("min_seconds") ? simpson::to_string(t["min_seconds"].get<double>(), 3) : "",
                             t.contains("median_seconds") ? simpson::to_string(t["median_seconds"].get<double>(), 3) : "");
          md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", scheme, prec.name(), N,
                            detail::figure_text(get("error_q_max")), detail::figure_text(get("error_p_max_over_m_omega")),
                            detail::figure_text(get("error_H_end_relative")),
                            r.contains("error_Hd_end_relative") ? detail::figure_text(r["error_Hd_end_relative"]) : "",
                            r["status"].get<std::string>(),
                            t.contains("min_seconds") ? simpson::to_string(t["min_seconds"].get<double>(), 3) + " s" : "",
                            t.contains("median_seconds") ? simpson::to_string(t["median_seconds"].get<double>(), 3) + " s" : "");
          data += fmt::format("{} {} {}\n", N, m.seconds == m.seconds ? simpson::to_string(m.seconds, 6) : "NaN",
                              m.error == m.error ? simpson::to_string(m.error, 6) : "NaN");
          // At the round-off floor: within 100 N eps of zero (N steps, each rounding a few times).
          const double floor_level = 100.0 * static_cast<double>(steps) * static_cast<double>(eps<Real>());
          json row = r;
          row["at_round_off_floor"] = m.error == m.error && m.error <= floor_level;
          rows.push_back(row);
        }
        data += "\n\n";
      }
    });
    out.files.push_back({"work_precision_" + tag + ".dat", data});
    const std::string floor_line =
        fmt::format("100*x*{}", simpson::to_string(std::stod(prec.epsilon()), 3));  // 100 N eps
    panels_time.push_back(fmt::format(
        "set title '{}'\nset xlabel 'run time (s, minimum of repeats)'\nset ylabel 'max error'\n"
        "plot for [i=0:{}] 'work_precision_{}.dat' index i u 2:3 w lp lc i+1 pt 7 t word(names, i+1)\n",
        prec.name(), s.schemes.size() - 1, tag));
    panels_n.push_back(fmt::format(
        "set title '{}'\nset xlabel 'N (steps per period)'\nset ylabel 'max error'\n"
        "plot for [i=0:{}] 'work_precision_{}.dat' index i u 1:3 w lp lc i+1 pt 7 t word(names, i+1), "
        "{} w l dt 2 lc rgb 'gray' t 'round-off floor 100 N eps'\n",
        prec.name(), s.schemes.size() - 1, tag, floor_line));
  }
  out.files.push_back({"work_precision.csv", csv});
  const std::size_t columns = std::min<std::size_t>(3, s.precisions.size());
  const std::size_t rows_of_panels = (s.precisions.size() + columns - 1) / columns;
  const std::string common = fmt::format(
      "names = '{}'\nset logscale xy\nset format y '10^{{%L}}'\nset format x '10^{{%L}}'\nset key bottom left font ',8'\n"
      "set multiplot layout {},{}\n",
      fmt::join(s.schemes, " "), rows_of_panels, columns);
  const int width = 420 * static_cast<int>(columns), height = 340 * static_cast<int>(rows_of_panels);
  out.plots.push_back({"work_precision_time", "Maximum error against run time (log-log), one panel per precision",
                       common + fmt::format("{}", fmt::join(panels_time, "")) + "unset multiplot\n", width, height});
  out.plots.push_back({"work_precision_n",
                       "Maximum error against N, one panel per precision; dashed: the round-off floor 100 N eps",
                       common + "set format x '%g'\n" + fmt::format("{}", fmt::join(panels_n, "")) + "unset multiplot\n",
                       width, height});
  out.data["conventions"] = {{"m", 1}, {"omega", "2 pi"}, {"periods", s.periods}, {"start", "y_0 = (m omega, 0)"},
                             {"timing", {{"warm_up_runs", 1}, {"max_runs", s.timing.max_runs}, {"max_seconds", s.timing.max_seconds}}}};
  out.data["rows"] = rows;
  out.markdown = md + "\n![error against run time](work_precision_time.svg)\n\n![error against N](work_precision_n.svg)\n\n" +
                 "Data: work_precision.csv (every metric, one row per scheme, precision and N).\n\n";
  return out;
}

}  // namespace simpson::verify

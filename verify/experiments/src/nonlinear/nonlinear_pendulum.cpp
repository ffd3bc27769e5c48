// The nonlinear section's pendulum table: the Simpson step for V = m ω² (1 − cos q) against the
// exact solution (Jacobi functions) in mpfr, Newton's iterations, the distance to its twin Lobatto
// IIIA–IIIB run beside it, and the energy over long runs in double.

#include "nonlinear_parts.hpp"

#include <simpson/verify/integration_driver.hpp>
#include <simpson/verify/floating_tools.hpp>
#include <simpson/verify/interruption.hpp>
#include <simpson/verify/progress.hpp>

#include <simpson/nonlinear_partitioned_rk.hpp>
#include <simpson/nonlinear_simpson_step.hpp>
#include <simpson/pendulum_exact.hpp>
#include <simpson/potential.hpp>
#include <simpson/runge_kutta_tableaux.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace simpson::verify::detail {
namespace {

/// One row's run in Real: Simpson and Lobatto IIIA–IIIB side by side over N steps.
template <class Real>
struct pendulum_run {
  figure status = figure::text("ok");
  Real error_q{0}, error_p{0}, largest_gap{0}, mean_iterations{0};
  int max_iterations = 0;
};

template <class Real>
pendulum_run<Real> run_pendulum(const nonlinear_settings& s, long long N) {
  using std::abs;
  const Real m(1), omega(1), T(s.pendulum_T), h = T / Real(N);
  const pendulum_potential<Real> V{m, omega};
  const pendulum_from_rest<Real> exact{m, omega, Real(s.pendulum_q0)};
  const auto for_q = lobatto_iiia3_tableau<Real>(), for_p = lobatto_iiib3_tableau<Real>();
  const auto coupling = couple(for_q, for_p);
  pendulum_run<Real> out;
  phase_point<Real> simpson = exact.at(Real(0)), lobatto = simpson;
  long long iterations = 0;
  try {
    for (long long j = 1; j <= N; ++j) {
      if ((j & 255) == 0) throw_if_interrupted();
      const auto step = simpson_nonlinear_step(m, h, V, simpson);
      simpson = step.state;
      lobatto = prk_nonlinear_step(for_q, for_p, coupling, m, h, V, lobatto).state;
      iterations += step.newton_iterations;
      out.max_iterations = std::max(out.max_iterations, step.newton_iterations);
      out.largest_gap = std::max({out.largest_gap, Real(abs(Real(simpson.q - lobatto.q))), Real(abs(Real(simpson.p - lobatto.p)))});
    }
  } catch (const std::domain_error& e) {
    out.status = figure::fault(std::string("failed: ") + e.what());
    return out;
  }
  const phase_point<Real> end = exact.at(T);
  out.error_q = abs(Real(simpson.q - end.q));
  out.error_p = abs(Real(simpson.p - end.p));
  out.mean_iterations = Real(iterations) / Real(N);
  return out;
}

/// The energy over `steps` steps of size h in double: the largest relative change of H, and its
/// per-window maxima against t for the plot.
struct energy_run {
  figure status = figure::text("ok");
  double largest = 0;
  series curve;
};

energy_run run_energy(const nonlinear_settings& s, long long N, int color) {
  const double h = s.pendulum_T / static_cast<double>(N);
  const pendulum_potential<double> V{1, 1};
  phase_point<double> y{0, s.pendulum_q0};
  const auto H = [&V](const phase_point<double>& z) { return z.p * z.p / 2 + V.value(z.q); };
  energy_run out{figure::text("ok"), 0, series(fmt::format("h = {}", simpson::to_string(h, 3)), line_style::lines, color)};
  const long long windows = 200, window = std::max<long long>(1, s.energy_steps / windows);
  // The largest |H(y_j) − H(y₀)|/H(y₀) in each window, drawn at the window's end.
  auto energy = relative_change_of<double>(H);
  auto window_ends = at_samples_of([&](long long j, const phase_point<double>&) {
    if (j == 0) return;
    out.curve.add(figure::of(h * static_cast<double>(j)), figure::of(energy.window_maximum));
    out.largest = std::max(out.largest, energy.window_maximum);
  });
  // window_ends reads each window's maximum before energy's own sample hook closes the window.
  out.status = integrate_n_steps([&](const phase_point<double>& z) { return simpson_nonlinear_step(1.0, h, V, z).state; }, y,
                                 s.energy_steps, window, never_stop{}, window_ends, energy)
                   .status;
  return out;
}

}  // namespace

void add_nonlinear_pendulum(const nonlinear_settings& s, section_result& out) {
  const precision prec = precision::mpfr_digits(s.mpfr_digits);
  table rows{"pendulum", "The pendulum: convergence, Newton's iterations, Lobatto IIIA–IIIB beside it",
             fmt::format("V = mω²(1 − cos q), m = ω = 1, q(0) = {} rad, p(0) = 0, T = {}, h = T/N; in {} against the exact "
                         "solution q(t) = 2 asin(k sn(K − ωt, k)), k = sin(q₀/2) (Boost.Math jacobi_elliptic, ellint_1, in "
                         "the same precision). Each step solves the internal node's equation by Newton's method to 16 eps of "
                         "its terms. |S − L|: the largest difference in q or p between the Simpson run and a Lobatto "
                         "IIIA–IIIB run beside it (its stage equations solved by the same Newton rule), over the whole run. "
                         "Energy: the largest |H(y_j) − H(y₀)|/H(y₀) over {} steps of the same h in double. Orders: "
                         "log₂ of the error ratios.",
                         fmt::format("{:g}", s.pendulum_q0), fmt::format("{:g}", s.pendulum_T), prec.name(), s.energy_steps),
             {{"N", "N"},
              {"h", "h"},
              {"error_q", "|q_N − q(T)|"},
              {"error_p", "|p_N − p(T)|"},
              {"order_q", "order q"},
              {"order_p", "order p"},
              {"newton_iterations_mean", "Newton it./step"},
              {"newton_iterations_max", "max it."},
              {"max_simpson_minus_lobatto", "max |S − L|"},
              {"energy_steps", "steps (double)"},
              {"energy_error_max_double", "max rel. H error (double)"},
              {"status", "status"}}};
  rows.csv_file = "nonlinear_pendulum.csv";
  panel errors{"Error at T against N (" + prec.name() + ")", {"N", true}, {"error", true}, {}, "bottom left"};
  panel energies{"Relative energy error, double", {"t", true}, {"per-window max |H - H_0|/H_0", true}, {}, "bottom right"};
  double first_ok_N = 0;
  series error_q("|q_N - q(T)|", line_style::lines_points, 1, 7), error_p("|p_N - p(T)|", line_style::lines_points, 2, 5, 2);
  visit_mpfr(s.mpfr_digits, [&](auto tag) {
    using Real = typename decltype(tag)::type;
    std::vector<pendulum_run<Real>> runs;
    std::vector<Real> eq, ep;
    std::vector<long long> ok_N;
    for (const long long N : s.pendulum_N) {
      runs.push_back(run_pendulum<Real>(s, N));
      progress_step(s.progress, "nonlinear", fmt::format("pendulum {} N = {}", prec.name(), N));
      if (runs.back().status.is_fault()) continue;
      eq.push_back(runs.back().error_q);
      ep.push_back(runs.back().error_p);
      ok_N.push_back(N);
    }
    const std::vector<Real> order_q = observed_orders(ok_N, eq), order_p = observed_orders(ok_N, ep);
    std::size_t ok = 0;
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const long long N = s.pendulum_N[k];
      const pendulum_run<Real>& r = runs[k];
      const energy_run e = run_energy(s, N, static_cast<int>(k) + 1);
      const bool failed = r.status.is_fault();
      const bool has_order = !failed && ok > 0;
      rows.add({figure::integer(N), figure::of(Real(Real(s.pendulum_T) / Real(N))), failed ? figure{} : figure::of(r.error_q),
                failed ? figure{} : figure::of(r.error_p), has_order ? figure::of(order_q[ok - 1]) : figure{},
                has_order ? figure::of(order_p[ok - 1]) : figure{}, failed ? figure{} : figure::of(r.mean_iterations),
                failed ? figure{} : figure::integer(r.max_iterations), failed ? figure{} : figure::of(r.largest_gap),
                figure::integer(s.energy_steps), e.status.is_fault() ? e.status : figure::of(e.largest),
                failed ? r.status : e.status});
      if (!failed) {
        if (ok == 0) first_ok_N = static_cast<double>(N);
        error_q.add(figure::integer(N), figure::of(r.error_q));
        error_p.add(figure::integer(N), figure::of(r.error_p));
        ++ok;
      }
      energies.curves.push_back(e.curve);
    }
  });
  errors.curves.push_back(error_q);
  errors.curves.push_back(error_p);
  if (const auto e0 = error_q.y.empty() ? std::nullopt : error_q.y.front().plottable(); e0 && *e0 > 0) {
    errors.curves.push_back(slope_guide("slope N^{-4}", 9, first_ok_N, *e0 / 4, s.pendulum_N, 4));
  }
  out.add(std::move(rows));
  out.add(plot_description{"nonlinear_pendulum",
                           "The pendulum: error at T against N (log-log, dashed guide N⁻⁴), and the relative energy error "
                           "over long runs in double (per-window maxima against t, one curve per h)",
                           {errors, energies}, 2, 1100, 450});
}

}  // namespace simpson::verify::detail

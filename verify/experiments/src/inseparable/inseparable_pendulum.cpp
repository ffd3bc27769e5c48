// The nonlinear_inseparable section's double pendulum: the five methods in double against an MPFR
// reference (reference_flow.hpp), inside the predictability horizon its Lyapunov exponent gives.

#include "inseparable_parts.hpp"

#include <simpson/verify/interruption.hpp>
#include <simpson/verify/progress.hpp>

#include <simpson/double_pendulum.hpp>
#include <simpson/lyapunov_exponent.hpp>
#include <simpson/reference_flow.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace simpson::verify::detail {

part_runs run_pendulum_part(const inseparable_settings& s, section_result& out) {
  const inseparable_pendulum_settings& d = s.pendulum;
  const simpson::double_pendulum<double> L{d.m1, d.m2, d.l1, d.l2, d.g};
  dense_vector<double> q(2), v(2);
  q << d.theta1, d.theta2;
  v << d.omega1, d.omega2;
  const ndof_state<double> y0{lagrangian_gradient_at(L, q, v).dv, q};
  const double T = s.pendulum_end_time;

  // The reference: the Hamiltonian equations in MPFR from the same double start (exactly).
  const unsigned digits = static_cast<unsigned>(std::ceil(s.pendulum_reference_digits)) + 10;
  const scoped_mpfr_digits mdigits(digits);
  const simpson::double_pendulum<mpfr> Lm{mpfr(d.m1), mpfr(d.m2), mpfr(d.l1), mpfr(d.l2), mpfr(d.g)};
  const ndof_state<mpfr> ym{dense_vector<mpfr>(y0.p.cast<mpfr>()), dense_vector<mpfr>(y0.q.cast<mpfr>())};
  const reference_state ref = lagrangian_reference(Lm, ym, mpfr(T), s.pendulum_reference_digits, 32, 7);
  progress_step(s.progress, "nonlinear_inseparable", "double pendulum: the MPFR reference");

  // The largest Lyapunov exponent, from RK4 steps of 0.01 in double, renormalised every 10 steps.
  const double h_lyapunov = 0.01;
  const int renormalisations = std::max(2, static_cast<int>(s.lyapunov_time / (10 * h_lyapunov)));
  const auto rk4 = [&](const ndof_state<double>& y) { return rk4_hamiltonian_step(L, h_lyapunov, y).state; };
  const lyapunov_estimate<double> lyapunov = largest_lyapunov_exponent(rk4, y0, h_lyapunov, 10, renormalisations, 1e-8);
  progress_step(s.progress, "nonlinear_inseparable", "double pendulum: the Lyapunov exponent");
  const double start_error = std::numeric_limits<double>::epsilon(), tolerance = 1e-6;
  const bool chaotic = lyapunov.exponent > 0;
  const double horizon = chaotic ? predictability_horizon(lyapunov.exponent, start_error, tolerance) : INFINITY;

  out.text(fmt::format(
      "### The nonlinear double pendulum\n\nMasses m₁ = {}, m₂ = {} on rods l₁ = {}, l₂ = {}, g = {}, angles from the downward vertical, "
      "L = ½(m₁ + m₂)l₁²θ̇₁² + ½m₂l₂²θ̇₂² + m₂l₁l₂θ̇₁θ̇₂ cos(θ₁ − θ₂) + (m₁ + m₂)gl₁ cos θ₁ + m₂gl₂ cos θ₂: a configuration-dependent mass, "
      "H not separable. Start θ₁ = {}, θ₂ = {}, θ̇₁ = {}, θ̇₂ = {}. The reference integrates the Hamiltonian equations in MPFR ({} digits) by "
      "Fehlberg's 7(8) at fixed steps from the same double start, halved until two runs agree: to {:.1f} digits at {} steps. "
      "**Largest Lyapunov exponent: {:.4g}** per unit time (Benettin's two-trajectory estimate, RK4 with h = {} in double, renormalised every "
      "10 steps over t = {:.4g}; after half the time it read {:.4g}). {}",
      d.m1, d.m2, d.l1, d.l2, d.g, d.theta1, d.theta2, d.omega1, d.omega2, digits, ref.agreed_digits, ref.steps, lyapunov.exponent, h_lyapunov,
      lyapunov.time, lyapunov.first_half,
      chaotic ? fmt::format("An error of one unit of double's round-off at the start grows to {} in about ln({} / eps) / λ = {:.3g} time units: the "
                            "comparison at T = {} is {} that horizon.",
                            tolerance, tolerance, horizon, T, T < horizon ? "inside" : "**outside**")
              : std::string("The estimate is not positive: no horizon limits the comparison.")));
  out.expect({"pendulum-inside-horizon",
              "The double pendulum's comparison time lies inside its predictability horizon.",
              fmt::format("T < ln({} / eps) / λ, λ estimated", tolerance),
              chaotic ? fmt::format("T = {}, horizon {:.3g} (λ = {:.3g})", T, horizon, lyapunov.exponent) : fmt::format("λ = {:.3g}: no horizon", lyapunov.exponent),
              T < horizon});

  table errors{"pendulum_errors", "The double pendulum: error against N",
               fmt::format("max over q and p of |y − y_ref| at T = {} (computed in MPFR from the double run), Newton's iterations per step.", T),
               {{"method", "method"}, {"N", "N"}, {"h", "h", "", 0}, {"error", "max |y − y_ref|"}, column::fixed_point("newton_per_step", "Newton / step", 2),
                {"status", "status"}}};
  table seconds{"pendulum_seconds", "The double pendulum: run times", "Each run's wall time on this machine, once.",
                {{"method", "method"}, {"N", "N"}, {"seconds", "seconds", "s"}}};
  seconds.timing = true;
  table orders{"pendulum_orders", "The double pendulum: local orders",
               "log(e_N / e_2N) / log 2 of the state error against the MPFR reference (measured: the reference's error is below 10^-digits "
               "agreed); pairs whose finer error is above the rounding allowance 1000 N eps e^{λT} (the flow amplifies roundings as it "
               "amplifies any error).",
               {{"method", "method"}, {"order", "expected order"}, {"local_orders", "local orders"}}};
  // The rounding allowance of a run of N steps: 1000 N eps, as the top's, times e^{λT}: the flow
  // amplifies a rounding error as it amplifies any other, by up to e^{λT} by T.
  const double amplification = std::max(1.0, std::exp(std::max(0.0, lyapunov.exponent) * T));
  const auto allowance = [&](long long N) { return 1000 * static_cast<double>(N) * std::numeric_limits<double>::epsilon() * amplification; };
  part_runs runs{{}, "double pendulum"};
  std::vector<series> by_N, by_time;
  std::string simpson_orders;
  bool simpson_order_holds = true;
  int simpson_pairs = 0;
  for (const ins_method m : ins_methods) {
    series e = styled_series(m, name_of(m)), t = styled_series(m, name_of(m));
    std::vector<convergence_point> points;
    for (const long long N : s.pendulum_N) {
      throw_if_interrupted();
      const double h = T / static_cast<double>(N);
      const ins_run r = run_method(m, L, y0, h, N, [](long long, const ins_step&) {});
      progress_step(s.progress, "nonlinear_inseparable", fmt::format("double pendulum: {} at N = {}", name_of(m), N));
      convergence_point p;
      p.N = N;
      p.run = r;
      p.seconds = r.seconds;
      if (r.ok()) {
        mpfr gap(0);
        for (Eigen::Index i = 0; i < 2; ++i) {
          gap = std::max(gap, mpfr(abs(mpfr(mpfr(r.state.q(i)) - ref.state.q(i)))));
          gap = std::max(gap, mpfr(abs(mpfr(mpfr(r.state.p(i)) - ref.state.p(i)))));
        }
        p.error = static_cast<double>(gap);
        p.shown = figure::of(gap);
      } else {
        p.error = INFINITY;
        p.shown = figure::fault(*r.failure);
      }
      errors.add({figure::text(name_of(m)), figure::integer(N), figure::of(h), p.shown,
                  figure::of(static_cast<double>(r.newton_iterations) / static_cast<double>(std::max(1LL, r.steps))),
                  r.ok() ? figure::text("ok") : figure::fault(*r.failure)});
      seconds.add({figure::text(name_of(m)), figure::integer(N), figure::of(r.seconds)});
      if (r.ok() && p.error > 0) {
        e.add(figure::integer(N), p.shown);
        t.add(figure::of(r.seconds), p.shown);
      }
      points.push_back(std::move(p));
    }
    std::vector<std::string> parts;
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
      const convergence_point &a = points[k], &b = points[k + 1];
      if (!a.run.ok() || !b.run.ok() || !(b.error > allowance(b.N))) continue;
      const double p = std::log(a.error / b.error) / std::log(static_cast<double>(b.N) / static_cast<double>(a.N));
      parts.push_back(fmt::format("{}→{}: {:.3f}", a.N, b.N, p));
      if (m == ins_method::simpson) {
        ++simpson_pairs;
        if (k + 2 >= points.size() || !(points[k + 2].error > allowance(points[k + 2].N))) {
          simpson_order_holds = std::abs(p - 4) < 0.5;  // the finest pair used
        }
      }
    }
    const std::string text = parts.empty() ? std::string("no pair above the rounding allowance") : fmt::format("{}", fmt::join(parts, ", "));
    if (m == ins_method::simpson) simpson_orders = text;
    orders.add({figure::text(name_of(m)), figure::integer(order_of(m)), figure::text(text)});
    by_N.push_back(std::move(e));
    by_time.push_back(std::move(t));
    runs.by_method.push_back(std::move(points));
  }
  out.add(std::move(errors));
  if (s.timed) out.add(std::move(seconds));
  out.add(std::move(orders));
  out.expect({"pendulum-simpson-order",
              "On the nonlinear double pendulum, Simpson's variational step converges at order 4 against the MPFR reference.",
              "the finest local order above the rounding allowance within 1/2 of 4 (measured)", simpson_orders,
              simpson_order_holds && simpson_pairs >= 1});
  out.add(plot_description{"inseparable_pendulum_error",
                           fmt::format("The double pendulum: max |y − y_ref| at T = {} against N (log–log).", T),
                           {panel{"double pendulum", axis{"N", true}, axis{"max |y − y_ref|", true}, by_N, "bottom left"}}});
  if (s.timed) {
    plot_description p{"inseparable_pendulum_time", "The double pendulum: max |y − y_ref| against the run's seconds (log–log).",
                       {panel{"double pendulum", axis{"seconds", true}, axis{"max |y − y_ref|", true}, by_time, "bottom left"}}};
    p.timing = true;
    out.add(std::move(p));
  }
  return runs;
}

}  // namespace simpson::verify::detail

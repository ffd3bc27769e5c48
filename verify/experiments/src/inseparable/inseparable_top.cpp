// The nonlinear_inseparable section's Lagrange top: the five methods in double against the top's exact
// motion enclosed (lagrange_top_exact.hpp, Arb), their orders decided by the enclosed errors, and the
// cyclic momenta and the energy over long runs.

#include "inseparable_parts.hpp"

#include "../enclosed_figures.hpp"

#include <simpson/verify/enclosure_undecided.hpp>
#include <simpson/verify/interruption.hpp>
#include <simpson/verify/progress.hpp>

#include <simpson/interval.hpp>
#include <simpson/lagrange_top.hpp>
#include <simpson/lagrange_top_exact.hpp>
#include <simpson/legendre_hamiltonian.hpp>
#include <simpson/reference_flow.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace simpson::verify {

void check_inseparable_top(const inseparable_top_settings& t) {
  const lagrange_top<double> top(t.I1, t.I3, t.Mgl);  // names 'I1', 'I3', 'Mgl'
  top.check_state(top_state<double>{t.theta0, 0, 0, t.theta_dot0, t.phi_dot0, t.psi_dot0});  // names 'theta', the rates
}

namespace detail {

namespace {
constexpr double eps = std::numeric_limits<double>::epsilon();
}  // namespace

/// The rounding allowance of a run of N steps: 1000 N eps (θ is of order 1). A run's roundings make
/// a random walk of about √N eps and add up to at most a few N eps; a pair is used when its finer
/// error is above this, so that the truncation error dominates what is measured.
double rounding_allowance(long long N) { return 1000 * static_cast<double>(N) * eps; }

order_decision decide_order(const std::vector<long long>& N, const std::vector<interval>& errors, int order) {
  order_decision d;
  const double lo = order - 0.5, hi = order + 0.5;  // exact in double and in the interval's digits
  std::vector<std::string> parts;
  bool refuted = false, all_within = true;
  for (std::size_t k = 0; k + 1 < errors.size(); ++k) {
    const bool use = lower(errors[k + 1]) > rounding_allowance(N[k + 1]) && lower(errors[k + 1]) > 0;
    d.used.push_back(use);
    if (!use) {
      d.local.emplace_back(0);
      continue;
    }
    const interval p = log(interval(errors[k] / errors[k + 1])) / log(interval(N[k + 1]) / interval(N[k]));
    d.local.push_back(p);
    ++d.pairs_used;
    const bool within = lower(p) > lo && upper(p) < hi;
    const bool outside = upper(p) < lo || lower(p) > hi;
    all_within = all_within && within;
    refuted = refuted || outside;
    parts.push_back(fmt::format("{}→{}: {}", N[k], N[k + 1], enclosure_text(p, 4)));
  }
  if (refuted) {
    d.outcome = order_decision::verdict::refuted;
  } else if (all_within && d.pairs_used >= 2) {
    d.outcome = order_decision::verdict::proved;
  }
  d.text = parts.empty() ? std::string("no pair above the rounding allowance") : fmt::format("{}", fmt::join(parts, ", "));
  return d;
}

namespace {

ndof_state<double> top_start(const lagrange_top<double>& L, const inseparable_top_settings& t) {
  dense_vector<double> q(3), v(3);
  q << t.theta0, 0, 0;
  v << t.theta_dot0, t.phi_dot0, t.psi_dot0;
  return {lagrangian_gradient_at(L, q, v).dv, q};  // p = ∂L/∂v, rounded once in double
}

lagrange_top<interval> top_enclosed(const inseparable_top_settings& t) { return {interval(t.I1), interval(t.I3), interval(t.Mgl)}; }

top_state<interval> start_enclosed(const inseparable_top_settings& t) {
  return {interval(t.theta0), interval(0), interval(0), interval(t.theta_dot0), interval(t.phi_dot0), interval(t.psi_dot0)};
}

double energy_of(const lagrange_top<double>& L, const ndof_state<double>& y) { return legendre_hamiltonian(L, y.q, y.p, false).value; }

std::string verdict_word(order_decision::verdict v) {
  switch (v) {
    case order_decision::verdict::proved: return "proved";
    case order_decision::verdict::refuted: return "refuted";
    case order_decision::verdict::undecided: return "undecided";
  }
  return "";
}

/// One method's convergence run on the top: θ's error enclosed, the energy's and the momenta's.
struct top_point {
  convergence_point point;
  interval theta_error;
  double max_energy_error = 0, max_momentum_change = 0;
  double theta_at_end = 0;
};

/// Everything the top's convergence runs find; the order fact reads it too.
struct top_convergence {
  std::vector<std::vector<top_point>> by_method;
  std::vector<order_decision> theta_orders;
  std::vector<std::string> energy_orders;  // measured in double, as text
  std::vector<bool> energy_order_holds;
  interval theta_exact;
};

/// θ's error is taken at this many times of each run, t_k = (kN/10) h: the same times for every N
/// that 10 divides.
constexpr int checkpoints = 10;

top_convergence converge_top(const inseparable_settings& s, const progress_sink& progress) {
  const lagrange_top<double> L(s.top.I1, s.top.I3, s.top.Mgl);
  const ndof_state<double> y0 = top_start(L, s.top);
  const double H0 = energy_of(L, y0);
  const scoped_interval_digits digits(s.exact_digits);
  const lagrange_top_exact exact(top_enclosed(s.top), start_enclosed(s.top));
  top_convergence out;
  for (const ins_method m : ins_methods) {
    std::vector<top_point> points;
    for (const long long N : s.top_N) {
      throw_if_interrupted();
      const double h = s.top_end_time / static_cast<double>(N);
      double max_energy = 0, max_momentum = 0;
      // θ's error at `checkpoints` times j h, j = kN/checkpoints: its largest, enclosed. The largest over
      // the run, not the error at T alone, which a nutation's phase error can make cross zero.
      interval worst(0);
      int next = 1;
      const ins_run r = run_method(m, L, y0, h, N, [&](long long j, const ins_step& step) {
        max_energy = std::max(max_energy, std::abs(energy_of(L, step.state) - H0));
        max_momentum = std::max({max_momentum, std::abs(step.state.p(1) - y0.p(1)), std::abs(step.state.p(2) - y0.p(2))});
        if (next <= checkpoints && j == std::max(1LL, next * N / checkpoints)) {
          interval theta = exact.at(interval(h) * interval(j)).state.theta;
          if (s.perturb_exact != 0) theta += interval(s.perturb_exact);
          const interval e = abs(interval(interval(step.state.q(0)) - theta));
          worst = interval(std::max(lower(worst), lower(e)), std::max(upper(worst), upper(e)));
          ++next;
        }
      });
      progress_step(progress, "nonlinear_inseparable", fmt::format("top: {} at N = {}", name_of(m), N));
      top_point p;
      p.point.N = N;
      p.point.run = r;
      p.point.seconds = r.seconds;
      p.max_energy_error = max_energy;
      p.max_momentum_change = max_momentum;
      if (r.ok()) {
        p.theta_error = worst;
        p.point.error = static_cast<double>(median(p.theta_error));
        p.point.shown = enclosed_figure(p.theta_error);
        p.theta_at_end = r.state.q(0);
      } else {
        p.point.shown = figure::fault(*r.failure);
        p.point.error = INFINITY;
      }
      points.push_back(std::move(p));
    }
    std::vector<interval> errors;
    std::vector<long long> Ns;
    std::vector<double> energy;
    for (const top_point& p : points) {
      if (!p.point.run.ok()) break;
      errors.push_back(p.theta_error);
      Ns.push_back(p.point.N);
      energy.push_back(p.max_energy_error);
    }
    out.theta_orders.push_back(decide_order(Ns, errors, order_of(m)));
    // The energy's local orders, in double: pairs whose finer error is above 1000 N eps |H₀|.
    std::vector<std::string> e_parts;
    bool e_holds = true;
    int e_used = 0;
    for (std::size_t k = 0; k + 1 < energy.size(); ++k) {
      if (!(energy[k + 1] > rounding_allowance(Ns[k + 1]) * std::abs(H0))) continue;
      const double p = std::log(energy[k] / energy[k + 1]) / std::log(static_cast<double>(Ns[k + 1]) / static_cast<double>(Ns[k]));
      ++e_used;
      e_holds = e_holds && std::abs(p - order_of(m)) < 0.5;
      e_parts.push_back(fmt::format("{}→{}: {:.3f}", Ns[k], Ns[k + 1], p));
    }
    out.energy_orders.push_back(e_parts.empty() ? std::string("no pair above the rounding allowance") : fmt::format("{}", fmt::join(e_parts, ", ")));
    out.energy_order_holds.push_back(e_holds && e_used >= 2);
    out.by_method.push_back(std::move(points));
  }
  out.theta_exact = exact.at(interval(s.top_end_time)).state.theta;
  return out;
}

/// One long run: the momenta's largest changes against the sums of the steps' bounds, the energy's
/// largest error in the first and the last tenth, and |ΔE| per window for the plot.
struct long_run {
  ins_method method;
  double h = 0;
  ins_run run;
  double max_dp_phi = 0, max_dp_psi = 0, bound_phi = 0, bound_psi = 0;
  bool within_bound = true;  // |Δp_k| after step j ≤ Σ_{i≤j} bound_k(i), at every j
  double first_tenth = 0, last_tenth = 0;
  std::vector<std::pair<double, double>> energy_windows;  // (t, max |ΔE| over the window)
};

long_run run_long(ins_method m, const lagrange_top<double>& L, const ndof_state<double>& y0, double h, long long steps, int samples) {
  const double H0 = energy_of(L, y0);
  long_run out;
  out.method = m;
  out.h = h;
  const long long tenth = std::max(1LL, steps / 10), window = std::max(1LL, steps / samples);
  double window_max = 0;
  out.run = run_method(m, L, y0, h, steps, [&](long long j, const ins_step& step) {
    const double dphi = std::abs(step.state.p(1) - y0.p(1)), dpsi = std::abs(step.state.p(2) - y0.p(2));
    out.bound_phi += step.noether_bound(1);
    out.bound_psi += step.noether_bound(2);
    out.max_dp_phi = std::max(out.max_dp_phi, dphi);
    out.max_dp_psi = std::max(out.max_dp_psi, dpsi);
    out.within_bound = out.within_bound && dphi <= out.bound_phi && dpsi <= out.bound_psi;
    const double e = std::abs(energy_of(L, step.state) - H0);
    if (j <= tenth) out.first_tenth = std::max(out.first_tenth, e);
    if (j > steps - tenth) out.last_tenth = std::max(out.last_tenth, e);
    window_max = std::max(window_max, e);
    if (j % window == 0) {
      out.energy_windows.emplace_back(static_cast<double>(j) * h, window_max);
      window_max = 0;
    }
  });
  return out;
}

/// The long runs' methods; VPRK (Simpson's map in velocity form, its step about as dear as
/// Simpson's) at the first h only.
constexpr std::array<ins_method, 4> long_methods{ins_method::simpson, ins_method::midpoint, ins_method::rk4, ins_method::vprk};

/// The convergence runs' tables (error against N, run times, orders), the orders' expectations, the
/// VPRK remark and the error plots; the runs, for the section's work-precision part.
part_runs add_convergence(const inseparable_settings& s, const top_convergence& c, section_result& out) {
  // Error against N.
  table errors{"top_errors", "The top: error against N",
               fmt::format("max_k |θ − θ(t_k)| over ten times up to T = {} (enclosed: the run's own error, only guaranteed digits), the largest |H − H₀| over the run "
                           "(double), the largest change of p_φ or p_ψ over the run, and Newton's iterations per step. VPRK is "
                           "GeometricIntegrators' variational form of Lobatto IIIA–IIIB(3) with its null vector (vprk_step.hpp).",
                           s.top_end_time),
               {{"method", "method"},
                {"N", "N"},
                {"h", "h", "", 0},
                {"theta_error", "max |θ − θ(t_k)|"},
                {"max_energy_error", "max |ΔH|"},
                {"max_momentum_change", "max |Δp_φ|, |Δp_ψ|"},
                column::fixed_point("newton_per_step", "Newton / step", 2),
                {"status", "status"}}};
  table seconds{"top_seconds", "The top: run times", "Each convergence run's wall time on this machine, once.",
                {{"method", "method"}, {"N", "N"}, {"seconds", "seconds", "s"}}};
  seconds.timing = true;
  part_runs runs{{}, "top"};
  std::vector<series> by_N, by_time;
  for (std::size_t k = 0; k < ins_methods.size(); ++k) {
    const ins_method m = ins_methods[k];
    series e = styled_series(m, name_of(m)), t = styled_series(m, name_of(m));
    std::vector<convergence_point> points;
    for (const top_point& p : c.by_method[k]) {
      const double h = s.top_end_time / static_cast<double>(p.point.N);
      const bool ok = p.point.run.ok();
      errors.add({figure::text(name_of(m)), figure::integer(p.point.N), figure::of(h), p.point.shown,
                  ok ? figure::of(p.max_energy_error) : figure{}, ok ? figure::of(p.max_momentum_change) : figure{},
                  figure::of(static_cast<double>(p.point.run.newton_iterations) / static_cast<double>(std::max(1LL, p.point.run.steps))),
                  ok ? figure::text("ok") : figure::fault(*p.point.run.failure)});
      seconds.add({figure::text(name_of(m)), figure::integer(p.point.N), figure::of(p.point.seconds)});
      if (ok && p.point.error > 0) {
        e.add(figure::integer(p.point.N), p.point.shown);
        t.add(figure::of(p.point.seconds), p.point.shown);
      }
      points.push_back(p.point);
    }
    by_N.push_back(std::move(e));
    by_time.push_back(std::move(t));
    runs.by_method.push_back(std::move(points));
  }
  // Slopes 4 and 2, below Simpson's (a factor 20: Lobatto runs 4 below it) and the midpoint rule's (4) first points.
  for (const ins_method m : {ins_method::simpson, ins_method::midpoint}) {
    const std::size_t k = m == ins_method::simpson ? 0 : 1;
    if (!c.by_method[k].empty() && c.by_method[k].front().point.run.ok() && c.by_method[k].front().point.error > 0) {
      const top_point& first = c.by_method[k].front();
      by_N.push_back(slope_guide(fmt::format("slope {}", order_of(m)), style_for(m).color, static_cast<double>(first.point.N),
                                 first.point.error / (m == ins_method::simpson ? 20 : 4), s.top_N, order_of(m)));
    }
  }
  out.add(std::move(errors));
  if (s.timed) out.add(std::move(seconds));
  // The orders.
  table orders{"top_orders", "The top: orders",
               "Local orders log(e_N / e_2N) / log 2 of θ's error, each an enclosure (from the enclosed errors); a pair is used when its finer "
               "error is above the rounding allowance 1000 N eps (a run's roundings are a random walk of about √N eps). The order is proved "
               "when at least two pairs are used and each lies within 1/2 of it (the margin is ours: the next term of the error shifts a local "
               "order by O(h)), refuted when a used pair lies wholly outside. The energy's local orders are of the largest |ΔH| over the run, "
               "in double, by the same rule (allowance 1000 N eps |H₀|): measured, not enclosed.",
               {{"method", "method"}, {"order", "expected order"}, {"theta_orders", "θ: local orders"}, {"theta_verdict", "θ: order"},
                {"energy_orders", "energy: local orders"}, {"energy_verdict", "energy: order"}}};
  for (std::size_t k = 0; k < ins_methods.size(); ++k) {
    const ins_method m = ins_methods[k];
    orders.add({figure::text(name_of(m)), figure::integer(order_of(m)), figure::text(c.theta_orders[k].text),
                figure::text(verdict_word(c.theta_orders[k].outcome)), figure::text(c.energy_orders[k]),
                figure::text(c.energy_order_holds[k] ? "within 1/2" : "not within 1/2")});
  }
  out.add(std::move(orders));
  for (const ins_method m : {ins_method::simpson, ins_method::midpoint}) {
    const std::size_t k = m == ins_method::simpson ? 0 : 1;
    out.expect({"top-" + name_of(m) + "-order",
                fmt::format("On the Lagrange top, {} is of order {} in nutation θ (decided by enclosures) and in energy (measured in double).",
                            name_of(m), order_of(m)),
                fmt::format("order {} (the classical order of the method)", order_of(m)),
                fmt::format("θ: {} ({}); energy: {} ({})", verdict_word(c.theta_orders[k].outcome), c.theta_orders[k].text, c.energy_orders[k],
                            c.energy_order_holds[k] ? "within 1/2" : "not within 1/2"),
                c.theta_orders[k].outcome == order_decision::verdict::proved && c.energy_order_holds[k]});
  }
  // Simpson and VPRK: the same map (vprk_step.hpp), so their θ agree to round-off.
  {
    double gap = 0;
    for (std::size_t j = 0; j < c.by_method[0].size() && j < c.by_method[4].size(); ++j) {
      gap = std::max(gap, std::abs(c.by_method[0][j].theta_at_end - c.by_method[4][j].theta_at_end));
    }
    out.text(fmt::format("GeometricIntegrators' VPRK form of Lobatto IIIA–IIIB(3), with its null vector, is Simpson's map in velocity form "
                         "(vprk_step.hpp): their θ(T) differ by at most {:.2g} here, and its order on the top is Simpson's 4, not the 2 "
                         "that GeometricIntegrators' report measured on a degenerate Lagrangian. Lobatto IIIA–IIIB on the Hamiltonian "
                         "is the cubic Galerkin step, not Simpson's: with a configuration-dependent mass the two differ.",
                         gap));
  }
  out.add(plot_description{"inseparable_top_error",
                           fmt::format("The top: the largest |θ − θ(t_k)| over ten times up to T = {} against N (log–log, each point an enclosure's "
                                       "midpoint).",
                                       s.top_end_time),
                           {panel{"Lagrange top", axis{"N", true}, axis{"max |θ − θ(t_k)|", true}, by_N, "bottom left"}}});
  if (s.timed) {
    plot_description p{"inseparable_top_time", "The top: the largest |θ − θ(t_k)| against the run's seconds (log–log).",
                       {panel{"Lagrange top", axis{"seconds", true}, axis{"max |θ − θ(t_k)|", true}, by_time, "bottom left"}}};
    p.timing = true;
    out.add(std::move(p));
  }
  return runs;
}

/// Nutation θ(t) against the exact one, at the coarsest N.
void add_nutation_plot(const inseparable_settings& s, const lagrange_top_exact& exact, const lagrange_top<double>& L, const ndof_state<double>& y0,
                       section_result& out) {
  const long long N = s.top_N.front();
  const double h = s.top_end_time / static_cast<double>(N);
  std::vector<series> curves;
  series ex("exact θ(t) (enclosed)", line_style::lines, 8, 0, 1);
  const int points = std::max(2, s.samples);
  for (int i = 0; i <= points; ++i) {
    const double t = s.top_end_time * i / points;
    ex.add(figure::of(t), enclosed_figure(exact.at(interval(t)).state.theta));
  }
  curves.push_back(std::move(ex));
  for (const ins_method m : {ins_method::simpson, ins_method::midpoint}) {
    series c2 = styled_series(m, fmt::format("{}, N = {}", name_of(m), N));
    c2.style = line_style::points;
    c2.add(figure::of(0.0), figure::of(y0.q(0)));
    run_method(m, L, y0, h, N, [&](long long j, const ins_step& step) { c2.add(figure::of(static_cast<double>(j) * h), figure::of(step.state.q(0))); });
    curves.push_back(std::move(c2));
  }
  out.add(plot_description{"inseparable_top_nutation",
                           fmt::format("The top's nutation θ(t): the exact motion (enclosed, its midpoint drawn) and each step of Simpson and "
                                       "the midpoint rule at N = {} (h = {:.3g}).",
                                       N, h),
                           {panel{"nutation", axis{"t"}, axis{"θ (rad)"}, curves, "below"}}});
}

/// Long runs: the momenta against the sums of their per-step bounds, and the energy, with their
/// expectations and the energy plot.
void add_long_runs(const inseparable_settings& s, const lagrange_top<double>& L, const ndof_state<double>& y0, section_result& out) {
  // Long runs: the momenta and the energy.
  table long_table{"top_long_runs", fmt::format("The top over {} steps", s.long_steps),
                   "Each method at each h: the largest change of p_φ and of p_ψ over the run, and beside it the sum over the steps of each step's "
                   "bound (discrete_lagrangian_step.hpp: the Newton residual left at the stated tolerance, 16 eps of the terms, and the "
                   "update's rounding; zero for RK4, whose update of a cyclic momentum adds h Σ b_i ∂H/∂φ = 0 exactly); whether every step "
                   "kept within the running sum; and the largest |H − H₀| in the first and in the last tenth of the run: a drift shows as growth.",
                   {{"method", "method"},
                    {"h", "h", "", 0},
                    {"steps", "steps"},
                    {"max_dp_phi", "max |Δp_φ|"},
                    {"bound_phi", "Σ bound φ"},
                    {"max_dp_psi", "max |Δp_ψ|"},
                    {"bound_psi", "Σ bound ψ"},
                    {"within", "within"},
                    {"energy_first", "max |ΔH|, first tenth"},
                    {"energy_last", "max |ΔH|, last tenth"},
                    {"status", "status"}}};
  bool momenta_ok = true, rk4_exact = true, rk4_drifts = true;
  std::vector<double> simpson_last, rk4_last;
  std::vector<std::string> momenta_text, energy_text;
  std::vector<series> energy_curves;
  for (std::size_t i = 0; i < s.long_h.size(); ++i) {
    const double h = s.long_h[i];
    for (const ins_method m : long_methods) {
      if (m == ins_method::vprk && i > 0) continue;
      throw_if_interrupted();
      const long_run r = run_long(m, L, y0, h, s.long_steps, s.samples);
      progress_step(s.progress, "nonlinear_inseparable", fmt::format("top: {} over {} steps of h = {}", name_of(m), s.long_steps, h));
      const bool ok = r.run.ok();
      long_table.add({figure::text(name_of(m)), figure::of(h), figure::integer(r.run.steps), figure::of(r.max_dp_phi), figure::of(r.bound_phi),
                      figure::of(r.max_dp_psi), figure::of(r.bound_psi), figure::flag(r.within_bound), figure::of(r.first_tenth),
                      figure::of(r.last_tenth), ok ? figure::text("ok") : figure::fault(*r.run.failure)});
      if (m == ins_method::rk4 || m == ins_method::vprk) {
        rk4_exact = rk4_exact && ok && r.max_dp_phi == 0 && r.max_dp_psi == 0;
        if (m == ins_method::rk4) {
          rk4_drifts = rk4_drifts && ok && r.last_tenth > 2 * r.first_tenth;
          rk4_last.push_back(r.last_tenth);
          energy_text.push_back(fmt::format("RK4 at h = {}: {:.2g} → {:.2g}", h, r.first_tenth, r.last_tenth));
        }
      } else {
        momenta_ok = momenta_ok && ok && r.within_bound;
        momenta_text.push_back(fmt::format("{} at h = {}: |Δp_φ| ≤ {:.2g} (bound {:.2g}), |Δp_ψ| ≤ {:.2g} (bound {:.2g})", name_of(m), h,
                                           r.max_dp_phi, r.bound_phi, r.max_dp_psi, r.bound_psi));
        if (m == ins_method::simpson) {
          simpson_last.push_back(ok ? r.last_tenth : INFINITY);
          energy_text.push_back(fmt::format("Simpson at h = {}: {:.2g} → {:.2g}", h, r.first_tenth, r.last_tenth));
        }
      }
      if (i == 0) {
        series e = styled_series(m, fmt::format("{}, h = {}", name_of(m), h));
        e.style = line_style::lines;
        for (const auto& [t, v] : r.energy_windows) {
          if (v > 0) e.add(figure::of(t), figure::of(v));
        }
        energy_curves.push_back(std::move(e));
      }
    }
  }
  out.add(std::move(long_table));
  out.expect({"top-momenta-within-bound",
              "Simpson's and the midpoint rule's steps change the top's cyclic momenta p_φ and p_ψ only within the sum of their per-step "
              "bounds (discrete Noether: exact for the exact map; the Newton residual and the rounding move them).",
              "|Δp| ≤ Σ per-step bound after every step, at each long h", fmt::format("{}", fmt::join(momenta_text, "; ")), momenta_ok});
  out.expect({"top-rk4-momenta-exact",
              "RK4 on the top's Hamiltonian equations, and the VPRK form (p' = p + h Σ b̄_i ∂L/∂q), keep p_φ and p_ψ bit for bit: ∂H/∂φ, ∂H/∂ψ, "
              "∂L/∂φ and ∂L/∂ψ are exactly 0 (every Runge–Kutta method keeps linear invariants).",
              "Δp_φ = Δp_ψ = 0 in double", rk4_exact ? "0 at every step of every run" : "a change", rk4_exact});
  bool below = simpson_last.size() == rk4_last.size();
  for (std::size_t i = 0; below && i < simpson_last.size(); ++i) below = simpson_last[i] < rk4_last[i];
  out.expect({"top-energy-below-rk4-drift",
              "Over long runs RK4's energy error on the top drifts, and Simpson's stays below it at every step size.",
              "RK4: max |ΔH| in the last tenth > 2 × the first tenth's; Simpson's last tenth below RK4's", fmt::format("{}", fmt::join(energy_text, "; ")),
              below && rk4_drifts});
  out.text("Simpson's energy error in double is not free of growth over these runs: it grows from the first tenth to the last by about "
           "the same amount, a few 1e-7, at every h. That is rounding, not the scheme: ψ grows like ψ̇t (to ψ̇ h N), and the "
           "position–momentum form rounds the node velocities (−3ψ_l + 4ψ_m − ψ_r)/h at about eps |ψ|/h a step, whatever h is; "
           "√N such roundings make the growth seen. The same rounding moves p_φ and p_ψ (the table's max |Δp|), within the per-step bounds, "
           "which carry the same eps |ψ|/h term and so are far from tight. The VPRK form of the same map, whose unknowns are the "
           "velocities themselves, keeps p_φ and p_ψ exactly.");
  out.add(plot_description{"inseparable_top_energy",
                           fmt::format("The top's energy error |H − H₀| against t (log scale), the largest over each of {} windows of a run of {} "
                                       "steps of h = {}: bounded for Simpson and the midpoint rule, a drift for RK4.",
                                       s.samples, s.long_steps, s.long_h.front()),
                           {panel{"energy error", axis{"t"}, axis{"|H − H₀|", true}, energy_curves, "below"}}});
}

}  // namespace

part_runs run_top_part(const inseparable_settings& s, section_result& out) {
  check_inseparable_top(s.top);
  const lagrange_top<double> L(s.top.I1, s.top.I3, s.top.Mgl);
  const ndof_state<double> y0 = top_start(L, s.top);
  const top_convergence c = converge_top(s, s.progress);
  const scoped_interval_digits digits(s.exact_digits);
  const lagrange_top_exact exact(top_enclosed(s.top), start_enclosed(s.top));
  out.text(fmt::format(
      "### The Lagrange top\n\nThe heavy symmetric top in Euler angles (θ, φ, ψ), L = ½I₁(θ̇² + φ̇² sin²θ) + ½I₃(ψ̇ + φ̇ cos θ)² − Mgl cos θ "
      "(Goldstein §5.7), with I₁ = {}, I₃ = {}, Mgl = {}, started at θ₀ = {}, θ̇₀ = {}, φ̇₀ = {}, ψ̇₀ = {} (φ₀ = ψ₀ = 0); p = ∂L/∂v is "
      "formed in double from these rates. φ and ψ are cyclic: p_φ = {:.17g} and p_ψ = {:.17g} are conserved, and so is the energy. The "
      "exact motion is enclosed in {} digits (u = cos θ = u₁ + (u₂ − u₁) sn²(τ₀ + λt, m), φ and ψ by elliptic integrals of the third "
      "kind, by Arb): {}; nutation between θ = {} and {} rad, period {}. Each method runs in double to T = {}; its error in θ is the largest "
      "over ten times t_k = (kN/10)h, k = 1…10, enclosed: the run's double θ enters an interval exactly and the exact θ(t_k) is an "
      "enclosure, so the error shown is the run's own, with only guaranteed digits.",
      s.top.I1, s.top.I3, s.top.Mgl, s.top.theta0, s.top.theta_dot0, s.top.phi_dot0, s.top.psi_dot0, y0.p(1), y0.p(2), s.exact_digits,
      exact.motion() == top_motion::nutation ? "a nutation between two proved-distinct roots" : "a steady precession (no nutation band at these digits)",
      enclosure_text(interval(acos(exact.u1())), 10), enclosure_text(interval(acos(exact.u2())), 10), enclosure_text(exact.nutation_period(), 10),
      s.top_end_time));
  if (s.perturb_exact != 0) out.text(fmt::format("**The exact θ is moved by {} here (a test of the checks).**", s.perturb_exact));

  add_top_reference_check(s, exact, out);
  part_runs runs = add_convergence(s, c, out);
  add_nutation_plot(s, exact, L, y0, out);
  add_long_runs(s, L, y0, out);
  return runs;
}
}  // namespace detail

std::string first_newton_failure(const inseparable_top_settings& top, const std::vector<double>& h) {
  check_inseparable_top(top);
  const lagrange_top<double> L(top.I1, top.I3, top.Mgl);
  dense_vector<double> q(3), v(3);
  q << top.theta0, 0, 0;
  v << top.theta_dot0, top.phi_dot0, top.psi_dot0;
  const ndof_state<double> y0{lagrangian_gradient_at(L, q, v).dv, q};
  for (const double step : h) {
    for (const detail::ins_method m : {detail::ins_method::simpson, detail::ins_method::midpoint, detail::ins_method::lobatto}) {
      try {
        const detail::ins_step r = detail::take_step(m, L, step, y0);
        if (!r.state.q.allFinite() || !r.state.p.allFinite()) return fmt::format("h = {}: {} gives a non-finite state", step, detail::name_of(m));
      } catch (const std::domain_error& e) {
        return fmt::format("h = {}: {}'s first step does not converge ({})", step, detail::name_of(m), e.what());
      }
    }
  }
  return {};
}

}  // namespace simpson::verify

namespace simpson::verify {

inseparable_settings inseparable_fact_settings() {
  inseparable_settings s;
  s.top_N = {100, 200, 400, 800};
  s.long_steps = 2000;
  return s;
}

published_fact inseparable_order_fact(const inseparable_settings& s) {
  check_inseparable_top(s.top);
  const detail::top_convergence c = detail::converge_top(s, {});
  json rows = json::array();
  for (std::size_t k = 0; k < detail::ins_methods.size(); ++k) {
    rows.push_back({{"method", detail::name_of(detail::ins_methods[k])},
                    {"expected_order", detail::order_of(detail::ins_methods[k])},
                    {"theta_local_orders", c.theta_orders[k].text},
                    {"theta_order", detail::verdict_word(c.theta_orders[k].outcome)},
                    {"energy_local_orders", c.energy_orders[k]}});
  }
  using verdict = detail::order_decision::verdict;
  const verdict simpson = c.theta_orders[0].outcome, midpoint = c.theta_orders[1].outcome;
  if (simpson == verdict::undecided || midpoint == verdict::undecided) {
    throw enclosure_undecided(fmt::format("nonlinear_inseparable.simpson-order: Simpson {} ({}), midpoint {} ({})", detail::verdict_word(simpson),
                                          c.theta_orders[0].text, detail::verdict_word(midpoint), c.theta_orders[1].text));
  }
  json evidence;
  evidence["enclosure"] = {{"method", fmt::format("double runs on the Lagrange top (I1 = {}, I3 = {}, Mgl = {}, theta0 = {}) to T = {}, N = {}; "
                                                  "theta's error enclosed against the exact motion (Arb, {} digits); a local order proved "
                                                  "when its enclosure lies within 1/2 of the order, pairs above 1000 N eps",
                                                  s.top.I1, s.top.I3, s.top.Mgl, s.top.theta0, s.top_end_time, fmt::join(s.top_N, ", "), s.exact_digits)},
                           {"methods", rows}};
  return {simpson == verdict::proved && midpoint == verdict::proved, evidence,
          fmt::format("Simpson: {}; implicit midpoint: {}.", c.theta_orders[0].text, c.theta_orders[1].text)};
}

published_fact inseparable_momenta_fact(const inseparable_settings& s) {
  check_inseparable_top(s.top);
  const lagrange_top<double> L(s.top.I1, s.top.I3, s.top.Mgl);
  const ndof_state<double> y0 = detail::top_start(L, s.top);
  json runs = json::array();
  bool holds = true;
  std::vector<std::string> notes;
  for (const double h : s.long_h) {
    for (const detail::ins_method m : {detail::ins_method::simpson, detail::ins_method::midpoint}) {
      const detail::long_run r = detail::run_long(m, L, y0, h, s.long_steps, 10);
      holds = holds && r.run.ok() && r.within_bound;
      runs.push_back({{"method", detail::name_of(m)}, {"h", h}, {"steps", r.run.steps}, {"max_dp_phi", r.max_dp_phi}, {"bound_phi", r.bound_phi},
                      {"max_dp_psi", r.max_dp_psi}, {"bound_psi", r.bound_psi}, {"within_bound_at_every_step", r.within_bound},
                      {"status", r.run.ok() ? std::string("ok") : *r.run.failure}});
      notes.push_back(fmt::format("{} h = {}: {:.2g} ≤ {:.2g}, {:.2g} ≤ {:.2g}", detail::name_of(m), h, r.max_dp_phi, r.bound_phi, r.max_dp_psi, r.bound_psi));
    }
  }
  json evidence;
  evidence["numeric"] = {{"method", fmt::format("{} steps in double at each h; the bound is the sum of each step's Noether bound (Newton residual "
                                                "and the update's rounding, discrete_lagrangian_step.hpp)",
                                                s.long_steps)},
                         {"runs", runs}};
  return {holds, evidence, fmt::format("{}", fmt::join(notes, "; "))};
}

}  // namespace simpson::verify

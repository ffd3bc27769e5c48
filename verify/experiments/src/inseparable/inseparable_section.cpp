// The nonlinear_inseparable section: the Lagrange top and the double pendulum (inseparable_top.cpp,
// inseparable_pendulum.cpp), and what an accuracy costs each method, against Simpson.

#include "inseparable_parts.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

namespace simpson::verify {
namespace detail {

reached interpolate_reach(const std::vector<convergence_point>& points, double target) {
  reached out;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const convergence_point& b = points[k];
    if (!b.run.ok() || !(b.error > 0)) break;
    if (b.error > target) continue;
    if (k == 0) {
      out.why_not = fmt::format("already below at N = {}", b.N);
      return out;
    }
    const convergence_point& a = points[k - 1];
    if (!a.run.ok()) break;
    // Linear in log N against log error between the two points bracketing the target.
    const double w = std::log(a.error / target) / std::log(a.error / b.error);
    out.N = std::exp(std::log(static_cast<double>(a.N)) + w * std::log(static_cast<double>(b.N) / static_cast<double>(a.N)));
    if (a.seconds > 0 && b.seconds > 0) out.seconds = std::exp(std::log(a.seconds) + w * std::log(b.seconds / a.seconds));
    return out;
  }
  out.why_not = points.empty() ? std::string("no run") : fmt::format("not reached by N = {}", points.back().N);
  return out;
}

namespace {

/// Steps and seconds to reach each target, as ratios to Simpson's.
void add_cost(const std::vector<part_runs>& parts, const inseparable_settings& s, section_result& out) {
  const std::vector<double> targets{1e-6, 1e-10};
  table steps{"cost", "The cost of an accuracy",
              "For each system and each target error (the top: the largest |θ − θ(t_k)|; the pendulum: max |y − y_ref| at T), the steps N each method needs, "
              "**interpolated** linearly in log N against log error between the two measured N that bracket the target (the error-against-N "
              "tables), and its ratio to Simpson's. A step of each method costs differently: the seconds are in the run-time report.",
              {{"system", "system"}, {"target", "target error", "", 0}, {"method", "method"}, {"N", "N to reach it"}, {"ratio", "N / Simpson's N"}}};
  table seconds{"cost_seconds", "The cost of an accuracy: seconds",
                "As the table \"The cost of an accuracy\", in seconds, interpolated in log seconds between the same two runs, and as ratios to "
                "Simpson's.",
                {{"system", "system"}, {"target", "target error", "", 0}, {"method", "method"}, {"seconds", "seconds", "s"}, {"ratio", "seconds / Simpson's"}}};
  seconds.timing = true;
  std::vector<std::string> winners;
  for (const part_runs& part : parts) {
    for (const double target : targets) {
      const reached simpson = interpolate_reach(part.by_method[0], target);
      std::string fewest;
      double fewest_N = INFINITY;
      for (std::size_t k = 0; k < ins_methods.size(); ++k) {
        const ins_method m = ins_methods[k];
        const reached r = interpolate_reach(part.by_method[k], target);
        steps.add({figure::text(part.system), figure::of(target), figure::text(name_of(m)), r.N ? figure::of(*r.N) : figure::text(r.why_not),
                   r.N && simpson.N ? figure::of(*r.N / *simpson.N) : figure{}});
        seconds.add({figure::text(part.system), figure::of(target), figure::text(name_of(m)), r.seconds ? figure::of(*r.seconds) : figure::text(r.why_not),
                     r.seconds && simpson.seconds ? figure::of(*r.seconds / *simpson.seconds) : figure{}});
        if (r.N && *r.N < fewest_N) {
          fewest_N = *r.N;
          fewest = name_of(m);
        }
      }
      if (!fewest.empty()) winners.push_back(fmt::format("{} at {:g}: {} ({:.3g} steps)", part.system, target, fewest, fewest_N));
    }
  }
  out.add(std::move(steps));
  if (s.timed) out.add(std::move(seconds));
  if (!winners.empty()) out.text(fmt::format("Fewest steps for each target: {}.", fmt::join(winners, "; ")));
}

}  // namespace
}  // namespace detail

section_result run_inseparable(const inseparable_settings& s) {
  section_result out;
  out.name = "nonlinear_inseparable";
  out.title = "Inseparable Hamiltonians: the Lagrange top and the nonlinear double pendulum";
  const auto& t = s.top;
  const auto& d = s.pendulum;
  out.conventions = {{"top", {{"I1", t.I1}, {"I3", t.I3}, {"Mgl", t.Mgl}, {"theta0", t.theta0}, {"theta_dot0", t.theta_dot0}, {"phi_dot0", t.phi_dot0}, {"psi_dot0", t.psi_dot0}}},
                     {"top_end_time", s.top_end_time},
                     {"top_N", s.top_N},
                     {"long_h", s.long_h},
                     {"long_steps", s.long_steps},
                     {"exact_digits", s.exact_digits},
                     {"reference_digits", s.reference_digits},
                     {"pendulum", {{"m1", d.m1}, {"m2", d.m2}, {"l1", d.l1}, {"l2", d.l2}, {"g", d.g}, {"theta1", d.theta1}, {"theta2", d.theta2}, {"omega1", d.omega1}, {"omega2", d.omega2}}},
                     {"pendulum_end_time", s.pendulum_end_time},
                     {"pendulum_N", s.pendulum_N},
                     {"pendulum_reference_digits", s.pendulum_reference_digits},
                     {"lyapunov_time", s.lyapunov_time},
                     {"samples", s.samples}};
  out.text("Two systems whose kinetic energy depends on the configuration, so that H is not separable, as the authors' tutorial "
           "(arXiv 2512.03330) poses them. Five methods in double, each in its natural form: Simpson's variational step for any L and the "
           "implicit midpoint variational integrator (position–momentum form, Newton on the control points with the exact Jacobian from "
           "L's AutoDiff Hessian), Lobatto IIIA–IIIB(3) and RK4 on the Legendre Hamiltonian, and GeometricIntegrators' VPRK form of "
           "Lobatto IIIA–IIIB(3). Every implicit step is solved to 16 eps of its terms; a step that does not converge stops its run "
           "with the reason in its row.");
  std::vector<detail::part_runs> parts;
  parts.push_back(detail::run_top_part(s, out));
  parts.push_back(detail::run_pendulum_part(s, out));
  detail::add_cost(parts, s, out);
  return out;
}

}  // namespace simpson::verify

// The nonlinear section's round-off part (Brouwer's law for the nonlinear step): the pendulum in
// double over a long run, with the step in three forms: as the paper's equations are written
// (simpson_nonlinear_step: coefficients h/2, h²/12, ... each rounded, Newton stopped at 16 eps of its
// terms), in Brouwer form (nonlinear_brouwer_step.hpp: coefficients that satisfy the symplecticity
// conditions exactly in floating point, Newton to stagnation), and in Brouwer form with compensated
// summation. The reference is the Brouwer form in long double with the same coefficients (exact in
// long double): the same map, rounded 2¹¹ times more finely.

#include "growth_tools.hpp"
#include "nonlinear_parts.hpp"

#include <simpson/verify/interruption.hpp>
#include <simpson/verify/progress.hpp>

#include <simpson/nonlinear_brouwer_step.hpp>
#include <simpson/nonlinear_simpson_step.hpp>
#include <simpson/potential.hpp>

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace simpson::verify::detail {
namespace {

constexpr std::array<const char*, 3> form_names{"standard", "brouwer", "brouwer-compensated"};

struct brouwer_runs {
  std::vector<long long> steps;
  std::array<std::vector<long double>, 3> energy_error;  // running max of |H(y_j) − H(y_j ref)|/H(y₀), per form
  std::array<long long, 3> newton_iterations{};
  std::string failure;  // a Newton failure ends the runs: what and where
};

/// The three forms and the reference, step by step in lockstep: one reference run serves all three.
brouwer_runs run_forms(const nonlinear_settings& s) {
  const double h = s.brouwer_h;
  const pendulum_potential<double> V{1, 1};
  const pendulum_potential<long double> V_reference{1, 1};
  const brouwer_coefficients<double> k = simpson_brouwer_coefficients(h);
  const brouwer_coefficients<long double> k_reference = k.cast<long double>();
  phase_point<double> standard{0, s.pendulum_q0}, plain = standard;
  compensated_point<double> compensated{standard};
  phase_point<long double> reference{0, s.pendulum_q0};
  const auto H = [&V_reference](long double p, long double q) { return p * p / 2 + V_reference.value(q); };
  const long double H0 = H(reference.p, reference.q);
  brouwer_runs out;
  out.steps = log_spaced_checkpoints(s.brouwer_steps);
  std::array<long double, 3> running{};
  std::size_t next = 0;
  try {
    for (long long j = 1; j <= s.brouwer_steps; ++j) {
      if ((j & 0xFFFF) == 0) {
        throw_if_interrupted();
        progress_step(s.progress, "nonlinear", fmt::format("Brouwer forms step {}", j), static_cast<double>(j) / static_cast<double>(s.brouwer_steps));
      }
      const nonlinear_step_result<double> step = simpson_nonlinear_step(1.0, h, V, standard);
      standard = step.state;
      out.newton_iterations[0] += step.newton_iterations;
      out.newton_iterations[1] += simpson_brouwer_step(k, 1.0, V, plain).newton_iterations;
      out.newton_iterations[2] += simpson_brouwer_step_compensated(k, 1.0, V, compensated).newton_iterations;
      simpson_brouwer_step(k_reference, 1.0L, V_reference, reference);
      const long double H_reference = H(reference.p, reference.q);
      const std::array<long double, 3> errors{std::abs(H(standard.p, standard.q) - H_reference) / H0,
                                              std::abs(H(plain.p, plain.q) - H_reference) / H0,
                                              std::abs(H(compensated.y.p, compensated.y.q) - H_reference) / H0};
      for (std::size_t f = 0; f < 3; ++f) running[f] = std::max(running[f], errors[f]);
      if (j == out.steps[next]) {
        for (std::size_t f = 0; f < 3; ++f) out.energy_error[f].push_back(running[f]);
        ++next;
      }
    }
  } catch (const std::domain_error& e) {
    out.failure = e.what();
    out.steps.resize(next);
  }
  return out;
}

}  // namespace

void add_nonlinear_brouwer(const nonlinear_settings& s, section_result& out) {
  table rows{"pendulum_brouwer", "Brouwer's law for the nonlinear step: the pendulum's energy round-off in three forms (double)",
             fmt::format(
                 "V = 1 − cos q, m = ω = 1, q(0) = {} rad, p(0) = 0, h = {}, {} steps in double. standard: "
                 "simpson_nonlinear_step, the paper's equations with each coefficient (h/2, h²/12, h²/24, h/6, ...) rounded on "
                 "its own, Newton stopped at 16 eps of its terms. brouwer: the same method as Lobatto IIIA–IIIB with h folded "
                 "into its coefficients B = (b₁, b₂, b₁), b₁ ≈ h/6, b₂ ≈ 2h/3 rounded to three fewer bits, every other entry "
                 "an exact multiple (5/4, 1/2, 1/4) of them, so that B_i Â_ij + B_j A_ji = B_i B_j holds exactly for the "
                 "stored numbers; Newton iterated until its correction stops decreasing. brouwer-compensated: the same with "
                 "Kahan's compensated summation of Δq and Δp. Energy error: the running maximum of |H(y_j) − H(y_j^ref)|/H(y₀), "
                 "y^ref the brouwer form in long double with the same coefficients (the same map, its rounding 2¹¹ times "
                 "smaller; H in long double), which removes the method's own O(h⁴) energy oscillation and leaves the "
                 "round-off. Growth exponent: least-squares slope of its log against log(steps) from {} steps to the end (1 a "
                 "drift, 0.5 a random walk).",
                 fmt::format("{:g}", s.pendulum_q0), fmt::format("{:g}", s.brouwer_h), s.brouwer_steps,
                 growth_fit_start(s.brouwer_steps)),
             {{"form", "form"},
              {"steps", "steps"},
              {"energy_error_relative", "energy error (rel.)"},
              {"growth_exponent", "growth exponent"},
              {"newton_iterations_mean", "Newton it./step"}}};
  panel growth{"Pendulum, relative energy round-off, double", {"steps", true}, {"running max |H - H_{ref}|/H_0", true}, {}, "top left"};
  const brouwer_runs runs = run_forms(s);
  const std::array<std::pair<int, int>, 3> styles{{{1, 7}, {3, 5}, {4, 9}}};  // colour, point
  std::array<long double, 3> exponents{};
  for (std::size_t f = 0; f < 3; ++f) {
    exponents[f] = growth_exponent(runs.steps, runs.energy_error[f]);
    const long long done = runs.steps.empty() ? 0 : runs.steps.back();
    const double iterations = done > 0 ? static_cast<double>(runs.newton_iterations[f]) / static_cast<double>(done) : 0;
    series curve(form_names[f], line_style::lines, styles[f].first, styles[f].second, static_cast<int>(f) + 1);
    for (std::size_t i = 0; i < runs.steps.size(); ++i) {
      curve.add(figure::integer(runs.steps[i]), figure::of(runs.energy_error[f][i]));
      if (is_decade(runs.steps[i]) || i + 1 == runs.steps.size()) {
        rows.add({figure::text(form_names[f]), figure::integer(runs.steps[i]), figure::of(runs.energy_error[f][i]),
                  figure::of(exponents[f]), figure::of(iterations)});
      }
    }
    growth.curves.push_back(curve);
  }
  add_slope_guide(growth, "slope t", 1.0, runs.steps, runs.energy_error[0]);
  add_slope_guide(growth, "slope √t", 0.5, runs.steps, runs.energy_error[1], 9, 3);  // black short dashes: not the slope-t guide
  if (!runs.failure.empty()) {
    rows.add({figure::text("all"), figure::integer(runs.steps.empty() ? 0 : runs.steps.back()), figure::fault("failed: " + runs.failure),
              figure::fault("failed"), figure::fault("failed")});
  }
  out.add(std::move(rows));
  out.add(plot_description{"nonlinear_brouwer",
                           "The pendulum's energy round-off in the nonlinear step's three forms in double against the step count "
                           "(log-log), with guides of slope 1 (drift) and 1/2 (random walk)",
                           {growth}, 1, 800, 500});
}

}  // namespace simpson::verify::detail

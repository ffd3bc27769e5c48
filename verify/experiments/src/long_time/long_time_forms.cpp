// The long_time section's comparison of three forms of Φ₃ in double (Brouwer's law): the matrix
// (4 products and 2 sums per step), the shear form L(c)U(b)L(c) (claim phi3-shear-factorization),
// and the shear form with compensated summation. For each, the running maximum of the relative H_d
// error at log-spaced step counts, its growth exponent, and the phase drift against Φ₃'s exact rotation.

#include "growth_tools.hpp"
#include "long_time_parts.hpp"

#include <simpson/verify/floating_tools.hpp>
#include <simpson/verify/interruption.hpp>
#include <simpson/verify/progress.hpp>

#include <simpson/shear_form.hpp>
#include <simpson/simpson_map.hpp>

#include <boost/math/constants/constants.hpp>
#include <fmt/format.h>

#include <array>
#include <cmath>

namespace simpson::verify::detail {
namespace {

enum class form { matrix, shear, shear_compensated };
constexpr std::array<form, 3> forms{form::matrix, form::shear, form::shear_compensated};

const char* name_of(form f) {
  switch (f) {
    case form::matrix: return "matrix";
    case form::shear: return "shear";
    default: return "shear-compensated";
  }
}

/// (x + π) mod 2π − π, in long double.
long double wrapped(long double x) {
  const long double two_pi = 2 * boost::math::constants::pi<long double>();
  x = std::fmod(x + two_pi / 2, two_pi);
  if (x < 0) x += two_pi;
  return x - two_pi / 2;
}

struct form_run {
  std::vector<long long> steps;
  std::vector<double> hd_error;     // running maximum of |H_d(y_j) − H_d(y_0)|/H_d(y_0)
  std::vector<long double> phase;   // angle on the H_d ellipse minus j φ, φ Φ₃'s exact rotation per step
  double growth_exponent = 0;
};

/// m = ω = 1, h = ωh, y₀ = (1, 0) in double. H_d = a p² + k q² with a = 1/(2m), k = mω²(1 − x/12)(1 − x/24)/(2(1 − x/8));
/// in the coordinates (√a p, √k q) Φ₃ is a rotation by φ, computed with the matrix in long double.
form_run run_form(form f, const long_time_settings& s) {
  const oscillator_parameters<double> par{1, 1, s.omega_h};
  const double x = par.omega2_h2(), a = 0.5, k = (1 - x / 12) * (1 - x / 24) / (2 * (1 - x / 8));
  const one_step_matrix<double> phi = simpson_map(par);
  const shear_coefficients<double> shear = simpson_shear_coefficients(par);
  const one_step_matrix<long double> exact = simpson_map(oscillator_parameters<long double>{1, 1, static_cast<long double>(s.omega_h)});
  const long double sa = std::sqrt(static_cast<long double>(a)), sk = std::sqrt(static_cast<long double>(k));
  const auto angle = [&](long double p, long double q) { return std::atan2(sk * q, sa * p); };
  const phase_point<long double> y1 = exact * phase_point<long double>{1, 0};
  const long double rotation = wrapped(angle(y1.p, y1.q) - angle(1, 0));
  compensated_point<double> z{{1, 0}};
  const double H0 = a;
  form_run out;
  out.steps = log_spaced_checkpoints(s.steps_double);
  double running = 0;
  std::size_t next = 0;
  for (long long j = 1; j <= s.steps_double; ++j) {
    if ((j & 0xFFFFF) == 0) {
      throw_if_interrupted();
      progress_step(s.progress, "long_time", fmt::format("form {} step {}", name_of(f), j), static_cast<double>(j) / static_cast<double>(s.steps_double));
    }
    switch (f) {
      case form::matrix: z.y = phi * z.y; break;
      case form::shear: z.y = shear_step(shear, z.y); break;
      default: shear_step_compensated(shear, z); break;
    }
    const double e = std::abs(a * z.y.p * z.y.p + k * z.y.q * z.y.q - H0) / H0;
    if (e > running) running = e;
    if (j == out.steps[next]) {
      out.hd_error.push_back(running);
      out.phase.push_back(wrapped(angle(z.y.p, z.y.q) - angle(1, 0) - std::fmod(static_cast<long double>(j) * rotation,
                                                                                   2 * boost::math::constants::pi<long double>())));
      ++next;
    }
  }
  out.growth_exponent = growth_exponent(out.steps, out.hd_error);
  return out;
}

}  // namespace

void add_long_time_forms(const long_time_settings& s, section_result& out) {
  table rows{"forms", "Brouwer's law: Φ₃ as a matrix, in shear form, and in shear form with compensated summation (double)",
             fmt::format(
                 "m = ω = 1, ωh = {}, y₀ = (1, 0), {} steps in double. matrix: p' = αp + βq, q' = γp + δq with the rounded "
                 "entries (det − 1 ≠ 0 after rounding: a drift ∝ t). shear: q += cp, p += bq, q += cp with b, c rounded "
                 "(claim phi3-shear-factorization; each shear has determinant 1 whatever its coefficient, so only the "
                 "rounding of each update remains, a random walk ∝ √t). shear-compensated: the same with Kahan's "
                 "compensated summation of the three updates. H_d error: the running maximum of |H_d(y_j) − H_d(y₀)|/H_d(y₀) "
                 "up to the step count. Growth exponent: least-squares slope of its log against log(steps) from {} "
                 "steps to the end (1 a drift, 0.5 a random walk). Phase: the angle on the H_d ellipse minus j φ, φ the "
                 "exact rotation per step of Φ₃ (in long double): the phase drift that rounding adds.",
                 simpson::to_string(s.omega_h, 3), s.steps_double,
                 growth_fit_start(s.steps_double)),
             {{"form", "form"},
              {"steps", "steps"},
              {"hd_error_relative", "H_d error (rel.)"},
              {"growth_exponent", "growth exponent"},
              {"phase_error_rad", "phase drift (rad)"}}};
  panel growth{"Relative H_d error, double", {"steps", true}, {"running max |H_d - H_d(0)|/H_d(0)", true}, {}, "top left"};
  const std::array<std::pair<int, int>, 3> styles{{{1, 7}, {3, 5}, {4, 9}}};  // colour, point
  std::vector<form_run> runs;
  for (std::size_t f = 0; f < forms.size(); ++f) {
    form_run r = run_form(forms[f], s);
    series curve(name_of(forms[f]), line_style::lines, styles[f].first, styles[f].second, static_cast<int>(f) + 1);
    for (std::size_t i = 0; i < r.steps.size(); ++i) {
      curve.add(figure::integer(r.steps[i]), figure::of(r.hd_error[i]));
      if (is_decade(r.steps[i]) || i + 1 == r.steps.size()) {
        rows.add({figure::text(name_of(forms[f])), figure::integer(r.steps[i]), figure::of(r.hd_error[i]), figure::of(r.growth_exponent),
                  figure::of(r.phase[i])});
      }
    }
    growth.curves.push_back(curve);
    runs.push_back(std::move(r));
  }
  // Guides through the matrix form's and the shear form's values at the fit's first step: slope 1
  // (a drift) and 1/2 (a random walk).
  add_slope_guide(growth, "slope t", 1.0, runs[0].steps, runs[0].hd_error);
  add_slope_guide(growth, "slope √t", 0.5, runs[1].steps, runs[1].hd_error, 9, 3);  // black short dashes: not the slope-t guide
  out.add(std::move(rows));
  out.add(plot_description{"long_time_forms",
                           "Relative H_d error of Φ₃'s three forms in double against the step count (log-log), with guides of "
                           "slope 1 (drift) and 1/2 (random walk)",
                           {growth}, 1, 800, 500});
}

}  // namespace simpson::verify::detail

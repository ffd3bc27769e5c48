// The stability section: the exact stability region of Φ₃, the behaviour at and around each
// endpoint, a stiff linear chain, extreme ωh in each precision, and extreme masses. Every figure is
// computed, and every fault decided, in the precision of its row.

#include <simpson/verify/stability_section.hpp>
#include <simpson/verify/interruption.hpp>
#include <simpson/verify/progress.hpp>

#include <simpson/verify/floating_tools.hpp>
#include "guarded_run.hpp"
#include "stability_parts.hpp"
#include <simpson/verify/stability_analysis.hpp>

#include <simpson/energy.hpp>
#include <simpson/exact_solution.hpp>
#include <simpson/iterate.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/three_term_scheme.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace simpson::verify {

stability_report simpson_exact_region() {
  return analyse_three_term_scheme([](const symbolic& qp, const symbolic& q, const symbolic& qn) {
    const oscillator_parameters<symbolic> unit{symbolic(1), symbolic(1), symbolic::variable()};
    return three_term_residual(unit, qp, q, qn);
  });
}

namespace {

table region_table(const stability_report& report) {
  table t{"intervals", "Exact stability region of Φ₃ (ωh > 0)",
          "From the exact discriminant Δ(x), x = ω²h², by Sturm sequences (the ledger's stability claims): stable where "
          "Δ < 0 (two simple roots on the unit circle).",
          {{"omega_h_from", "ωh from"}, {"omega_h_to", "ωh to"}, {"x_from", "x from"}, {"x_to", "x to"},
           {"sign_of_discriminant", "Δ"}, {"stable", "stable"}}};
  for (const stability_band& b : report.bands) {
    t.add({figure::text(b.omega_h_from), figure::text(b.omega_h_to), figure::exact(b.x_from),
           b.to ? (b.to->exact() ? figure::exact(b.to->low) : figure::text(root_text(*b.to))) : figure::text("infinity"),
           figure::text(b.discriminant_negative ? "negative" : "positive"), figure::flag(b.stable)});
  }
  return t;
}

/// Exact truncation coefficients F(θ)/θ⁴, F(θ) = (2 cos θ − 2)/θ² + (2 cos θ + 22)/24 − θ²/24 (the
/// scheme's residual on q = cos, divided by q), as decimal strings with more digits than any
/// precision of the run: F/θ⁴ cancels about 4 log10(1/θ) digits, and the reference keeps 40 more.
std::vector<std::string> exact_truncation_coefficients(const std::vector<double>& omega_h, unsigned run_digits) {
  double smallest = 1;
  for (const double th : omega_h) smallest = std::min(smallest, th);
  const unsigned digits = std::max(200u, run_digits + 40 + static_cast<unsigned>(std::ceil(4 * std::max(0.0, -std::log10(smallest)))));
  std::vector<std::string> out;
  visit_mpfr(std::min(digits, precision::max_mpfr_digits), [&](auto tag) {
    using Real = typename decltype(tag)::type;
    using std::cos;
    for (const double th : omega_h) {
      const Real t(th), c = cos(t);
      const Real F = (2 * c - 2) / (t * t) + (2 * c + 22) / 24 - t * t / 24;
      out.push_back(simpson::to_string(Real(F / (t * t * t * t)), static_cast<int>(digits)));
    }
  });
  return out;
}

/// Correct significant digits of a value whose relative error is `rel`, at most what the precision carries.
template <class Real>
figure digits_kept(const Real& rel, double carried) {
  using std::log10;
  if (rel == 0) return figure::of(carried);
  const double d = std::clamp(-static_cast<double>(log10(rel)), 0.0, carried);
  return figure::of(std::round(d * 10) / 10);  // a count of digits, rounded to 0.1: double carries it whole
}

/// Extreme ωh in each precision: the digits of the truncation coefficient c against its exact
/// value, and of H_d over a run; one panel of the digits plot per precision.
std::pair<table, plot_description> extreme_omega_h(const stability_settings& s) {
  table extreme{"extreme_omega_h", "Extreme ωh in each precision",
                "Truncation coefficient: c = T_h(q_j)/(ω⁶h⁴q_j) computed from the scheme's own formula (schema-ordre-3) on "
                "exact values, against its exact value F(θ)/θ⁴ (closed form, in mpfr with more digits than the run), which "
                "tends to 1/1440; 'digits' = correct significant digits of c. H_d: the largest relative change over the run, "
                "and the digits it keeps. A precision 'loses 1/1440' where c has no correct digit.",
                {{"precision", "precision"}, {"omega_h", "ωh", "", 0}, {"c", "c"}, {"c_exact", "exact c", "", 6},
                 column::fixed_point("digits_of_c", "digits of c", 1), {"max_Hd_drift_relative", "max H_d drift"},
                 column::fixed_point("digits_of_Hd", "digits of H_d", 1), {"status", "status"}}};
  unsigned run_digits = 0;
  for (const precision& p : s.precisions) run_digits = std::max(run_digits, p.digits10());
  const std::vector<std::string> exact_c = exact_truncation_coefficients(s.omega_h, run_digits);
  std::vector<panel> digit_panels;
  for (const precision& prec : s.precisions) {
    // A digits axis per precision: from 0 to the digits the precision carries (-log10 eps), drawn as a guide.
    panel digits_panel{"digits of c and H_d in " + prec.name(), {"ωh (dimensionless)", true}, {"correct significant digits"}, {}, "bottom right"};
    const double precision_digits = static_cast<double>(prec.digits10());
    digits_panel.y.range = std::pair{0.0, precision_digits * 1.08};
    series c_digits{"c (truncation coefficient)", line_style::lines_points, 0, 7};
    series hd_digits{"H_d", line_style::lines_points, 1, 6};
    visit_floating(prec, [&](auto tag) {
      using Real = typename decltype(tag)::type;
      using std::abs;
      using std::cos;
      using std::sin;
      const double carried = static_cast<double>(prec.digits10());
      for (std::size_t k = 0; k < s.omega_h.size(); ++k) {
        throw_if_interrupted();
        const double th = s.omega_h[k];
        const oscillator_parameters<Real> par{Real(1), Real(1), Real(th)};
        // c from the scheme's residual at t = 0.3 on the exact solution q = sin t.
        const phase_point<Real> at{Real(cos(Real(3) / 10)), Real(sin(Real(3) / 10))};
        const Real q_prev = exact_solution(par, at, Real(-par.h())).q, q_next = exact_solution(par, at, par.h()).q;
        const Real t4 = Real(th) * Real(th) * Real(th) * Real(th);
        const Real c = three_term_residual(par, q_prev, at.q, q_next) / (t4 * at.q);
        const Real c_exact = from_decimal<Real>(exact_c[k]);
        // |c_exact|: F/θ⁴ changes sign in the second stable band.
        const figure c_digits_kept = digits_kept(Real(abs(Real(c - c_exact)) / abs(c_exact)), carried);
        const auto run = detail::guarded_iterate(simpson_map(par), par, phase_point<Real>{Real(1), Real(0)}, s.steps,
                                                 [&](const phase_point<Real>& y) { return discrete_energy(par, y); });
        const figure hd_digits_kept = run.ok() ? digits_kept(run.max_relative_drift, carried) : figure{};
        extreme.add({figure::text(prec.name()), figure::of(th), figure::of(c), figure::of(c_exact), c_digits_kept,
                     run.ok() ? figure::of(run.max_relative_drift) : run.status, hd_digits_kept, run.status});
        c_digits.add(figure::of(th), c_digits_kept);
        hd_digits.add(figure::of(th), hd_digits_kept);
      }
    });
    progress_step(s.progress, "stability", prec.name());
    series carried{"digits the precision carries", line_style::dashed, 8};
    carried.reference = true;
    const auto [lowest, highest] = std::minmax_element(s.omega_h.begin(), s.omega_h.end());
    carried.add(figure::of(*lowest), figure::of(precision_digits));
    carried.add(figure::of(*highest), figure::of(precision_digits));
    digits_panel.curves = {c_digits, hd_digits, carried};
    digit_panels.push_back(digits_panel);
  }
  const int columns = static_cast<int>(std::min<std::size_t>(3, std::max<std::size_t>(1, s.precisions.size())));
  const int rows = static_cast<int>((s.precisions.size() + static_cast<std::size_t>(columns) - 1) / static_cast<std::size_t>(columns));
  return {std::move(extreme),
          plot_description{"truncation_digits",
                           "Digits of the truncation coefficient and of H_d: correct significant digits of c = T_h/(ω⁶h⁴q) "
                           "(against its exact value, which tends to 1/1440) and of H_d over the run, against ωh, one panel "
                           "per precision (each with its own digits axis)",
                           digit_panels, columns, 400 * columns, 330 * std::max(1, rows)}};
}

/// Extreme masses in each precision: every figure and fault decided in the precision.
table mass_table(const stability_settings& s) {
  table masses{"extreme_masses", "Extreme masses (ω = 1, ωh = 1, y₀ = (mω, 0))",
               "Every figure is decided in its precision: a value beyond the precision's range is 'overflow', an energy "
               "lost to zero or a value below its smallest normal number 'underflow', a NaN 'non-finite'.",
               {{"precision", "precision"}, {"m", "m", "", 1}, {"H0", "H(y₀)"}, {"Hd0", "H_d(y₀)"},
                {"max_Hd_drift_relative", "max H_d drift (relative)"}, {"error_q_end", "error q (end)"}, {"status", "status"}}};

  for (const precision& prec : s.precisions) {
    visit_floating(prec, [&](auto tag) {
      using Real = typename decltype(tag)::type;
      using std::abs;
      for (const double mass : s.masses) {
        throw_if_interrupted();
        // The mass is converted to Real first: 1e300 is finite in every precision here, its square not in double.
        const oscillator_parameters<Real> par{Real(mass), Real(1), Real(1)};
        const phase_point<Real> y0{par.m(), Real(0)};
        const Real H0 = energy(par, y0), Hd0 = discrete_energy(par, y0);
        const auto run = detail::guarded_iterate(simpson_map(par), par, y0, s.steps,
                                                 [&](const phase_point<Real>& y) { return discrete_energy(par, y); });
        const figure h0 = H0 == 0 ? figure::fault("underflow") : figure::of(H0);
        const figure hd0 = Hd0 == 0 ? figure::fault("underflow") : figure::of(Hd0);
        const figure drift = run.ok() ? figure::of(run.max_relative_drift) : run.status;
        // The state's error stays meaningful when only the energy faults (it under- or overflows, the state does not).
        const phase_point<Real> end = run.steps_done == s.steps || is_unstable(run.status)
                                          ? run.end
                                          : iterate(simpson_map(par), y0, static_cast<std::size_t>(s.steps), [](std::size_t, const phase_point<Real>&) {});
        const figure error = is_unstable(run.status) ? figure{}
                                                     : figure::of(Real(abs(Real(end.q - exact_solution(par, y0, Real(s.steps)).q))));
        // The row's status: the run's, else the first fault among its figures.
        figure status = run.status;
        for (const figure& f : {h0, hd0, drift, error}) {
          if (!status.is_fault() && f.is_fault()) status = f;
        }
        masses.add({figure::text(prec.name()), figure::of(mass), h0, hd0, drift, error, status});
      }
    });
  }
  return masses;
}

}  // namespace

section_result run_stability(const stability_settings& s) {
  section_result out;
  out.name = "stability";
  out.title = "Stability: exact region, endpoints, stiff and extreme cases";
  out.conventions = {{"steps", s.steps}, {"endpoint_power", s.endpoint_power}, {"stiff_ratios", s.stiff_ratios}, {"stiff_doublings", s.stiff_doublings}};
  const stability_report report = simpson_exact_region();
  out.add(region_table(report));
  detail::add_spectral_radius(report, out);
  detail::add_endpoint_growth(report, s.endpoint_power, out);
  progress_step(s.progress, "stability", "exact region and endpoints");
  detail::add_stiff_chain(report, s.stiff_ratios, s.stiff_doublings, out);
  progress_step(s.progress, "stability", "stiff chain");
  auto [extreme, digits_plot] = extreme_omega_h(s);
  out.add(std::move(extreme)).add(mass_table(s)).add(std::move(digits_plot));
  return out;
}

}  // namespace simpson::verify

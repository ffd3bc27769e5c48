// The stability section: the exact stability region of Φ₃, the behaviour at and around each
// endpoint, stiff ω at fixed ωh, extreme ωh in each precision, and extreme masses.

#include <simpson/verify/experiments.hpp>
#include <simpson/verify/interruption.hpp>

#include "figures.hpp"
#include "stability_analysis.hpp"

#include <simpson/energy.hpp>
#include <simpson/exact_solution.hpp>
#include <simpson/iterate.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/three_term_scheme.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace simpson::verify {
namespace {

using detail::figure;
using detail::figure_text;

/// Eigenvalues of Φ₃ = ((α, β), (γ, α)) with det 1: α ± sqrt(α² − 1), on the unit circle when |α| <= 1.
template <class Real>
json eigen_description(const one_step_matrix<Real>& phi) {
  using std::abs;
  using std::sqrt;
  const Real a = phi.alpha, d = a * a - 1;
  if (d <= 0) {
    return {{"eigenvalues", fmt::format("{} ± {} i", simpson::to_string(a, 8), simpson::to_string(Real(sqrt(Real(-d))), 8))},
            {"modulus", "1"},
            {"growth_factor", "1"}};
  }
  const Real root = sqrt(d);
  const Real big = abs(a) + root;
  return {{"eigenvalues", fmt::format("{}, {}", simpson::to_string(Real(a + root), 8), simpson::to_string(Real(a - root), 8))},
          {"modulus", "real pair"},
          {"growth_factor", simpson::to_string(big, 8)}};
}

/// max_j (|q_j| + |p_j|/(mω)) over the first `steps` steps from y_0 = (0.6 mω, 0.8), a start
/// with a component off every eigenvector (A = 1), sampled at j = 10, 100, 1000, 10000 and steps.
template <class Real>
json growth_run(const oscillator_parameters<Real>& par, long long steps) {
  using std::abs;
  const phase_point<Real> y0{Real(par.m() * par.omega() * 6 / 10), Real(Real(8) / 10)};
  const one_step_matrix<Real> phi = simpson_map(par);
  json samples = json::object();
  Real largest(0);
  phase_point<Real> y = y0;
  for (long long j = 1; j <= steps; ++j) {
    y = phi * y;
    largest = std::max(largest, Real(abs(y.q) + abs(y.p) / (par.m() * par.omega())));
    if (j == 10 || j == 100 || j == 1000 || j == 10000 || j == steps) samples[std::to_string(j)] = figure(largest);
  }
  return samples;
}

}  // namespace

section_output run_stability(const stability_settings& s) {
  section_output out;
  out.name = "stability";
  std::string md = "## Stability: exact region, endpoints, stiff and extreme cases\n\n";

  // 1. The exact region (the ledger's Sturm-sequence analysis of Δ).
  const detail::stability_report report = detail::analyse_three_term_scheme(
      [](const symbolic& qp, const symbolic& q, const symbolic& qn) {
        const oscillator_parameters<symbolic> unit{symbolic(1), symbolic(1),
                                                           symbolic::variable()};
        return three_term_residual(unit, qp, q, qn);
      });
  json intervals = json::array();
  md += "### Exact stability region of Φ₃ (ωh > 0)\n\nFrom the exact discriminant Δ(x), x = ω²h², by Sturm sequences "
        "(the ledger's stability claims): stable where Δ < 0 (two simple roots on the unit circle).\n\n"
        "| ωh from | ωh to | x from | x to | Δ | stable |\n|---|---|---|---|---|---|\n";
  std::vector<rational> endpoints;  // x = ω²h² at each finite endpoint, exact
  for (const json& band : report.evidence["bands"]) {
    intervals.push_back(band);
    md += fmt::format("| {} | {} | {} | {} | {} | {} |\n", band["omega_h_from"].get<std::string>(),
                      band["omega_h_to"].get<std::string>(), band["x_from"].get<std::string>(), band["x_to"].get<std::string>(),
                      band["sign_of_discriminant"].get<std::string>(), band["stable"].get<bool>() ? "yes" : "no");
  }
  out.data["intervals"] = intervals;
  out.data["stable_intervals_omega_h"] = json::array();
  for (const json& band : report.evidence["bands"]) {
    if (band["stable"].get<bool>()) {
      out.data["stable_intervals_omega_h"].push_back({band["omega_h_from"], band["omega_h_to"]});
    }
    if (band["omega_h_to"] != "infinity") {
      // An exact root prints as a rational ("8"); an inexact one as an interval, which has no exact endpoint to run at.
      const std::string x_text = band["x_to"].get<std::string>();
      if (x_text.find('[') != std::string::npos) throw std::logic_error("stability: endpoint x = " + x_text + " is not exact");
      endpoints.push_back(rational(x_text));
    }
  }

  // 2. At and around each endpoint, in mpfr:50: eigenvalues, growth factor and runs.
  md += fmt::format("\n### At and around each endpoint (mpfr:50, m = ω = 1, {} steps from y₀ = (0.6 mω, 0.8), amplitude A = |q| + |p|/(mω))\n\n"
                    "At an endpoint Φ₃ has a double eigenvalue ±1 with a Jordan block (Φ₃ ∓ I ≠ 0), so |y_j| grows "
                    "linearly; inside a stable interval it stays bounded; outside it grows like the growth factor^j.\n\n"
                    "| ωh | eigenvalues | growth factor | Φ₃ − λI ≠ 0 | max |y|/A by j = 10 | 100 | 1000 |\n|---|---|---|---|---|---|---|\n",
                    s.steps);
  json endpoint_rows = json::array();
  detail::visit_floating(precision::mpfr_digits(50), [&](auto tag) {
    using Real = typename decltype(tag)::type;
    using std::sqrt;
    for (const rational& x_end : endpoints) {
      const std::string x_text = simpson::to_string(x_end);
      const Real theta_end = sqrt(Real(detail::from_decimal<Real>(boost::multiprecision::numerator(x_end).str()) /
                                       detail::from_decimal<Real>(boost::multiprecision::denominator(x_end).str())));
      for (const int side : {-1, 0, 1}) {
        throw_if_interrupted();
        const Real theta = theta_end * (1 + Real(side) / 1000000);
        const oscillator_parameters<Real> par{Real(1), Real(1), theta};
        const one_step_matrix<Real> phi = simpson_map(par);
        json row = eigen_description(phi);
        row["omega_h"] = side == 0 ? fmt::format("sqrt({}) = {}", x_text, simpson::to_string(theta, 8))
                                   : fmt::format("sqrt({}) (1 {} 1e-6)", x_text, side < 0 ? "-" : "+");
        using std::abs;
        // At the endpoint α = ±1 up to round-off: θ carries one rounding, and α(x) has slope
        // |dα/dx| <= 1 on (0, 24], so |α − λ| <= 64 eps x covers θ², the formula's ~20 roundings and room.
        // A Jordan block: the double root λ with Φ₃ − λI ≠ 0 (β or γ non-zero).
        const Real lambda = phi.alpha > 0 ? Real(1) : Real(-1);
        const Real x = theta * theta;
        row["jordan_block"] = side == 0 ? json(abs(phi.beta) + abs(phi.gamma) > 0 &&
                                               abs(Real(phi.alpha - lambda)) <= 64 * eps<Real>() * x)
                                        : json("n/a");
        row["max_amplitude_ratio"] = growth_run(par, s.steps);
        const json& g = row["max_amplitude_ratio"];
        md += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", row["omega_h"].get<std::string>(),
                          row["eigenvalues"].get<std::string>(), figure_text(row["growth_factor"]),
                          row["jordan_block"].is_boolean() ? (row["jordan_block"].get<bool>() ? "yes (Jordan block)" : "no") : "",
                          g.contains("10") ? figure_text(g["10"]) : "", g.contains("100") ? figure_text(g["100"]) : "",
                          g.contains("1000") ? figure_text(g["1000"]) : "");
        endpoint_rows.push_back(row);
      }
    }
  });
  out.data["endpoints"] = endpoint_rows;

  // 3. Stiff: ω up to 1e8 at fixed ωh, and 4. extreme ωh, in each precision.
  md += fmt::format("\n### Stiff: ω up to {} at ωh = {} ({} steps, m = 1)\n\nRelative errors at the end against the "
                    "exact solution and the largest relative change of H_d; by the scaling lemma they depend on ωh "
                    "alone, so each column should be constant down the precision's round-off.\n\n"
                    "| precision | ω | error q | error p/(mω) | max H_d drift (relative) |\n|---|---|---|---|---|\n",
                    simpson::to_string(s.stiff_omegas.empty() ? 0.0 : s.stiff_omegas.back(), 1),
                    simpson::to_string(s.stiff_omega_h, 3), s.steps);
  json stiff_rows = json::array();
  std::string extreme_md =
      "\n### Extreme ωh in each precision\n\nTruncation coefficient: c = T_h(q_j)/(ω⁶h⁴q_j) computed from the "
      "scheme's own formula (schema-ordre-3) on exact values, against its exact value F(θ)/θ⁴ (closed form, mpfr:200), "
      "which tends to 1/1440; 'digits' = correct significant digits of c. H_d: the largest relative change over the run, "
      "and the digits it keeps. A precision 'loses 1/1440' where c has no correct digit.\n\n"
      "| precision | ωh | c | exact c | digits of c | max H_d drift | digits of H_d |\n|---|---|---|---|---|---|---|\n";
  json extreme_rows = json::array();
  std::string mass_md = "\n### Extreme masses (ω = 1, ωh = 1, y₀ = (mω, 0))\n\nEvery figure is checked first: "
                        "a value beyond double's range is 'overflow', one lost below it 'underflow', a NaN 'non-finite'.\n\n"
                        "| precision | m | H(y₀) | H_d(y₀) | max H_d drift (relative) | error q (end) | status |\n|---|---|---|---|---|---|---|\n";
  json mass_rows = json::array();
  std::string extreme_data = "# blocks: one per precision; columns omega_h digits_of_c digits_of_Hd\n";

  // Exact truncation coefficients F(θ)/θ⁴ in mpfr:200, as decimal strings.
  std::vector<std::string> exact_c;
  detail::visit_floating(precision::mpfr_digits(200), [&](auto tag) {
    using Real = typename decltype(tag)::type;
    using std::cos;
    for (const double th : s.omega_h) {
      const Real t(th), c = cos(t);
      const Real F = (2 * c - 2) / (t * t) + (2 * c + 22) / 24 - t * t / 24;
      exact_c.push_back(simpson::to_string(Real(F / (t * t * t * t)), 120));
    }
  });

  for (const precision& prec : s.precisions) {
    detail::visit_floating(prec, [&](auto tag) {
      using Real = typename decltype(tag)::type;
      using std::abs;
      using std::log10;
      const double digits_carried = static_cast<double>(prec.digits10());
      for (const double w : s.stiff_omegas) {
        throw_if_interrupted();
        const oscillator_parameters<Real> par{Real(1), Real(w), Real(Real(s.stiff_omega_h) / Real(w))};
        const phase_point<Real> y0{Real(w), Real(0)};
        const Real Hd0 = discrete_energy(par, y0);
        Real drift(0);
        const phase_point<Real> y = iterate(simpson_map(par), y0, static_cast<std::size_t>(s.steps),
                                            [&](std::size_t, const phase_point<Real>& z) {
                                              drift = std::max(drift, Real(abs(Real(discrete_energy(par, z) - Hd0)) / abs(Hd0)));
                                            });
        const phase_point<Real> exact = exact_solution(par, y0, Real(par.h() * Real(s.steps)));
        const Real eq = abs(Real(y.q - exact.q)), ep = abs(Real(y.p - exact.p)) / w;
        stiff_rows.push_back({{"precision", prec.name()}, {"omega", w}, {"error_q", figure(eq)},
                              {"error_p_over_m_omega", figure(ep)}, {"max_Hd_drift_relative", figure(drift)}});
        md += fmt::format("| {} | {} | {} | {} | {} |\n", prec.name(), simpson::to_string(w, 1), figure_text(eq),
                          figure_text(ep), figure_text(drift));
      }
      extreme_data += "# " + prec.name() + "\n";
      for (std::size_t k = 0; k < s.omega_h.size(); ++k) {
        throw_if_interrupted();
        const double th = s.omega_h[k];
        const oscillator_parameters<Real> par{Real(1), Real(1), Real(th)};
        const phase_point<Real> y0{Real(1), Real(0)};
        // c from the scheme's residual at t = 0.3 on the exact solution q = sin t.
        const phase_point<Real> at{Real(cos(Real(3) / 10)), Real(sin(Real(3) / 10))};
        const Real q_prev = exact_solution(par, at, Real(-par.h())).q, q_next = exact_solution(par, at, par.h()).q;
        const Real t4 = Real(th) * Real(th) * Real(th) * Real(th);
        const Real c = three_term_residual(par, q_prev, at.q, q_next) / (t4 * at.q);
        const Real c_exact = detail::from_decimal<Real>(exact_c[k]);
        const Real rel = abs(Real(c - c_exact)) / c_exact;
        const double digits_c = rel == 0 ? digits_carried : std::clamp(-static_cast<double>(log10(rel)), 0.0, digits_carried);
        const Real Hd0 = discrete_energy(par, y0);
        Real drift(0);
        std::string status = "ok";
        try {
          iterate(simpson_map(par), y0, static_cast<std::size_t>(s.steps), [&](std::size_t, const phase_point<Real>& z) {
            drift = std::max(drift, Real(abs(Real(discrete_energy(par, z) - Hd0)) / abs(Hd0)));
          });
        } catch (const std::domain_error& e) {
          status = std::string("failed: ") + e.what();
        }
        const double digits_hd = drift == 0 ? digits_carried
                                            : std::clamp(-static_cast<double>(log10(drift)), 0.0, digits_carried);
        extreme_rows.push_back({{"precision", prec.name()}, {"omega_h", th}, {"c", figure(c)}, {"c_exact", simpson::to_string(static_cast<double>(c_exact), 9)},
                                {"digits_of_c", std::round(digits_c * 10) / 10}, {"max_Hd_drift_relative", figure(drift)},
                                {"digits_of_Hd", std::round(digits_hd * 10) / 10}, {"status", status}});
        extreme_md += fmt::format("| {} | {} | {} | {} | {:.1f} | {} | {:.1f} |\n", prec.name(), simpson::to_string(th, 2),
                                  figure_text(c), simpson::to_string(static_cast<double>(c_exact), 6), digits_c, figure_text(drift), digits_hd);
        extreme_data += fmt::format("{} {:.2f} {:.2f}\n", simpson::to_string(th, 3), digits_c, digits_hd);
      }
      extreme_data += "\n\n";
      for (const double mass : s.masses) {
        throw_if_interrupted();
        // The mass is converted to Real first: 1e300 is finite in every precision here, its square not in double.
        const oscillator_parameters<Real> par{Real(mass), Real(1), Real(1)};
        const phase_point<Real> y0{par.m(), Real(0)};
        const Real H0 = energy(par, y0), Hd0 = discrete_energy(par, y0);
        Real drift(0);
        phase_point<Real> y = y0;
        std::string status = "ok";
        const one_step_matrix<Real> phi = simpson_map(par);
        for (long long j = 0; j < s.steps; ++j) {
          y = phi * y;
          drift = std::max(drift, Real(abs(Real(discrete_energy(par, y) - Hd0)) / abs(Hd0)));
        }
        const Real eq = abs(Real(y.q - exact_solution(par, y0, Real(s.steps)).q));
        if (H0 == 0 || Hd0 == 0) status = "underflow";  // a non-zero state whose energy rounds to 0
        for (const std::string& f : {detail::fault_of(H0), detail::fault_of(Hd0), detail::fault_of(drift), detail::fault_of(eq)}) {
          if (status == "ok" && f != "ok") status = f;
        }
        mass_rows.push_back({{"precision", prec.name()}, {"m", mass}, {"H0", figure(H0)}, {"Hd0", figure(Hd0)},
                             {"max_Hd_drift_relative", status == "ok" ? figure(drift) : json(status)},
                             {"error_q_end", figure(eq)}, {"status", status}});
        mass_md += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", prec.name(), simpson::to_string(mass, 1),
                               figure_text(H0), figure_text(Hd0), status == "ok" ? figure_text(drift) : status,
                               figure_text(eq), status);
      }
    });
  }
  out.data["stiff"] = stiff_rows;
  out.data["extreme_omega_h"] = extreme_rows;
  out.data["extreme_masses"] = mass_rows;
  out.files.push_back({"stability_extreme.dat", extreme_data});
  std::vector<std::string> names;
  for (const precision& p : s.precisions) {
    std::string n = p.name();
    std::replace(n.begin(), n.end(), ' ', '-');
    names.push_back(n);
  }
  out.plots.push_back(
      {"stability_extreme", "Correct digits of the truncation coefficient (solid) and of H_d (dashed) against ωh, per precision",
       fmt::format("set title 'Digits kept against omega h'\nset xlabel 'omega h (dimensionless)'\n"
                   "set ylabel 'correct significant digits'\nset logscale x\nset format x '10^{{%L}}'\nset key outside right\n"
                   "names = '{}'\nn = words(names)\n"
                   "plot for [i=0:{}] 'stability_extreme.dat' index i u 1:2 w lp lc i+1 pt 7 t 'c: '.word(names, i+1), "
                   "for [i=0:{}] '' index i u 1:3 w lp dt 2 lc i+1 pt 6 t 'H_d: '.word(names, i+1)\n",
                   fmt::join(names, " "), names.size() - 1, names.size() - 1)});
  out.markdown = md + extreme_md + mass_md + "\n![digits against omega h](stability_extreme.svg)\n\n";
  return out;
}

}  // namespace simpson::verify

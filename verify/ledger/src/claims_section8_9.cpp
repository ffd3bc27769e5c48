// The scaling lemma the exact proofs rest on; Section 8 (Table 1) and Section 9 (conclusion).

#include "claim_support.hpp"
#include "claims_section8_9.hpp"
#include <simpson/verify/paper_table.hpp>
#include <simpson/verify/stability_analysis.hpp>

#include <simpson/classical_lagrangian.hpp>
#include <simpson/energy.hpp>
#include <simpson/internal_node.hpp>
#include <simpson/reduced_lagrangian.hpp>
#include <simpson/simpson_lagrangian.hpp>
#include <simpson/simpson_momentum.hpp>
#include <simpson/exact_solution.hpp>
#include <simpson/iterate.hpp>
#include <simpson/newmark_map.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/three_term_scheme.hpp>

#include <boost/math/constants/constants.hpp>

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace simpson::verify::detail {
namespace {

claim_result check_scaling(const run_context&) {
  // h = θ/ω with θ symbolic and m, ω, p, q on a grid. Each quantity is m^a ω^b h^c F(ω²h²) with
  // |a|, |b|, |c| <= 2, so (mω)² × gap is a polynomial of degree <= 4 in m and in ω, and of degree
  // <= 2 in p and q.
  const symbolic theta = symbolic::variable();
  const oscillator_parameters<symbolic> unit{symbolic(1), symbolic(1), theta};
  const proof p = prove_zero_on_grid(
      "h = theta/omega; (m omega)^2 times: Phi_3 and Phi entries minus S Phi(1, 1, theta) S^-1 with S = diag(m omega, 1); "
      "H_d and H minus m omega^2 times their unit values at (p/(m omega), q); (schema-ordre-3) minus omega^2 times its "
      "unit value",
      {"m", "omega", "p", "q"}, std::vector<int>{4, 4, 2, 2}, [&](const std::vector<rational>& v) {
        const symbolic m(v[0]), w(v[1]), p(v[2]), q(v[3]);
        const oscillator_parameters<symbolic> par{m, w, theta / w};
        const symbolic mw = m * w, clear = mw * mw;
        std::vector<symbolic> gaps;
        for (const bool simpson_scheme : {true, false}) {
          const one_step_matrix<symbolic> full = simpson_scheme ? simpson_map(par) : newmark_map(par);
          const one_step_matrix<symbolic> reduced = simpson_scheme ? simpson_map(unit) : newmark_map(unit);
          gaps.push_back(clear * (full.alpha - reduced.alpha));
          gaps.push_back(clear * (full.beta - mw * reduced.beta));
          gaps.push_back(clear * (full.gamma - reduced.gamma / mw));
          gaps.push_back(clear * (full.delta - reduced.delta));
        }
        const phase_point<symbolic> y{p, q}, scaled{p / mw, q};
        gaps.push_back(clear * (discrete_energy(par, y) - m * w * w * discrete_energy(unit, scaled)));
        gaps.push_back(clear * (energy(par, y) - m * w * w * energy(unit, scaled)));
        gaps.push_back(clear * (three_term_residual(par, p, q, p + q) - w * w * three_term_residual(unit, p, q, p + q)));
        return gaps;
      });
  // The formulas the other proofs evaluate at m = omega = 1 as well, with (q_l, q_r) = (p, q): q_m is
  // invariant, p_r and the Lagrangians scale by m omega. The elimination route of Section 6 solves
  // p_j = p_r(q_{j-1}, q_j) and (schema-ordre-3) and evaluates p_r: built from p_r and the scheme
  // alone, both covered, it scales as Phi_3 does (and phi3-elimination proves it equal to Phi_3
  // in GiNaC with every symbol free). Each is (m omega)^a F(theta) with |a| <= 1, so
  // m omega × gap has degree <= 2 in m and in omega, and <= 2 in p and q. The unit values depend on
  // (p, q) only and are computed once per pair.
  std::map<std::pair<std::string, std::string>, std::vector<symbolic>> unit_values;
  const auto unit_at = [&](const symbolic& p, const symbolic& q) -> const std::vector<symbolic>& {
    const auto key = std::make_pair(to_string(p.numerator(), "θ"), to_string(q.numerator(), "θ"));
    auto it = unit_values.find(key);
    if (it != unit_values.end()) return it->second;
    const auto V = [&](const symbolic& x) { return unit.potential(x); };
    const auto force = [&](const symbolic& x) { return unit.force_gradient(x); };
    return unit_values[key] = {harmonic_internal_node(unit, p, q), simpson_momentum(unit, p, q), reduced_lagrangian(unit, p, q),
                               simpson_lagrangian(symbolic(1), theta, V, p, p + q, q), classical_lagrangian(symbolic(1), theta, V, p, q),
                               classical_momentum(symbolic(1), theta, force, p, q)};
  };
  const proof extended = prove_zero_on_grid(
      "h = theta/omega; m omega times: q_m (qm-oscillateur-harmonique) minus its unit value; p_r (moment-ordre-3), L_h^r "
      "(Lagrangien-reduit), L_h (LLhh, harmonic V), L_d (lagrangien-discret) and its momentum minus m omega times their unit "
      "values, at (q_l, q_r) = (p, q)",
      {"m", "omega", "p", "q"}, std::vector<int>{2, 2, 2, 2}, [&](const std::vector<rational>& v) {
        const symbolic m(v[0]), w(v[1]), p(v[2]), q(v[3]);
        const oscillator_parameters<symbolic> par{m, w, theta / w};
        const symbolic mw = m * w;
        const auto V = [&](const symbolic& x) { return par.potential(x); };
        const auto force = [&](const symbolic& x) { return par.force_gradient(x); };
        const std::vector<symbolic>& u = unit_at(p, q);
        return std::vector<symbolic>{mw * (harmonic_internal_node(par, p, q) - u[0]), mw * (simpson_momentum(par, p, q) - mw * u[1]),
                                     mw * (reduced_lagrangian(par, p, q) - mw * u[2]),
                                     mw * (simpson_lagrangian(m, par.h(), V, p, p + q, q) - mw * u[3]),
                                     mw * (classical_lagrangian(m, par.h(), V, p, q) - mw * u[4]),
                                     mw * (classical_momentum(m, par.h(), force, p, q) - mw * u[5])};
      });
  json evidence = json::object();
  evidence["exact"] = json::array({p.evidence, extended.evidence});
  return confirmed_if(p.proved && extended.proved, evidence,
                      "With p scaled by m omega and t by omega every result depends on theta = omega h alone; the exact "
                      "proofs therefore take m = omega = 1, h = theta.");
}

/// "exact" when every error is at round-off (at_round_off_floor); otherwise the closest integer to
/// log2 of successive ratios, when both ratios agree.
std::string estimated_order(const std::array<double, 3>& errors, double H0) {
  bool round_off = true;
  for (std::size_t k = 0; k < errors.size(); ++k) round_off = round_off && at_round_off_floor(errors[k], published_meshes[k], H0);
  if (round_off) return "exact";
  const long first = std::lround(std::log2(errors[0] / errors[1]));
  const long second = std::lround(std::log2(errors[1] / errors[2]));
  return first == second ? std::to_string(first) : "inconsistent (" + std::to_string(first) + ", " + std::to_string(second) + ")";
}

json table_evidence(bool& orders_match, bool& conservation_match, bool& values_match) {
  orders_match = conservation_match = values_match = true;
  std::array<std::array<table_errors, 3>, 2> runs{};
  for (int s = 0; s < 2; ++s) {
    for (std::size_t k = 0; k < 3; ++k) runs[static_cast<std::size_t>(s)][k] = run_table_experiment(s == 1, published_meshes[k]);
  }
  const double H0 = 2 * boost::math::constants::pi<double>() * boost::math::constants::pi<double>();  // (mω)²/(2m)
  json rows = json::array();
  for (const published_row& row : published_rows()) {
    std::array<double, 3> ours{};
    json ratios = json::array(), values = json::array();
    for (std::size_t k = 0; k < 3; ++k) {
      ours[k] = runs[row.simpson_scheme ? 1 : 0][k].*row.field;
      values.push_back(simpson::to_string(ours[k], 3));
      ratios.push_back(simpson::to_string(row.published[k] / ours[k], 3));
    }
    const std::string order = estimated_order(ours, H0);
    const bool exact_column = std::string(row.published_order) == "exact";
    if (exact_column) {
      conservation_match = conservation_match && order == "exact";
    } else {
      orders_match = orders_match && order == row.published_order;
      for (std::size_t k = 0; k < 3; ++k) {
        const double ratio = row.published[k] / ours[k];
        values_match = values_match && ratio > 0.95 && ratio < 1.05;
      }
    }
    rows.push_back({{"scheme", row.scheme},
                    {"quantity", row.quantity},
                    {"ours_N_10_20_40", values},
                    {"published_N_10_20_40", {simpson::to_string(row.published[0], 3), simpson::to_string(row.published[1], 3),
                                              simpson::to_string(row.published[2], 3)}},
                    {"published_over_ours", exact_column ? json("round-off on both sides") : ratios},
                    {"order_ours", order},
                    {"order_published", row.published_order}});
  }
  json e;
  e["method"] = "numeric (double)";
  e["conventions"] = "m = 1, omega = 2 pi, T = 1, N = 10, 20, 40; y_0 = (m omega, 0) exact, then y_{j+1} = Phi y_j; maximum over "
                     "j = 0..N of |p_j - p(t_j)|, |q_j - q(t_j)|, |H(y_j) - H(y_0)|, |H_d(y_j) - H_d(y_0)|; order = closest "
                     "integer to log2 of successive ratios (both must agree), 'exact' when every error is below 64 eps N H_0";
  e["rows"] = rows;
  return e;
}

claim_result check_table_orders(const run_context&) {
  bool orders = false, conservation = false, values = false;
  json evidence;
  evidence["numeric"] = table_evidence(orders, conservation, values);
  return confirmed_if(orders, evidence);
}

claim_result check_table_conservation(const run_context&) {
  bool orders = false, conservation = false, values = false;
  json evidence;
  evidence["numeric"] = table_evidence(orders, conservation, values);
  return confirmed_if(conservation, evidence,
                      "'exact' means conserved to round-off: the errors grow with N only through rounding.");
}

claim_result check_table_values(const run_context&) {
  bool orders = false, conservation = false, values = false;
  json evidence;
  evidence["numeric"] = table_evidence(orders, conservation, values);
  evidence["numeric"]["also_tried"] = table_also_tried;
  return confirmed_if(values, evidence, table_not_reproduced);
}

claim_result check_conclusion_symplectic_stable(const run_context&) {
  const proof det = prove_zero("m = omega = 1, h = theta; det Phi_3 - 1", determinant(simpson_map(unit_oscillator_in_theta())) - 1);
  const auto par = unit_oscillator_in_theta();
  const stability_report report = analyse_three_term_scheme([&](const symbolic& qp, const symbolic& q, const symbolic& qn) {
    return three_term_residual(par, qp, q, qn);
  });
  // Conditionally stable: some band is stable, and a stable band ends at a finite root.
  bool bounded = false, any_stable = false;
  for (const stability_band& b : report.bands) {
    any_stable = any_stable || b.stable;
    bounded = bounded || (b.stable && b.to);
  }
  json evidence;
  evidence["exact"] = json::array({det.evidence, report.evidence});
  return confirmed_if(det.proved && bounded && any_stable, evidence,
                      "Conditionally stable: stable for omega h in (0, 2 sqrt(2)) and (2 sqrt(3), 2 sqrt(6)), unstable "
                      "elsewhere.");
}

claim_result check_conclusion_fourth_order(const run_context&) {
  // Exact: Phi_3 (m = ω = 1, h = θ) against the exact flow ((cos θ, −sin θ), (sin θ, cos θ)).
  const one_step_matrix<symbolic> phi = simpson_map(unit_oscillator_in_theta());
  const symbolic c(cos_taylor(14), make_polynomial({rational(1)})), s(sin_taylor(15), make_polynomial({rational(1)}));
  json local = json::object();
  long lowest = 100;
  const std::pair<const char*, symbolic> gaps[] = {
      {"alpha - cos", phi.alpha - c}, {"beta + sin", phi.beta + s}, {"gamma - sin", phi.gamma - s}, {"delta - cos", phi.delta - c}};
  for (const auto& [name, gap] : gaps) {
    // Taylor of the rational entries: multiply out 1/(1 + θ²/24) as a series by dividing numerator
    // by the denominator's series through θ^14.
    const polynomial& d = gap.denominator();
    std::vector<rational> inverse(15, rational(0));
    inverse[0] = 1 / d[0];
    for (std::size_t k = 1; k < inverse.size(); ++k) {
      rational acc = 0;
      for (std::size_t i = 1; i <= k && i < d.size(); ++i) acc += d[i] * inverse[k - i];
      inverse[k] = -acc / d[0];
    }
    const polynomial series = gap.numerator() * polynomial(inverse.begin(), inverse.end());
    std::vector<std::pair<long, rational>> terms;
    for (long k = 0; k < 14 && k <= degree(series); ++k) {
      if (series[static_cast<std::size_t>(k)] != 0) terms.emplace_back(k, series[static_cast<std::size_t>(k)]);
    }
    if (!terms.empty()) lowest = std::min(lowest, terms.front().first);
    local[name] = series_to_string(terms, "θ") + " + O(θ^14)";
  }
  // Numeric: global errors of the paper's experiment for N = 10 ... 320, least-squares slope.
  json global = json::array();
  double slopes[2] = {0, 0};
  {
    std::vector<double> lx, lp, lq;
    for (long N = 10; N <= 320; N *= 2) {
      const table_errors e = run_table_experiment(true, N);
      lx.push_back(std::log(1.0 / N));
      lp.push_back(std::log(e.p));
      lq.push_back(std::log(e.q));
      global.push_back({{"N", N}, {"error_p", simpson::to_string(e.p, 3)}, {"error_q", simpson::to_string(e.q, 3)}});
    }
    const auto slope = [&](const std::vector<double>& ly) {
      double mx = 0, my = 0;
      for (std::size_t k = 0; k < lx.size(); ++k) mx += lx[k], my += ly[k];
      mx /= lx.size(), my /= ly.size();
      double num = 0, den = 0;
      for (std::size_t k = 0; k < lx.size(); ++k) num += (lx[k] - mx) * (ly[k] - my), den += (lx[k] - mx) * (lx[k] - mx);
      return num / den;
    };
    slopes[0] = slope(lp);
    slopes[1] = slope(lq);
  }
  json evidence;
  evidence["exact"] = {{"method", "exact series"},
                       {"reduction", "m = omega = 1, h = theta; entries of Phi_3 minus the exact flow over one step"},
                       {"local_error", local},
                       {"lowest_power", lowest}};
  evidence["numeric"] = {{"method", "numeric (double)"},
                         {"experiment", "Section 8 conventions, N = 10 ... 320"},
                         {"runs", global},
                         {"slope_p", simpson::to_string(slopes[0], 3)},
                         {"slope_q", simpson::to_string(slopes[1], 3)}};
  const bool fourth = lowest == 5 && std::abs(slopes[0] - 4) < 0.1 && std::abs(slopes[1] - 4) < 0.1;
  return confirmed_if(fourth, evidence,
                      "Local error O(h^5) per step (the off-diagonal entries differ from sin(omega h) at theta^5), hence "
                      "global error O(h^4) over a fixed time, measured slopes about 4 for p and q.");
}

/// Figure 1 (N = 15, one period, q = sin omega t, p = m omega cos omega t): the momentum of the
/// symplectic Simpson scheme is "very close" to the exact one. Read as: indistinguishable on the
/// figure, below 1/500 of the amplitude m omega (one pixel of a 500-pixel panel). That is a
/// resolution threshold for a plot, not a round-off tolerance.
claim_result check_figure1(const run_context&) {
  const table_errors simpson = run_table_experiment(true, 15), newmark = run_table_experiment(false, 15);
  const double amplitude = boost::math::constants::two_pi<double>();  // m omega with m = 1
  const double resolution = 1.0 / 500;
  json evidence;
  evidence["numeric"] = {{"method", "numeric (double)"},
                         {"experiment", "Section 8 conventions, N = 15 (Figure 1), errors at the nodes over one period"},
                         {"simpson_p_error_over_m_omega", fmt::format("{:.2e}", simpson.p / amplitude)},
                         {"simpson_q_error", fmt::format("{:.2e}", simpson.q)},
                         {"newmark_p_error_over_m_omega", fmt::format("{:.2e}", newmark.p / amplitude)},
                         {"newmark_q_error", fmt::format("{:.2e}", newmark.q)},
                         {"resolution", "1/500 of the amplitude"}};
  const bool close = simpson.p / amplitude < resolution && simpson.q < resolution;
  return confirmed_if(close, evidence,
                      fmt::format("The Simpson curves are within {:.1e} of the amplitude, invisible on the figure; Newmark's "
                                  "momentum is off by {:.1f}% of it and its state by {:.1f}%, visible: 'both schemes give very "
                                  "satisfactory results' holds for Newmark only at the eye's tolerance. Figure 1 itself is "
                                  "missing from the source; table1 redraws it (figure1.svg).",
                                  std::max(simpson.p / amplitude, simpson.q), 100 * newmark.p / amplitude, 100 * newmark.q));
}

/// Section 9: "the elimination of the internal degree of freedom is not possible" in the nonlinear
/// case. What holds: (equation-milieu-intervalle) is q_m = G(q_m) with G(x) = (q_l + q_r)/2 +
/// h^2 V'(x)/(8m), so G' = h^2 V''/(8m); when h^2 sup|V''|/(8m) < 1, G is a contraction and q_m is
/// unique and the limit of the iteration (Banach): eliminated implicitly, not in closed form.
claim_result check_nonlinear_internal_node(const run_context&) {
  const symbolic theta = symbolic::variable();
  claim_result r = identity_for_quartic_potentials(
      "h = theta, m on the grid; (equation-milieu-intervalle) + (8 m/h^2) (q_m - (q_l + q_r)/2 - h^2 V'(q_m)/(8 m))",
      {"m", "q_l", "q_m", "q_r"}, std::vector<int>{1, 1, 4, 1},
      [&](const monomial_potential& V, const std::vector<rational>& v) {
        const symbolic m(v[0]), ql(v[1]), qm(v[2]), qr(v[3]);
        const auto force = [&V](const symbolic& x) { return V.derivative(x); };
        return internal_equation_residual(m, theta, force, ql, qm, qr) +
               8 * m / (theta * theta) * (qm - (ql + qr) / 2 - theta * theta * force(qm) / (8 * m));
      },
      "");
  json& evidence = r.evidence;
  evidence["pendulum"] = "V = m omega^2 (1 - cos q): sup|V''| = m omega^2, so the contraction condition is omega^2 h^2/8 < 1, "
                         "omega h < 2 sqrt(2): the same bound as (stabilite)";
  r.note = std::string("Holds for elimination in closed form only (a wording finding): (equation-milieu-intervalle) is the "
                      "fixed-point equation q_m = (q_l + q_r)/2 + h^2 V'(q_m)/(8m), whose map has derivative h^2 V''/(8m); when "
                      "h^2 sup|V''|/(8m) < 1 it is a contraction, so q_m is unique and the limit of the fixed-point iteration "
                      "(Banach), and the internal node is eliminated implicitly. For the pendulum this condition is omega h < "
                      "2 sqrt(2), the harmonic stability bound.");
  return r;
}

}  // namespace

void add_scaling_lemma(std::vector<claim>& claims) {
  claims.push_back({"lemma-dimensional-scaling", "harness", "all",
                    "(Not a claim of the paper; the reduction every exact proof uses.) With S = diag(m omega, 1), Phi_3(m, omega, h) "
                    "= S Phi_3(1, 1, omega h) S^-1 and likewise for Phi; H_d and H scale by m omega^2 with p/(m omega); "
                    "(schema-ordre-3) scales by omega^2; q_m is invariant, and p_r, L_h^r, L_h, L_d and its momentum scale by m omega (so "
                    "the elimination route of Section 6, built from p_r and the scheme, transforms like Phi_3).",
                    {"exact"}, verdict::holds, check_scaling});
}

void add_section8_9_claims(std::vector<claim>& claims) {
  claims.push_back({"table-orders", "8", "Table 1",
                    "Estimated orders: Newmark 2 for momentum and state, 4 for the energy (hamiltonien-discret); symplectic "
                    "Simpson 4 for momentum, state and the energy (HH-exact).",
                    {"numeric"}, verdict::holds, check_table_orders});
  claims.push_back({"table-conservation", "8", "Table 1",
                    "Newmark conserves (HH-exact) and symplectic Simpson conserves (hamiltonien-discret) exactly (errors "
                    "~1e-13).",
                    {"numeric"}, verdict::holds, check_table_conservation});
  claims.push_back({"table-values", "8", "Table 1",
                    "The maximum-norm errors of Table 1 for N = 10, 20, 40 (q = sin omega t, p = m omega cos omega t, one "
                    "period T = 1).",
                    {"numeric"}, verdict::fails, check_table_values});
  claims.push_back({"figure1-statements", "8", "Figure 1",
                    "Figure 1 (N = 15): both schemes give very satisfactory results; the momentum p is very close to the exact "
                    "solution with the symplectic Simpson scheme.",
                    {"numeric"}, verdict::holds, check_figure1});
  claims.push_back({"conclusion-symplectic-stable", "9", "prose",
                    "The symplectic Simpson method is symplectic and conditionally stable.", {"exact"}, verdict::holds,
                    check_conclusion_symplectic_stable});
  claims.push_back({"conclusion-fourth-order", "9", "prose",
                    "The method is fourth order accurate for state and momentum.", {"exact series", "numeric"},
                    verdict::holds, check_conclusion_fourth_order});
  claims.push_back({"nonlinear-internal-node", "9", "equation-milieu-intervalle",
                    "An important question is still open concerning the nonlinear case. The elimination of the internal degree "
                    "of freedom is not possible in that case.",
                    {"exact"}, verdict::holds, check_nonlinear_internal_node});
}

}  // namespace simpson::verify::detail

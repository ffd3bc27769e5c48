// The family section (family_section.hpp).

#include <simpson/verify/family_section.hpp>
#include <simpson/verify/progress.hpp>

#include <simpson/verify/galerkin_ginac.hpp>
#include <simpson/verify/galerkin_member.hpp>
#include <simpson/verify/galerkin_pendulum.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

namespace simpson::verify {
namespace {

std::string bands_text(const member_analysis& a) {
  std::string out;
  for (const stable_piece& p : a.stable_set) out += (out.empty() ? "" : " ∪ ") + piece_text(p);
  return out.empty() ? "none" : out;
}

/// GiNaC's verdict on a member: "agrees", or what differs.
std::string ginac_text(const member_analysis& a, const ginac_member_check& g, bool ran) {
  if (!ran) return "not run";
  if (!g.derived) return "no map: " + g.failure;
  std::vector<std::string> differs;
  if (g.det_one != a.det_one) differs.push_back("det");
  if (g.form_conserved != a.form_conserved) differs.push_back("form");
  if (!g.same_as_exact_kernel) differs.push_back("Φ(1, 1, θ) differs from ours");
  if (!g.scaling) differs.push_back("the scaling law fails");
  return differs.empty() ? "agrees" : fmt::format("DIFFERS: {}", fmt::join(differs, ", "));
}

/// The characteristic polynomial r² − (tr Φ) r + 1 (det Φ = 1 proved) of each member with a map,
/// and its discriminant factored over Q, from GiNaC.
table discriminant_table(const std::vector<std::pair<member_analysis, ginac_member_check>>& members) {
  table t{"characteristic", "Characteristic polynomials and discriminants",
          "For each member with a map: tr Φ in x = ω²h² (it depends on ωh alone), so that the characteristic polynomial "
          "is r² − (tr Φ) r + 1 (det Φ = 1 is proved above), and its discriminant (tr Φ)² − 4 factored over Q (GiNaC's "
          "factor, numerator and denominator apart). The stable set is where it is negative, with the ends decided above.",
          {{"member", "member"}, {"trace", "tr Φ"}, {"discriminant", "(tr Φ)² − 4, factored"}}};
  for (const auto& [a, g] : members) {
    if (!a.derived || !g.derived) continue;
    t.add({figure::text(member_name(a.member)), figure::text(g.trace), figure::text(g.discriminant_factored)});
  }
  return t;
}

/// The order question, answered from the members derived: which reach 2s, which lose order, and
/// the rule that separates them, stated only as far as every member here bears it out.
std::string order_answer(const std::vector<member_analysis>& members, const std::vector<std::string>& lobatto_orders) {
  std::string out = "**The order question.** Lobatto with s + 1 points: " + fmt::format("{}", fmt::join(lobatto_orders, ", ")) + ".";
  std::size_t derived = 0, sufficient = 0, sufficient_full = 0, insufficient_full = 0, above_exactness = 0, not_derived = 0;
  std::vector<std::string> inconsistent;
  for (const member_analysis& a : members) {
    if (!a.derived) {
      ++not_derived;
      continue;
    }
    ++derived;
    const int s = a.member.degree, exact = exactness_degree(a.member.rule);
    const bool enough = exact >= 2 * s - 1;
    sufficient += enough;
    sufficient_full += enough && a.order >= 2 * s;
    insufficient_full += !enough && a.order >= 2 * s;
    if (!enough && a.order > exact + 1) ++above_exactness;
    if (a.order <= 0) inconsistent.push_back(fmt::format("{} (order {})", member_name(a.member), a.order));
  }
  if (derived == 0) return out;
  out += fmt::format(" Of the {} members derived, {} have a rule exact to degree 2s − 1 (the degree of the kinetic term "
                     "q̇² of a degree-s interpolant is 2s − 2, of the potential q² 2s), and {} of those reach order 2s; of the "
                     "{} with a less exact rule, {} reach it.",
                     derived, sufficient, sufficient_full, derived - sufficient, insufficient_full);
  if (sufficient_full == sufficient && insufficient_full == 0) {
    out += " So here a member reaches order 2s exactly when its rule is exact to degree 2s − 1: a rule with too few "
           "points (or points in the wrong places) for the degree costs order.";
  }
  if (above_exactness == 0 && derived > sufficient) {
    out += " A member with a less exact rule never passes the rule's exactness + 1.";
  }
  if (!inconsistent.empty()) {
    out += fmt::format(" Not convergent (order ≤ 0): {}.", fmt::join(inconsistent, ", "));
  }
  if (not_derived > 0) {
    out += fmt::format(" {} members give no one-step map: the rule cannot fix the internal degrees of freedom, or leaves "
                       "q_j and q_(j+1) uncoupled.",
                       not_derived);
  }
  return out;
}

/// Each member with a one-step map, stepped for V = 1 − cos q (the implicit step, Newton in long
/// double), its order measured against the pendulum's exact solution beside its linear order.
table pendulum_table(const std::vector<member_analysis>& members, const std::vector<long long>& steps, const progress_sink& progress) {
  std::vector<column> columns{{"member", "member"}, {"linear_order", "order (oscillator, exact)"}, column::fixed_point("pendulum_order", "order (pendulum)", 2)};
  for (const long long n : steps) columns.push_back({fmt::format("error_N{}", n), fmt::format("error, N = {}", n)});
  columns.push_back({"note", "note"});
  table t{"pendulum", "The implicit step for a general V, on the pendulum",
          fmt::format("Each member with a one-step map: the discrete Euler–Lagrange equations with the rule's own nodes and "
                      "weights (Gauss: Boost's Legendre zeros; Lobatto: the zeros of P′ by bisection; weights from the exact "
                      "moments), solved by Newton's method in long double, for V = 1 − cos q (m = ω = 1) from rest at q₀ = 1. "
                      "Error: max(|p − p_exact|, |q − q_exact|) at t = 5, with N steps (the exact solution by Jacobi's elliptic "
                      "functions, Boost.Math; t = 5 is not a whole period, so a map that only returns to its start cannot look exact). Order: log₂ of the ratio of consecutive errors, from the finest pair whose finer error is above "
                      "1e-15 (long double's unit round-off is 5.4e-20; the floor allows for its accumulation over {} steps).",
                      steps.empty() ? 0 : steps.back()),
          columns};
  for (const member_analysis& a : members) {
    if (!a.derived) continue;
    const pendulum_order r = measure_pendulum_order(a.member, steps);
    table_row row{figure::text(member_name(a.member)), figure::integer(a.order)};
    row.push_back(r.order ? figure::of(*r.order) : figure::text(r.ran ? "below the floor" : "no solve"));
    for (std::size_t k = 0; k < steps.size(); ++k) row.push_back(k < r.errors.size() ? figure::of(r.errors[k]) : figure{});
    row.push_back(figure::text(r.failure));
    t.add(row);
    progress_step(progress, "family", "pendulum " + member_name(a.member));
  }
  return t;
}

/// The stable sets in ωh, one panel per degree s, one row per rule: a line over each stable band,
/// a point at each stable end or isolated stable point.
plot_description stability_chart(const std::vector<member_analysis>& members, int max_degree) {
  constexpr double right = 20;  // ωh drawn up to here; every band's ends are in the table
  std::vector<panel> panels;
  for (int degree = 1; degree <= max_degree; ++degree) {
    panel pan{fmt::format("s = {}", degree), axis{"ωh"}, axis{""}};
    pan.x.range = std::pair{0.0, right};
    double row = 0;
    for (const member_analysis& a : members) {
      if (a.member.degree != degree) continue;
      ++row;
      // The paper's member: s = 2 with Simpson's rule (Newton–Cotes 3, the same rule as Lobatto 3).
      const bool papers = degree == 2 && a.member.rule.points == 3 &&
                          (a.member.rule.family == quadrature_family::newton_cotes || a.member.rule.family == quadrature_family::lobatto);
      pan.y.tics.emplace_back(row, rule_name(a.member.rule) + (papers ? " (the paper's)" : "") +
                                       (!a.derived ? " (no map)" : a.stable_set.empty() ? " (unstable)" : ""));
      const int color = papers ? 3 : a.member.rule.family == quadrature_family::newton_cotes ? 0 : a.member.rule.family == quadrature_family::lobatto ? 1 : 2;
      const std::string family = papers ? "the paper's member"
                                 : a.member.rule.family == quadrature_family::newton_cotes ? "Newton–Cotes"
                                 : a.member.rule.family == quadrature_family::lobatto      ? "Lobatto"
                                                                                            : "Gauss";
      // A rule with no one-step map, and a map stable nowhere, are drawn apart: a grey dashed line
      // and a row of open circles, so that neither reads as the other or as a missing computation.
      if (!a.derived) {
        series none{"no one-step map", line_style::dashed, 8, 7, 2};
        none.add(figure::of(0.0), figure::of(row));
        none.add(figure::of(right), figure::of(row));
        pan.curves.push_back(none);
        continue;
      }
      if (a.stable_set.empty()) {
        series nowhere{"stable nowhere", line_style::points, 8, 6};
        for (int k = 1; k < static_cast<int>(right); k += 2) nowhere.add(figure::of(static_cast<double>(k)), figure::of(row));
        pan.curves.push_back(nowhere);
        continue;
      }
      // Each unstable gap between two bands, however narrow (Lobatto 5's (3.1404, 3.1425) is 0.002
      // wide, below a pixel at this scale), is marked by a cross at its middle.
      series gaps{"unstable gap (any width)", line_style::points, 8, 2};
      for (std::size_t k = 0; k + 1 < a.stable_set.size(); ++k) {
        const double from = a.stable_set[k].to_value, to = a.stable_set[k + 1].from_value;
        if (to > from && from < right) gaps.add(figure::of((from + to) / 2), figure::of(row));
      }
      if (!gaps.x.empty()) pan.curves.push_back(gaps);
      for (const stable_piece& p : a.stable_set) {
        if (p.from_value >= right) continue;
        const double to = std::min(p.to_value, right);
        if (p.from_closed && p.to_closed && p.from == p.to) {
          series point{family + ": stable point (Φ = ±I)", line_style::points, color, 7};
          point.add(figure::of(p.from_value), figure::of(row));
          pan.curves.push_back(point);
          continue;
        }
        series band{papers ? std::string("the paper's member") : family + " rules", line_style::lines, color};
        band.add(figure::of(p.from_value), figure::of(row));
        band.add(figure::of(to), figure::of(row));
        pan.curves.push_back(band);
        for (const auto& [closed, at] : {std::pair{p.from_closed, p.from_value}, std::pair{p.to_closed, p.to_value}}) {
          if (!closed || at > right) continue;
          series end{family + ": stable point (Φ = ±I)", line_style::points, color, 7};
          end.add(figure::of(at), figure::of(row));
          pan.curves.push_back(end);
        }
      }
    }
    pan.y.range = std::pair{0.4, row + 0.6};
    panels.push_back(std::move(pan));
  }
  const int columns = std::min(3, max_degree);
  const int rows = (max_degree + columns - 1) / columns;
  return plot_description{"family_bands",
                          "The stable set in ωh of each member (m = ω = 1 by scaling), one panel per degree s: a line over "
                          "each open band where (tr Φ)² < 4, drawn up to ωh = 20 (a line reaching the right edge runs on; "
                          "the table gives every end); a cross at the middle of each unstable gap between bands, however "
                          "narrow; the paper's member (s = 2, Simpson's rule) in its own colour; a rule without a one-step "
                          "map as a grey dashed line, a map stable nowhere as a row of grey circles.",
                          panels, columns, 600 * columns, 80 + 30 * (3 * max_degree + 5) * rows};
}

}  // namespace

section_result run_family(const family_settings& s) {
  section_result out;
  out.name = "family";
  out.title = "The scheme's family: Galerkin variational integrators of degree s with a quadrature rule";
  out.conventions = {{"max_degree", s.max_degree},
                     {"budget_seconds", s.budget_seconds},
                     {"ginac", s.ginac},
                     {"node_check_degree", s.node_check_degree},
                     {"pendulum_steps", s.pendulum_steps}};
  table rows{"members", "",
             "Each member: the interpolant of degree s on one step (end values q_j, q_{j+1} and s − 1 internal degrees of "
             "freedom), the action by the quadrature rule, for the harmonic oscillator. Derived exactly in our kernel "
             "(rational functions of θ = ωh; m = ω = 1, restored by dimensional scaling): the discrete Lagrangian, the "
             "internal equations eliminated, the one-step map Φ in (p, q) (verify/family). det: det Φ = 1, exactly. form: "
             "ΦᵀWΦ = W for W = [[−γ, (α−δ)/2], [(α−δ)/2, β]], exactly. Stable ωh: where Φ is power-bounded: the open bands "
             "where (tr Φ)² < 4, from Sturm sequences (an irrational end is isolated in an interval of x = (ωh)² below "
             "2⁻⁴⁰ and printed ≈ to 10 digits), and a root of (tr Φ)² − 4 joined to them, with a closed bracket, exactly "
             "when Φ = ±I there (decided by a gcd with β and γ; elsewhere a Jordan block grows linearly). order and c: (2 cos ωh − tr Φ)/h² = "
             "c ω^(order+2) h^order + …, the three-term scheme's truncation error. equals: the known schemes whose Φ is "
             "identical (the core's own formulas in the same kernel; Gauss–Legendre by its diagonal Padé approximant; Lobatto "
             "IIIA–IIIB with 4 or more stages, whose tableaux are irrational, exactly in the nodal quotient ring, "
             "verify/family/partitioned_pair.hpp). GiNaC: "
             "the member derived again with m, ω, h symbolic and the rule's moments from its own nodal polynomial; 'agrees' "
             "when its det Φ = 1 and form match ours, Φ(1, 1, θ) is our Φ entry by entry, and Φ(m, ω, h) = S Φ(1, 1, ωh) S⁻¹ "
             "with S = diag(mω, 1). Internal nodes: for small s, the derivation with the interpolant's internal nodes as "
             "symbols ν_k; 'any' when Φ does not depend on them (equispaced, Lobatto, Gauss or any distinct nodes).",
             {{"member", "member"},
              {"exactness", "rule exact to degree"},
              {"derived", "derived"},
              {"det_one", "det Φ = 1"},
              {"form", "form conserved"},
              {"order", "order"},
              {"reaches_2s", "order 2s"},
              {"error_constant", "c"},
              {"stable", "stable ωh"},
              {"equals", "equals"},
              {"ginac", "GiNaC, m, ω, h symbolic"},
              {"nodes", "internal nodes"},
              {"size", "degree in θ"}}};
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> lobatto_orders;
  std::vector<member_analysis> analysed;
  std::vector<std::pair<member_analysis, ginac_member_check>> checked;
  bool stopped = false;
  for (int degree = 1; degree <= s.max_degree; ++degree) {
    for (const quadrature_rule& rule : family_rules(degree)) {
      const galerkin_member member{degree, rule};
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (elapsed > s.budget_seconds) {
        rows.add({figure::text(member_name(member)), figure::integer(exactness_degree(rule)),
                  figure::text(fmt::format("not run: the section's budget of {} s was spent", s.budget_seconds)), figure{}, figure{},
                  figure{}, figure{}, figure{}, figure{}, figure{}, figure{}, figure{}, figure{}});
        stopped = true;
        continue;
      }
      const member_analysis a = analyse_member(member);
      std::string equals;
      for (const std::string& e : a.equals) equals += (equals.empty() ? "" : "; ") + e;
      if (!a.derived) {
        rows.add({figure::text(member_name(member)), figure::integer(exactness_degree(rule)), figure::text("no: " + a.failure), figure{},
                  figure{}, figure{}, figure{}, figure{}, figure{}, figure{}, figure{}, figure{}, figure{}});
        analysed.push_back(a);
        continue;
      }
      const bool full = a.order == 2 * degree;
      const ginac_member_check g = s.ginac ? check_member_in_ginac(a, s.node_check_degree) : ginac_member_check{};
      checked.emplace_back(a, g);
      const std::string nodes_text = !g.node_independent ? "" : *g.node_independent ? "any" : "Φ depends on them";
      rows.add({figure::text(member_name(member)), figure::integer(exactness_degree(rule)), figure::text("yes"),
                figure::text(a.det_one ? "yes" : "no"), figure::text(a.form_conserved ? "yes" : "no"), figure::integer(a.order),
                figure::text(full ? "yes" : "no"), figure::text(a.error_constant), figure::text(bands_text(a)),
                figure::text(equals), figure::text(ginac_text(a, g, s.ginac)), figure::text(nodes_text), figure::integer(a.size)});
      if (rule.family == quadrature_family::lobatto && rule.points == degree + 1) {
        lobatto_orders.push_back(fmt::format("s = {}: order {}{}", degree, a.order, full ? "" : " (not 2s)"));
      }
      analysed.push_back(a);
      progress_step(s.progress, "family", member_name(member));
    }
  }
  out.add(std::move(rows));
  out.text(order_answer(analysed, lobatto_orders));
  if (s.ginac) out.add(discriminant_table(checked));
  out.add(pendulum_table(analysed, s.pendulum_steps, s.progress));
  out.add(stability_chart(analysed, s.max_degree));
  if (stopped) out.text(fmt::format("Stopped at the budget of {} s: the members marked 'not run' were not derived.", s.budget_seconds));
  return out;
}

}  // namespace simpson::verify

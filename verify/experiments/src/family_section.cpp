// The family section (family_section.hpp).

#include <simpson/verify/family_section.hpp>
#include <simpson/verify/progress.hpp>

#include <simpson/verify/galerkin_member.hpp>

#include <fmt/format.h>

#include <chrono>

namespace simpson::verify {
namespace {

std::vector<quadrature_rule> rules_for(int s) {
  std::vector<quadrature_rule> out;
  for (int k = 2; k <= s + 2; ++k) out.push_back({quadrature_family::newton_cotes, k});
  for (int k = 2; k <= s + 2; ++k) out.push_back({quadrature_family::lobatto, k});
  for (int k = 1; k <= s + 1; ++k) out.push_back({quadrature_family::gauss, k});
  return out;
}

std::string bands_text(const member_analysis& a) {
  std::string out;
  for (const auto& [from, to] : a.stable_intervals) {
    out += (out.empty() ? "" : " ∪ ") + fmt::format("({}, {})", from, to.empty() ? "∞" : to);
  }
  return out.empty() ? "none" : out;
}

}  // namespace

section_result run_family(const family_settings& s) {
  section_result out;
  out.name = "family";
  out.title = "The scheme's family: Galerkin variational integrators of degree s with a quadrature rule";
  out.conventions = {{"max_degree", s.max_degree}, {"budget_seconds", s.budget_seconds}};
  table rows{"members", "",
             "Each member: the interpolant of degree s on one step (end values q_j, q_{j+1} and s − 1 internal degrees of "
             "freedom), the action by the quadrature rule, for the harmonic oscillator. Derived exactly in our kernel "
             "(rational functions of θ = ωh; m = ω = 1, restored by dimensional scaling): the discrete Lagrangian, the "
             "internal equations eliminated, the one-step map Φ in (p, q) (verify/family). det: det Φ = 1, exactly. form: "
             "ΦᵀWΦ = W for W = [[−γ, (α−δ)/2], [(α−δ)/2, β]], exactly. Stable ωh: the open bands where (tr Φ)² < 4, from "
             "Sturm sequences (an irrational end is an isolating interval below 2⁻⁴⁰). order and c: (2 cos ωh − tr Φ)/h² = "
             "c ω^(order+2) h^order + …, the three-term scheme's truncation error. equals: the known schemes whose Φ is "
             "identical (the core's own formulas in the same kernel; Gauss–Legendre by its diagonal Padé approximant).",
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
              {"size", "degree in θ"}}};
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> lobatto_orders, lost;
  bool stopped = false;
  for (int degree = 1; degree <= s.max_degree; ++degree) {
    for (const quadrature_rule& rule : rules_for(degree)) {
      const galerkin_member member{degree, rule};
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (elapsed > s.budget_seconds) {
        rows.add({figure::text(member_name(member)), figure::integer(exactness_degree(rule)),
                  figure::text(fmt::format("not run: the section's budget of {} s was spent", s.budget_seconds)), figure{}, figure{},
                  figure{}, figure{}, figure{}, figure{}, figure{}, figure{}});
        stopped = true;
        continue;
      }
      const member_analysis a = analyse_member(member);
      std::string equals;
      for (const std::string& e : a.equals) equals += (equals.empty() ? "" : "; ") + e;
      if (!a.derived) {
        rows.add({figure::text(member_name(member)), figure::integer(exactness_degree(rule)), figure::text("no: " + a.failure), figure{},
                  figure{}, figure{}, figure{}, figure{}, figure{}, figure{}, figure{}});
        lost.push_back(member_name(member) + " (" + a.failure + ")");
        continue;
      }
      const bool full = a.order == 2 * degree;
      rows.add({figure::text(member_name(member)), figure::integer(exactness_degree(rule)), figure::text("yes"),
                figure::text(a.det_one ? "yes" : "no"), figure::text(a.form_conserved ? "yes" : "no"), figure::integer(a.order),
                figure::text(full ? "yes" : "no"), figure::text(a.error_constant), figure::text(bands_text(a)),
                figure::text(equals), figure::integer(a.size)});
      if (rule.family == quadrature_family::lobatto && rule.points == degree + 1) {
        lobatto_orders.push_back(fmt::format("s = {}: order {}{}", degree, a.order, full ? "" : " (not 2s)"));
      }
      if (!full && a.order < 2 * degree) {
        lost.push_back(fmt::format("{} (order {}; the rule is exact to degree {}, the Lagrangian of the interpolant has degree {})",
                                   member_name(member), a.order, exactness_degree(rule), 2 * degree));
      }
      progress_step("family", member_name(member));
    }
  }
  out.add(std::move(rows));
  std::string answer = "Lobatto with s + 1 points: ";
  for (std::size_t k = 0; k < lobatto_orders.size(); ++k) answer += (k ? ", " : "") + lobatto_orders[k];
  answer += ". Below order 2s: ";
  for (std::size_t k = 0; k < lost.size(); ++k) answer += (k ? "; " : "") + lost[k];
  out.text(answer + (lost.empty() ? "none." : "."));
  if (stopped) out.text(fmt::format("Stopped at the budget of {} s: the members marked 'not run' were not derived.", s.budget_seconds));
  return out;
}

}  // namespace simpson::verify

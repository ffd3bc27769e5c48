// The family's claim: every Galerkin variational integrator of the family up to a degree that gives
// a one-step map is symplectic and conserves its quadratic form, proved in both kernels with m, ω, h
// symbolic, and certified in Coq member by member.

#include "bespoke_checks.hpp"
#include "derivation_support.hpp"

#include "symbolic_derivation.hpp"

#include <simpson/verify/galerkin_ginac.hpp>
#include <simpson/verify/galerkin_ginac_map.hpp>

#include <fmt/format.h>

namespace simpson::verify::detail {
namespace {

/// The degrees the claim covers: s = 1 … family_claim_degree.
constexpr int family_claim_degree = 6;

/// Our kernel's derivation and GiNaC's (m, ω, h symbolic) of every member up to the claim's
/// degree: holds when each member with a one-step map has det Φ = 1 and ΦᵀWΦ = W in both, GiNaC's
/// Φ(1, 1, θ) is ours and obeys the scaling law, and the two kernels agree on which members have a map.
decider_evidence check_family_symplectic(const run_context& ctx) {
  // The Lobatto pairs every member is compared with, made once: the run's memo, or this check's own.
  run_memo own;
  run_memo* memo = ctx.memo != nullptr ? ctx.memo : &own;
  decider_evidence judged;
  claim_result& out = judged.found;
  json members = json::array();
  bool all = true;
  int derived = 0, without_map = 0;
  for (int s = 1; s <= family_claim_degree; ++s) {
    for (const quadrature_rule& rule : family_rules(s)) {
      const member_analysis ours = analyse_member({s, rule}, 400, memo);
      json row = {{"member", member_name(ours.member)}, {"derived", ours.derived}};
      if (!ours.derived) {
        ++without_map;
        row["why_not"] = ours.failure;
        // GiNaC must find no map either.
        const bool agrees = !ginac_one_step_map(ours.member, GiNaC::symbol("m"), GiNaC::symbol("omega"), GiNaC::symbol("h"));
        row["ginac_agrees"] = agrees;
        all = all && agrees;
        members.push_back(row);
        continue;
      }
      ++derived;
      const ginac_member_check g = check_member_in_ginac(ours, 0);
      const bool ok = ours.det_one && ours.form_conserved && g.derived && g.det_one && g.form_conserved &&
                      g.same_as_exact_kernel && g.scaling;
      row["own"] = {{"det_Phi_is_1", ours.det_one}, {"Phi^T W Phi = W", ours.form_conserved}};
      row["ginac"] = {{"det_Phi_is_1", g.det_one}, {"Phi^T W Phi = W", g.form_conserved},
                      {"Phi(1, 1, theta) is our kernel's", g.same_as_exact_kernel},
                      {"Phi(m, omega, h) = S Phi(1, 1, omega h) S^-1, S = diag(m omega, 1)", g.scaling}};
      all = all && ok;
      members.push_back(row);
    }
  }
  judged.own = answer_of(all);
  judged.if_false = verdict::fails;
  out.evidence["method"] = fmt::format(
      "each member s = 1 … {} with each rule of family_rules(s), derived in our kernel (verify/family, m = omega = 1, h = theta) "
      "and in GiNaC (m, omega, h symbolic, the rule's moments from its own nodal polynomial)",
      family_claim_degree);
  out.evidence["members"] = members;
  out.evidence["summary"] = fmt::format("{} members with a one-step map, {} without", derived, without_map);
  return judged;
}

/// The Coq goals: det Φ = 1 and ΦᵀWΦ = W for each member with a one-step map (GiNaC's Φ).
std::vector<proof_goal> family_symplectic_goals() {
  const symbolic_derivation& d = derivation();
  const GiNaC::symbol& m = GiNaC::ex_to<GiNaC::symbol>(d.m);
  const GiNaC::symbol& omega = GiNaC::ex_to<GiNaC::symbol>(d.omega);
  const GiNaC::symbol& h = GiNaC::ex_to<GiNaC::symbol>(d.h);
  std::vector<proof_goal> goals;
  for (int s = 1; s <= family_claim_degree; ++s) {
    for (const quadrature_rule& rule : family_rules(s)) {
      const auto phi = ginac_one_step_map({s, rule}, m, omega, h);
      if (!phi) continue;
      const GiNaC::matrix& P = *phi;
      const std::string name = fmt::format("s{}_{}", s, rule_name(rule));
      goals.push_back(decided(name + "_det", P(0, 0) * P(1, 1) - P(0, 1) * P(1, 0), 1));
      // W = [[−γ, (α−δ)/2], [(α−δ)/2, β]] on (p, q).
      const GiNaC::matrix W{{-P(1, 0), (P(0, 0) - P(1, 1)) / 2}, {(P(0, 0) - P(1, 1)) / 2, P(0, 1)}};
      goals.push_back(decided(name + "_form", P.transpose().mul(W).mul(P), W));
    }
  }
  return goals;
}

}  // namespace

void add_family_checks(check_registry& checks) {
  checks.add("family-symplectic", check_family_symplectic);
  checks.add_coq_goals("family-symplectic", family_symplectic_goals);
}

}  // namespace simpson::verify::detail

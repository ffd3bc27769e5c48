// Section 5: the discrete Euler-Lagrange equations of the Simpson Lagrangian, the internal node,
// the three-term scheme, its truncation error and its stability.

#include "claim_support.hpp"
#include "bespoke_checks.hpp"

#include <simpson/verify/quoted_words.hpp>
#include <simpson/verify/stability_analysis.hpp>

#include <simpson/exact_solution.hpp>
#include <simpson/internal_node.hpp>
#include <simpson/quadratic_interpolation.hpp>
#include <simpson/reduced_lagrangian.hpp>
#include <simpson/simpson_lagrangian.hpp>
#include <simpson/simpson_rule.hpp>
#include <simpson/three_term_scheme.hpp>

namespace simpson::verify::detail {
namespace {

/// "Maupertuis's stationary-action principle delta Sigma_d = 0": Sigma_d sums L_h, Simpson's rule on
/// the Lagrangian m q'^2/2 - V along the interpolant, at fixed times: Hamilton's action. Maupertuis's
/// principle varies the abbreviated action, the integral of p q' = m q'^2, at fixed energy. Shown: L_h
/// is Simpson's rule on L (corrected), and differs from Simpson's rule on p q' by Simpson's rule on
/// H = m q'^2/2 + V, which is not zero (printed). The words decide what is said: Hamilton's, or a
/// stationary action unnamed, holds; Maupertuis's name on a stationary action holds with a naming
/// remark (the field often gives his name to any least-action principle); the abbreviated action
/// named is false under every reading, an erratum.
decider_evidence check_maupertuis_naming(const run_context& ctx) {
  const quoted_sentence said = quote(ctx, "We first write the {principle} principle $ \\, \\delta \\Sigma_d = 0 \\, $");
  // Maupertuis's principle varies the abbreviated action at fixed energy (Landau-Lifshitz, Mechanics, §44; Goldstein §8.6);
  // Hamilton's varies the integral of L dt with the end times fixed. "Least"/"stationary action" alone names no functional.
  const std::string named = said.containing("principle", {{"abbreviated", "abbreviated action"},
                                                          {"maupertuis", "stationary action, Maupertuis's name"},
                                                          {"hamilton", "integral of L dt (Hamilton)"},
                                                          {"action", "unnamed stationary action"}});
  const auto along = [&](const auto& v, bool abbreviated) {
    using S = std::decay_t<decltype(v[0])>;
    const auto par = theta_oscillator<S>();
    const auto V = [&](const S& x) { return par.potential(x); };
    const S ql(v[0]), qm(v[1]), qr(v[2]);
    const S rule = simpson_rule<S>([&](const S& s) {
      const S velocity = quadratic_interpolant_derivative(ql, qm, qr, par.h(), s);
      return abbreviated ? S(par.h() * par.m() * velocity * velocity)
                         : S(par.h() * (par.m() / 2 * velocity * velocity - V(quadratic_interpolant(ql, qm, qr, s))));
    });
    return S(simpson_lagrangian(par.m(), par.h(), V, ql, qm, qr) - rule);
  };
  const proof printed = prove_zero_on_grid(std::string(unit_reduction) +
                                               "; L_h (LLhh) minus Simpson's rule on the abbreviated action's integrand p dq/dt = m (dq/dt)^2",
                                           {"q_l", "q_m", "q_r"}, 2, [&](const auto& v) { return along(v, true); }, ctx.memo);
  const proof corrected = prove_zero_on_grid(std::string(unit_reduction) +
                                                 "; L_h (LLhh) minus Simpson's rule on Hamilton's integrand L = m (dq/dt)^2/2 - V(q)",
                                             {"q_l", "q_m", "q_r"}, 2, [&](const auto& v) { return along(v, false); }, ctx.memo);
  const std::string computed = "the computation (L_h is Simpson's rule on L, not on p dq/dt) is the same whatever the name";
  if (named != "abbreviated action" && corrected.proved && !printed.proved) {
    json evidence;
    evidence["exact"] = corrected.evidence;
    evidence["not_the_abbreviated_action"] = printed.evidence;
    evidence["named"] = named;
    decider_evidence holds = lexical(confirmed_if(true, evidence, "delta Sigma_d = 0, the nodes varied at fixed times, is a stationary-action "
                                                                  "principle: Sigma_d is Simpson's rule on the integral of L dt (proved), not on p dq/dt."),
                                     said.words("principle"), computed);
    if (named == "stationary action, Maupertuis's name") {
      holds.found.remark_kind = finding::naming;
      holds.found.remark = "Stationary action as meant, under the name the field often gives any least-action principle; strictly "
                           "Hamilton's: delta Sigma_d = 0 varies the nodes at fixed times, and Sigma_d is Simpson's rule on the "
                           "integral of L dt (proved), not on the abbreviated action (the integral of p dq) that Maupertuis's "
                           "principle makes stationary at fixed energy. The equations derived from it (internal-equation, "
                           "scheme-order-3) are unaffected.";
    }
    return holds;
  }
  return lexical(amended(erratum(printed, corrected,
                 "delta Sigma_d = 0 (variations of the nodes, times fixed) is the discrete form of Hamilton's stationary-action "
                 "principle: Sigma_d approximates the integral of L dt",
                 "A naming finding, not a formula: Maupertuis's principle makes the abbreviated action (the integral of p dq) "
                 "stationary among motions of fixed energy; the equations derived from delta Sigma_d = 0 (internal-equation, "
                 "scheme-order-3) are unaffected."),
                         "the principle named", said.words("principle"), "Hamilton's stationary-action"),
                 said.words("principle"), computed);
}

}  // namespace

void add_section5_checks(check_registry& checks) {
  checks.add("maupertuis-naming", check_maupertuis_naming);
}

}  // namespace simpson::verify::detail

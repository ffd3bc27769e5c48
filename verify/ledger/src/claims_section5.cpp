// Section 5: the discrete Euler-Lagrange equations of the Simpson Lagrangian, the internal node,
// the three-term scheme, its truncation error and its stability.

#include "claim_support.hpp"
#include "claims_section5.hpp"

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

claim_result check_qm_not_affine(const run_context& ctx) {
  const quoted_sentence said = quote(ctx, "This interpolation is {linearity} if $ \\, h > 0 $.");
  // Literally: "not linear" says the map (q_l, q_r) -> q_m is not linear (false: it is); "not affine"
  // says it is not the affine interpolant's midpoint (true); "linear" is true; "affine" false.
  const std::string stated = said.choice("linearity", {{"not linear", "not linear"}, {"nonlinear", "not linear"},
                                                       {"non linear", "not linear"}, {"non-linear", "not linear"},
                                                       {"not affine", "not the affine midpoint"}, {"linear", "linear"},
                                                       {"affine", "the affine midpoint"}});
  const proof p = prove_zero_on_grid(std::string(unit_reduction) +
                                         "; q_m - (q_l + q_r)/2 - ((q_l + q_r)/2) (x/8)/(1 - x/8), x = theta^2",
                                     {"q_l", "q_r"}, 1, [&](const auto& v) {
                                       using S = std::decay_t<decltype(v[0])>;
                                       const auto par = theta_oscillator<S>();
                                       const S x = par.omega2_h2();
                                       const S ql(v[0]), qr(v[1]);
                                       return S(harmonic_internal_node(par, ql, qr) - (ql + qr) / 2 - (ql + qr) / 2 * (x / 8) / (1 - x / 8));
                                     });
  const std::string proved = "q_m differs from the affine interpolant's midpoint (q_l + q_r)/2 by ((q_l + q_r)/2)(omega^2 h^2/8)/"
                             "(1 - omega^2 h^2/8), nonzero for h > 0 unless q_l + q_r = 0";
  if (stated == "the affine midpoint" && p.proved) {
    proof printed;
    printed.evidence = {{"stated", said.words("linearity")}, {"result", "refuted: " + proved}};
    return erratum(printed, p, "The interpolation is not the affine one: " + proved);
  }
  if (!p.proved) return identity(p);
  if (stated == "not linear") {
    json evidence;
    evidence["exact"] = p.evidence;
    evidence["stated"] = said.words("linearity");
    return words_erratum(evidence, "q_m = (q_l + q_r)/(2 (1 - omega^2 h^2/8)) is linear in (q_l, q_r); what holds is that it is not "
                                   "the affine interpolant's midpoint: " + proved,
                         "Wording: 'not linear' is false of q_m, a linear function of (q_l, q_r); the intended content, that q_m is "
                         "not the midpoint (q_l + q_r)/2, is proved.");
  }
  return identity(p, "What was proved: " + proved + ".");
}

/// "Maupertuis's stationary-action principle delta Sigma_d = 0": Sigma_d sums L_h, Simpson's rule on
/// the Lagrangian m q'^2/2 - V along the interpolant, at fixed times: Hamilton's action. Maupertuis's
/// principle varies the abbreviated action, the integral of p q' = m q'^2, at fixed energy. Shown: L_h
/// is Simpson's rule on L (corrected), and differs from Simpson's rule on p q' by Simpson's rule on
/// H = m q'^2/2 + V, which is not zero (printed).
claim_result check_maupertuis_naming(const run_context& ctx) {
  const quoted_sentence said = quote(ctx, "We first write the {principle} principle $ \\, \\delta \\Sigma_d = 0 \\, $");
  // Maupertuis's principle varies the abbreviated action at fixed energy (Landau-Lifshitz, Mechanics, §44; Goldstein §8.6);
  // Hamilton's varies the integral of L dt with the end times fixed. "Least"/"stationary action" alone names no functional.
  const std::string named = said.containing("principle", {{"maupertuis", "abbreviated action (Maupertuis)"},
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
                                           {"q_l", "q_m", "q_r"}, 2, [&](const auto& v) { return along(v, true); });
  const proof corrected = prove_zero_on_grid(std::string(unit_reduction) +
                                                 "; L_h (LLhh) minus Simpson's rule on Hamilton's integrand L = m (dq/dt)^2/2 - V(q)",
                                             {"q_l", "q_m", "q_r"}, 2, [&](const auto& v) { return along(v, false); });
  if (named != "abbreviated action (Maupertuis)" && corrected.proved && !printed.proved) {
    json evidence;
    evidence["exact"] = corrected.evidence;
    evidence["named"] = named;
    return confirmed_if(true, evidence, "The words name the principle whose functional L_h discretises: Simpson's rule on L = "
                                        "m (dq/dt)^2/2 - V(q), proved; not Simpson's rule on p dq/dt.");
  }
  return erratum(printed, corrected,
                 "delta Sigma_d = 0 (variations of the nodes, times fixed) is the discrete form of Hamilton's stationary-action "
                 "principle: Sigma_d approximates the integral of L dt",
                 "A naming finding, not a formula: Maupertuis's principle makes the abbreviated action (the integral of p dq) "
                 "stationary among motions of fixed energy; the equations derived from delta Sigma_d = 0 (internal-equation, "
                 "scheme-order-3) are unaffected.");
}

}  // namespace

void add_section5_checks(check_registry& checks) {
  checks.add("maupertuis-naming", check_maupertuis_naming);
  checks.add("qm-not-affine", check_qm_not_affine);
}

}  // namespace simpson::verify::detail

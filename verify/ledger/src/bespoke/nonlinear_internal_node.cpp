// Section 9's conclusion: "the elimination of the internal degree of freedom is not possible" in the
// nonlinear case, against the printed equation read as a contraction.

#include "bespoke_checks.hpp"
#include "claim_support.hpp"

#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/quoted_words.hpp>
#include <simpson/verify/readable_math.hpp>
#include <simpson/verify/tex_math.hpp>

#include <ginac/ginac.h>

#include <fmt/format.h>

#include <string>

namespace simpson::verify::detail {
namespace {

/// Section 9: "the elimination of the internal degree of freedom is not possible" in the nonlinear
/// case. What holds: (equation-milieu-intervalle), as printed, is A q_m + B + V'(q_m) = 0 with A
/// constant, so q_m = G(q_m), G(x) = -(B + V'(x))/A, G' = -V''/A; when sup|V''| < |A|, G is a
/// contraction and q_m is unique and the limit of the iteration (Banach): eliminated implicitly,
/// not in closed form. Computed in GiNaC from the printed equation, and for the pendulum V = m ω²
/// (1 − cos q) the contraction constant exactly.
decider_evidence check_nonlinear_internal_node(const run_context& ctx) {
  const auto text_of = [](const GiNaC::ex& e) { return canonical_text(e); };
  const quoted_sentence said = quote(ctx, "The elimination of the internal degree of freedom is {possibility} in that case.");
  // Literally: "not possible" denies that q_m can be eliminated at all; "possible" affirms it.
  const std::string stated = said.choice("possibility", {{"not possible", "not possible"}, {"impossible", "not possible"},
                                                         {"possible", "possible"}});
  const paper_reading& paper = paper_of(ctx);
  const GiNaC::ex printed = paper.at("equation-milieu-intervalle").sides.at(0);
  tex_symbols& symbols = paper_symbols();
  const GiNaC::symbol &qm = symbols["q_m"], &x = symbols["x_contraction"], &m = symbols["m"], &omega = symbols["omega"],
                      &h = symbols["h"];
  // V uninterpreted: the printed equation is linear in q_m apart from V'(q_m).
  const GiNaC::ex force = GiNaC::diff(apply_function("V", {qm}), qm);
  const GiNaC::symbol f("force_at_q_m");
  const GiNaC::ex linear = GiNaC::expand(printed.subs(force == f));
  const bool linear_in_qm = linear.is_polynomial(qm) && linear.degree(qm) == 1 && linear.degree(f) == 1 &&
                            GiNaC::normal(linear.coeff(f, 1) - 1).is_zero();
  json evidence;
  if (!linear_in_qm) {
    evidence["exact"] = {{"kernel", "GiNaC"}, {"printed", text_of(printed)}, {"result", "the printed equation is not A q_m + B + V'(q_m)"}};
    return confirmed_if(false, evidence);
  }
  const GiNaC::ex A = GiNaC::normal(linear.coeff(qm, 1).subs(f == 0));
  const GiNaC::ex B = GiNaC::normal(linear.subs(GiNaC::lst{qm == 0, f == 0}));
  // The pendulum V = m ω² (1 − cos q): G(x) = −(B + m ω² sin x)/A, G'(x) = −m ω² cos(x)/A.
  const GiNaC::ex pendulum_g = -(B + m * omega * omega * GiNaC::sin(x)) / A;
  const GiNaC::ex derivative = GiNaC::normal(GiNaC::diff(pendulum_g, x));
  const GiNaC::ex constant = GiNaC::normal(derivative.subs(x == 0));  // |cos| <= 1, attained at 0
  const bool is_cos_multiple = GiNaC::normal(derivative - constant * GiNaC::cos(x)).is_zero();
  // The contraction condition constant < 1 on ω h: the root of |constant| = 1 in y = (ω h)².
  const GiNaC::symbol y("y");
  const GiNaC::ex root_y = GiNaC::lsolve(GiNaC::numer(GiNaC::normal(constant.subs(h == GiNaC::sqrt(y) / omega) - 1)) == 0, y);
  const GiNaC::ex bound = GiNaC::sqrt(root_y);
  const GiNaC::ex printed_bound = paper.at("stabilite").sides.at(2);
  const bool same_as_stability = GiNaC::normal(GiNaC::pow(bound, 2) - GiNaC::pow(printed_bound, 2)).is_zero();
  evidence["exact"] = {{"kernel", "GiNaC"},
                       {"printed_equation", text_of(printed) + " = 0"},
                       {"as_fixed_point", "q_m = G(q_m), G(x) = -(B + V'(x))/A, A = " + text_of(A) + ", B = " + text_of(B)},
                       {"derivative", "G'(x) = -V''(x)/A"},
                       {"pendulum_derivative", text_of(derivative)},
                       {"pendulum_contraction_constant", text_of(constant)},
                       {"pendulum_bound_omega_h", text_of(bound)},
                       {"stability_bound_printed", text_of(printed_bound)},
                       {"same_bound", same_as_stability}};
  const bool proved = is_cos_multiple && !GiNaC::is_zero(A);
  evidence["stated"] = stated;
  const std::string eliminated =
      "(equation-milieu-intervalle) is the fixed-point equation q_m = G(q_m) with G' = -V''/A, A = " + text_of(A) +
      "; when sup|V''| < |A| it is a contraction, so q_m is unique and the limit of the fixed-point iteration (Banach): the "
      "internal node is eliminated, implicitly. For the pendulum the contraction constant is " + text_of(constant) +
      " (exact: G' = that constant times cos x), below 1 exactly for omega h < " + text_of(bound) +
      (same_as_stability ? ", the harmonic stability bound (stabilite)" : ", not the printed stability bound");
  if (!proved) return confirmed_if(false, evidence);
  const std::string fixed = "the computation (the printed equation as a contraction) is the same whatever the word";
  if (stated == "possible") return lexical(confirmed_if(true, evidence, eliminated + "."), said.words("possibility"), fixed);
  // "Not possible", as an expert reads it of a general V, is "not in closed form": true. It holds,
  // with the wording remark that the elimination is possible implicitly (the policy: an erratum is
  // false under every reasonable reading).
  decider_evidence holds = confirmed_if(true, evidence);
  holds.found.remark_kind = finding::wording;
  holds.found.remark = "Not possible in closed form for a general V, as meant; possible implicitly: " + eliminated + ".";
  holds.found.amendments.push_back(
      amendment{"the elimination of q_m", said.words("possibility"),
                fmt::format("not possible in closed form for a general V; possible implicitly, by a contraction when sup|V''| < |A|, A = ${}$", canonical_tex(A)),
                false});
  return lexical(std::move(holds), said.words("possibility"), fixed);
}

}  // namespace

void add_nonlinear_internal_node_check(check_registry& checks) { checks.add("nonlinear-internal-node", check_nonlinear_internal_node); }

}  // namespace simpson::verify::detail

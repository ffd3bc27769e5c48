// The quadrature shapes (shape_support.hpp): the degree of exactness a sentence states for a printed
// quadrature rule, against the degree computed on the rule as printed; and a discrete Lagrangian as
// a printed rule applied to a printed action integral along a printed interpolant.

#include <simpson/shapes/shape_support.hpp>

#include <simpson/prove/printed_check_support.hpp>

#include <simpson/verify/quoted_words.hpp>
#include <simpson/verify/tex_math.hpp>

#include <fmt/format.h>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

/// The highest degree a stated bound admits ("smaller or equal to 1": 1; "smaller than 2": 1); an
/// open-ended bound ("at least 1") admits every degree, and is never the sharp degree.
int highest_admitted(const stated_bound& b, int beyond) {
  int top = -1;
  for (int k = 0; k < beyond; ++k) {
    if (b.admits(k)) top = k;
  }
  return b.admits(beyond) ? beyond : top;
}

/// The integral a formula is; throws std::invalid_argument naming `what` when it is not one.
const GiNaC::integral& as_integral(const ex& e, const std::string& what) {
  if (!GiNaC::is_a<GiNaC::integral>(e)) throw std::invalid_argument(what + " is not an integral \\int_a^b ... \\dd x");
  return GiNaC::ex_to<GiNaC::integral>(e);
}

}  // namespace

/// A rule's degree of exactness: the printed rule and the printed integral it approximates, each
/// with the function replaced by x^k, for k = 0, 1, ... until they differ (GiNaC integrates the
/// monomial; both sides are then exact rationals, compared again in our kernel's arithmetic). The
/// degree the sentence states ("of degree three", "of degree smaller or equal to 1") must be it.
decider_evidence quadrature_exactness_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex rule = read.formula("rule"), integral = read.formula("integral");
  const std::string printed_name = read.symbols("function").front().get_name();
  const std::string function = function_name(printed_name, 1);  // as GiNaC registered it
  (void)as_integral(integral, reference_of(call, "integral"));
  constexpr int most = 20;  // a rule exact beyond this degree is reported as such, not searched further
  const quoted_sentence said = quote(ctx, call.with.at("sentence").values.front());
  int stated = 0;
  try {
    stated = highest_admitted(said.bound("degree"), most + 1);  // "smaller or equal to 1"
  } catch (const text_changed&) {
    stated = said.number("degree");  // "degree three": every degree up to it
  }
  json rows = json::array();
  int exact_up_to = -1;
  bool own_agrees = true;
  std::string own_evidence;
  for (int k = 0; k <= most; ++k) {
    const ex on_rule = GiNaC::normal(with_monomial(rule, function, k));
    const ex on_integral = GiNaC::normal(with_monomial(integral, function, k).eval_integ());
    const bool exact = GiNaC::normal(on_rule - on_integral).is_zero();
    const kernel_decision own = kernel_decides_zero(on_rule - on_integral);
    own_agrees = own_agrees && own.outcome == (exact ? kernel_decision::result::zero : kernel_decision::result::nonzero);
    if (!own_agrees && own_evidence.empty()) own_evidence = fmt::format("degree {}: {}", k, own.evidence);
    rows.push_back({{"degree", k}, {"rule", text_of(on_rule)}, {"integral", text_of(on_integral)}, {"exact", exact}});
    if (!exact) break;
    exact_up_to = k;
  }
  const std::string computed = exact_up_to == most ? fmt::format("exact for every polynomial of degree <= {} (searched no further)", most)
                                                   : fmt::format("exact for every polynomial of degree <= {} and not for degree {}", exact_up_to,
                                                                 exact_up_to + 1);
  claim_result r;
  r.printed = read.printed();
  r.evidence["exact"] = {{"statement", fmt::format("the degree of exactness of ({}) for ({}), against the words '{}'", reference_of(call, "rule"),
                                                   reference_of(call, "integral"), said.words("degree"))},
                         {"monomials", rows},
                         {"exact_up_to_degree", exact_up_to},
                         {"stated", said.words("degree")},
                         {"stated_up_to_degree", stated},
                         {"ginac", fmt::format("{}: {}", stated == exact_up_to ? "holds" : "fails", computed)},
                         {"own", own_agrees ? fmt::format("{}: each degree's rule and integral compared again in our kernel's rational arithmetic "
                                                          "(constants once {} = x^k is put in: GiNaC's integral and substitution)",
                                                          stated == exact_up_to ? "holds" : "fails", printed_name)
                                            : "disagrees: " + own_evidence}};
  // Our kernel compares each degree again: agreeing on every one, its answer on the words is GiNaC's.
  decider_evidence e;
  e.statement = "a degree";
  e.ginac = answer_of(stated == exact_up_to);
  e.own = own_agrees ? e.ginac : answer::none;
  e.parts_differ = !own_agrees;
  if (stated == exact_up_to) {
    r.note = "As stated ('" + said.words("degree") + "'): " + computed + ".";
  } else {
    r.correction = "The rule is " + computed + " (the printed words say '" + said.words("degree") + "')";
  }
  e.found = std::move(r);
  return e;
}

/// A discrete Lagrangian as printed, against the printed rule ∫_{a0}^{b0} ψ(x) dx ≃ Σ w_k ψ(x_k)
/// applied to the printed action integral ∫_a^b f dt of one interval: Σ w_k (b − a)/(b0 − a0)
/// f(t_k), t_k = a + (b − a)(x_k − a0)/(b0 − a0), the integrand's state q and its dq/dt taken at t_k
/// and then given by the definitions (the interpolant), V uninterpreted. Decided in both kernels.
decider_evidence discrete_lagrangian_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex printed = read.formula("printed");
  const referenced_formula rule_read = read.raw("rule"), action_read = read.raw("integral");  // as read: their bound variables untouched
  const ex rule_integral = read_side(rule_read, 0, read.reading());
  const GiNaC::integral& reference = as_integral(rule_integral, reference_of(call, "rule") + ":lhs");
  const GiNaC::integral& action = as_integral(action_read.value, reference_of(call, "integral"));
  const std::string psi = function_name(read.symbols("function").front().get_name(), 1);
  const GiNaC::symbol state = read.symbols("state").front();
  const GiNaC::symbol& t = GiNaC::ex_to<GiNaC::symbol>(action.op(0));
  const ex a = action.op(1), b = action.op(2), a0 = reference.op(1), b0 = reference.op(2);
  const GiNaC::symbol x("rule_node"), y("state_argument");
  const ex node = a + (b - a) * (x - a0) / (b0 - a0);
  // The integrand at the node: its state and the state's derivative there, and its variable.
  GiNaC::exmap at;
  at[state] = apply_function(state.get_name(), {node});
  at[paper_symbols()[derivative_name(state.get_name(), t.get_name(), 1, 1)]] = GiNaC::diff(apply_function(state.get_name(), {y}), y).subs(y == node);
  at[t] = node;
  const ex integrand = GiNaC::ex(action.op(3)).subs(at, GiNaC::subs_options::no_pattern);
  const definition applied{GiNaC::symbol(psi), (b - a) / (b0 - a0) * integrand, "the action's integrand at the rule's nodes", 0, "", psi, x};
  const ex derived = read.defined(with_definitions(rule_read.value, {applied}));
  const std::string what = fmt::format("({}) = ({}) applied to ({})", reference_of(call, "printed"), reference_of(call, "rule"), reference_of(call, "integral"));
  return identity_evidence(read, "lagrangian", what, derived, printed,
                           fmt::format("as derived: ({}) = {}", reference_of(call, "printed"), text_of(GiNaC::normal(derived))));
}

/// The shapes of this file, each one's name, summary, principal argument and parameters beside the
/// function that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> quadrature_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  add({"quadrature-exactness", "the degree of exactness a sentence states ({degree}) is the printed rule's, for the printed integral it approximates", "rule",
       with_where({{"rule", argument_kind::formula, true, "the printed rule, a combination of the function's values"},
                   {"integral", argument_kind::formula, true, "the printed integral it approximates, \\int_a^b f(x) \\dd x"},
                   {"function", argument_kind::symbols, true, "the function integrated (psi)", 1},
                   pattern_with_hole("sentence", "the sentence's pattern, with the hole {degree} (a number: 'degree three'; or a bound: 'smaller or equal to 1')",
                                     "degree")}),
       quadrature_exactness_shape});
  add({"discrete-lagrangian", "the printed discrete Lagrangian is the printed rule applied to the printed action integral along the interpolant the definitions give",
       "printed",
       with_where({{"printed", argument_kind::formula, true, "the printed discrete Lagrangian"},
                   {"integral", argument_kind::formula, true, "the action integral of one interval, \\int_a^b f \\dd t, f written in the state and its derivative"},
                   {"rule", argument_kind::formula, true, "the printed rule: an equation \\int_{a0}^{b0} psi(x) \\dd x = (or \\simeq) a combination of psi's values"},
                   {"function", argument_kind::symbols, true, "the rule's function (psi)", 1},
                   {"state", argument_kind::symbols, true, "the state q, a function the definitions give (q(t) = ...)", 1}}),
       discrete_lagrangian_shape});
  return all;
}

}  // namespace simpson::verify::detail

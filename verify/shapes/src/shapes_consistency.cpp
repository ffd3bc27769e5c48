// The shapes on smooth states (shape_support.hpp): a scheme's relations consistent with printed
// differential equations, and printed Taylor expansions, each state x_{j+k} the smooth function x at
// t + k h.

#include <simpson/shapes/shape_support.hpp>

#include <simpson/prove/coq_export.hpp>
#include <simpson/prove/printed_check_support.hpp>

#include <simpson/verify/quoted_words.hpp>
#include <simpson/verify/tex_math.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <optional>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

/// The states of `e` named <base>_<index>±k ("q_j+1", "p_j", "q_j-1/2"): each the smooth function
/// <base> at t + k h.
std::vector<smooth_state> indexed_states(const ex& e, const std::string& index, const ex& h) {
  std::vector<smooth_state> states;
  for (const std::string& name : symbol_names(e)) {
    if (const std::optional<GiNaC::numeric> k = index_offset(name, index)) states.push_back({paper_symbols()[name], name.substr(0, name.find('_')), *k * h});
  }
  return states;
}

/// e with each state replaced by its smooth function's Taylor polynomial of degree `degree` about t,
/// the k-th derivative named as the reader names d^kx/dt^k (x itself for k = 0).
ex on_taylor_polynomials(const ex& e, const std::vector<smooth_state>& states, int degree) {
  GiNaC::exmap on;
  for (const smooth_state& s : states) {
    ex sum = 0, term = 1;
    for (int k = 0; k <= degree; ++k) {
      if (k > 0) term = term * s.shift / k;
      sum += term * (k == 0 ? paper_symbols()[s.function] : paper_symbols()[derivative_name(s.function, "t", k, k)]);
    }
    on[s.state] = sum;
  }
  return e.subs(on, GiNaC::subs_options::no_pattern);
}

/// The reader's functions `e` applies, each once.
std::vector<std::string> function_names(const ex& e) {
  std::vector<std::string> names;
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (!is_reader_function(*it)) continue;
    const std::string name = GiNaC::ex_to<GiNaC::function>(*it).get_name();
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

/// Whether `e` applies `name` to an argument holding a time node t_<index>, t_<index>+k.
bool applies_at_node(const ex& e, const std::string& name, const std::string& index) {
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (!is_reader_function(*it) || GiNaC::ex_to<GiNaC::function>(*it).get_name() != name) continue;
    for (const std::string& symbol : symbol_names(*it)) {
      if (symbol.rfind("t_", 0) == 0 && index_offset(symbol, index)) return true;
    }
  }
  return false;
}

}  // namespace

/// Printed relations of a scheme consistent with printed differential equations: each relation
/// a = b, its states x_{j+k} put on smooth functions x(t + k h), is as a series in h (GiNaC's) h^p
/// times a nonzero multiple, free of the unknowns, of its equation a' = b' (x(t) read as x). Our
/// kernel decides, on the Taylor polynomials of the states (exact through h^p, taylor_degree), that
/// the relation is h^p times GiNaC's leading term plus h^(p+1) times a function regular at h = 0, and
/// that this term is the factor times the printed equation; V uninterpreted, for every polynomial V
/// of degree <= 4.
decider_evidence consistency_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const std::vector<referenced_formula> relations = read.equations("scheme"), equations = read.equations("equation");
  const GiNaC::symbol h = read.symbols("step").front();
  const std::string index = call.with.at("index").values.front();
  if (relations.size() != equations.size()) {
    throw std::invalid_argument(fmt::format("{} relations of the scheme and {} equations: one equation each", relations.size(), equations.size()));
  }
  // The order a sentence states, when given: each relation's, the power of its first term beyond the
  // leading one (expanded about the stencil's centre, where a symmetric stencil has no odd terms).
  const std::optional<quoted_sentence> said =
      read.has("sentence") ? std::optional<quoted_sentence>(quote(ctx, call.with.at("sentence").values.front())) : std::nullopt;
  const int series_order = said ? 8 : 4;
  std::optional<int> order;  // the least over the relations
  claim_result result;
  json decided_relations = json::array();
  std::vector<std::string> corrections;
  bool ginac_all = true, own_contradicts = false;
  std::vector<std::string> own_lines, not_decided;
  for (std::size_t i = 0; i < relations.size(); ++i) {
    std::vector<ex> sides = read.sides(relations[i]), printed_sides = read.sides(equations[i]);
    // The exact solution written at the nodes (x(t_n + k h), x(t_{n+k}), x declared a solution): the
    // state x_{n+k} on the smooth function, as the scheme's states are put; x(t_n) in an equation is x.
    for (const std::string& x : call.declared->solutions) {
      for (ex& side : sides) side = solution_at_nodes(side, *call.declared, x, index, h, "scheme");
      for (ex& side : printed_sides) {
        side = side.subs(apply_function(x, {paper_symbols()["t_" + index]}) == paper_symbols()[x]);
        side = solution_at_nodes(side, *call.declared, x, index, h, "equation");
        if (side.has(paper_symbols()[x + "_" + index])) side = side.subs(paper_symbols()[x + "_" + index] == paper_symbols()[x]);
      }
    }
    const ex relation = sides.front() - sides.back();
    std::vector<smooth_state> states = indexed_states(relation, index, h);
    if (states.empty()) throw std::invalid_argument(fmt::format("{} has no state x_{}, x_{}+1, ...", relations[i].locator, index, index));
    ex centre = 0;
    for (const smooth_state& s : states) centre += s.shift / static_cast<int>(states.size());
    for (smooth_state& s : states) s.shift = GiNaC::normal(s.shift - centre);
    // The unknowns: each state's function and its derivatives, as the reader names them; x(t) in the
    // printed equation read as x.
    std::vector<ex> unknowns;
    ex equation = printed_sides.front() - printed_sides.back();
    for (const smooth_state& s : states) {
      unknowns.push_back(paper_symbols()[s.function]);
      for (int k = 1; k <= 4; ++k) unknowns.push_back(paper_symbols()[derivative_name(s.function, "t", k, k)]);
      equation = equation.subs(apply_function(s.function, {paper_symbols()["t"]}) == paper_symbols()[s.function]);
    }
    const smooth_expansion expansion = expand_on_smooth(relation, states, h, series_order);
    const std::optional<ex> factor = equation_factor(equation, expansion.leading, unknowns);
    ginac_all = ginac_all && factor.has_value();
    if (!factor) corrections.push_back(fmt::format("{} is consistent with {} = 0", relations[i].place, text_of(expansion.leading)));
    // The relation's order: its next nonzero power less the leading one (none found: at least to the
    // series' end).
    int next = series_order;
    if (said) {
      const ex series = GiNaC::expand(expansion.series);
      for (int k = expansion.lowest_power + 1; k < series_order && next == series_order; ++k) {
        if (!GiNaC::normal(series.coeff(h, k)).is_zero()) next = k;
      }
      order = std::min(order.value_or(next - expansion.lowest_power), next - expansion.lowest_power);
    }
    const int confirmed_to = said ? next : expansion.lowest_power + 1;  // the remainder is O(h^confirmed_to)
    // Our kernel, on the Taylor polynomials.
    const int degree = taylor_degree(call, relation, [&] {
      std::vector<GiNaC::symbol> out;
      for (const smooth_state& s : states) out.push_back(GiNaC::ex_to<GiNaC::symbol>(s.state));
      return out;
    }(), h, confirmed_to);
    const ex on_taylor = on_taylor_polynomials(relation, states, degree);
    const ex remainder = on_taylor - GiNaC::pow(h, expansion.lowest_power) * expansion.leading;
    // An uninterpreted function (V) the relation applies: our kernel takes V(x) = x^k, k = 0..4, one
    // by one (GiNaC's witness of the order has no other way to be free of h in its denominator).
    // (Only the reader's uninterpreted functions: GiNaC's own, sin or exp, are what they are.)
    std::string function;
    for (GiNaC::const_preorder_iterator it = relation.preorder_begin(); it != relation.preorder_end(); ++it) {
      if (is_reader_function(*it)) function = GiNaC::ex_to<GiNaC::function>(*it).get_name();
    }
    kernel_decision own;
    if (function.empty()) {
      own = kernel_confirms_order(remainder, h, confirmed_to, false);
    } else {
      own = {kernel_decision::result::zero, ""};
      for (int k = 0; k <= 4 && own.outcome == kernel_decision::result::zero; ++k) {
        const kernel_decision at_k = kernel_confirms_order(with_monomial(remainder, function, k), h, confirmed_to, false);
        own = {at_k.outcome, at_k.outcome == kernel_decision::result::zero ? fmt::format("for {}(x) = x^k, k = 0..4, each: {}", function, at_k.evidence)
                                                                           : fmt::format("{}(x) = x^{}: {}", function, k, at_k.evidence)};
      }
    }
    if (own.outcome == kernel_decision::result::zero && factor) {
      const kernel_decision multiple = kernel_decides_zero(expansion.leading - *factor * equation);
      own = {multiple.outcome, own.evidence + "; leading term − factor × equation: " + multiple.evidence};
    }
    if (own.outcome == kernel_decision::result::nonzero) own_contradicts = true;
    if (own.outcome == kernel_decision::result::not_applicable) not_decided.push_back(relations[i].place + ": " + own.evidence);
    decided_relations.push_back({{"relation", folded_space(relations[i].tex) + " (" + relations[i].place + ")"},
                                 {"equation", folded_space(equations[i].tex) + " (" + equations[i].place + ")"},
                                 {"series", text_of(expansion.series)},
                                 {"leading", fmt::format("{}^{} ({})", h.get_name(), expansion.lowest_power, text_of(expansion.leading))},
                                 {"factor", factor ? text_of(*factor) : "none: not a multiple of the equation"},
                                 {"own", own.evidence}});
  }
  result.printed = read.printed();
  const std::string what = fmt::format("({}) consistent with ({})", reference_of(call, "scheme"), reference_of(call, "equation"));
  result.evidence["exact"] = {
      {"statement", what},
      {"relations", decided_relations},
      {"ginac", ginac_all ? "holds: each relation's leading term on smooth states is a multiple of its equation (GiNaC's series, V and the solution uninterpreted)"
                          : "fails: a relation's leading term is not a multiple of its equation"},
      {"own", own_contradicts        ? std::string("contradicts GiNaC: a relation's series or multiple does not hold on the Taylor polynomials")
              : !not_decided.empty() ? "not applicable: " + fmt::format("{}", fmt::join(not_decided, "; "))
                                     : std::string(ginac_all ? "holds" : "fails") +
                                           ": each relation on the states' Taylor polynomials is h^p times the leading term plus " +
                                           (said ? "O(h^(p+order)), no term between" : "O(h^(p+1))") + ", and that term the factor times its equation"}};
  if (said) {
    result.evidence["exact"]["stated_order"] = said->number("order");
    result.evidence["exact"]["order"] = *order < series_order ? std::to_string(*order) : "at least " + std::to_string(*order);
    if (said->number("order") != *order) {
      corrections.push_back(*order < series_order ? fmt::format("a discretization of order {}", *order)
                                                  : fmt::format("a discretization of order at least {}", *order));
    }
  }
  if (!not_decided.empty()) result.note = "Our kernel could not decide it: GiNaC's series alone. ";
  // Our kernel confirms GiNaC's series and multiples relation by relation: where it decided them all,
  // its answer is GiNaC's; where it refutes one, they differ on that relation.
  const answer ginac = answer_of(ginac_all && corrections.empty());
  decider_evidence e = settled(std::move(result), ginac, not_decided.empty() ? ginac : answer::none, what,
                               "as derived: " + fmt::format("{}", fmt::join(corrections, "; ")));
  e.parts_differ = own_contradicts;
  return e;
}

/// Printed Taylor expansions "x_{j+k} = x_j + k h dx/dt + ... + O(h^N)": each printed series is the
/// Taylor polynomial of x(t_j + k h) through h^(N-1), x_j its value at t_j and d^ix/dt^i its
/// derivatives there as the reader names them. GiNaC's normal form and our kernel each compare the
/// printed terms with it.
decider_evidence taylor_expansion_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const std::vector<referenced_formula> expansions = read.equations("expansions");
  const GiNaC::symbol h = read.symbols("step").front();
  const std::string index = call.with.at("index").values.front();
  claim_result result;
  json rows = json::array();
  std::vector<std::string> corrections, not_decided;
  std::vector<proof_goal> goals;
  bool ginac_all = true, disagree = false;
  for (const referenced_formula& expansion : expansions) {
    const std::vector<ex> sides = read.sides(expansion);
    const std::vector<smooth_state> states = indexed_states(sides.front(), index, h);
    if (states.size() != 1 || !GiNaC::is_a<GiNaC::symbol>(sides.front())) {
      throw std::invalid_argument(expansion.locator + ": its left side is not one state x_" + index + "+k");
    }
    const smooth_state& state = states.front();
    const auto [terms, order] = split_order(sides.back(), h);
    if (order <= 0) throw std::invalid_argument(expansion.locator + ": no order term O(" + h.get_name() + "^N)");
    ex series = paper_symbols()[state.function + "_" + index], term = 1;
    for (int k = 1; k < order; ++k) {
      term = term * state.shift / k;
      series += term * paper_symbols()[derivative_name(state.function, "t", k, k)];
    }
    const ex gap = GiNaC::normal(terms - series);
    const kernel_decision own = kernel_decides_zero(terms - series);
    if (own.outcome == kernel_decision::result::not_applicable) not_decided.push_back(expansion.place + ": " + own.evidence);
    if (own.outcome != kernel_decision::result::not_applicable && (own.outcome == kernel_decision::result::zero) != gap.is_zero()) disagree = true;
    ginac_all = ginac_all && gap.is_zero();
    const std::string big_o = fmt::format("O({}^{})", h.get_name(), order);
    if (!gap.is_zero()) {
      // What is wrong, term by term: "printed X, should be Y" for each power of h that differs.
      const ex printed_terms = GiNaC::expand(terms), taylor = GiNaC::expand(series);
      std::vector<std::string> wrong;
      for (int k = 0; k < order; ++k) {
        const ex p = printed_terms.coeff(h, k), t = taylor.coeff(h, k);
        if (GiNaC::normal(p - t).is_zero()) continue;
        wrong.push_back(fmt::format("its {} term is printed {}, should be {}", k == 0 ? std::string("constant") : fmt::format("{}^{}", h.get_name(), k),
                                    text_of(p * GiNaC::pow(h, k)), text_of(t * GiNaC::pow(h, k))));
      }
      corrections.push_back(fmt::format("in {} = ... + {}: {}", folded_space(expansion.sides.front()), big_o, fmt::join(wrong, "; ")));
      for (int k = 0; k < order; ++k) {
        const std::optional<amendment> a =
            amendment_between(fmt::format("the {} term of ${}$", k == 0 ? std::string("constant") : fmt::format("${}^{}$", canonical_tex(h), k), folded_space(expansion.sides.front())),
                              printed_terms.coeff(h, k) * GiNaC::pow(h, k), taylor.coeff(h, k) * GiNaC::pow(h, k));
        if (a) result.amendments.push_back(*a);
      }
    }
    rows.push_back({{"expansion", folded_space(expansion.sides.front()) + " (" + expansion.place + ")"},
                    {"series", text_of(series) + " + " + big_o},
                    {"printed_minus_series", text_of(gap)},
                    {"own", own.evidence}});
  }
  result.printed = read.printed();
  result.evidence["exact"] = {
      {"statement", fmt::format("the printed expansions ({}) are the Taylor polynomials of the states", reference_of(call, "expansions"))},
      {"expansions", rows},
      {"ginac", ginac_all ? std::string("holds: printed terms − Taylor polynomial = 0 (normal form)")
                          : fmt::format("holds: {} expansion(s) differ from the Taylor polynomial (normal form)", corrections.size())},
      {"own", disagree               ? std::string("contradicts GiNaC on an expansion")
              : !not_decided.empty() ? "not applicable: " + fmt::format("{}", fmt::join(not_decided, "; "))
                                     : std::string("holds: printed terms − Taylor polynomial decided on a grid, as GiNaC")}};
  decider_evidence e = settled(std::move(result), answer_of(ginac_all), not_decided.empty() ? answer_of(ginac_all) : answer::none, "an expansion",
                               fmt::format("{}", fmt::join(corrections, "; ")));
  e.parts_differ = disagree;  // on an expansion
  return e;
}

/// The shapes of this file, each one's name, summary, principal argument and parameters beside the
/// function that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> consistency_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  add({"consistency", "each printed relation of the scheme, on smooth states x_{j+k} = x(t + k h), is h^p times a multiple of its printed differential equation",
       "scheme",
       with_where({{"scheme", argument_kind::equations, true, "the scheme's printed relations 'a = b' (or 'a = 0')"},
                   {"equation", argument_kind::equations, true, "the printed differential equations, one per relation, in order"},
                   {"step", argument_kind::symbols, true, "the step h", 1},
                   {"index", argument_kind::word, true, "the index of the states, 'j' for x_j, x_{j+1}, x_{j-1}"},
                   pattern_with_hole("sentence", "optionally, a sentence stating the order, with the hole {order}", "order", false)}),
       consistency_shape,
       [](shape_reader& read, const shape_call& call) {  // x(t_j) of a function not declared a solution: refused before the run
         const std::string index = call.with.at("index").values.front();
         const GiNaC::symbol h = read.symbols("step").front();
         for (const char* parameter : {"scheme", "equation"}) {
           for (const referenced_formula& f : read.equations(parameter)) {
             for (const GiNaC::ex& side : read.sides(f)) {
               for (const std::string& name : function_names(side)) {
                 if (!applies_at_node(side, name, index)) continue;
                 solution_at_nodes(side, *call.declared, name, index, h, parameter);
               }
             }
           }
         }
       }});
  add({"taylor-expansion", "each printed expansion x_{j+k} = ... + O(h^N) is the Taylor polynomial of x(t_j + k h) through h^(N-1)", "expansions",
       with_where({{"expansions", argument_kind::equations, true, "the printed expansions 'x_{j+k} = x_j + ... + O(h^N)'"},
                   {"step", argument_kind::symbols, true, "the step h", 1},
                   {"index", argument_kind::word, true, "the index of the states, 'j' for x_j, x_{j+1}, x_{j-1}"}}),
       taylor_expansion_shape});
  return all;
}

}  // namespace simpson::verify::detail

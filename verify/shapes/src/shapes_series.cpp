// The series shapes (shape_support.hpp): a printed truncation error, and the order a sentence states,
// each a series GiNaC expands and our kernel confirms on the solution's Taylor polynomials.

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

/// The degree K of the Taylor polynomials of the exact solution that makes the scheme's series exact
/// through h^(order − 1): the scheme is a polynomial in its states (none of them in a denominator)
/// whose coefficients have a pole at h = 0 of order at most d, the degree in h of the denominators of
/// the tree as read (our kernel's bound, kernel_zero.hpp), so states wrong by O(h^(K+1)) change it by
/// O(h^(K+1−d)). Throws std::invalid_argument when a state is in a denominator.
int taylor_degree(const shape_call& call, const ex& scheme, const std::vector<GiNaC::symbol>& sequence, const GiNaC::symbol& h, int order) {
  for (const GiNaC::symbol& state : sequence) {
    if (kernel_denominator_degree(scheme, state.get_name()) > 0) {
      throw std::invalid_argument(reference_of(call, "scheme") + " has " + state.get_name() +
                                  " in a denominator: the series shapes take a scheme polynomial in its states");
    }
  }
  return order - 1 + static_cast<int>(kernel_denominator_degree(scheme, h.get_name()));
}

/// The scheme a series shape expands: as printed, or divided by the record's `scale` (the text's
/// "the scheme divided by m"), a factor free of the states.
ex scaled_scheme(shape_reader& read) {
  const ex scheme = read.formula("scheme");
  if (!read.has("scale")) return scheme;
  const ex scale = read.formula("scale");
  if (GiNaC::normal(scale).is_zero()) throw argument_error("scale", "the scale is 0");
  for (const GiNaC::symbol& state : read.symbols("sequence")) {
    if (scale.has(state)) throw argument_error("scale", "the scale depends on the state " + state.get_name());
  }
  return scheme / scale;
}

/// The scheme (= 0, in three consecutive states) on the Taylor polynomials of degree `degree` of the
/// exact solution of q'' = −ω² q through the middle state, q(t_j ± h) = q_j cos ωh ± (v_j/ω) sin ωh.
ex on_taylor_solution(const ex& scheme, const std::vector<GiNaC::symbol>& sequence, const GiNaC::symbol& h, const ex& omega, int degree) {
  const GiNaC::symbol velocity("v_j");
  ex c = 0, sn = 0, term = 1;
  for (int k = 0; k <= degree; ++k) {
    if (k > 0) term = term * omega * h / k;
    if (k % 2 == 0) c += (k % 4 == 0 ? 1 : -1) * term;
    else sn += (k % 4 == 1 ? 1 : -1) * term;
  }
  const ex shift = velocity / omega * sn;
  return scheme.subs(GiNaC::lst{sequence[0] == sequence[1] * c - shift, sequence[2] == sequence[1] * c + shift});
}

/// GiNaC's series in h to O(h^order) of the scheme on the solution (on_taylor_solution, exact to that order).
ex series_of(const ex& on_taylor, const GiNaC::symbol& h, int order) {
  return GiNaC::expand(GiNaC::series_to_poly(GiNaC::series(on_taylor, h == 0, order)));
}

/// The lowest power of h with a nonzero coefficient, or nothing.
std::optional<int> lowest_power(const ex& e, const GiNaC::symbol& h) {
  const ex expanded = GiNaC::expand(e);
  for (int k = expanded.ldegree(h); k <= expanded.degree(h); ++k) {
    if (!GiNaC::normal(expanded.coeff(h, k)).is_zero()) return k;
  }
  return std::nullopt;
}

/// Our kernel's decision that f = h^power w with w regular at h = 0 (and, when `exact`, w(0) ≠ 0):
/// w = n/d is GiNaC's witness, normal(f / h^power); our kernel decides f − h^power n/d = 0 as read,
/// and that d (and n, when exact) at h = 0 is not zero. `zero` when all three hold, `nonzero` when
/// one of them fails: the witness is then not one, and the claim is not confirmed.
kernel_decision kernel_confirms_order(const ex& f, const GiNaC::symbol& h, int power, bool exact) {
  const ex w = GiNaC::normal(f / GiNaC::pow(h, power));
  const ex n = GiNaC::numer(w), d = GiNaC::denom(w);
  const kernel_decision identity = kernel_decides_zero(f - GiNaC::pow(h, power) * n * GiNaC::pow(d, -1));
  if (identity.outcome != kernel_decision::result::zero) {
    return {identity.outcome, "f − " + h.get_name() + "^" + std::to_string(power) + " w as written: " + identity.evidence};
  }
  const kernel_decision regular = kernel_decides_zero(d.subs(h == 0));
  if (regular.outcome != kernel_decision::result::nonzero) {
    return {regular.outcome == kernel_decision::result::zero ? kernel_decision::result::nonzero : regular.outcome,
            "w's denominator at " + h.get_name() + " = 0: " + regular.evidence};
  }
  std::string evidence = fmt::format("f = {}^{} w, w = n/d: f − {}^{} n/d {}; d at {} = 0 {}", h.get_name(), power, h.get_name(), power,
                                     identity.evidence, h.get_name(), regular.evidence);
  if (exact) {
    const kernel_decision leading = kernel_decides_zero(n.subs(h == 0));
    if (leading.outcome != kernel_decision::result::nonzero) {
      return {leading.outcome == kernel_decision::result::zero ? kernel_decision::result::nonzero : leading.outcome,
              "w's numerator at " + h.get_name() + " = 0: " + leading.evidence};
    }
    evidence += "; n at " + h.get_name() + " = 0 " + leading.evidence;
  }
  return {kernel_decision::result::zero, evidence};
}

/// Our kernel's line of evidence: `verdict` ("holds" or "fails", the claim's as our kernel decided it)
/// and what it proved, or where it contradicts GiNaC's witness, or why it could not decide.
std::string own_text(const kernel_decision& own, const std::string& verdict, const std::string& what) {
  switch (own.outcome) {
    case kernel_decision::result::zero: return verdict + ": " + what + " (" + own.evidence + ")";
    case kernel_decision::result::nonzero: return "contradicts GiNaC: " + own.evidence;
    default: return "not applicable: " + own.evidence;
  }
}

/// The verdict on the order a sentence states, `order` being GiNaC's and `own` our kernel's decision
/// of its witness: kernels-disagree when ours contradicts it (`on` says of what), holds when the two
/// orders agree, else an erratum with `correction`, the note saying `as_printed`.
claim_result settled_order(claim_result result, const kernel_decision& own, int stated, int order, const std::string& on, const std::string& correction,
                           const std::string& as_printed) {
  if (kernels_disagree_if(result, own.outcome == kernel_decision::result::nonzero, kernels_differ_on(on))) return result;
  if (own.outcome == kernel_decision::result::not_applicable) result.note = "Our kernel could not decide it (" + own.evidence + "): GiNaC's series alone. ";
  if (order == stated) {
    result.outcome = verdict::holds;
    return result;
  }
  result.outcome = verdict::erratum;
  result.correction = correction;
  result.note += as_printed;
  return result;
}

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

}  // namespace

/// Printed relations of a scheme consistent with printed differential equations: each relation
/// a = b, its states x_{j+k} put on smooth functions x(t + k h), is as a series in h (GiNaC's) h^p
/// times a nonzero multiple, free of the unknowns, of its equation a' = b' (x(t) read as x). Our
/// kernel decides, on the Taylor polynomials of the states (exact through h^p, taylor_degree), that
/// the relation is h^p times GiNaC's leading term plus h^(p+1) times a function regular at h = 0, and
/// that this term is the factor times the printed equation; V uninterpreted, for every polynomial V
/// of degree <= 4.
claim_result consistency_shape(const shape_call& call, const run_context& ctx) {
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
    const std::vector<ex> sides = read.sides(relations[i]), printed_sides = read.sides(equations[i]);
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
  settle(result, own_contradicts, ginac_all && corrections.empty(), what, "as derived: " + fmt::format("{}", fmt::join(corrections, "; ")));
  return result;
}

/// Printed Taylor expansions "x_{j+k} = x_j + k h dx/dt + ... + O(h^N)": each printed series is the
/// Taylor polynomial of x(t_j + k h) through h^(N-1), x_j its value at t_j and d^ix/dt^i its
/// derivatives there as the reader names them. GiNaC's normal form and our kernel each compare the
/// printed terms with it.
claim_result taylor_expansion_shape(const shape_call& call, const run_context& ctx) {
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
  settle(result, disagree, ginac_all, "an expansion", fmt::format("{}", fmt::join(corrections, "; ")));
  return result;
}

/// A printed truncation error: the scheme (an expression in three consecutive states, = 0) on the
/// exact solution of q'' = −ω² q through the middle state, q(t_j ± h) = q_j cos ωh ± (v_j/ω) sin ωh,
/// as a series in h, against the printed terms and order O(h^N). GiNaC expands the series; our kernel
/// decides, on the Taylor polynomials of the solution (exact through h^(N−1), taylor_degree), that
/// the scheme there is the terms plus h^N times a function regular at h = 0, GiNaC's quotient being
/// only the witness: the printed terms when they hold, GiNaC's series (and that it differs from the
/// printed terms) when they do not. That identity is the Coq certificate.
claim_result truncation_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex printed = read.formula("printed");
  const ex scheme = scaled_scheme(read);
  const ex omega = read.formula("frequency");
  const std::vector<GiNaC::symbol> sequence = read.symbols("sequence"), step = read.symbols("step");
  const GiNaC::symbol& h = step.front();
  claim_result result;
  result.printed = read.printed();
  // The printed terms and its order term O(h^N).
  const auto [terms, order] = split_order(printed, h);
  if (order <= 0) throw std::invalid_argument(reference_of(call, "printed") + " has no order term O(" + h.get_name() + "^k)");
  const int degree = taylor_degree(call, scheme, sequence, h, order);
  const ex on_taylor = on_taylor_solution(scheme, sequence, h, omega, degree);
  const ex series = series_of(on_taylor, h, order);
  // The next terms, for the reader (two more even powers), from the Taylor polynomials of a higher degree.
  const int further = order + 4;
  const ex series_further = series_of(on_taylor_solution(scheme, sequence, h, omega, taylor_degree(call, scheme, sequence, h, further)), h, further);
  const ex gap = GiNaC::normal(series - terms);
  const std::string big_o = "O(" + h.get_name() + "^" + std::to_string(order) + ")";
  const std::string what = fmt::format("({}) on the exact solution = ({}) + {}", reference_of(call, "scheme"), reference_of(call, "printed"), big_o);
  const bool ginac_holds = gap.is_zero();
  // Our kernel: the printed terms when GiNaC finds them right, else GiNaC's series and its difference
  // from the printed terms.
  kernel_decision own = kernel_confirms_order(on_taylor - (ginac_holds ? terms : series), h, order, false);
  std::string own_claim = fmt::format("the scheme on the solution's Taylor polynomials of degree {} = {} + {}", degree,
                                      ginac_holds ? "the printed terms" : "GiNaC's series", big_o);
  if (!ginac_holds && own.outcome == kernel_decision::result::zero) {
    const kernel_decision differs = kernel_decides_zero(series - terms);
    if (differs.outcome == kernel_decision::result::nonzero) {
      own.evidence += "; series − printed terms " + differs.evidence;
    } else {
      own = {differs.outcome == kernel_decision::result::zero ? kernel_decision::result::nonzero : differs.outcome,
             "series − printed terms: " + differs.evidence};
    }
    own_claim += ", and the printed terms differ from it";
  }
  result.evidence["exact"] = {{"statement", what},
                              {"series", text_of(series) + " + " + big_o},
                              {"series_further", text_of(series_further) + " + O(" + h.get_name() + "^" + std::to_string(further) + ")"},
                              {"leading_power", lowest_power(series, h).value_or(-1)},
                              {"taylor_degree", degree},
                              {"ginac", ginac_holds ? "holds: series − printed terms = 0 through the printed order"
                                                    : "fails: series − printed terms = " + text_of(gap)},
                              {"own", own_text(own, ginac_holds ? "holds" : "fails", own_claim)}};
  // What Coq certifies: the scheme on the Taylor polynomials is the terms plus h^N times GiNaC's quotient.
  const ex remainder = GiNaC::normal((on_taylor - (ginac_holds ? terms : series)) / GiNaC::pow(h, order));
  std::vector<proof_goal> goals{decided(ginac_holds ? "printed_taylor_remainder" : "derived_taylor_remainder", on_taylor,
                                        (ginac_holds ? terms : series) + GiNaC::pow(h, order) * remainder)};
  if (!ginac_holds) goals.push_back(decided("printed", series, terms));
  record_certificate(result, coq_certificate(call.claim_id, call.statement, goals));
  if (kernels_disagree_if(result, own.outcome == kernel_decision::result::nonzero, kernels_differ_on(what))) return result;
  if (own.outcome == kernel_decision::result::not_applicable) result.note = "Our kernel could not decide it (" + own.evidence + "): GiNaC's series alone. ";
  if (ginac_holds) {
    result.outcome = verdict::holds;
    return result;
  }
  result.outcome = verdict::erratum;
  result.correction = "as derived: " + text_of(series) + " + " + big_o;
  result.note += "As printed: " + what + " is false; the series differs by " + text_of(gap) + ".";
  return result;
}

/// The order a sentence states ("the scheme is of {order} order"), its words quoted from the
/// document and parsed, against the order computed: the scheme on the exact solution of
/// q'' = −ω² q is O(h^(p + s + 2)) when its q_{j+1} coefficient is of order h^s, so p = that power − s − 2.
/// GiNaC finds both powers; our kernel decides each (f = h^k w, w(0) finite and nonzero, as in
/// kernel_confirms_order).
claim_result stated_order_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex scheme = scaled_scheme(read);
  const ex omega = read.formula("frequency");
  const std::vector<GiNaC::symbol> sequence = read.symbols("sequence"), step = read.symbols("step");
  const GiNaC::symbol& h = step.front();
  const quoted_sentence sentence = quote(ctx, call.with.at("sentence").values.front());
  const int stated = sentence.number("order");
  claim_result result;
  result.printed = read.printed();
  const ex next_coefficient = GiNaC::diff(scheme, sequence[2]);
  const std::optional<int> scale = lowest_power(GiNaC::expand(GiNaC::normal(next_coefficient)), h);
  constexpr int series_order = 10;
  const ex on_taylor = on_taylor_solution(scheme, sequence, h, omega, taylor_degree(call, scheme, sequence, h, series_order));
  const ex series = series_of(on_taylor, h, series_order);
  const std::optional<int> leading = lowest_power(series, h);
  if (!scale) throw std::invalid_argument(reference_of(call, "scheme") + " has no " + sequence[2].get_name() + " term");
  result.evidence["exact"] = {{"statement", "the order the sentence states, against the order computed"},
                              {"stated", stated},
                              {"series", text_of(series) + " + O(" + h.get_name() + "^" + std::to_string(series_order) + ")"},
                              {"q_next_coefficient_power", *scale}};
  if (!leading) {
    result.outcome = verdict::undecided;
    result.note = "The series vanishes through O(h^" + std::to_string(series_order) + "): the order is at least " +
                  std::to_string(series_order - *scale - 2) + ", beyond what the shape expands.";
    return result;
  }
  const int order = *leading - *scale - 2;
  result.evidence["exact"]["computed"] = order;
  kernel_decision own = kernel_confirms_order(next_coefficient, h, *scale, true);
  if (own.outcome == kernel_decision::result::zero) {
    const kernel_decision on_solution = kernel_confirms_order(on_taylor, h, *leading, true);
    own = {on_solution.outcome, "the " + sequence[2].get_name() + " coefficient: " + own.evidence + "; the scheme on the solution: " + on_solution.evidence};
  }
  // What Coq certifies: the two factorisations by powers of h (that their cofactors are finite and
  // nonzero at h = 0 is our kernel's alone).
  const auto factored = [&h](const std::string& name, const ex& f, int power) {
    return decided(name, f, GiNaC::pow(h, power) * GiNaC::normal(f / GiNaC::pow(h, power)));
  };
  record_certificate(result, coq_certificate(call.claim_id, call.statement,
                                              {factored("next_coefficient", next_coefficient, *scale), factored("taylor_order", on_taylor, *leading)}));
  const std::string verdict_word = order == stated ? "holds" : "fails";
  result.evidence["exact"]["ginac"] = fmt::format("{}: the series' leading power {}^{} less the {} coefficient's {}^{} less 2 is order {}",
                                                  verdict_word, h.get_name(), *leading, sequence[2].get_name(), h.get_name(), *scale, order);
  result.evidence["exact"]["own"] = own_text(own, verdict_word, fmt::format("the {} coefficient is of order {}^{} and the scheme on the solution of order {}^{}",
                                                              sequence[2].get_name(), h.get_name(), *scale, h.get_name(), *leading));
  return settled_order(std::move(result), own, stated, order, "the powers of the series", fmt::format("the scheme is of order {}", order),
                       fmt::format("As printed: the sentence states order {}; on the exact solution the scheme is {} + O(h^{}).", stated, text_of(series),
                                   series_order));
}

/// The order of accuracy a sentence states ({order}) against the printed one-step map's: each entry
/// of the map minus the exact flow of q'' = −ω²q over one step (q' = p/m) is O(h^(p+1)), and one is
/// not O(h^(p+2)): a local error of order p + 1, so the order p. GiNaC expands the entries; our kernel
/// decides, on the flow's Taylor polynomials through h^(p+1), that each entry is h^(p+1) times a
/// function finite at h = 0, nonzero there for the entries of the lowest power; Coq certifies the
/// factorisations. Over a fixed time the global error is then O(h^p) wherever the map is stable.
claim_result map_order_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const GiNaC::matrix map = as_square_matrix(read.formula("map"), reference_of(call, "map"));
  const ex mass = read.formula("mass"), omega = read.formula("frequency");
  const GiNaC::symbol h = read.symbols("step").front();
  const bool momentum_first = read.has("order") && call.with.at("order").values.front() == "p q";
  const quoted_sentence sentence = quote(ctx, call.with.at("sentence").values.front());
  const int stated = sentence.number("order");
  claim_result result;
  result.printed = read.printed();
  // The exact flow over one step, in the printed map's state order, and its Taylor polynomials.
  const auto flow = [&](const ex& c, const ex& s) {
    return momentum_first ? GiNaC::matrix{{c, -mass * omega * s}, {s / (mass * omega), c}}
                          : GiNaC::matrix{{c, s / (mass * omega)}, {-mass * omega * s, c}};
  };
  const auto taylor_flow = [&](int degree) {
    ex c = 0, s = 0, term = 1;
    for (int k = 0; k <= degree; ++k) {
      if (k > 0) term = term * omega * h / k;
      if (k % 2 == 0) c += (k % 4 == 0 ? 1 : -1) * term;
      else s += (k % 4 == 1 ? 1 : -1) * term;
    }
    return flow(c, s);
  };
  constexpr int series_order = 12;
  const GiNaC::matrix exact = flow(GiNaC::cos(omega * h), GiNaC::sin(omega * h));
  const char* const names[2][2] = {{"(1,1)", "(1,2)"}, {"(2,1)", "(2,2)"}};
  std::optional<int> lowest;
  json local = json::object();
  ex series[2][2];
  for (unsigned i = 0; i < 2; ++i) {
    for (unsigned j = 0; j < 2; ++j) {
      series[i][j] = series_of(map(i, j) - exact(i, j), h, series_order);
      const std::optional<int> power = lowest_power(series[i][j], h);
      local[names[i][j]] = (series[i][j].is_zero() ? std::string("0") : text_of(series[i][j])) + " + O(" + h.get_name() + "^" + std::to_string(series_order) + ")";
      if (power && (!lowest || *power < *lowest)) lowest = power;
    }
  }
  result.evidence["exact"] = {{"statement", fmt::format("({}) minus the exact flow over one step, entry by entry, as a series in {}", reference_of(call, "map"),
                                                        h.get_name())},
                              {"flow", text_of(ex(exact))},
                              {"local_error", local},
                              {"stated", stated}};
  if (!lowest) {
    result.outcome = verdict::undecided;
    result.note = fmt::format("The map is the flow through O({}^{}): the order is at least {}, beyond what the shape expands.", h.get_name(), series_order,
                              series_order - 1);
    return result;
  }
  const int order = *lowest - 1;
  result.evidence["exact"]["computed"] = order;
  result.evidence["exact"]["lowest_power"] = *lowest;
  // Our kernel, and what Coq certifies: each entry minus the flow's Taylor polynomials through
  // h^lowest is h^lowest times a function finite at h = 0 (nonzero there where GiNaC's series starts).
  const GiNaC::matrix near = taylor_flow(*lowest);
  std::vector<proof_goal> goals;
  kernel_decision own{kernel_decision::result::zero, ""};
  std::vector<std::string> own_parts;
  for (unsigned i = 0; i < 2 && own.outcome == kernel_decision::result::zero; ++i) {
    for (unsigned j = 0; j < 2 && own.outcome == kernel_decision::result::zero; ++j) {
      const ex f = map(i, j) - near(i, j);
      const bool leading = lowest_power(series[i][j], h) == lowest;
      const kernel_decision entry = kernel_confirms_order(f, h, *lowest, leading);
      if (entry.outcome != kernel_decision::result::zero) own = {entry.outcome, std::string("entry ") + names[i][j] + ": " + entry.evidence};
      if (leading) own_parts.push_back(names[i][j]);
      // An entry equal to the flow's Taylor polynomial has nothing to certify.
      if (!GiNaC::normal(f).is_zero()) {
        goals.push_back(decided(fmt::format("entry_{}{}", i + 1, j + 1), f, GiNaC::pow(h, *lowest) * GiNaC::normal(f / GiNaC::pow(h, *lowest))));
      }
    }
  }
  record_certificate(result, coq_certificate(call.claim_id, call.statement, goals));
  const std::string verdict_word = order == stated ? "holds" : "fails";
  result.evidence["exact"]["ginac"] = fmt::format("{}: the entries' series start at {}^{} (local error), order {}", verdict_word, h.get_name(), *lowest, order);
  result.evidence["exact"]["own"] =
      own_text(own, verdict_word,
               fmt::format("each entry minus the flow's Taylor polynomials of degree {} is {}^{} times a function finite at {} = 0, nonzero there for the entries {}", *lowest,
                           h.get_name(), *lowest, h.get_name(), fmt::join(own_parts, ", ")));
  return settled_order(std::move(result), own, stated, order, "the map's local error",
                       fmt::format("the map is of order {}: its local error is O({}^{})", order, h.get_name(), *lowest),
                       fmt::format("As printed: the sentence states order {}; the map differs from the exact flow over one step at {}^{}.", stated,
                                   h.get_name(), *lowest));
}

}  // namespace simpson::verify::detail

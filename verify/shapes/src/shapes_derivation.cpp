// The derivation shapes (shape_support.hpp): the discrete Euler-Lagrange equation, and the one-step map of a
// discrete Lagrangian with its internal nodes eliminated.

#include <simpson/shapes/shape_support.hpp>

#include <simpson/prove/coq_export.hpp>

#include <simpson/prove/printed_check_support.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>
#include <set>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

/// The derived equation (= 0) scaled so that as many of its terms as can be have the printed
/// coefficients, in words with the terms whose printed coefficient differs (a wrong coefficient
/// named, with the right one), and as an expression: what stands for the printed one when the claims
/// that read it are judged again.
struct scaled_equation {
  std::string text;
  ex value;
};

/// The derived equation scaled to the printed one's coefficients; none when no term is shared, or
/// when the printed equation holds a denominator in the unknowns.
std::optional<scaled_equation> scaled_correction(const ex& printed, const ex& derived, const std::vector<GiNaC::symbol>& unknowns) {
  const ex p = GiNaC::normal(printed), d = GiNaC::normal(derived);
  const auto free_denominator = [&](const ex& e) {
    const ex den = GiNaC::denom(e);
    return std::none_of(unknowns.begin(), unknowns.end(), [&](const GiNaC::symbol& u) { return den.has(u); });
  };
  if (!free_denominator(p) || !free_denominator(d)) return std::nullopt;
  const auto depends = [&](const ex& f) { return std::any_of(unknowns.begin(), unknowns.end(), [&](const GiNaC::symbol& u) { return f.has(u); }); };
  const auto printed_terms = terms_by_parts(printed, depends), derived_terms = terms_by_parts(d, depends);
  std::optional<ex> best_scale;
  std::size_t best_agreeing = 0;
  for (const auto& [key, term] : printed_terms) {
    const auto it = derived_terms.find(key);
    if (it == derived_terms.end() || GiNaC::normal(term.second).is_zero()) continue;
    const ex scale = GiNaC::normal(it->second.second / term.second);
    std::size_t agreeing = 0;
    for (const auto& [k, t] : printed_terms) {
      const auto o = derived_terms.find(k);
      if (o != derived_terms.end() && GiNaC::normal(o->second.second / scale - t.second).is_zero()) ++agreeing;
    }
    if (agreeing > best_agreeing) {
      best_agreeing = agreeing;
      best_scale = scale;
    }
  }
  if (!best_scale) return std::nullopt;
  std::vector<std::string> differing;
  ex scaled = 0;
  std::set<std::string> keys;
  for (const auto& [k, t] : printed_terms) keys.insert(k);
  for (const auto& [k, t] : derived_terms) keys.insert(k);
  for (const std::string& k : keys) {
    const auto pt = printed_terms.find(k), dt = derived_terms.find(k);
    const ex printed_coefficient = pt == printed_terms.end() ? ex(0) : GiNaC::normal(pt->second.second);
    const ex derived_coefficient = dt == derived_terms.end() ? ex(0) : GiNaC::normal(dt->second.second / *best_scale);
    const ex part = pt != printed_terms.end() ? pt->second.first : dt->second.first;
    scaled += derived_coefficient * part;
    if (!GiNaC::normal(printed_coefficient - derived_coefficient).is_zero()) {
      differing.push_back(fmt::format("the coefficient of {}: printed {}, derived {}", text_of(part), text_of(printed_coefficient), text_of(derived_coefficient)));
    }
  }
  std::string out = "as derived, with the printed coefficients where they are right: " + text_of(scaled) + " = 0";
  for (std::size_t k = 0; k < differing.size(); ++k) out += (k ? "; " : " (") + differing[k];
  return scaled_equation{differing.empty() ? out : out + ")", scaled};
}

/// The printed equation (= 0) against the derived one (= 0): the same when the printed one times a
/// factor free of the unknowns (GiNaC finds it) is the derived one, an identity both kernels decide.
decider_evidence same_equation_evidence(shape_reader& read, const std::string& goal, const std::string& what, const ex& printed,
                                   const ex& derived, const std::vector<GiNaC::symbol>& unknowns) {
  const auto factor = equation_factor(printed, derived, std::vector<ex>(unknowns.begin(), unknowns.end()));
  if (factor) {
    decider_evidence e = identity_evidence(read, goal, what, *factor * printed, derived, "");
    e.found.evidence["exact"]["factor"] = text_of(*factor);
    return e;
  }
  decider_evidence e;
  e.statement = what;
  e.ginac = answer::fails;
  claim_result& result = e.found;
  const std::optional<scaled_equation> scaled = scaled_correction(printed, derived, unknowns);
  result.correction = scaled ? scaled->text : "as derived: " + text_of(GiNaC::normal(derived)) + " = 0";
  // The claims that read the printed equation are judged again with the derived one in its place:
  // one that fails only through it follows from this erratum (consequences.cpp).
  result.corrected_formulas.push_back(read.correction_of("printed", scaled ? scaled->value : GiNaC::normal(derived)));
  result.note = "As printed: no factor free of the unknowns makes the printed equation the derived one (GiNaC: the ratio depends on them); our kernel decides identities only, not this refutation.";
  result.evidence["exact"] = {{"statement", what}, {"ginac", "fails: derived / printed depends on the unknowns"},
                              {"own", "not applicable: a refutation of proportionality"}};
  result.printed = read.printed();
  result.certificate_missing = "a refuted proportionality: no identity to state";
  return e;
}

}  // namespace

decider_evidence euler_lagrange_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex printed = read.formula("printed"), lagrangian = read.formula("lagrangian");
  const std::vector<GiNaC::symbol> nodes = read.symbols("nodes"), sequence = read.symbols("sequence");
  if (nodes.size() != 2) throw std::invalid_argument("'nodes' names the Lagrangian's two arguments (q_0, q_1)");
  if (sequence.size() != 3) throw std::invalid_argument("'sequence' names three consecutive states (q_{j-1}, q_j, q_{j+1})");
  const auto at = [&](const ex& e, const ex& a, const ex& b) { return e.subs(GiNaC::lst{nodes[0] == a, nodes[1] == b}); };
  // D_2 L(q_{j-1}, q_j) + D_1 L(q_j, q_{j+1}) = 0.
  const ex derived = at(lagrangian.diff(nodes[1]), sequence[0], sequence[1]) + at(lagrangian.diff(nodes[0]), sequence[1], sequence[2]);
  const std::string what = fmt::format("({}) = 0 is the discrete Euler-Lagrange equation of ({})", reference_of(call, "printed"),
                                       reference_of(call, "lagrangian"));
  return same_equation_evidence(read, "euler_lagrange", what, printed, derived, sequence);
}

/// The printed equation (= 0) is the stationarity condition d function / d variable = 0 (an internal
/// node's equation), up to a factor free of the unknowns.
decider_evidence stationary_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex printed = read.formula("printed"), function = read.formula("function");
  const GiNaC::symbol variable = read.symbols("variable").front();
  const std::string what = fmt::format("({}) = 0 is d({})/d{} = 0", reference_of(call, "printed"), reference_of(call, "function"), variable.get_name());
  return same_equation_evidence(read, "stationary", what, printed, GiNaC::diff(function, variable), read.symbols("unknowns"));
}

/// A printed system in the states and momenta of one step, each equation's sides equal once the
/// momenta are the discrete Legendre transforms of the Lagrangian on that step, p_j = −D_1 L(q_j,
/// q_{j+1}) and p_{j+1} = D_2 L(q_j, q_{j+1}) (the paper prints p_{j+1} and says "an analogous
/// relation for p_j"): equal-sides with them put in.
decider_evidence discrete_momenta_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const std::vector<referenced_formula> equations = read.equations("equations");
  const ex lagrangian = read.formula("lagrangian");
  const std::vector<GiNaC::symbol> nodes = read.symbols("nodes"), at = read.symbols("at"), momenta = read.symbols("momenta");
  const GiNaC::exmap on_step{{nodes[0], at[0]}, {nodes[1], at[1]}};
  // In normal form: the derivatives as written would cancel against the printed sides term by term
  // (GiNaC's evaluation), leaving our kernel and Coq a 0 to check.
  const ex left = GiNaC::normal(-lagrangian.diff(nodes[0]).subs(on_step, GiNaC::subs_options::no_pattern));
  const ex right = GiNaC::normal(lagrangian.diff(nodes[1]).subs(on_step, GiNaC::subs_options::no_pattern));
  const GiNaC::exmap given{{momenta[0], left}, {momenta[1], right}};
  return equal_sides_evidence(call, read, equations, given,
                              fmt::format(", with {} = -D_1 L({}, {}) = {} and {} = D_2 L({}, {}) = {}", momenta[0].get_name(), at[0].get_name(), at[1].get_name(),
                                         text_of(left), momenta[1].get_name(), at[0].get_name(), at[1].get_name(), text_of(right)));
}

/// The one-step map of a discrete Lagrangian L(q_0, q_1) of a linear system, derived: each internal
/// node eliminated by its equation D_{q_m} L = 0, then p_0 = −D_1 L solved for q_1 and p_1 = D_2 L,
/// as a matrix in (q_0, p_0), or in (p_0, q_0) when the record's `order` says "p q"; compared with
/// the printed map in both kernels.
decider_evidence discrete_map_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const GiNaC::matrix printed = as_square_matrix(read.formula("map"), reference_of(call, "map"));
  const ex lagrangian = read.formula("lagrangian");
  const std::vector<GiNaC::symbol> nodes = read.symbols("nodes"), momenta = read.symbols("momenta");
  const std::vector<GiNaC::symbol> internal = read.has("internal") ? read.symbols("internal") : std::vector<GiNaC::symbol>{};
  const auto no_map = [&](const std::string& why) {
    claim_result result;
    result.note = why;
    result.printed = read.printed();
    result.certificate_missing = "no map derived";
    return beyond_reach(std::move(result));  // no map derived: the shape's limit
  };
  const auto not_linear = [&](const std::string& step) {
    return no_map("The shape derives the map of a linear system: " + step + " is not linear in its unknowns.");
  };
  ex reduced = lagrangian;
  if (!internal.empty()) {
    GiNaC::lst equations, unknowns;
    for (const GiNaC::symbol& q : internal) {
      equations.append(lagrangian.diff(q) == 0);
      unknowns.append(q);
    }
    ex solution;
    try {
      solution = GiNaC::lsolve(equations, unknowns);
    } catch (const std::exception&) {
      return not_linear("the internal nodes' equations");
    }
    if (solution.nops() != internal.size()) return not_linear("the internal nodes' equations");
    reduced = lagrangian.subs(solution);
  }
  // p_0 = −D_1 L(q_0, q_1), solved for q_1; then p_1 = D_2 L.
  ex q1;
  try {
    // GiNaC's lsolve of one equation in one symbol returns the value itself; of lists, a list of
    // relations, empty when there is no unique solution.
    const ex solved = GiNaC::lsolve(GiNaC::lst{momenta[0] == -reduced.diff(nodes[0])}, GiNaC::lst{nodes[1]});
    if (solved.nops() != 1 || !GiNaC::is_a<GiNaC::relational>(solved.op(0))) return not_linear("p_0 = -D_1 L");
    q1 = GiNaC::normal(solved.op(0).rhs());
  } catch (const std::exception& e) {
    return not_linear(std::string("p_0 = -D_1 L (") + e.what() + ")");
  }
  const ex p1 = GiNaC::normal(reduced.diff(nodes[1]).subs(nodes[1] == q1));
  GiNaC::matrix derived(2, 2);
  const ex state[2] = {nodes[0], momenta[0]};
  for (unsigned c = 0; c < 2; ++c) {
    derived(0, c) = GiNaC::normal(q1.diff(GiNaC::ex_to<GiNaC::symbol>(state[c])));
    derived(1, c) = GiNaC::normal(p1.diff(GiNaC::ex_to<GiNaC::symbol>(state[c])));
  }
  // Linear: nothing of the state is left in the matrix; and no other symbol the document declares
  // real (a node left free: an internal node not named in `internal`).
  std::set<std::string> real;
  if (call.declared->complete) real = call.declared->real;
  for (unsigned r = 0; r < 2; ++r) {
    for (unsigned c = 0; c < 2; ++c) {
      if (derived(r, c).has(nodes[0]) || derived(r, c).has(momenta[0])) return not_linear("the map");
      for (const std::string& name : symbol_names(derived(r, c))) {
        if (real.count(name)) {
          return no_map("The derived map depends on " + name +
                        ", which the document declares real (a state, not a parameter): an internal node left free? Name it in 'internal'.");
        }
      }
    }
  }
  // The printed map's state order: (q, p) as derived, or (p, q) (rows and columns swapped).
  const bool momentum_first = read.has("order") && call.with.at("order").values.front() == "p q";
  if (momentum_first) derived = GiNaC::matrix{{derived(1, 1), derived(1, 0)}, {derived(0, 1), derived(0, 0)}};
  const std::string what = fmt::format("({}) is the one-step map of ({}), in ({})", reference_of(call, "map"), reference_of(call, "lagrangian"),
                                       momentum_first ? "p, q" : "q, p");
  decider_evidence e = identity_evidence(read, "printed", what, ex(printed), ex(derived),
                                         fmt::format("as derived from ({}): ({}) = {}", reference_of(call, "lagrangian"), reference_of(call, "map"),
                                                     text_of(ex(derived))));
  if (e.found_false()) e.found.corrected_formulas.push_back(read.correction_of("map", ex(derived)));
  e.found.evidence["exact"]["derivation"] = {{"q_1", text_of(q1)}, {"p_1", text_of(p1)},
                                            {"internal_nodes", internal.empty() ? std::string("none") : std::to_string(internal.size()) + " eliminated"}};
  // Coq is also told the derived map's defining property, which "printed = derived" leaves to GiNaC's
  // normal form: with q_1 from it, the momenta of the (reduced) Lagrangian are p_0 and its p_1.
  e.goals = std::vector<proof_goal>{decided("printed", ex(printed), ex(derived)),
                                    decided("derived_momentum_left", -reduced.diff(nodes[0]).subs(nodes[1] == q1), momenta[0]),
                                    decided("derived_momentum_right", reduced.diff(nodes[1]).subs(nodes[1] == q1), p1)};
  return e;
}

/// The shapes of this file, each one's name, summary, principal argument and parameters beside the
/// function that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> derivation_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  add({"euler-lagrange", "printed = 0 is D_2 L(q_{j-1}, q_j) + D_1 L(q_j, q_{j+1}) = 0, up to a factor free of the states", "printed",
       with_where({{"lagrangian", argument_kind::formula, true, "the discrete Lagrangian L(q_0, q_1)"},
                   {"nodes", argument_kind::symbols, true, "its two arguments", 2},
                   {"sequence", argument_kind::symbols, true, "three consecutive states", 3},
                   {"printed", argument_kind::formula, true, "the printed equation's side that is 0"}}),
       euler_lagrange_shape});
  add({"discrete-momenta", "every side of each printed equation equals its first once p_j = -D_1 L(q_j, q_{j+1}) and p_{j+1} = D_2 L(q_j, q_{j+1}) are put in",
       "equations",
       with_where({{"equations", argument_kind::equations, true, "the printed system: equations in the states and the momenta of one step"},
                   {"lagrangian", argument_kind::formula, true, "the discrete Lagrangian L(q_0, q_1)"},
                   {"nodes", argument_kind::symbols, true, "its two arguments", 2},
                   {"at", argument_kind::symbols, true, "the two states of the step, q_j and q_{j+1}", 2},
                   {"momenta", argument_kind::symbols, true, "the momenta at them, p_j and p_{j+1}", 2}}),
       discrete_momenta_shape});
  add({"stationary", "the printed equation (= 0) is d function / d variable = 0, up to a factor free of the unknowns", "printed",
       with_where({{"printed", argument_kind::formula, true, "the printed equation's side that is 0"},
                   {"function", argument_kind::formula, true, "the function made stationary (a discrete Lagrangian)"},
                   {"variable", argument_kind::symbols, true, "the variable it is stationary in (an internal node)", 1},
                   {"unknowns", argument_kind::symbols, true, "the states the factor must be free of"}}),
       stationary_shape});
  add({"discrete-map", "map is the one-step map of the discrete Lagrangian (internal nodes eliminated), p_0 = -D_1 L, p_1 = D_2 L", "map",
       with_where({{"map", argument_kind::matrix, true, "the printed one-step map of (q_0, p_0)", 2},
                   {"lagrangian", argument_kind::formula, true, "the discrete Lagrangian L(q_0, q_1), quadratic"},
                   {"nodes", argument_kind::symbols, true, "its end nodes q_0, q_1", 2},
                   {"momenta", argument_kind::symbols, true, "the momenta p_0, p_1", 2},
                   {"internal", argument_kind::symbols, false, "its internal nodes, eliminated by their equations"},
                   {"order", argument_kind::word, false, "the printed map's state order: 'q p' (the default) or 'p q'", 0, "", false, {"q p", "p q"}}}),
       discrete_map_shape});
  return all;
}

}  // namespace simpson::verify::detail

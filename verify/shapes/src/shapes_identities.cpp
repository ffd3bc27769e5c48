// The identity shapes (shape_support.hpp): identity, equal-sides, derivative, solves, determinant,
// symplectic, linear.

#include <simpson/shapes/shape_support.hpp>

#include <simpson/prove/coq_export.hpp>
#include <simpson/prove/printed_check_support.hpp>

#include <simpson/verify/sentence_holes.hpp>
#include <simpson/verify/quoted_words.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <utility>

namespace simpson::verify::detail {

using GiNaC::ex;

decider_evidence identity_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex rhs = read.formula("rhs"), lhs = read.formula("lhs");
  const std::string what = fmt::format("({}) = ({})", reference_of(call, "lhs"), reference_of(call, "rhs"));
  decider_evidence e = identity_evidence(read, "identity", what, lhs, rhs,
                                         fmt::format("as derived from ({}): ({}) = {}{}", reference_of(call, "lhs"), reference_of(call, "rhs"), text_of(lhs),
                                                     differing_application_coefficients(rhs, lhs)));
  if (e.found_false()) e.found.corrected_formulas.push_back(read.correction_of("rhs", lhs));
  return e;
}

/// Printed equations whose sides are all equal ("q(0) = q_l", "g_l = dq/dt(0) = (1/h)(...)"), the
/// definitions put in: each side against the equation's first, decided in both kernels, one Coq
/// goal each. A chain's first side that is a symbol nothing defines (g_l) names what the chain
/// defines and is not compared; the next one is then the reference. An erratum's correction gives
/// each side that differs as derived from the reference.
decider_evidence equal_sides_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  return equal_sides_evidence(call, read, read.equations("equations"), {}, "");
}

decider_evidence equal_sides_evidence(const shape_call& call, shape_reader& read, const std::vector<referenced_formula>& equations, const GiNaC::exmap& given,
                                      const std::string& given_text) {
  claim_result result;
  std::vector<std::shared_ptr<const corrected_formula>> corrected;  // each side that differs, as derived: what the claims that read it are judged again with
  std::vector<proof_goal> goals;
  json decided_sides = json::array();
  std::vector<std::string> corrections, not_decided;
  bool any_false = false, disagree = false, own_any_nonzero = false, own_all_decided = true;
  for (std::size_t i = 0; i < equations.size(); ++i) {
    const referenced_formula& equation = equations[i];
    std::vector<ex> sides = read.sides(equation);
    for (ex& side : sides) side = side.subs(given);
    std::size_t first = 0;
    if (sides.size() > 2 && GiNaC::is_a<GiNaC::symbol>(sides.front()) && !read.defines(GiNaC::ex_to<GiNaC::symbol>(sides.front()))) {
      const bool elsewhere = std::any_of(sides.begin() + 1, sides.end(), [&](const ex& side) { return side.has(sides.front()); });
      if (!elsewhere) first = 1;  // the name the chain defines
    }
    for (std::size_t k = first + 1; k < sides.size(); ++k) {
      const std::string what = fmt::format("({}) = ({}) of {}", folded_space(equation.sides[first]), folded_space(equation.sides[k]), equation.place);
      const ex difference = normal_difference(sides[first], sides[k]);
      const bool ginac_zero = is_zero_expression(difference);
      const kernel_decision own = kernel_decides_zero((sides[first] - sides[k]).evalm());
      const bool own_decided = own.outcome != kernel_decision::result::not_applicable;
      own_all_decided = own_all_decided && own_decided;
      if (own_decided && (own.outcome == kernel_decision::result::zero) != ginac_zero) disagree = true;
      if (!own_decided) not_decided.push_back(what + " (" + own.evidence + ")");
      own_any_nonzero = own_any_nonzero || own.outcome == kernel_decision::result::nonzero;
      any_false = any_false || !ginac_zero;
      if (!ginac_zero) {
        corrections.push_back(fmt::format("{} = {}, not {}", folded_space(equation.sides[first]), text_of(GiNaC::normal(sides[first])),
                                          folded_space(equation.sides[k])));
        corrected.push_back(read.correction_of_side(equation, k, sides[first]));
      }
      decided_sides.push_back({{"statement", what},
                               {"with_definitions", text_of(sides[first]) + " = " + text_of(sides[k])},
                               {"ginac", ginac_zero ? "holds: lhs − rhs = 0 (normal form, every symbol free)" : "fails: lhs − rhs = " + text_of(difference)},
                               {"own", (own.outcome == kernel_decision::result::zero      ? "holds: "
                                        : own.outcome == kernel_decision::result::nonzero ? "fails: "
                                                                                          : "not applicable: ") +
                                           own.evidence}});
      goals.push_back(decided(fmt::format("equation_{}_side_{}", i + 1, k + 1), sides[first], sides[k]));
    }
  }
  if (goals.empty()) throw std::invalid_argument(reference_of(call, "equations") + ": no two sides to compare");
  result.evidence["exact"] = {{"statement", fmt::format("every side of {} printed equation(s) equals its first, the definitions put in{}", equations.size(), given_text)},
                              {"ginac", any_false ? fmt::format("fails: {} side(s) differ from their equation's first", corrections.size())
                                                  : "holds: every side equals its equation's first (normal form, every symbol free)"},
                              {"own", own_any_nonzero        ? std::string("fails: a side differs from its equation's first")
                                      : !not_decided.empty() ? "not applicable: " + fmt::format("{}", fmt::join(not_decided, "; "))
                                                             : std::string("holds: every side equals its equation's first (each grid below)")},
                              {"sides", decided_sides}};
  if (any_false) result.note = fmt::format("As printed: {} side(s) differ from the first of their equation.", corrections.size());
  if (!not_decided.empty()) result.note += fmt::format("{}Our kernel could not decide {}: GiNaC's proof alone.", result.note.empty() ? "" : " ", fmt::join(not_decided, "; "));
  result.printed = read.printed();
  // Our kernel's answer: a side it finds different, else every side equal where it decided them all.
  const answer own = own_any_nonzero ? answer::fails : own_all_decided ? answer::holds : answer::none;
  decider_evidence e = settled(std::move(result), answer_of(!any_false), own, "a side",
                               fmt::format("as derived from the definitions{}: {}", given_text, fmt::join(corrections, "; ")));
  e.parts_differ = disagree;
  e.goals = std::move(goals);
  if (e.found_false()) e.found.corrected_formulas = std::move(corrected);
  return e;
}

/// A printed partial derivative: d function / d variable = printed, the definitions put in both. The
/// derivative is GiNaC's (structural differentiation of the tree as read, an uninterpreted V
/// differentiated to V'); the identity with the printed one is decided in both kernels.
decider_evidence derivative_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex printed = read.formula("printed"), function = read.formula("function");
  const GiNaC::symbol variable = read.symbols("variable").front();
  ex derived = GiNaC::diff(function, variable);
  std::string at;
  if (read.has("arguments")) {  // taken at other arguments: each put in at once
    const std::vector<GiNaC::symbol> arguments = read.symbols("arguments"), values = read.symbols("at");
    GiNaC::exmap to;
    for (std::size_t k = 0; k < arguments.size(); ++k) {
      to[arguments[k]] = values[k];
      at += (at.empty() ? " at " : ", ") + arguments[k].get_name() + " = " + values[k].get_name();
    }
    if (const auto pole = vanishing_denominator(derived, to)) {
      return undefined_there(read, fmt::format("d({})/d{}{}", reference_of(call, "function"), variable.get_name(), at), *pole);
    }
    derived = derived.subs(to, GiNaC::subs_options::no_pattern);
  }
  const std::string what = fmt::format("d({})/d{}{} = ({})", reference_of(call, "function"), variable.get_name(), at, reference_of(call, "printed"));
  decider_evidence e =
      identity_evidence(read, "derivative", what, derived, printed,
                        fmt::format("as derived: d({})/d{}{} = {}", reference_of(call, "function"), variable.get_name(), at, text_of(GiNaC::normal(derived))));
  // What should stand where the derivative is printed: the claims that read it are judged again with it.
  if (e.found_false()) e.found.corrected_formulas.push_back(read.correction_of("printed", GiNaC::normal(derived)));
  return e;
}

/// A printed solution: the equation (= 0) is 0 with the unknown replaced by the solution, the
/// definitions put in. Else an erratum corrected by the solution GiNaC finds when the equation is
/// linear in the unknown, or fails when it is not.
decider_evidence solves_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex solution = read.formula("solution"), equation = read.formula("equation");
  const GiNaC::symbol unknown = read.symbols("unknown").front();
  const std::string what = fmt::format("({}) = 0 at {} = ({})", reference_of(call, "equation"), unknown.get_name(), reference_of(call, "solution"));
  std::string correction;
  ex solved;
  try {
    solved = GiNaC::lsolve(equation == 0, unknown);
    if (!solved.has(unknown) && !(GiNaC::is_a<GiNaC::lst>(solved) && solved.nops() == 0)) {
      correction = fmt::format("as derived from ({}): {} = {}", reference_of(call, "equation"), unknown.get_name(), text_of(GiNaC::normal(solved)));
    }
  } catch (const std::exception&) {  // not linear in the unknown: no correction
  }
  if (const auto pole = vanishing_denominator(equation, {{unknown, solution}})) {
    return undefined_there(read, fmt::format("({}) at {} = ({})", reference_of(call, "equation"), unknown.get_name(), reference_of(call, "solution")), *pole);
  }
  decider_evidence e = identity_evidence(read, "solution", what, equation.subs(unknown == solution), 0, correction,
                                          correction.empty() ? verdict::fails : verdict::erratum);
  // What should stand where the solution is printed: the claims that read it are judged again with it.
  if (e.found_false() && !correction.empty()) e.found.corrected_formulas.push_back(read.correction_of("solution", GiNaC::normal(solved)));
  return e;
}

decider_evidence determinant_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex equals = read.formula("equals");
  const GiNaC::matrix m = as_square_matrix(read.formula("matrix"), reference_of(call, "matrix"));
  // As written (a d − b c for 2 × 2): the statement a certificate proves, not GiNaC's evaluated value.
  const ex det = m.rows() == 2 ? determinant_2x2(m) : m.determinant(GiNaC::determinant_algo::laplace);
  const std::string what = fmt::format("det ({}) = {}", reference_of(call, "matrix"), text_of(equals));
  // A property of the printed matrix: false, it fails (no corrected matrix is derived); the note
  // gives the determinant.
  decider_evidence e = identity_evidence(read, "determinant", what, det, equals, "", verdict::fails);
  if (e.found_false()) e.found.note += fmt::format(" det ({}) = {}.", reference_of(call, "matrix"), text_of(GiNaC::normal(det)));
  return e;
}

decider_evidence symplectic_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const GiNaC::matrix m = as_square_matrix(read.formula("matrix"), reference_of(call, "matrix"));
  if (m.rows() % 2 != 0) throw std::invalid_argument(reference_of(call, "matrix") + " has an odd dimension: no symplectic form");
  const GiNaC::matrix j = canonical_j(m.rows() / 2);
  const ex lhs = (m.transpose() * j * m).evalm();
  const std::string what = fmt::format("({})^T J ({}) = J", reference_of(call, "matrix"), reference_of(call, "matrix"));
  GiNaC::matrix normal = GiNaC::ex_to<GiNaC::matrix>(lhs);
  for (unsigned r = 0; r < normal.rows(); ++r) {
    for (unsigned c = 0; c < normal.cols(); ++c) normal(r, c) = GiNaC::normal(normal(r, c));
  }
  // A property of the printed matrix: false, it fails, the note giving M^T J M.
  decider_evidence e = identity_evidence(read, "symplectic", what, lhs, ex(j), "", verdict::fails);
  if (e.found_false()) e.found.note += fmt::format(" ({})^T J ({}) = {}.", reference_of(call, "matrix"), reference_of(call, "matrix"), text_of(normal));
  return e;
}

/// "This interpolation is not linear": whether a printed expression is linear in the variables, against
/// the sentence's word for it (hole {linearity}: linear, or not linear, nonlinear, non-linear). Linear
/// is one identity, e = Σ v_i × e(v = the i-th unit vector), decided in both kernels and in Coq; its
/// refutation proves the expression is not linear. Words that say otherwise are a wording erratum,
/// corrected by what the expression is.
/// The factors of `departure` (an expression's difference from the linear part it is compared with)
/// that vanish for some data: in its numerator, free of the `variables`, and neither a number nor a
/// product of powers of symbols declared positive. Where one vanishes the expression is linear after
/// all: "not linear" holds of the data in general, not of every datum.
std::vector<ex> vanishing_data_factors(const ex& departure, const std::vector<GiNaC::symbol>& variables, const std::set<std::string>& positive) {
  const auto positive_only = [&](const ex& f) {
    for (auto it = f.preorder_begin(); it != f.preorder_end(); ++it) {
      if (GiNaC::is_a<GiNaC::symbol>(*it) && !positive.count(GiNaC::ex_to<GiNaC::symbol>(*it).get_name())) return false;
      if (GiNaC::is_a<GiNaC::add>(*it)) return false;
    }
    return true;
  };
  std::vector<ex> found;
  const ex numerator = GiNaC::factor(GiNaC::numer(GiNaC::normal(departure)));
  std::vector<ex> factors;
  if (GiNaC::is_a<GiNaC::mul>(numerator)) {
    for (const ex& f : numerator) factors.push_back(f);
  } else {
    factors.push_back(numerator);
  }
  for (const ex& factor : factors) {
    const ex base = GiNaC::is_a<GiNaC::power>(factor) ? factor.op(0) : factor;
    if (GiNaC::is_a<GiNaC::numeric>(base) || positive_only(base)) continue;
    if (std::any_of(variables.begin(), variables.end(), [&](const GiNaC::symbol& v) { return base.has(v); })) continue;
    found.push_back(base);
  }
  return found;
}

decider_evidence linear_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex e = read.formula("expression");
  const std::vector<GiNaC::symbol> variables = read.symbols("variables");
  const quoted_sentence said = quote(ctx, call.with.at("sentence").values.front());
  const std::string stated = said.choice("linearity", hole_named("linearity").phrases);
  // "Linear" as the field reads it: of an equation in its unknowns, or of a function of a real
  // variable (an interpolation, a curve), affine (degree at most 1: "linear in q_{j+1}", "linear
  // interpolation"); of a map or a form, additive and homogeneous (the record says sense =
  // "homogeneous").
  const bool homogeneous = read.has("sense") && call.with.at("sense").values.front() == "homogeneous";
  const std::string sense = homogeneous ? "linear (homogeneous)" : "affine";
  ex combination = 0;
  std::vector<std::string> names, terms;
  std::string pole;  // a point where the expression has no value: not linear
  // Its values at a base point and at the base plus each unit vector, from its normal form where no
  // denominator of it vanishes: linearity is the function's, whatever the tree as read divides by on
  // the way. The base is the origin (homogeneous: its value there must be 0, so the origin itself is
  // not evaluated; affine: e(0)), or, affine, where the origin is a pole of the tree as written
  // (q_0^2 + q_1^2 over q_0 + q_1), the point of ones: an affine function is determined by any point.
  const ex normal = GiNaC::normal(e);
  GiNaC::exmap base;
  for (const GiNaC::symbol& v : variables) base[v] = 0;
  ex constant = 0;
  if (!homogeneous) {
    if (vanishing_denominator(normal, base)) {
      for (const GiNaC::symbol& v : variables) base[v] = 1;
      if (vanishing_denominator(normal, base)) pole = "the origin, every variable 0, and the point of ones";
    }
    if (pole.empty()) {
      constant = GiNaC::normal(normal.subs(base, GiNaC::subs_options::no_pattern));
      combination = constant;
      if (!constant.is_zero()) terms.push_back(text_of(constant));
    }
  }
  for (std::size_t i = 0; i < variables.size() && pole.empty(); ++i) {
    GiNaC::exmap unit = base;
    unit[variables[i]] = base[variables[i]] + 1;
    names.push_back(variables[i].get_name());
    if (vanishing_denominator(normal, unit)) {
      if (pole.empty()) pole = fmt::format("{} = {}, the others {}", variables[i].get_name(), text_of(unit[variables[i]]), text_of(base[variables[i]]));
      continue;
    }
    const ex coefficient = GiNaC::normal(normal.subs(unit, GiNaC::subs_options::no_pattern) - constant);
    const ex shifted = GiNaC::normal(variables[i] - base[variables[i]]);
    combination += shifted * coefficient;
    terms.push_back(fmt::format("{} ({})", text_of(shifted), text_of(coefficient)));
  }
  names.clear();
  for (const GiNaC::symbol& v : variables) names.push_back(v.get_name());
  const std::string expression_ref = reference_of(call, "expression");
  const std::string what = fmt::format("({}) is {} in {}: it is {}", expression_ref, sense, fmt::join(names, ", "), fmt::join(terms, " + "));
  decider_evidence judged;
  if (pole.empty()) {
    judged = identity_evidence(read, "linear", what, e, combination, "", verdict::fails);
  } else {
    judged.statement = what;
    judged.ginac = answer::fails;  // a pole: not linear
  }
  claim_result& result = judged.found;
  if (!pole.empty()) {
    result.printed = read.printed();
    result.evidence["exact"] = {{"statement", fmt::format("({}) is {} in {}", expression_ref, sense, fmt::join(names, ", "))},
                                {"ginac", "fails: it has no value at " + pole + " (a pole), where a linear function is defined"},
                                {"own", "not applicable: nothing to evaluate at a pole"}};
    result.certificate_missing = "a pole: no identity to state";
  }
  result.evidence["stated"] = said.words("linearity");
  result.evidence["sense"] = sense;
  if (judged.agreed() == answer::none) return judged;  // the kernels disagree
  const bool linear = judged.found_holds();
  const std::string computed = linear ? fmt::format("({}) is {} in {}: {} = {}", expression_ref, sense, fmt::join(names, ", "), text_of(GiNaC::normal(e)),
                                                    fmt::join(terms, " + "))
                      : !pole.empty() ? fmt::format("({}) is not {} in {}: it has no value at {}", expression_ref, sense, fmt::join(names, ", "), pole)
                                      : fmt::format("({}) is not {} in {}: it differs from {} by {}", expression_ref, sense, fmt::join(names, ", "),
                                                    fmt::join(terms, " + "), text_of(GiNaC::factor(normal_difference(e, combination))));
  result.note = result.note.empty() || linear ? "" : result.note;
  // The claim is the sentence's word: each kernel's answer on "not linear" is the denial of its
  // answer on "linear"; words that are false are an erratum, corrected by what the expression is.
  if (stated != "linear") {
    judged.ginac = negated(judged.ginac);
    judged.own = negated(judged.own);
    // Each kernel's line said of the denial the sentence makes: its "fails" on "linear" is a "holds".
    json& exact = result.evidence["exact"];
    for (const char* kernel : {"ginac", "own"}) {
      if (!exact.contains(kernel) || !exact[kernel].is_string()) continue;
      const std::string said = exact[kernel].get<std::string>();
      if (said.rfind("fails", 0) == 0) exact[kernel] = "holds (not " + sense + "): " + said.substr(said.find(':') == std::string::npos ? 5 : said.find(':') + 2);
      else if (said.rfind("holds", 0) == 0) exact[kernel] = "fails (it is " + sense + "): " + said.substr(said.find(':') == std::string::npos ? 5 : said.find(':') + 2);
    }
  }
  judged.if_false = verdict::erratum;
  if ((stated == "linear") == linear) {
    result.note = "As the sentence says: " + computed + ".";
    // Under its condition ("if h > 0"): what the expression is at the condition's boundary, where the
    // words would not hold.
    if (!linear && read.has("positive")) {
      const GiNaC::symbol s = read.symbols("positive").front();
      const ex at_zero = GiNaC::normal(normal.subs(s == 0));
      const ex at_zero_difference = GiNaC::normal(at_zero - GiNaC::normal(combination.subs(s == 0)));
      if (at_zero_difference.is_zero()) result.note += fmt::format(" At {} = 0 it is {}: the condition {} > 0 is what makes it not {}.", s.get_name(), sense, s.get_name(), sense);
    }
    // "Not linear" of data for which it is linear after all (a factor of the departure vanishes):
    // true of the data in general, as the field reads it, with the exception said in a remark.
    if (!linear && pole.empty()) {
      std::set<std::string> positive = call.declared ? call.declared->positive : std::set<std::string>{};
      if (read.has("positive")) {
        for (const GiNaC::symbol& p : read.symbols("positive")) positive.insert(p.get_name());
      }
      // Sorted by their text: GiNaC orders a product's factors by hash, which differs from run to run.
      std::vector<std::string> factors, exceptions;
      for (const ex& f : vanishing_data_factors(normal_difference(e, combination), variables, positive)) factors.push_back(text_of(f));
      std::sort(factors.begin(), factors.end());
      for (const std::string& f : factors) exceptions.push_back(f + " = 0");
      if (!exceptions.empty()) {
        result.remark_kind = finding::wording;
        result.remark = fmt::format("Not {} in {} for the data in general, as meant; {} where {}: the departure from {}, {}, has the factor{} {}.", sense,
                                    fmt::join(names, ", "), sense, fmt::join(exceptions, " or "),
                                    GiNaC::normal(combination).is_zero() ? std::string("0") : fmt::format("{}", fmt::join(terms, " + ")),
                                    [&] {  // each side's factors in canonical text, sorted (GiNaC orders a product by hash)
                                      const ex nd = GiNaC::normal(normal_difference(e, combination)).numer_denom();
                                      const auto factored = [](const ex& side) {
                                        const ex f = GiNaC::factor(side);
                                        std::vector<std::string> parts;
                                        if (GiNaC::is_a<GiNaC::mul>(f)) {
                                          for (const ex& part : f) parts.push_back(text_of(part));
                                        } else {
                                          parts.push_back(text_of(f));
                                        }
                                        std::sort(parts.begin(), parts.end());
                                        std::string out;
                                        for (const std::string& part : parts) {
                                          const bool bracket = parts.size() > 1 && part.find_first_of("+-") != std::string::npos && part.front() != '-';
                                          out += (out.empty() ? "" : "*") + (bracket ? "(" + part + ")" : part);
                                        }
                                        return out;
                                      };
                                      return "(" + factored(nd.op(0)) + ")/(" + factored(nd.op(1)) + ")";
                                    }(),
                                    factors.size() > 1 ? "s" : "", fmt::join(factors, ", "));
      }
    }
  } else {
    result.correction = computed;
    result.note = fmt::format("As printed, the sentence says '{}'.", said.words("linearity"));
    result.amendments.push_back(amendment_in_words("the sentence's words", said.words("linearity"), linear ? "linear" : "not linear"));
  }
  return judged;
}

/// The shapes of this file, each one's name, summary, principal argument and parameters beside the
/// function that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> identities_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  add({"identity", "lhs = rhs, the definitions put in", "rhs",
       with_where({{"lhs", argument_kind::formula, true, "a formula"}, {"rhs", argument_kind::formula, true, "the formula it equals"}}),
       identity_shape});
  add({"derivative", "d function / d variable = printed, the definitions put in", "printed",
       with_where({{"function", argument_kind::formula, true, "the formula differentiated"},
                   {"variable", argument_kind::symbols, true, "the symbol it is differentiated by", 1},
                   {"printed", argument_kind::formula, true, "the printed derivative"},
                   {"arguments", argument_kind::symbols, false, "the function's arguments, when the printed derivative is taken at others", 0, "",
                    false, {}, "", "", "at"},
                   {"at", argument_kind::symbols, false, "the values of the arguments in the printed derivative (q_j, q_{j+1} for q_l, q_r)", 0,
                    "arguments", false, {}, "", "", "arguments"}}),
       derivative_shape});
  add({"equal-sides", "every side of each printed equation is equal to its first, the definitions put in", "equations",
       with_where({{"equations", argument_kind::equations, true,
                    "printed equations 'a = b = ...', each read whole (a chain's first side, a symbol nothing defines, names what it defines)"}}),
       equal_sides_shape});
  add({"solves", "the equation (= 0) holds with the unknown replaced by the printed solution, the definitions put in", "solution",
       with_where({{"equation", argument_kind::formula, true, "the equation's side that is 0"},
                   {"unknown", argument_kind::symbols, true, "the symbol it is solved for", 1},
                   {"solution", argument_kind::formula, true, "the printed solution"}}),
       solves_shape});
  add({"determinant", "det matrix = equals", "equals",
       with_where({{"matrix", argument_kind::matrix, true, "a square matrix"}, {"equals", argument_kind::formula, true, "its determinant"}}),
       determinant_shape});
  add({"symplectic", "matrix^T J matrix = J, J = [[0, I], [-I, 0]]", "matrix",
       with_where({{"matrix", argument_kind::matrix, true, "a one-step map of (q, p)"}}), symplectic_shape});
  add({"linear", "the sentence's {linearity} (linear, or not linear) is what the expression is in the variables, as the field reads it: affine "
                 "(e = e(0) + sum of v_i (e(unit v_i) - e(0))) for an equation or a curve, homogeneous for a map or a form (sense)", "expression",
       with_where({{"expression", argument_kind::formula, true, "the printed expression"},
                   {"variables", argument_kind::symbols, true, "the variables it is linear in, or not"},
                   pattern_with_hole("sentence", "the sentence's pattern: the hole {linearity}, 'linear' or 'not linear'", "linearity"),
                   {"positive", argument_kind::symbols, false,
                    "the symbol the sentence's condition makes positive ('if h > 0'): the note says what the expression is where it is 0", 1},
                   {"sense", argument_kind::word, false,
                    "'affine' (the default: an equation in its unknowns, a function of a real variable such as an interpolation) or "
                    "'homogeneous' (a map or a form: additive and homogeneous)",
                    0, "", false, {"affine", "homogeneous"}}}),
       linear_shape});
  return all;
}

}  // namespace simpson::verify::detail

// The identity shapes (shape_support.hpp): identity, equal-sides, derivative, solves, determinant,
// symplectic, linear, conserved, proportional.

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

namespace {

GiNaC::matrix canonical_j(unsigned n) {
  GiNaC::matrix j(2 * n, 2 * n);
  for (unsigned k = 0; k < n; ++k) {
    j(k, n + k) = 1;
    j(n + k, k) = -1;
  }
  return j;
}

/// P with f = y^T P y when f is a quadratic form in y (P_ij = ∂²f/∂y_i∂y_j / 2, as written, not
/// normalised); whether f is one is the caller's to decide.
GiNaC::matrix form_matrix(const ex& f, const GiNaC::matrix& y) {
  const unsigned n = y.rows();
  GiNaC::matrix p(n, n);
  for (unsigned i = 0; i < n; ++i) {
    for (unsigned j = 0; j < n; ++j) p(i, j) = GiNaC::diff(GiNaC::diff(f, GiNaC::ex_to<GiNaC::symbol>(y(i, 0))), GiNaC::ex_to<GiNaC::symbol>(y(j, 0))) / 2;
  }
  return p;
}

/// The quadratic form y^T Q y that `m` conserves (Q symmetric, from the linear system m^T Q m = Q,
/// as Section 7 of the paper derives its Q_c) and that agrees with `printed`, a quadratic form in
/// `state`, in the coefficient of state[keep]^2 (else the first coefficient both have): none when the printed function is not a quadratic
/// form, or the map conserves no form or more than one family of them.
struct found_conserved_form {
  std::optional<ex> form;
  std::string why_none;  // when there is none
  std::string matched;   // the monomial whose coefficient the two share
};

found_conserved_form conserved_quadratic_form(const GiNaC::matrix& m, const std::vector<GiNaC::symbol>& state, const ex& printed, unsigned keep) {
  const unsigned n = m.rows();
  GiNaC::matrix q(n, n), y(n, 1);
  GiNaC::lst unknowns;
  for (unsigned i = 0; i < n; ++i) {
    y(i, 0) = state[i];
    for (unsigned j = i; j < n; ++j) {
      const GiNaC::symbol u("conserved_form_" + std::to_string(i) + std::to_string(j));
      unknowns.append(u);
      q(i, j) = q(j, i) = u;
    }
  }
  const GiNaC::matrix defect = GiNaC::ex_to<GiNaC::matrix>((m.transpose() * q * m - q).evalm());
  GiNaC::lst equations;
  for (unsigned i = 0; i < n; ++i) {
    for (unsigned j = i; j < n; ++j) equations.append(GiNaC::numer(GiNaC::normal(defect(i, j))) == 0);
  }
  GiNaC::ex solution;
  try {
    solution = GiNaC::lsolve(equations, unknowns);
  } catch (const std::exception& e) {
    return {std::nullopt, std::string("the linear system for the conserved forms does not solve: ") + e.what(), ""};
  }
  if (!GiNaC::is_a<GiNaC::lst>(solution) || solution.nops() == 0) return {std::nullopt, "the map conserves no quadratic form", ""};
  GiNaC::matrix family(n, n);
  std::vector<GiNaC::symbol> free;
  for (unsigned i = 0; i < n; ++i) {
    for (unsigned j = 0; j < n; ++j) family(i, j) = GiNaC::normal(q(i, j).subs(solution));
  }
  for (const ex& u : unknowns) {
    bool appears = false;
    for (unsigned k = 0; k < n * n; ++k) appears = appears || family(k / n, k % n).has(u);
    if (appears) free.push_back(GiNaC::ex_to<GiNaC::symbol>(u));
  }
  if (free.empty()) return {std::nullopt, "the map conserves no quadratic form but 0", ""};
  if (free.size() > 1) return {std::nullopt, "the map conserves " + std::to_string(free.size()) + " independent quadratic forms: no one correction", ""};
  // The printed function as y^T P y.
  GiNaC::matrix p = form_matrix(printed, y);
  for (unsigned k = 0; k < n * n; ++k) p(k / n, k % n) = GiNaC::normal(p(k / n, k % n));
  const ex as_form = ((y.transpose() * p * y).evalm()).op(0);
  if (!GiNaC::normal(printed - as_form).is_zero()) return {std::nullopt, "the printed function is not a quadratic form in the state", ""};
  // The coefficient of keep^2 first, then the others in the state's order.
  std::vector<std::pair<unsigned, unsigned>> order{{keep, keep}};
  for (unsigned i = 0; i < n; ++i) {
    for (unsigned j = i; j < n; ++j) {
      if (i != keep || j != keep) order.emplace_back(i, j);
    }
  }
  for (const auto& [i, j] : order) {
    {
      const ex unit = GiNaC::normal(family(i, j).subs(free[0] == 1));
      if (unit.is_zero() || GiNaC::normal(p(i, j)).is_zero()) continue;
      const ex scale = GiNaC::normal(p(i, j) / unit);
      GiNaC::matrix scaled(n, n);
      for (unsigned k = 0; k < n * n; ++k) scaled(k / n, k % n) = GiNaC::normal(family(k / n, k % n).subs(free[0] == scale));
      const ex form = GiNaC::normal(((y.transpose() * scaled * y).evalm()).op(0));
      return {form, "", text_of(i == j ? ex(GiNaC::pow(state[i], 2)) : ex(state[i] * state[j]))};
    }
  }
  return {std::nullopt, "the conserved forms and the printed function share no coefficient to scale by", ""};
}

/// Our kernel's decision of function(map y) = function(y) when the function is a quadratic form
/// y^T P y: then it holds exactly when map^T P map = P, which our kernel decides without the state's
/// symbols (its grid the map's alone), after deciding function = y^T P y itself. P is read off by
/// GiNaC (second derivatives), but both identities are our kernel's: a wrong P fails one of them.
/// None (our kernel then decides the statement as written) when the function is not such a form.
std::optional<kernel_decision> own_decision_as_forms(const GiNaC::matrix& m, const GiNaC::matrix& y, const ex& h) {
  const GiNaC::matrix p = form_matrix(h, y);
  const kernel_decision form = kernel_decides_zero(h - (y.transpose() * p * y).evalm().op(0));
  if (form.outcome != kernel_decision::result::zero) return std::nullopt;
  kernel_decision invariant = kernel_decides_zero((m.transpose() * p * m - p).evalm());
  invariant.evidence = "as quadratic forms: function = y^T P y (" + form.evidence + "); map^T P map = P (" + invariant.evidence + ")";
  return invariant;
}

/// e's coefficients as a polynomial in the state, each by its monomial's text (GiNaC's expansion;
/// the coefficients in normal form); none when e is not a polynomial in the state.
std::optional<std::map<std::string, std::pair<ex, ex>>> coefficients_in(const ex& e, const std::vector<GiNaC::symbol>& state) {
  const ex expanded = GiNaC::expand(e);
  GiNaC::lst variables;
  for (const GiNaC::symbol& s : state) variables.append(s);
  if (!expanded.is_polynomial(variables)) return std::nullopt;
  std::map<std::string, std::pair<ex, ex>> out;
  const auto add = [&](const ex& term) {
    ex monomial = 1;
    for (const GiNaC::symbol& s : state) monomial *= GiNaC::pow(s, term.degree(s));
    auto& entry = out.emplace(text_of(monomial), std::make_pair(monomial, ex(0))).first->second;
    entry.second += term / monomial;
  };
  if (GiNaC::is_a<GiNaC::add>(expanded)) {
    for (const ex& term : expanded) add(term);
  } else {
    add(expanded);
  }
  for (auto& entry : out) entry.second.second = GiNaC::normal(entry.second.second);
  return out;
}

}  // namespace

claim_result identity_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex rhs = read.formula("rhs"), lhs = read.formula("lhs");
  const std::string what = fmt::format("({}) = ({})", reference_of(call, "lhs"), reference_of(call, "rhs"));
  claim_result result = identity_verdict(call, read, "identity", what, lhs, rhs,
                                         fmt::format("as derived from ({}): ({}) = {}", reference_of(call, "lhs"), reference_of(call, "rhs"), text_of(lhs)));
  if (result.outcome == verdict::erratum) result.corrected_formulas.push_back(read.correction_of("rhs", lhs));
  return result;
}

/// Printed equations whose sides are all equal ("q(0) = q_l", "g_l = dq/dt(0) = (1/h)(...)"), the
/// definitions put in: each side against the equation's first, decided in both kernels, one Coq
/// goal each. A chain's first side that is a symbol nothing defines (g_l) names what the chain
/// defines and is not compared; the next one is then the reference. An erratum's correction gives
/// each side that differs as derived from the reference.
claim_result equal_sides_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  return equal_sides_verdict(call, read, read.equations("equations"), {}, "");
}

claim_result equal_sides_verdict(const shape_call& call, shape_reader& read, const std::vector<referenced_formula>& equations, const GiNaC::exmap& given,
                                 const std::string& given_text) {
  claim_result result;
  std::vector<proof_goal> goals;
  json decided_sides = json::array();
  std::vector<std::string> corrections, not_decided;
  bool any_false = false, disagree = false, own_any_nonzero = false;
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
      if (own_decided && (own.outcome == kernel_decision::result::zero) != ginac_zero) disagree = true;
      if (!own_decided) not_decided.push_back(what + " (" + own.evidence + ")");
      own_any_nonzero = own_any_nonzero || own.outcome == kernel_decision::result::nonzero;
      any_false = any_false || !ginac_zero;
      if (!ginac_zero) {
        corrections.push_back(fmt::format("{} = {}, not {}", folded_space(equation.sides[first]), text_of(GiNaC::normal(sides[first])),
                                          folded_space(equation.sides[k])));
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
  settle(result, disagree, !any_false, "a side", fmt::format("as derived from the definitions{}: {}", given_text, fmt::join(corrections, "; ")));
  if (result.outcome == verdict::erratum) result.note = fmt::format("As printed: {} side(s) differ from the first of their equation.", corrections.size());
  if (!not_decided.empty()) result.note += fmt::format("{}Our kernel could not decide {}: GiNaC's proof alone.", result.note.empty() ? "" : " ", fmt::join(not_decided, "; "));
  result.printed = read.printed();
  record_certificate(result, coq_certificate(call.claim_id, call.statement, goals));
  return result;
}

/// A printed partial derivative: d function / d variable = printed, the definitions put in both. The
/// derivative is GiNaC's (structural differentiation of the tree as read, an uninterpreted V
/// differentiated to V'); the identity with the printed one is decided in both kernels.
claim_result derivative_shape(const shape_call& call, const run_context& ctx) {
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
  claim_result result =
      identity_verdict(call, read, "derivative", what, derived, printed,
                       fmt::format("as derived: d({})/d{}{} = {}", reference_of(call, "function"), variable.get_name(), at, text_of(GiNaC::normal(derived))));
  // What should stand where the derivative is printed: the claims that read it are judged again with it.
  if (result.outcome == verdict::erratum) result.corrected_formulas.push_back(read.correction_of("printed", GiNaC::normal(derived)));
  return result;
}

/// A printed solution: the equation (= 0) is 0 with the unknown replaced by the solution, the
/// definitions put in. Else an erratum corrected by the solution GiNaC finds when the equation is
/// linear in the unknown, or fails when it is not.
claim_result solves_shape(const shape_call& call, const run_context& ctx) {
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
  claim_result result = identity_verdict(call, read, "solution", what, equation.subs(unknown == solution), 0, correction,
                                         correction.empty() ? verdict::fails : verdict::erratum);
  // What should stand where the solution is printed: the claims that read it are judged again with it.
  if (result.outcome == verdict::erratum) result.corrected_formulas.push_back(read.correction_of("solution", GiNaC::normal(solved)));
  return result;
}

claim_result determinant_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex equals = read.formula("equals");
  const GiNaC::matrix m = as_square_matrix(read.formula("matrix"), reference_of(call, "matrix"));
  // As written (a d − b c for 2 × 2): the statement a certificate proves, not GiNaC's evaluated value.
  const ex det = m.rows() == 2 ? determinant_2x2(m) : m.determinant(GiNaC::determinant_algo::laplace);
  const std::string what = fmt::format("det ({}) = {}", reference_of(call, "matrix"), text_of(equals));
  // A property of the printed matrix: false, it fails (no corrected matrix is derived); the note
  // gives the determinant.
  claim_result result = identity_verdict(call, read, "determinant", what, det, equals, "", verdict::fails);
  if (result.outcome == verdict::fails) {
    result.note += fmt::format(" det ({}) = {}.", reference_of(call, "matrix"), text_of(GiNaC::normal(det)));
  }
  return result;
}

claim_result symplectic_shape(const shape_call& call, const run_context& ctx) {
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
  claim_result result = identity_verdict(call, read, "symplectic", what, lhs, ex(j), "", verdict::fails);
  if (result.outcome == verdict::fails) {
    result.note += fmt::format(" ({})^T J ({}) = {}.", reference_of(call, "matrix"), reference_of(call, "matrix"), text_of(normal));
  }
  return result;
}

/// "This interpolation is not linear": whether a printed expression is linear in the variables, against
/// the sentence's word for it (hole {linearity}: linear, or not linear, nonlinear, non-linear). Linear
/// is one identity, e = Σ v_i × e(v = the i-th unit vector), decided in both kernels and in Coq; its
/// refutation proves the expression is not linear. Words that say otherwise are a wording erratum,
/// corrected by what the expression is.
claim_result linear_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex e = read.formula("expression");
  const std::vector<GiNaC::symbol> variables = read.symbols("variables");
  const quoted_sentence said = quote(ctx, call.with.at("sentence").values.front());
  const std::string stated = said.choice("linearity", hole_named("linearity").phrases);
  ex combination = 0;
  std::vector<std::string> names, terms;
  std::string pole;  // a unit vector where the expression has no value: not linear
  // Its value at each unit vector from its normal form, where no denominator of it vanishes there:
  // linearity is the function's, whatever the tree as read divides by on the way.
  const ex normal = GiNaC::normal(e);
  for (std::size_t i = 0; i < variables.size(); ++i) {
    GiNaC::exmap unit;
    for (std::size_t k = 0; k < variables.size(); ++k) unit[variables[k]] = k == i ? 1 : 0;
    names.push_back(variables[i].get_name());
    if (vanishing_denominator(normal, unit)) {
      if (pole.empty()) pole = fmt::format("{} = 1, the others 0", variables[i].get_name());
      continue;
    }
    const ex coefficient = GiNaC::normal(normal.subs(unit, GiNaC::subs_options::no_pattern));
    combination += variables[i] * coefficient;
    terms.push_back(fmt::format("{} ({})", variables[i].get_name(), text_of(coefficient)));
  }
  const std::string expression_ref = reference_of(call, "expression");
  const std::string what = fmt::format("({}) is linear in {}: it is {}", expression_ref, fmt::join(names, ", "), fmt::join(terms, " + "));
  claim_result result;
  if (pole.empty()) {
    result = identity_verdict(call, read, "linear", what, e, combination, "", verdict::fails);
  } else {
    result.outcome = verdict::fails;
    result.printed = read.printed();
    result.evidence["exact"] = {{"statement", fmt::format("({}) is linear in {}", expression_ref, fmt::join(names, ", "))},
                                {"ginac", "fails: it has no value at " + pole + " (a pole), where a linear function is defined"},
                                {"own", "not applicable: nothing to evaluate at a pole"}};
    result.certificate_missing = "a pole: no identity to state";
  }
  result.evidence["stated"] = said.words("linearity");
  if (result.outcome == verdict::kernels_disagree) return result;
  const bool linear = result.outcome == verdict::holds;
  const std::string computed = linear ? fmt::format("({}) is linear in {}: {} = {}", expression_ref, fmt::join(names, ", "), text_of(GiNaC::normal(e)),
                                                    fmt::join(terms, " + "))
                      : !pole.empty() ? fmt::format("({}) is not linear in {}: it has no value at {}", expression_ref, fmt::join(names, ", "), pole)
                                      : fmt::format("({}) is not linear in {}: it differs from {} by {}", expression_ref, fmt::join(names, ", "),
                                                    fmt::join(terms, " + "), text_of(normal_difference(e, combination)));
  result.note = result.note.empty() || linear ? "" : result.note;
  if ((stated == "linear") == linear) {
    result.outcome = verdict::holds;
    if (!linear) result.note = "As the sentence says: " + computed + ".";
  } else {
    result.outcome = verdict::erratum;
    result.correction = computed;
    // A wording erratum only where the words' weaker meaning holds (below); else the words are false.
    result.note = fmt::format("As printed, the sentence says '{}'.", said.words("linearity"));
    if (!linear || stated == "linear" || !read.has("positive")) {
      result.amendments.push_back(amendment_in_words("the sentence's words", said.words("linearity"), linear ? "linear" : "not linear"));
    }
    // What the words can mean under their condition ("if h > 0"): the expression is not its value at
    // h = 0 (GiNaC: the ratio of the two, in normal form).
    if (linear && stated != "linear" && read.has("positive")) {
      const GiNaC::symbol s = read.symbols("positive").front();
      const ex at_zero = GiNaC::normal(GiNaC::normal(e).subs(s == 0));
      if (!at_zero.is_zero() && !normal_difference(e, at_zero).is_zero()) {
        result.note = fmt::format("Wording: the sentence says '{}'.", said.words("linearity"));
        result.note += fmt::format(" What holds for {} > 0: ({}) is not its value at {} = 0, {}, but {} times it", s.get_name(), expression_ref,
                                   s.get_name(), text_of(at_zero), text_of(GiNaC::factor(GiNaC::normal(e / at_zero))));
        result.correction += fmt::format("; for {} > 0 it is not its value at {} = 0, {}, but {} times it", s.get_name(), s.get_name(),
                                         text_of(at_zero), text_of(GiNaC::factor(GiNaC::normal(e / at_zero))));
        result.evidence["positive"] = {{"at_zero", text_of(at_zero)}, {"ratio", text_of(GiNaC::factor(GiNaC::normal(e / at_zero)))}};
        result.amendments.push_back(amendment_in_words(
            "the sentence's words", said.words("linearity"),
            fmt::format("linear in {}, but for {} > 0 not its value at {} = 0: ${}$ times ${}$", fmt::join(names, ", "), s.get_name(), s.get_name(),
                        canonical_tex(GiNaC::factor(GiNaC::normal(e / at_zero))), canonical_tex(at_zero))));
      }
    }
  }
  return result;
}

claim_result conserved_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex h = read.formula("function");
  const GiNaC::matrix m = as_square_matrix(read.formula("map"), reference_of(call, "map"));
  const std::vector<GiNaC::symbol> state = read.symbols("state");
  if (state.size() != m.rows()) {
    throw std::invalid_argument(fmt::format("the state has {} symbols and the map {} rows", state.size(), m.rows()));
  }
  GiNaC::matrix y(m.rows(), 1);
  for (unsigned k = 0; k < m.rows(); ++k) y(k, 0) = state[k];
  const GiNaC::matrix next = GiNaC::ex_to<GiNaC::matrix>((m * y).evalm());
  GiNaC::lst step;
  for (unsigned k = 0; k < m.rows(); ++k) step.append(state[k] == next(k, 0));
  const ex after = h.subs(step);
  const std::string what = fmt::format("({})(({}) y) = ({})(y)", reference_of(call, "function"), reference_of(call, "map"), reference_of(call, "function"));
  claim_result result = identity_verdict(call, read, "conserved", what, after, h, "", verdict::erratum, own_decision_as_forms(m, y, h));
  if (result.outcome != verdict::erratum) return result;
  // Not conserved as printed: the correction is the map's conserved quadratic form, scaled to agree
  // with the printed function in one coefficient (proved conserved in GiNaC); without one, fails.
  unsigned keep = 0;
  if (read.has("keep")) {
    const GiNaC::symbol kept = read.symbols("keep").front();
    while (keep + 1 < state.size() && state[keep].get_name() != kept.get_name()) ++keep;  // one of them: checked at reading
  }
  const found_conserved_form corrected = conserved_quadratic_form(m, state, h, keep);
  const std::string change = fmt::format("({})(({}) y) − ({})(y) = {}", reference_of(call, "function"), reference_of(call, "map"),
                                         reference_of(call, "function"), text_of(GiNaC::normal(after - h)));
  if (!corrected.form || !GiNaC::normal(corrected.form->subs(step) - *corrected.form).is_zero()) {
    result.outcome = verdict::fails;
    result.correction.clear();
    result.note += " No correction: " + (corrected.form ? std::string("the form found is not conserved") : corrected.why_none) + " (" + change + ").";
    return result;
  }
  result.correction = fmt::format("the quadratic form ({}) conserves, with the coefficient of {} that ({}) prints: {}", reference_of(call, "map"),
                                  corrected.matched, reference_of(call, "function"), text_of(*corrected.form));
  result.evidence["corrected"] = {{"conserved_form", text_of(*corrected.form)},
                                  {"how", "Q symmetric solved from (map)^T Q (map) = Q (GiNaC lsolve), one family t Q_0, t set by the coefficient of " +
                                              corrected.matched + "; conserved: checked in normal form"}};
  return result;
}

/// printed = c × of with c free of the state and nonzero (H_d is Q_c "up to a multiplicative
/// constant"). GiNaC finds c as printed/of in normal form and that it is free of the state; our kernel
/// decides printed − c of = 0 on its grid, the state's symbols among its variables, so a c GiNaC got
/// wrong fails there. When there is no such c: with both polynomials in the state, the two
/// coefficients whose ratio differs from the first's, and our kernel decides that the 2 × 2
/// determinant of those coefficients is not zero; the correction is the multiple of `of` that keeps
/// printed's coefficient of the first monomial both have (an erratum), and without one it fails.
claim_result proportional_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex printed = read.formula("printed"), of = read.formula("of");
  const std::vector<GiNaC::symbol> state = read.symbols("state");
  std::vector<std::string> names;
  std::vector<ex> unknowns;
  for (const GiNaC::symbol& s : state) {
    names.push_back(s.get_name());
    unknowns.push_back(s);
  }
  const std::string what =
      fmt::format("({}) = c ({}), c nonzero and free of {}", reference_of(call, "printed"), reference_of(call, "of"), fmt::join(names, ", "));
  const std::optional<ex> factor = is_zero_expression(GiNaC::normal(of)) ? std::nullopt : equation_factor(of, printed, unknowns);
  if (factor) {
    claim_result result = identity_verdict(call, read, "proportional", what, printed, *factor * of, "", verdict::fails);
    result.evidence["exact"]["factor"] = text_of(*factor);
    if (result.outcome == verdict::holds) {
      result.evidence["exact"]["ginac"] = fmt::format("holds: ({})/({}) = {} in normal form, free of {}", reference_of(call, "printed"),
                                                      reference_of(call, "of"), text_of(*factor), fmt::join(names, ", "));
      result.note = (result.note.empty() ? "" : result.note + " ") + "c = " + text_of(*factor) + ".";
    }
    return result;
  }
  // No such c. Both polynomials in the state: two coefficients not in the ratio of the first's.
  claim_result result;
  result.printed = read.printed();
  const ex ratio = is_zero_expression(GiNaC::normal(of)) ? ex(0) : GiNaC::normal(printed / of);
  const auto p = coefficients_in(printed, state), o = coefficients_in(of, state);
  std::string first, other;
  if (p && o) {
    for (const auto& [monomial, coefficient] : *o) {
      const auto in_printed = p->find(monomial);
      if (!coefficient.second.is_zero() && in_printed != p->end() && !in_printed->second.second.is_zero()) {
        first = monomial;
        break;
      }
    }
  }
  kernel_decision own;
  own.evidence = "the two functions are not both polynomials in the state, or have no coefficient in common";
  if (!first.empty()) {
    std::set<std::string> monomials;
    for (const auto& entry : *p) monomials.insert(entry.first);
    for (const auto& entry : *o) monomials.insert(entry.first);
    const auto coefficient = [](const std::map<std::string, std::pair<ex, ex>>& of_one, const std::string& m) {
      const auto it = of_one.find(m);
      return it == of_one.end() ? ex(0) : it->second.second;
    };
    const ex p0 = coefficient(*p, first), o0 = coefficient(*o, first);
    for (const std::string& m : monomials) {
      const ex determinant = coefficient(*p, m) * o0 - p0 * coefficient(*o, m);
      if (m == first || GiNaC::normal(determinant).is_zero()) continue;
      other = m;
      own = kernel_decides_zero(determinant);
      own.evidence = fmt::format("the coefficients of {} and {}, (a, b) in ({}) and (c, d) in ({}): a d − b c ≠ 0 ({})", first, m,
                                 reference_of(call, "printed"), reference_of(call, "of"), own.evidence);
      break;
    }
  }
  const std::string ginac = fmt::format("fails: ({})/({}) = {}", reference_of(call, "printed"), reference_of(call, "of"), text_of(ratio)) +
                            (ratio.is_zero() ? "" : fmt::format(", not free of {}", fmt::join(names, ", ")));
  result.evidence["exact"] = {{"statement", what},
                              {"ginac", ginac},
                              {"own", (own.outcome == kernel_decision::result::zero      ? "holds: "
                                       : own.outcome == kernel_decision::result::nonzero ? "fails: "
                                                                                         : "not applicable: ") +
                                          own.evidence}};
  if (kernels_disagree_if(result, own.outcome == kernel_decision::result::zero, kernels_differ_on(what))) return result;
  result.note = "As printed: " + what + " is false; " + ginac.substr(7) + ".";
  if (own.outcome == kernel_decision::result::not_applicable) result.note += " Our kernel could not decide it (" + own.evidence + "): GiNaC's proof alone.";
  if (first.empty() || other.empty()) {
    result.outcome = verdict::fails;
    return result;
  }
  const ex c = GiNaC::normal(p->at(first).second / o->at(first).second);
  result.outcome = verdict::erratum;
  result.correction = fmt::format("the multiple of ({}) with the coefficient of {} that ({}) prints: {}", reference_of(call, "of"), first,
                                  reference_of(call, "printed"), text_of(GiNaC::normal(c * of)));
  result.evidence["corrected"] = {{"factor", text_of(c)}, {"multiple", text_of(GiNaC::normal(c * of))}};
  return result;
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
  add({"linear", "the sentence's {linearity} (linear, or not linear) is what the expression is in the variables: e = sum of v_i e(unit v_i)", "expression",
       with_where({{"expression", argument_kind::formula, true, "the printed expression"},
                   {"variables", argument_kind::symbols, true, "the variables it is linear in, or not"},
                   pattern_with_hole("sentence", "the sentence's pattern: the hole {linearity}, 'linear' or 'not linear'", "linearity"),
                   {"positive", argument_kind::symbols, false,
                    "the symbol the sentence's condition makes positive ('if h > 0'): a wording erratum then says what holds, that "
                    "for it > 0 the expression is not its value at 0",
                    1}}),
       linear_shape});
  add({"conserved", "function(map y) = function(y), y the state", "function",
       with_where({{"map", argument_kind::matrix, true, "a one-step map"},
                   {"function", argument_kind::formula, true, "a function of the state"},
                   {"state", argument_kind::symbols, true, "the state's symbols, in the map's order", 0, "map"},
                   {"keep", argument_kind::symbols, false,
                    "a state symbol whose square's coefficient a correction keeps as printed (the first of the state when left out)", 1, "",
                    false, {}, "state"}}),
       conserved_shape});
  add({"proportional", "printed = c of, c free of the state and nonzero", "printed",
       with_where({{"printed", argument_kind::formula, true, "a function of the state"},
                   {"of", argument_kind::formula, true, "the function it is a constant multiple of"},
                   {"state", argument_kind::symbols, true, "the symbols c must be free of"}}),
       proportional_shape});
  return all;
}

}  // namespace simpson::verify::detail

// The shapes of quadratic forms (shape_support.hpp): conserved (a function of the state kept by a
// one-step map) and proportional (one function a constant multiple of another).

#include <simpson/shapes/shape_support.hpp>

#include <simpson/prove/printed_check_support.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <map>
#include <optional>
#include <set>
#include <utility>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

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

decider_evidence conserved_shape(const shape_call& call, const run_context& ctx) {
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
  decider_evidence e = identity_evidence(read, "conserved", what, after, h, "", verdict::erratum, own_decision_as_forms(m, y, h));
  if (!e.found_false()) return e;
  claim_result& result = e.found;
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
    e.if_false = verdict::fails;
    result.correction.clear();
    result.note += " No correction: " + (corrected.form ? std::string("the form found is not conserved") : corrected.why_none) + " (" + change + ").";
    return e;
  }
  result.correction = fmt::format("the quadratic form ({}) conserves, with the coefficient of {} that ({}) prints: {}", reference_of(call, "map"),
                                  corrected.matched, reference_of(call, "function"), text_of(*corrected.form));
  result.evidence["corrected"] = {{"conserved_form", text_of(*corrected.form)},
                                  {"how", "Q symmetric solved from (map)^T Q (map) = Q (GiNaC lsolve), one family t Q_0, t set by the coefficient of " +
                                              corrected.matched + "; conserved: checked in normal form"}};
  return e;
}

/// printed = c × of with c free of the state and nonzero (H_d is Q_c "up to a multiplicative
/// constant"). GiNaC finds c as printed/of in normal form and that it is free of the state; our kernel
/// decides printed − c of = 0 on its grid, the state's symbols among its variables, so a c GiNaC got
/// wrong fails there. When there is no such c: with both polynomials in the state, the two
/// coefficients whose ratio differs from the first's, and our kernel decides that the 2 × 2
/// determinant of those coefficients is not zero; the correction is the multiple of `of` that keeps
/// printed's coefficient of the first monomial both have (an erratum), and without one it fails.
decider_evidence proportional_shape(const shape_call& call, const run_context& ctx) {
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
    decider_evidence e = identity_evidence(read, "proportional", what, printed, *factor * of, "", verdict::fails);
    claim_result& result = e.found;
    result.evidence["exact"]["factor"] = text_of(*factor);
    if (e.found_holds()) {
      result.evidence["exact"]["ginac"] = fmt::format("holds: ({})/({}) = {} in normal form, free of {}", reference_of(call, "printed"),
                                                      reference_of(call, "of"), text_of(*factor), fmt::join(names, ", "));
      result.note = (result.note.empty() ? "" : result.note + " ") +
                    fmt::format("({}) = c ({}) with c = {}.", reference_of(call, "printed"), reference_of(call, "of"), text_of(*factor));
    }
    return e;
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
  // Our kernel decided a d − b c ≠ 0: its "zero" would make the coefficients proportional after all.
  decider_evidence e;
  e.statement = what;
  e.ginac = answer::fails;
  e.own = answer_of(own);
  result.note = "As printed: " + what + " is false; " + ginac.substr(7) + ".";
  if (own.outcome == kernel_decision::result::not_applicable) result.note += " Our kernel could not decide it (" + own.evidence + "): GiNaC's proof alone.";
  if (first.empty() || other.empty()) {
    e.if_false = verdict::fails;
    e.found = std::move(result);
    return e;
  }
  const ex c = GiNaC::normal(p->at(first).second / o->at(first).second);
  result.correction = fmt::format("the multiple of ({}) with the coefficient of {} that ({}) prints: {}", reference_of(call, "of"), first,
                                  reference_of(call, "printed"), text_of(GiNaC::normal(c * of)));
  result.evidence["corrected"] = {{"factor", text_of(c)}, {"multiple", text_of(GiNaC::normal(c * of))}};
  e.found = std::move(result);
  return e;
}
/// The shapes of this file, each one's name, summary, principal argument and parameters beside the
/// function that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> forms_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
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

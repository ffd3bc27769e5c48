// What the proof shapes share: see shape_support.hpp.

#include <simpson/shapes/shape_support.hpp>

#include <simpson/verify/formula_reference.hpp>

#include <simpson/prove/coq_export.hpp>
#include <simpson/prove/decide.hpp>
#include <simpson/prove/kernel_zero.hpp>
#include <simpson/prove/printed_check_support.hpp>

#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/quoted_words.hpp>
#include <simpson/verify/readable_math.hpp>
#include <simpson/verify/tex_math.hpp>

#include <fmt/format.h>

#include <sstream>

#include <algorithm>
#include <iterator>
#include <set>

namespace simpson::verify::detail {

using GiNaC::ex;

/// The symbol a TeX name reads as ('q_0', '\omega', 'q_{j+1}'); throws std::invalid_argument.
GiNaC::symbol symbol_named(const std::string& tex) { return paper_symbols()[reader_name(tex)]; }

/// The GiNaC names of the symbols a file declares.
std::set<std::string> declared_names(const claim_declarations& d) {
  std::set<std::string> names = d.reading.symbols;
  names.insert(d.reading.functions.begin(), d.reading.functions.end());
  return names;
}

shape_reader::shape_reader(const shape_call& call, const tex_document& document) : call_(call), document_(document) {
  if (call.declared->complete) declared_ = declared_names(*call.declared);
  const auto where = call.with.find("where");
  if (where != call.with.end()) {
    for (const std::string& reference : where->second.values) {
      definitions_.push_back(read_definition(document_, reading(), reference));
      if (call.corrections) {  // a definition whose display a proved correction replaces: its value corrected
        const std::string identity = read_reference(document_, reading(), reference).identity;
        for (const auto& c : call.corrections->corrected) {
          if (c->identity != identity) continue;
          definitions_.back().value = c->value;
          corrected_ = true;
        }
      }
      const definition& d = definitions_.back();
      definitions_read_.push_back({{"reference", reference},
                                   {"label", d.locator + ", put in"},
                                   {"line", d.line},
                                   {"tex", folded_space(d.tex)},
                                   {"parsed", json::array({text_of(d.name) + " = " + text_of(d.value)})}});
    }
  }
  const auto entries = call.with.find("entries");
  if (entries != call.with.end()) read_entries(entries->second.values);
  // A symbol a definition defines is declared by it (Phi = (map)); what it is defined as must be declared.
  for (const definition& d : definitions_) {
    declared_.insert(d.name.get_name());
    for (int k = 1; d.parameter && k <= 4; ++k) declared_.insert(derivative_name(d.function, d.parameter->get_name(), k, k));  // dq/dt, q(t) defined
  }
  for (const definition& d : definitions_) {  // a function's own variables (L(q, \dot q) = ...) are bound in its value
    GiNaC::exmap bound;
    if (d.parameter) bound[*d.parameter] = 0;
    for (const GiNaC::symbol& p : d.parameters) bound[p] = 0;
    declared_only(bound.empty() ? d.value : d.value.subs(bound), d.locator);
  }
  (void)with_definitions(GiNaC::ex(0), definitions_);  // each function read in its argument, or refused now, before anything runs
}

/// A generic matrix printed with a symbol for each entry (Φ = (α β; γ δ)) named for the entries of
/// another printed matrix: each symbol is defined as its entry there, the `where` definitions put in.
void shape_reader::read_entries(const std::vector<std::string>& references) {
  const auto fail = [](const std::string& what) { throw argument_error("entries", what); };
  if (references.size() != 2) {
    fail(fmt::format("{} references, not 2: a printed matrix of symbols, then the matrix whose entries they name", references.size()));
  }
  referenced_formula names_read, values_read;
  ex names, values;
  try {
    names_read = read_reference(document_, reading(), references[0]);
    values_read = read_reference(document_, reading(), references[1]);
    names = names_read.value.evalm();
    values = with_definitions(values_read.value, definitions_).evalm();
  } catch (const document_error&) {
    throw;
  } catch (const std::invalid_argument& e) {
    fail(e.what());
  }
  if (!GiNaC::is_a<GiNaC::matrix>(names)) fail(names_read.locator + " is not a matrix");
  if (!GiNaC::is_a<GiNaC::matrix>(values)) fail(values_read.locator + " is not a matrix");
  const GiNaC::matrix& n = GiNaC::ex_to<GiNaC::matrix>(names);
  const GiNaC::matrix& v = GiNaC::ex_to<GiNaC::matrix>(values);
  if (n.rows() != v.rows() || n.cols() != v.cols()) {
    fail(fmt::format("{} is {} x {} and {} is {} x {}", names_read.locator, n.rows(), n.cols(), values_read.locator, v.rows(), v.cols()));
  }
  json parsed = json::array();
  std::set<std::string> named;
  for (unsigned r = 0; r < n.rows(); ++r) {
    for (unsigned c = 0; c < n.cols(); ++c) {
      if (!GiNaC::is_a<GiNaC::symbol>(n(r, c))) {
        fail(fmt::format("{}: the entry ({}, {}), {}, is not one symbol", names_read.locator, r + 1, c + 1, text_of(n(r, c))));
      }
      const GiNaC::symbol& name = GiNaC::ex_to<GiNaC::symbol>(n(r, c));
      if (!named.insert(name.get_name()).second) fail(fmt::format("{}: the symbol {} names two entries", names_read.locator, name.get_name()));
      definitions_.push_back({name, v(r, c), fmt::format("{}, entry ({}, {}) of {}", names_read.locator, r + 1, c + 1, values_read.place),
                              names_read.line, names_read.tex});
      parsed.push_back(text_of(name) + " = " + text_of(v(r, c)));
    }
  }
  definitions_read_.push_back({{"reference", references[0] + " entries of " + references[1]},
                               {"label", names_read.place + ", its entries those of " + values_read.locator + ", put in"},
                               {"line", names_read.line},
                               {"tex", folded_space(names_read.tex)},
                               {"parsed", parsed}});
}

ex shape_reader::formula(const std::string& parameter) {
  const referenced_formula f = raw(parameter);
  return with_definitions(f.value, definitions_);
}

referenced_formula shape_reader::corrected(referenced_formula f) const {
  if (!call_.corrections) return f;
  for (const auto& c : call_.corrections->corrected) {
    if (c->identity != f.identity) continue;
    f.value = c->value;
    corrected_ = true;
  }
  return f;
}

const std::string& shape_reader::identity_of(const std::string& parameter) const {
  const auto it = identities_.find(parameter);
  if (it == identities_.end()) throw std::logic_error("identity_of: the argument '" + parameter + "' was never read");
  return it->second;
}

namespace {

/// A corrected formula named as a reader of the document names it: (label), or the display or
/// formula at its phrase.
std::shared_ptr<const corrected_formula> named_correction(const std::string& identity, const GiNaC::ex& value) {
  const std::string place = identity.substr(0, identity.rfind('#'));
  std::string shown = place;
  if (place.rfind("label ", 0) == 0) shown = "(" + place.substr(6) + ")";
  if (place.rfind("anchor ", 0) == 0) shown = "the display after " + place.substr(7);
  if (place.rfind("inline formula at ", 0) == 0) shown = "the formula at " + place.substr(18);
  return std::make_shared<const corrected_formula>(corrected_formula{identity, shown, value});
}

}  // namespace

std::shared_ptr<const corrected_formula> shape_reader::correction_of(const std::string& parameter, const GiNaC::ex& value) const {
  return named_correction(identity_of(parameter), value);
}

std::shared_ptr<const corrected_formula> shape_reader::correction_of_side(const referenced_formula& equation, std::size_t k, const GiNaC::ex& value) const {
  // The identity sides() looks for when the call is judged again with it.
  const std::string stem = equation.identity.substr(0, equation.identity.rfind(":side"));
  return named_correction(stem + ":side" + std::to_string(k + 1), value);
}

referenced_formula shape_reader::raw(const std::string& parameter) {
  const std::string& reference = call_.with.at(parameter).values.front();
  referenced_formula f = corrected(read_reference(document_, reading(), reference));
  identities_[parameter] = f.identity;
  declared_only(f.value, f.locator);
  // Shown with its matrix products multiplied out (1/(1 + x) times a matrix, as printed), unless a
  // definition is still to make one of its symbols a matrix.
  GiNaC::ex shown = f.value;
  const bool defines_a_matrix =
      std::any_of(definitions_.begin(), definitions_.end(), [](const definition& d) { return GiNaC::is_a<GiNaC::matrix>(d.value.evalm()); });
  if (!defines_a_matrix) {
    try {
      shown = with_definitions(f.value, {});
    } catch (const std::exception&) {
    }
  }
  record(reference, f.place, f.line, f.tex, shown);
  return f;
}

std::vector<GiNaC::symbol> shape_reader::symbols(const std::string& parameter) const {
  std::vector<GiNaC::symbol> out;
  for (const std::string& tex : call_.with.at(parameter).values) {
    out.push_back(symbol_named(tex));
    declared_only(out.back(), "'" + tex + "'");
  }
  return out;
}

std::vector<referenced_formula> shape_reader::equations(const std::string& parameter) {
  std::vector<referenced_formula> out;
  for (const std::string& reference : call_.with.at(parameter).values) {
    out.push_back(read_reference(document_, reading(), reference));
    const referenced_formula& f = out.back();
    json parsed = json::array();
    for (std::size_t k = 0; k < f.sides.size(); ++k) parsed.push_back(text_of(parsed_side(f, k)));
    json entry = {{"reference", reference}, {"label", f.place}, {"line", f.line}, {"tex", folded_space(f.tex)}, {"parsed", parsed}};
    if (f.line >= 1 && std::find(read_.begin(), read_.end(), entry) == read_.end()) read_.push_back(entry);
  }
  return out;
}

ex shape_reader::parsed_side(const referenced_formula& equation, std::size_t k) const {
  const ex side = read_side(equation, k, reading());
  // A chain's first side, one symbol, may be the name the chain defines (g = dq/dt(0) = ...).
  const bool named = equation.sides.size() > 2 && k == 0 && GiNaC::is_a<GiNaC::symbol>(side);
  if (!named) declared_only(side, equation.locator);
  return side;
}

std::vector<ex> shape_reader::sides(const referenced_formula& equation) const {
  std::vector<ex> out;
  // A side a proved correction replaces, when the call is judged again with it: its value corrected.
  const std::string stem = equation.identity.substr(0, equation.identity.rfind(":side"));
  for (std::size_t k = 0; k < equation.sides.size(); ++k) {
    ex side = parsed_side(equation, k);
    if (call_.corrections) {
      for (const auto& c : call_.corrections->corrected) {
        if (c->identity != stem + ":side" + std::to_string(k + 1)) continue;
        side = c->value;
        corrected_ = true;
      }
    }
    out.push_back(with_definitions(side, definitions_));
  }
  return out;
}

bool shape_reader::defines(const GiNaC::symbol& name) const {
  return std::any_of(definitions_.begin(), definitions_.end(), [&](const definition& d) { return d.name.get_name() == name.get_name(); });
}

json shape_reader::printed() const {
  json all = read_;
  for (const json& d : definitions_read_) all.push_back(d);
  json out = {{"source", document_.origin()}, {"formulas", all}};
  if (corrected_) out["corrected"] = true;  // a correction was read in place of a printed formula (consequences.hpp)
  return out;
}

void shape_reader::declared_only(const ex& e, const std::string& where) const {
  if (!call_.declared->complete) return;
  std::set<std::string> bound;  // an integral's variable and a sum's index: bound in it, not symbols of the document
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::integral>(*it)) bound.insert(GiNaC::ex_to<GiNaC::symbol>(it->op(0)).get_name());
    if (is_sum(*it) && GiNaC::is_a<GiNaC::symbol>(it->op(1))) bound.insert(GiNaC::ex_to<GiNaC::symbol>(it->op(1)).get_name());
  }
  // A derivative of a declared symbol, d^kx/dt^k (the state's, in a differential equation), is declared.
  const auto derivative_of_declared = [&](const std::string& name) {
    const std::size_t slash = name.find("/d");
    if (name.size() < 4 || name[0] != 'd' || slash == std::string::npos) return false;
    std::size_t from = 1;
    if (name[1] == '^') from = name.find_first_not_of("0123456789", 2);
    return from != std::string::npos && from < slash && declared_.count(name.substr(from, slash - from)) > 0;
  };
  for (const std::string& name : symbol_names(e)) {
    if (!declared_.count(name) && !bound.count(name) && !derivative_of_declared(name)) {
      // dL_d/dq_n: a derivative of something the document defines, read from its definition in 'where'.
      const std::size_t slash = name.find("/d");
      if (name.size() > 3 && name[0] == 'd' && name[1] != '^' && slash != std::string::npos && slash > 1) {
        const std::string of = name.substr(1, slash - 1), by = name.substr(slash + 2);
        throw std::invalid_argument(where + ": the derivative '" + name + "' of " + of + " by " + by + ": " + of +
                                    " is neither declared nor defined; put the label of its definition (" + of + " = ...) in 'where', "
                                    "or declare " + of + " under functions with its variables (" + of + "(a, b)) and write its partial derivative at a point");
      }
      throw std::invalid_argument(where + ": the symbol '" + name + "' is not declared in [symbols] (declare it under positive or real; "
                                  "or under functions if the document applies it, " + name + "(x))");
    }
  }
}

void shape_reader::record(const std::string& reference, const std::string& locator, int line, const std::string& tex,
                          const std::optional<ex>& value) {
  if (line < 1) return;  // the record's own TeX ('$\omega h$'): not read from the document
  json entry = {{"reference", reference}, {"label", locator}, {"line", line}};
  if (!tex.empty()) entry["tex"] = folded_space(tex);
  if (value) entry["parsed"] = json::array({text_of(*value)});
  for (const json& seen : read_) {
    if (seen == entry) return;
  }
  read_.push_back(entry);
}

const tex_document& document_of(const run_context& ctx) {
  // The run's document, passed as a value (a note's run always has one: its claims file's
  // [document] requires --paper).
  const paper_reading& reading = paper_of(ctx);
  if (!reading.document) throw std::logic_error("the run's paper (" + reading.origin + ") was never read as TeX");  // a harness fault
  return *reading.document;
}

std::optional<std::string> vanishing_denominator(const ex& e, const GiNaC::exmap& values) {
  for (auto it = e.postorder_begin(); it != e.postorder_end(); ++it) {
    if (!GiNaC::is_a<GiNaC::power>(*it) || !it->op(1).info(GiNaC::info_flags::negative)) continue;
    // The inner denominators of the base are not 0 (postorder: checked before it), so this cannot throw.
    if (GiNaC::normal(it->op(0).subs(values, GiNaC::subs_options::no_pattern)).is_zero()) return text_of(it->op(0));
  }
  return std::nullopt;
}

decider_evidence undefined_there(shape_reader& read, const std::string& what, const std::string& pole) {
  decider_evidence e;
  e.statement = what;
  e.ginac = answer::fails;  // undefined: neither true nor correctable
  e.if_false = verdict::fails;
  e.found.printed = read.printed();
  e.found.note = fmt::format("As printed: {} is undefined: the denominator {} is 0 there.", what, pole);
  e.found.evidence["exact"] = {{"statement", what}, {"ginac", "fails: the denominator " + pole + " is 0 there"}, {"own", "not applicable: undefined"}};
  e.found.certificate_missing = "undefined there: no identity to state";
  return e;
}

decider_evidence identity_evidence(shape_reader& read, const std::string& goal, const std::string& what, const ex& lhs, const ex& rhs,
                                   const std::string& correction, verdict when_false, const std::optional<kernel_decision>& given) {
  decider_evidence e;
  claim_result& result = e.found;
  const ex difference = normal_difference(lhs, rhs);
  const bool ginac_zero = is_zero_expression(difference);
  const kernel_decision own = given ? *given : kernel_decides_zero((lhs - rhs).evalm());
  result.evidence["exact"] = {
      {"statement", what},
      {"ginac", ginac_zero ? "holds: lhs − rhs = 0 (normal form, every symbol free)" : "fails: lhs − rhs = " + text_of(difference) + " ≠ 0"},
      {"own", (own.outcome == kernel_decision::result::zero      ? "holds: "
               : own.outcome == kernel_decision::result::nonzero ? "fails: "
                                                                 : "not applicable: ") +
                  own.evidence}};
  e.statement = what;
  e.ginac = answer_of(ginac_zero);
  e.own = answer_of(own);
  e.if_false = when_false;
  const bool own_decided = own.outcome != kernel_decision::result::not_applicable;
  if (ginac_zero) {
    if (!own_decided) result.note = "Our kernel could not decide it (" + own.evidence + "): GiNaC's proof alone.";
  } else {
    result.correction = correction;
    // The difference in the note when a reader can take it in; a long one (a 600-character
    // polynomial) goes to the evidence, and the note says where.
    const std::string shown = text_of(lhs) + " − (" + text_of(rhs) + ") = " + text_of(difference) + " ≠ 0";
    if (shown.size() <= 240) {
      result.note = "As printed: " + what + " is false; " + shown + ".";
    } else {
      result.note = "As printed: " + what + " is false: the two sides differ (lhs − rhs in the evidence, exact.difference).";
      result.evidence["exact"]["difference"] = shown;
    }
    if (!own_decided) result.note += " Our kernel could not decide it (" + own.evidence + "): GiNaC's proof alone.";
  }
  result.printed = read.printed();
  e.goals = std::vector<proof_goal>{decided(goal, lhs, rhs)};
  return e;
}

decider_evidence settled(claim_result found, answer ginac, answer own, const std::string& what, const std::string& correction) {
  decider_evidence e;
  e.found = std::move(found);
  e.statement = what;
  e.ginac = ginac;
  e.own = own;
  if (ginac == answer::fails) e.found.correction = correction;
  return e;
}

namespace {

std::set<std::string> symbol_names(const ex& e) {
  std::set<std::string> names;
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::symbol>(*it)) names.insert(GiNaC::ex_to<GiNaC::symbol>(*it).get_name());
  }
  return names;
}

std::optional<GiNaC::symbol> symbol_named(const ex& e, const std::string& name) {
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::symbol>(*it) && GiNaC::ex_to<GiNaC::symbol>(*it).get_name() == name) return GiNaC::ex_to<GiNaC::symbol>(*it);
  }
  return std::nullopt;
}

}  // namespace

std::optional<amendment> amendment_between(const std::string& where, const ex& printed, const ex& derived) {
  if (GiNaC::normal(printed - derived).is_zero()) return std::nullopt;
  const std::set<std::string> in_printed = symbol_names(printed), in_derived = symbol_names(derived);
  std::vector<std::string> only_printed, only_derived;
  std::set_difference(in_printed.begin(), in_printed.end(), in_derived.begin(), in_derived.end(), std::back_inserter(only_printed));
  std::set_difference(in_derived.begin(), in_derived.end(), in_printed.begin(), in_printed.end(), std::back_inserter(only_derived));
  // One symbol for another in a term of several (d^6q/dt^5 h^6/720): the symbol; in an expression
  // of that one symbol ((gamma^2 - 1)/2), the whole expression, which is as short.
  const std::string printed_tex = canonical_tex(printed), derived_tex = canonical_tex(derived);
  if (only_printed.size() == 1 && only_derived.size() == 1 && in_printed.size() > 1) {
    const GiNaC::symbol a = *symbol_named(printed, only_printed.front()), b = *symbol_named(derived, only_derived.front());
    if (GiNaC::normal(printed.subs(a == b, GiNaC::subs_options::no_pattern) - derived).is_zero()) {
      return amendment{where, canonical_tex(a), canonical_tex(b)};
    }
  }
  if (!printed.is_zero() && printed_tex.size() > 40) {  // a long expression off by a factor: the factor (a short one is shown whole)
    const ex ratio = GiNaC::normal(derived / printed);
    if (GiNaC::is_a<GiNaC::numeric>(ratio)) return amendment{where, printed_tex, canonical_tex(ratio) + " \\times \\text{the printed}"};
  }
  return amendment{where, printed_tex, derived_tex};
}

amendment amendment_in_words(const std::string& where, const std::string& printed, const std::string& should_be) {
  return amendment{where, printed, readable_math(should_be), false};
}

GiNaC::matrix as_square_matrix(const ex& e, const std::string& what) {
  const ex m = e.evalm();
  if (!GiNaC::is_a<GiNaC::matrix>(m)) throw std::invalid_argument(what + " is not a matrix");
  const GiNaC::matrix& out = GiNaC::ex_to<GiNaC::matrix>(m);
  if (out.rows() != out.cols()) throw std::invalid_argument(what + " is not square");
  return out;
}

std::optional<three_term_coefficients> linear_three_term(const ex& scheme, const std::vector<GiNaC::symbol>& q) {
  const three_term_coefficients c{GiNaC::diff(scheme, q[0]), GiNaC::diff(scheme, q[1]), GiNaC::diff(scheme, q[2])};
  if (!GiNaC::normal(scheme - (c.previous * q[0] + c.current * q[1] + c.next * q[2])).is_zero()) return std::nullopt;
  for (const GiNaC::symbol& state : q) {
    for (const ex& coefficient : {c.previous, c.current, c.next}) {
      if (GiNaC::normal(coefficient).has(state)) return std::nullopt;
    }
  }
  return c;
}

bool reversible(const three_term_coefficients& terms, kernel_decision& own) {
  own = kernel_decides_zero(terms.next - terms.previous);
  return GiNaC::normal(terms.next - terms.previous).is_zero() && own.outcome != kernel_decision::result::nonzero;
}

ex monic_discriminant(const three_term_coefficients& terms) {
  return GiNaC::normal((terms.current * terms.current - 4 * terms.previous * terms.next) / (terms.next * terms.next));
}

std::optional<GiNaC::numeric> index_offset(const std::string& name, const std::string& index) {
  const std::size_t bar = name.find('_');
  if (bar == std::string::npos || bar == 0 || name.compare(bar + 1, index.size(), index) != 0) return std::nullopt;
  const std::string rest = name.substr(bar + 1 + index.size());
  if (rest.empty()) return GiNaC::numeric(0);
  const std::string digits = rest.substr(1);
  if ((rest[0] != '+' && rest[0] != '-') || digits.empty() || digits.find_first_not_of("0123456789/") != std::string::npos ||
      digits.front() == '/' || digits.back() == '/') {
    return std::nullopt;
  }
  const GiNaC::numeric k(digits.c_str());
  return rest[0] == '-' ? -k : k;
}

bool applies(const ex& e, const std::string& base) {
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (is_reader_function(*it) && GiNaC::ex_to<GiNaC::function>(*it).get_name() == base) return true;
  }
  return false;
}

ex solution_at_nodes(const ex& e, const claim_declarations& declared, const std::string& base, const std::string& index, const GiNaC::symbol& h,
                     const std::string& parameter) {
  if (!applies(e, base)) return e;
  if (!declared.solutions.count(base)) {
    throw argument_error(parameter, fmt::format("{0}(t_{1}) is read, but nothing says which {0} it is: when {0}(t) is the exact solution, declare it "
                                                "([symbols] solutions = ['{0}'], docs/claims-file.md); when it is the scheme's value at the node, "
                                                "write {0}_{1}",
                                                base, index));
  }
  GiNaC::exmap at_nodes;
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (!is_reader_function(*it) || GiNaC::ex_to<GiNaC::function>(*it).get_name() != base) continue;
    const ex& application = *it;
    const std::string shown = text_of(application);
    if (application.nops() != 1) throw argument_error(parameter, fmt::format("{} applies the solution {} to {} arguments, not to a node", shown, base, application.nops()));
    const ex argument = GiNaC::expand(application.op(0));
    // t_{n+m} + c h: one node symbol, the rest a rational multiple of the step.
    std::optional<GiNaC::numeric> offset;
    ex rest = argument;
    for (const std::string& name : symbol_names(argument)) {
      const std::optional<GiNaC::numeric> m = name.rfind("t_", 0) == 0 ? index_offset(name, index) : std::nullopt;
      if (!m) continue;
      if (offset || argument.degree(paper_symbols()[name]) != 1 || !argument.coeff(paper_symbols()[name], 1).is_equal(1)) {
        offset.reset();
        break;
      }
      offset = *m;
      rest = GiNaC::expand(argument - paper_symbols()[name]);
    }
    const ex c = GiNaC::normal(rest / h);
    if (!offset || !GiNaC::is_a<GiNaC::numeric>(c) || !GiNaC::ex_to<GiNaC::numeric>(c).is_rational()) {
      throw argument_error(parameter, fmt::format("{} is the solution {} at {}, which is no node t_{} + k h", shown, base, text_of(argument), index));
    }
    const GiNaC::numeric k = *offset + GiNaC::ex_to<GiNaC::numeric>(c);
    std::ostringstream digits_stream;
    digits_stream << GiNaC::abs(k);
    const std::string digits = digits_stream.str();
    const std::string state = base + "_" + index + (k.is_zero() ? std::string() : (k.is_positive() ? "+" : "-") + digits);
    at_nodes[application] = paper_symbols()[state];
  }
  return e.subs(at_nodes, GiNaC::subs_options::no_pattern);
}

std::string reference_of(const shape_call& call, const std::string& parameter) {
  // A reference as a reader names it, not in the claims file's syntax: "Phi3", "Phi3, equation 2,
  // left side", "the formula at 'The discriminant'", "the display after 'with a matrix'".
  const std::string& text = call.with.at(parameter).values.front();
  formula_reference r;
  try {
    r = parse_reference(text);
  } catch (const std::invalid_argument&) {
    return text;
  }
  std::string out;
  switch (r.where) {
    case formula_reference::kind::labelled: out = r.key; break;
    case formula_reference::kind::inline_formula: out = "the formula at '" + r.key + "'"; break;
    case formula_reference::kind::display_after: out = "the display after '" + r.key + "'"; break;
    case formula_reference::kind::literal: return text;
  }
  if (r.equation > 1) out += ", equation " + std::to_string(r.equation);
  if (r.side == 1) out += ", left side";
  else if (r.side > 1) out += ", side " + std::to_string(r.side);
  return out;
}

// The parameters the shapes' specs share (shape_support.hpp).
/// What every shape takes besides its own arguments: definitions, and the sentence that states the
/// claim in words (its hole {property} must affirm `property`, or deny it: "not symplectic").
const std::vector<shape_parameter>& common_parameters() {
  static const std::vector<shape_parameter> parameters{
    {"where", argument_kind::definitions, false, "displays 'x = ...' whose definitions are put in the other formulas"},
    {"entries", argument_kind::definitions, false,
     "two matrices: one printed with a symbol for each entry (Phi = (alpha beta; gamma delta)), then the matrix whose entries they name"},
    {"says", argument_kind::word, false, "the sentence that states the claim, a pattern with the hole {property}"},
    {"property", argument_kind::word, false, "the word the sentence's hole must say (or deny: 'not ...')"}};
  return parameters;
}

/// The scheme and the equation a series shape expands on: what truncation and stated-order share.
std::vector<shape_parameter> with_series(std::vector<shape_parameter> parameters) {
  for (shape_parameter p : std::vector<shape_parameter>{
           {"scheme", argument_kind::formula, true, "the scheme's expression (= 0) in three consecutive states"},
           {"sequence", argument_kind::symbols, true, "the three states q_{j-1}, q_j, q_{j+1}", 3},
           {"step", argument_kind::symbols, true, "the step h", 1},
           {"frequency", argument_kind::formula, true, "omega of q'' = -omega^2 q"},
           {"scale", argument_kind::formula, false, "a factor the text divides the scheme by ('the scheme divided by m'), free of the states"}}) {
    if (p.name == "scale") p.free_of = "sequence";
    parameters.push_back(std::move(p));
  }
  return parameters;
}

/// A sentence's pattern that must hold the hole {name} (an optional argument when not `required`).
shape_parameter pattern_with_hole(std::string name, std::string meaning, std::string hole, bool required) {
  shape_parameter p{std::move(name), argument_kind::word, required, std::move(meaning)};
  p.hole = std::move(hole);
  return p;
}

std::vector<shape_parameter> with_where(std::vector<shape_parameter> parameters) {
  parameters.insert(parameters.end(), common_parameters().begin(), common_parameters().end());
  return parameters;
}

// The series helpers the oscillator's series shapes and the consistency shapes share.
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

GiNaC::matrix canonical_j(unsigned n) {
  GiNaC::matrix j(2 * n, 2 * n);
  for (unsigned k = 0; k < n; ++k) {
    j(k, n + k) = 1;
    j(n + k, k) = -1;
  }
  return j;
}

std::map<std::string, std::pair<ex, ex>> terms_by_parts(const ex& e, const std::function<bool(const ex&)>& depends) {
  std::map<std::string, std::pair<ex, ex>> out;
  const ex expanded = GiNaC::expand(e);
  const auto add = [&](const ex& term) {
    ex part = 1, coefficient = 1;
    for (const ex& f : GiNaC::is_a<GiNaC::mul>(term) ? GiNaC::exvector(term.begin(), term.end()) : GiNaC::exvector{term}) {
      (depends(f) ? part : coefficient) *= f;
    }
    auto& slot = out[text_of(part)];
    slot.first = part;
    slot.second = slot.second + coefficient;
  };
  if (GiNaC::is_a<GiNaC::add>(expanded)) {
    for (const ex& term : expanded) add(term);
  } else {
    add(expanded);
  }
  return out;
}

std::string differing_application_coefficients(const ex& printed, const ex& derived) {
  const auto applies = [](const ex& f) {
    for (GiNaC::const_preorder_iterator it = f.preorder_begin(); it != f.preorder_end(); ++it) {
      if (is_reader_function(*it)) return true;
    }
    return false;
  };
  if (!applies(printed) || !applies(derived)) return "";
  const auto p = terms_by_parts(printed, applies), d = terms_by_parts(derived, applies);
  std::set<std::string> keys;
  for (const auto& [k, t] : p) keys.insert(k);
  for (const auto& [k, t] : d) keys.insert(k);
  std::vector<std::string> differing;
  for (const std::string& k : keys) {
    const auto pt = p.find(k), dt = d.find(k);
    const ex part = pt != p.end() ? pt->second.first : dt->second.first;
    if (!applies(part)) continue;
    const ex a = pt == p.end() ? ex(0) : GiNaC::normal(pt->second.second), b = dt == d.end() ? ex(0) : GiNaC::normal(dt->second.second);
    if (!GiNaC::normal(a - b).is_zero()) differing.push_back(fmt::format("the coefficient of {}: printed {}, derived {}", text_of(part), text_of(a), text_of(b)));
  }
  if (differing.empty()) return "";
  std::string out;
  for (std::size_t k = 0; k < differing.size(); ++k) out += (k ? "; " : " (") + differing[k];
  return out + ")";
}

}  // namespace simpson::verify::detail

// Formulas named by a claims-file record: see formula_reference.hpp.

#include <simpson/verify/formula_reference.hpp>

#include <simpson/verify/tex_math.hpp>
#include <simpson/verify/tex_macros.hpp>

#include <algorithm>
#include <cctype>
#include <set>

namespace simpson::verify {
namespace {

/// Strips a side suffix, ":lhs" (the first side) or ":sideN" (the N-th, from 1), from `key` into
/// `side`; throws std::invalid_argument for ":side" without a number from 1.
void strip_side(std::string& key, int& side, const std::string& text) {
  if (key.size() > 4 && key.compare(key.size() - 4, 4, ":lhs") == 0) {
    side = 1;
    key.resize(key.size() - 4);
    return;
  }
  const std::size_t colon = key.rfind(":side");
  if (colon == std::string::npos || colon == 0) return;
  const std::string number = key.substr(colon + 5);
  if (number.empty() || number.size() > 2 || number.find_first_not_of("0123456789") != std::string::npos || std::stoi(number) == 0) {
    throw std::invalid_argument("'" + text + "': after ':side' a side number from 1");
  }
  side = std::stoi(number);
  key.resize(colon);
}

}  // namespace

formula_reference parse_reference(const std::string& text) {
  formula_reference r;
  if (text.size() >= 2 && text.front() == '$' && text.back() == '$') {
    r.where = formula_reference::kind::literal;
    r.key = text.substr(1, text.size() - 2);
    if (r.key.find_first_not_of(" \t") == std::string::npos) throw std::invalid_argument("an empty TeX fragment '$$'");
    return r;
  }
  for (const auto& [prefix, kind] : {std::pair<std::string, formula_reference::kind>{"inline:", formula_reference::kind::inline_formula},
                                     {"after:", formula_reference::kind::display_after}}) {
    if (text.rfind(prefix, 0) != 0) continue;
    r.where = kind;
    r.key = text.substr(prefix.size());
    strip_side(r.key, r.side, text);  // the phrase's formula's first side, or its N-th
    const std::size_t hash = r.key.rfind('#');  // after:phrase#2, the display's second equation
    if (kind == formula_reference::kind::display_after && hash != std::string::npos && hash + 1 < r.key.size() && hash + 3 >= r.key.size() &&
        r.key.find_first_not_of("0123456789", hash + 1) == std::string::npos) {
      r.equation = std::stoi(r.key.substr(hash + 1));
      if (r.equation == 0) throw std::invalid_argument("'" + text + "': after '#' an equation number from 1");
      r.key.resize(hash);
    }
    if (r.key.find_first_not_of(" \t") == std::string::npos) throw std::invalid_argument("'" + prefix + "' names no phrase");
    return r;
  }
  std::string rest = text;
  strip_side(rest, r.side, text);
  const std::size_t hash = rest.find('#');
  if (hash != std::string::npos) {
    const std::string number = rest.substr(hash + 1);
    if (number.empty() || number.size() > 2 || number.find_first_not_of("0123456789") != std::string::npos || number == "0" || number == "00") {
      throw std::invalid_argument("'" + text + "': after '#' an equation number from 1");
    }
    r.equation = std::stoi(number);
    rest.resize(hash);
  }
  if (rest.empty() || rest.find_first_of("{}$\\") != std::string::npos || rest.front() == ' ' || rest.back() == ' ') {  // a \label may hold spaces
    throw std::invalid_argument("'" + text + "' is not a reference (a \\label, label#k, label:lhs, label:sideN, inline:phrase, after:phrase, or $TeX$)");
  }
  r.key = rest;
  return r;
}

namespace {

/// "'origin', label x: line N: why" for a tex_error of the document.
document_error document_fault(const tex_document& document, const std::string& where, const tex_error& e) {
  return document_error(where + ", " + describe(e, document.text()));
}

}  // namespace

referenced_formula read_reference(const tex_document& document, const tex_declarations& declared, const std::string& reference) {
  const formula_reference r = parse_reference(reference);
  referenced_formula f;
  std::vector<tex_equation> equations;
  if (r.where == formula_reference::kind::literal) {
    f.locator = f.place = "the record's TeX '" + r.key + "'";
    try {
      std::vector<tex_token> tokens = expand_all(tex_tokenize(r.key), document.macros());
      tex_region region;
      region.display = false;
      region.rows.push_back({tokens, 0, r.key.size(), {}, 0});
      equations = equations_of(region);
      if (equations.size() != 1) throw tex_error("one formula, not " + std::to_string(equations.size()), 0);
    } catch (const tex_error& e) {
      throw std::invalid_argument(f.locator + ": " + e.what() + (e.hint().empty() ? "" : " (" + e.hint() + ")"));
    }
  } else {
    const std::string origin = "'" + document.origin() + "'";
    f.origin = document.origin();
    f.document = &document;
    const tex_region* region = nullptr;
    int row = -1;
    if (r.where == formula_reference::kind::labelled) {
      try {
        const tex_document::located at = document.labelled(r.key);
        region = at.region;
        row = at.row;
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string(e.what()) + " in a formula of " + origin);
      }
      f.place = "label " + r.key;
    } else {
      const auto found = find_ignoring_space(document.text(), r.key);
      if (!found) throw std::invalid_argument(origin + ": the phrase '" + r.key + "' is not there");
      region = r.where == formula_reference::kind::display_after ? document.display_after(found->first) : document.inline_at(found->first);
      if (!region) {
        throw std::invalid_argument(origin + ": no " + std::string(r.where == formula_reference::kind::display_after ? "display" : "inline formula") +
                                    " after the phrase '" + r.key + "'");
      }
      f.place = r.where == formula_reference::kind::display_after ? "anchor '" + r.key + "'" : "inline formula at '" + r.key + "'";
    }
    f.line = line_of(*region, row);
    f.locator = f.place + " (line " + std::to_string(f.line) + ")";
    try {
      equations = equations_of(*region, row);
    } catch (const tex_error& e) {
      throw document_fault(document, "document " + origin + ", " + f.place, e);
    }
  }
  if (equations.empty()) throw std::invalid_argument(f.locator + ": no formula");
  if (r.equation > static_cast<int>(equations.size())) {
    throw std::invalid_argument(f.locator + ": equation " + std::to_string(r.equation) + " is not there (the display has " +
                                std::to_string(equations.size()) + ")");
  }
  const tex_equation& e = equations[static_cast<std::size_t>(r.equation - 1)];
  f.tex = e.tex;
  f.sides = e.side_tex;
  f.relations = e.relations;
  f.side_trees = e.sides;
  if (r.side > static_cast<int>(f.sides.size())) {
    throw std::invalid_argument(f.locator + ": side " + std::to_string(r.side) + " is not there (the equation has " + std::to_string(f.sides.size()) +
                                ")");
  }
  // Not evaluated as matrices yet: a symbol a definition makes a matrix (Phi in "Phi (q_0, p_0)")
  // must not be taken for a scalar factor first.
  const std::size_t side = r.side == 0 ? f.sides.size() - 1 : static_cast<std::size_t>(r.side - 1);
  f.identity = f.place + "#" + std::to_string(r.equation) + ":side" + std::to_string(side + 1);
  f.side = side;
  f.value = read_side(f, side, declared);
  return f;
}

GiNaC::ex read_side(const referenced_formula& f, std::size_t k, const tex_declarations& declared) {
  try {
    return read_math(f.side_trees.at(k), declared, paper_symbols());
  } catch (const tex_error& e) {
    const std::string what = "cannot read '" + folded_space(f.sides.at(k)) + "': " + e.what() + (e.hint().empty() ? "" : " (" + e.hint() + ")");
    if (!f.document) throw std::invalid_argument(f.locator + ": " + what);
    throw document_error("document '" + f.origin + "', " + f.place + ", line " + std::to_string(line_at(f.document->text(), e.offset())) + ": " + what);
  }
}

std::vector<std::string> symbol_names(const GiNaC::ex& e) {
  std::set<std::string> names;
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::symbol>(*it)) names.insert(GiNaC::ex_to<GiNaC::symbol>(*it).get_name());
  }
  return {names.begin(), names.end()};
}

definition read_definition(const tex_document& document, const tex_declarations& declared, const std::string& reference) {
  formula_reference r = parse_reference(reference);
  if (r.side != 0) throw std::invalid_argument("'" + reference + "': a definition is a whole equation, without ':lhs' or ':sideN'");
  const referenced_formula f = read_reference(document, declared, reference);
  if (f.sides.size() < 2) throw std::invalid_argument(f.locator + ": a definition is an equation 'x = ...'");
  const GiNaC::ex name = read_side(f, 0, declared);
  if (GiNaC::is_a<GiNaC::symbol>(name)) return {GiNaC::ex_to<GiNaC::symbol>(name), f.value, f.locator, f.line, f.tex};
  // V(q) = ...: a function of one symbol.
  if (GiNaC::is_exactly_a<GiNaC::function>(name) && name.nops() == 1 && GiNaC::is_a<GiNaC::symbol>(name.op(0))) {
    const std::string function = GiNaC::ex_to<GiNaC::function>(name).get_name();
    return {GiNaC::symbol(function), f.value, f.locator, f.line, f.tex, function, GiNaC::ex_to<GiNaC::symbol>(name.op(0))};
  }
  // L(q, \dot q) = ..., or L = ... when L declares its variables: a function of several symbols.
  if (GiNaC::is_exactly_a<GiNaC::function>(name) && name.nops() > 1) {
    std::vector<GiNaC::symbol> parameters;
    for (const GiNaC::ex& a : name) {
      const bool fresh = GiNaC::is_a<GiNaC::symbol>(a) && std::none_of(parameters.begin(), parameters.end(), [&](const GiNaC::symbol& s) { return GiNaC::ex(s).is_equal(a); });
      if (!fresh) throw std::invalid_argument(f.locator + ": the left side '" + folded_space(f.sides.front()) + "' of a definition applies its function to what is not distinct names");
      parameters.push_back(GiNaC::ex_to<GiNaC::symbol>(a));
    }
    const std::string function = GiNaC::ex_to<GiNaC::function>(name).get_name();
    return {GiNaC::symbol(function), f.value, f.locator, f.line, f.tex, function, std::nullopt, parameters};
  }
  std::string hint;  // f(x) read as a product: f is not declared a function
  if (GiNaC::is_a<GiNaC::mul>(name) && !f.side_trees.front().empty()) {
    try {
      hint = " (to read it as a function, declare " + symbol_name(f.side_trees.front().front()) + " under [symbols] functions)";
    } catch (const tex_error&) {
    }
  }
  throw std::invalid_argument(f.locator + ": the left side '" + folded_space(f.sides.front()) +
                              "' of a definition is not one symbol, nor a function of one symbol" + hint);
}

namespace {

/// evalm, with a product of two matrices (a symbol a definition made a matrix, times a matrix the
/// formula prints) multiplied in the one order whose sizes agree: GiNaC keeps a product's factors
/// in its own order, not the TeX's, and takes a second matrix for a scalar.
GiNaC::ex evaluated_matrices(const GiNaC::ex& e) {
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    GiNaC::ex scalar = 1;
    std::vector<GiNaC::matrix> matrices;
    for (const GiNaC::ex& factor : e) {
      const GiNaC::ex f = evaluated_matrices(factor);
      if (GiNaC::is_a<GiNaC::matrix>(f)) {
        matrices.push_back(GiNaC::ex_to<GiNaC::matrix>(f));
      } else {
        scalar *= f;
      }
    }
    if (matrices.empty()) return scalar;
    if (matrices.size() > 2) throw std::invalid_argument("a product of more than two matrices: their order is not in the expression");
    GiNaC::matrix product = matrices.front();
    if (matrices.size() == 2) {
      const GiNaC::matrix& a = matrices[0];
      const GiNaC::matrix& b = matrices[1];
      const bool ab = a.cols() == b.rows(), ba = b.cols() == a.rows();
      if (ab && ba) throw std::invalid_argument("a product of two matrices that fit in either order: its order is not in the expression");
      if (!ab && !ba) throw std::invalid_argument("a product of two matrices whose sizes do not agree");
      product = ab ? a.mul(b) : b.mul(a);
    }
    return product.mul_scalar(scalar);
  }
  if (GiNaC::is_a<GiNaC::add>(e)) {
    GiNaC::ex sum = 0;
    for (const GiNaC::ex& term : e) sum = (sum + evaluated_matrices(term)).evalm();
    return sum;
  }
  if (GiNaC::is_a<GiNaC::matrix>(e)) {
    GiNaC::matrix m = GiNaC::ex_to<GiNaC::matrix>(e);
    for (unsigned r = 0; r < m.rows(); ++r) {
      for (unsigned c = 0; c < m.cols(); ++c) m(r, c) = evaluated_matrices(m(r, c));
    }
    return m;
  }
  return e.evalm();
}

}  // namespace

namespace {

/// Whether `e` applies the function `name`, or a derivative of it.
bool applies(const GiNaC::ex& e, const std::string& name) {
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::function>(*it) && GiNaC::ex_to<GiNaC::function>(*it).get_name() == name) return true;
  }
  return false;
}

/// Each application of a defined function, V(x) or its k-th derivative V^(k)(x), replaced by the
/// definition's value (its k-th derivative) at x.
struct function_values : GiNaC::map_function {
  const definition& d;
  explicit function_values(const definition& given) : d(given) {}
  GiNaC::ex operator()(const GiNaC::ex& e) override {
    const std::size_t arity = d.parameter ? 1 : d.parameters.size();
    if (!GiNaC::is_a<GiNaC::function>(e) || GiNaC::ex_to<GiNaC::function>(e).get_name() != d.function || e.nops() != arity) return e.map(*this);
    if (d.parameter) {
      const GiNaC::ex at = (*this)(e.op(0));
      unsigned order = 0;
      if (GiNaC::is_a<GiNaC::fderivative>(e)) order = static_cast<unsigned>(GiNaC::ex_to<GiNaC::fderivative>(e).derivatives().size());
      return GiNaC::diff(d.value, *d.parameter, order).subs(*d.parameter == at);
    }
    // L(a, b), D[0,1](L)(a, b): the value's derivatives by those slots, at the arguments all at once.
    GiNaC::ex value = d.value;
    if (GiNaC::is_a<GiNaC::fderivative>(e)) {
      for (const unsigned slot : GiNaC::ex_to<GiNaC::fderivative>(e).derivatives()) value = value.diff(d.parameters.at(slot));
    }
    GiNaC::lst at;
    for (std::size_t k = 0; k < arity; ++k) at.append(d.parameters[k] == (*this)(e.op(k)));
    return value.subs(at, GiNaC::subs_options::no_pattern);
  }
};

}  // namespace

namespace {

/// A function defined in another variable than its argument, q(t) = ... σ, is read in its argument
/// when the definitions say how the two relate: σ = t/h (a symbol of the value defined by an
/// expression in the argument) is put in as it is; t = h σ (the argument's definition, linear in
/// exactly one symbol of the value) is solved for σ. A value that holds symbols but not its argument,
/// and that no definition relates to it, is refused: read as printed it would be constant in t, and
/// its derivatives 0, which the text does not say.
std::vector<definition> in_their_arguments(const std::vector<definition>& definitions) {
  std::vector<definition> out = definitions;
  for (definition& d : out) {
    if (d.function.empty() || !d.parameter || d.value.has(*d.parameter)) continue;
    for (const definition& change : definitions) {
      if (!change.function.empty()) continue;
      if (d.value.has(change.name) && change.value.has(*d.parameter)) {  // σ = t/h
        d.value = d.value.subs(change.name == change.value);
        continue;
      }
      if (change.name.get_name() != d.parameter->get_name()) continue;  // t = h σ
      std::vector<GiNaC::symbol> shared;
      for (GiNaC::const_preorder_iterator it = change.value.preorder_begin(); it != change.value.preorder_end(); ++it) {
        if (!GiNaC::is_a<GiNaC::symbol>(*it) || !d.value.has(*it)) continue;
        const GiNaC::symbol& s = GiNaC::ex_to<GiNaC::symbol>(*it);
        if (std::none_of(shared.begin(), shared.end(), [&](const GiNaC::symbol& k) { return k.is_equal(s); })) shared.push_back(s);
      }
      if (shared.size() != 1) continue;
      const GiNaC::ex slope = GiNaC::diff(change.value, shared.front());
      if (slope.has(shared.front()) || GiNaC::normal(slope).is_zero()) continue;  // not linear in it
      const GiNaC::ex solved = GiNaC::normal((GiNaC::ex(*d.parameter) - change.value.subs(shared.front() == 0)) / slope);
      d.value = d.value.subs(shared.front() == solved);
    }
    bool holds_symbols = false;
    for (GiNaC::const_preorder_iterator it = d.value.preorder_begin(); it != d.value.preorder_end() && !holds_symbols; ++it) {
      holds_symbols = GiNaC::is_a<GiNaC::symbol>(*it);
    }
    if (holds_symbols && !d.value.has(*d.parameter)) {
      throw std::invalid_argument(d.locator + ": " + d.function + "(" + d.parameter->get_name() +
                                  ") is defined without " + d.parameter->get_name() + "; when its value is written in another variable, put that variable's " +
                                  "definition in 'where' (as s = " + d.parameter->get_name() + "/h or " + d.parameter->get_name() + " = h s)");
    }
  }
  return out;
}

/// The symbols that name a derivative of a definition, as a derivative without an argument parses:
/// a defined function's in its own argument ({{\dd q}\over{\dd t}}, "dq/dt", with q(t) defined), and
/// a defined symbol's partial derivative by a symbol of its value ({{\partial g}\over{\partial x}},
/// "dg/dx", with g = ... defined): each with the derivative of the value.
GiNaC::exmap derivative_symbols(const GiNaC::ex& e, const std::vector<definition>& definitions) {
  GiNaC::exmap out;
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (!GiNaC::is_a<GiNaC::symbol>(*it)) continue;
    const std::string name = GiNaC::ex_to<GiNaC::symbol>(*it).get_name();
    if (name.size() < 4 || name[0] != 'd' || name.find("/d") == std::string::npos) continue;
    for (const definition& d : definitions) {
      if (!d.function.empty()) {
        for (int k = 1; d.parameter && k <= 4; ++k) {
          if (name == derivative_name(d.function, d.parameter->get_name(), k, k)) out[*it] = GiNaC::diff(d.value, *d.parameter, static_cast<unsigned>(k));
        }
        continue;
      }
      for (int k = 1; k <= 2; ++k) {  // d^k<name>/d<by>^k, by any symbol (one the value does not hold gives 0)
        const std::string suffix = k == 1 ? "" : "^" + std::to_string(k), prefix = "d" + suffix + d.name.get_name() + "/d";
        if (name.size() <= prefix.size() + suffix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) {
          continue;
        }
        const std::string by = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
        out[*it] = GiNaC::diff(d.value, GiNaC::ex_to<GiNaC::symbol>(paper_symbols()[by]), static_cast<unsigned>(k));
      }
    }
  }
  return out;
}

}  // namespace

GiNaC::ex with_definitions(const GiNaC::ex& e, const std::vector<definition>& given) {
  std::vector<definition> definitions = in_their_arguments(given);
  GiNaC::exmap values;
  for (const definition& d : definitions) {
    if (d.function.empty()) values[d.name] = d.value;
  }
  // A symbol's value with the other symbols' put in (q_1 = q_0 + h v_{1/2}, v_{1/2} = v_0 - ...): a
  // partial derivative of it (dq_1/dq_0) is the derivative of that, not of the value as printed.
  for (std::size_t round = 0; round <= definitions.size(); ++round) {
    bool changed = false;
    for (definition& d : definitions) {
      if (!d.function.empty()) continue;
      const GiNaC::ex next = d.value.subs(values);
      if (!next.is_equal(d.value)) {
        d.value = next;
        values[d.name] = next;
        changed = true;
      }
    }
    if (!changed) break;
    if (round == definitions.size()) throw std::invalid_argument("the definitions use each other without end");
  }
  // A function's value with the symbols' definitions put in before anything differentiates it
  // (L_d(q_0, q_1) = h L(\bar q, v), with \bar q and v defined): D_1 L_d is then taken through them, not
  // 0. Its own variables stay its variables.
  for (definition& d : definitions) {
    if (d.function.empty()) continue;
    GiNaC::exmap outside = values;
    if (d.parameter) outside.erase(GiNaC::ex(*d.parameter));
    for (const GiNaC::symbol& p : d.parameters) outside.erase(GiNaC::ex(p));
    d.value = d.value.subs(outside);
  }
  GiNaC::ex out = e;
  for (std::size_t round = 0; round <= definitions.size(); ++round) {
    const GiNaC::exmap derivatives = derivative_symbols(out, definitions);
    bool any = !derivatives.empty();
    for (const definition& d : definitions) any = any || (d.function.empty() ? out.has(d.name) : applies(out, d.function));
    if (!any) return evaluated_matrices(out);
    out = out.subs(derivatives).subs(values);
    for (const definition& d : definitions) {
      if (!d.function.empty()) out = function_values(d)(out);
    }
    out = evaluated_matrices(out);
  }
  throw std::invalid_argument("the definitions use each other without end");
}

}  // namespace simpson::verify

// What a document's math means: see tex_math.hpp and tex_reader.hpp. This file: sums, products,
// atoms, numbers, names and applications; tex_math_operators.cpp the rest.

#include "tex_reader.hpp"

#include <simpson/verify/tex_macros.hpp>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>

namespace simpson::verify::tex_reading {

GiNaC::ex reader::whole(const tex_list& list) {
  cursor c{&list, 0};
  GiNaC::ex e = sum(c, {});
  if (!c.done()) refuse("unexpected '" + c.node().text + "'", c.node());
  return e;
}

bool reader::is_atom(const tex_node& n, const std::string& text) {
  return n.kind == tex_node_kind::atom && n.text == text;
}

bool reader::closes(const tex_node& n, const std::vector<std::string>& closers) {
  const tex_node& atom = n.kind == tex_node_kind::scripts ? n.children.front() : n;
  return atom.kind == tex_node_kind::atom && std::find(closers.begin(), closers.end(), atom.text) != closers.end();
}

bool reader::ends_term(cursor& c, const std::vector<std::string>& closers) {
  if (c.done()) return true;
  const tex_node& n = c.node();
  if (closes(n, closers)) return true;
  if (n.kind == tex_node_kind::atom && (n.text == "+" || n.text == "-" || n.atom_class == tex_class::rel || n.atom_class == tex_class::punct)) {
    return true;
  }
  return false;
}

GiNaC::ex reader::sum(cursor& c, const std::vector<std::string>& closers) {
  if (c.done()) throw tex_error("an empty formula", 0);
  bool negative = false;
  if (is_atom(c.node(), "-")) {
    negative = true;
    ++c.k;
  } else if (is_atom(c.node(), "+")) {
    ++c.k;
  } else if (is_atom(c.node(), "\\pm") || is_atom(c.node(), "\\mp")) {
    refuse("a " + c.node().text + " (two formulas in one)", c.node());
  }
  GiNaC::ex s = term(c, closers);
  if (negative) s = -s;
  for (;;) {
    if (c.done() || closes(c.node(), closers)) return s;
    const tex_node& n = c.node();
    if (is_atom(n, "+")) {
      ++c.k;
      s += term(c, closers);
    } else if (is_atom(n, "-")) {
      ++c.k;
      s -= term(c, closers);
    } else if (n.atom_class == tex_class::punct && std::find(closers.begin(), closers.end(), n.text) != closers.end()) {
      return s;
    } else {
      refuse("unexpected '" + n.text + "'", n);
    }
  }
}

GiNaC::ex reader::term(cursor& c, const std::vector<std::string>& closers) {
  if (ends_term(c, closers)) {
    if (c.done()) throw tex_error("a term missing at the end of the formula", 0);
    refuse("a term missing before '" + c.node().text + "'", c.node());
  }
  GiNaC::ex p = factor(c, closers);
  for (;;) {
    if (ends_term(c, closers)) return p;
    const tex_node& n = c.node();
    if (is_atom(n, "\\cdot") || is_atom(n, "\\times") || is_atom(n, "*")) {
      ++c.k;
      p *= factor(c, closers);
      continue;
    }
    if (is_atom(n, "/")) {
      const tex_node& slash = n;
      ++c.k;
      if (ends_term(c, closers)) refuse("a '/' with nothing after it", slash);
      if (is_atom(c.node(), "\\partial")) refuse("a / before a slanted derivative: which '/' divides first is not written", slash, "\\frac{...}{...}");
      const GiNaC::ex divisor = factor(c, closers);
      if (!ends_term(c, closers)) {
        refuse("a / b followed by more factors: whether they divide or multiply is not written", slash, "write \\frac{...}{...}");
      }
      return p / divisor;
    }
    if (n.kind == tex_node_kind::atom && n.atom_class == tex_class::bin) refuse("the operation " + n.text, n);
    p *= factor(c, closers);
  }
}

GiNaC::ex reader::factor(cursor& c, const std::vector<std::string>& closers) {
  GiNaC::ex f = primary(c, closers);
  while (!c.done() && is_atom(c.node(), "!")) {  // n!
    const tex_node& bang = c.node();
    ++c.k;
    if (GiNaC::is_a<GiNaC::numeric>(f) && GiNaC::ex_to<GiNaC::numeric>(f) > 1000) refuse("a factorial beyond the reader's exact arithmetic", bang);
    f = GiNaC::factorial(f);
  }
  return f;
}

GiNaC::ex reader::primary(cursor& c, const std::vector<std::string>& closers) {
  if (c.done()) throw tex_error("a factor missing at the end of the formula (after \\cdot, \\times or an operator)", c.list->empty() ? 0 : c.list->back().offset);
  const tex_node& n = c.node();
  switch (n.kind) {
    case tex_node_kind::atom: return atom(c, closers);
    case tex_node_kind::group: {
      if (const auto landau = order_term(c)) return *landau;
      if (const auto op = named_operator(c, closers)) return *op;
      // {{dV}\over{dq}}(x): a fraction alone in its group (\over's braces) is read where the group
      // is, so that an application after it applies to it.
      if (unwrapped(n).kind == tex_node_kind::fraction) return fraction(c, closers);
      if (differential_of(n)) refuse("an upright d outside a derivative or an integral", n);
      ++c.k;
      return whole(n.children);
    }
    case tex_node_kind::fraction: return fraction(c, closers);
    case tex_node_kind::root: {
      ++c.k;
      const GiNaC::ex radicand = whole(n.children[0].children);
      if (n.children.size() == 1) return GiNaC::sqrt(radicand);
      return power_of(radicand, 1 / whole(n.children[1].children));
    }
    case tex_node_kind::scripts: return scripts(c, closers);
    case tex_node_kind::delimited: {
      ++c.k;
      return delimited(n);
    }
    case tex_node_kind::environment: {
      ++c.k;
      return environment(n);
    }
    case tex_node_kind::font: {
      if (const auto landau = order_term(c)) return *landau;
      if (const auto op = named_operator(c, closers)) return *op;
      if (n.text == "mathbf" || n.text == "boldsymbol" || n.text == "mathcal" || n.text == "mathbb") return named(c, symbol_name(n));
      if (differential_of(n)) refuse("an upright d outside a derivative or an integral", n);
      refuse("the font " + n.text + " on '" + normal_form(n.children) + "': an upright name the reader gives no meaning to", n,
             "\\operatorname{tr}, \\det, \\mathrm d in a derivative, \\mathcal O(h^k)");
    }
    case tex_node_kind::op: return op(c, closers);
    case tex_node_kind::accent: {
      // A dotted function applied at a point, \dot q(0) (q a state or a function): its time
      // derivative there, D[0](q)(0), as \frac{dq}{dt}(0) reads; never dq/dt times (0). Alone, a
      // dotted state is its own quantity (dq/dt).
      const int order = n.text == "\\dot" ? 1 : n.text == "\\ddot" ? 2 : n.text == "\\dddot" ? 3 : 0;
      if (order > 0 && c.k + 1 < c.list->size()) {
        const tex_node& base = unwrapped(n.children.front());
        const tex_node* next = &(*c.list)[c.k + 1];
        if ((is_greek_or_letter(base) || base.kind == tex_node_kind::scripts) && opens_application(next)) {
          const std::string name = symbol_name(base);
          if (declared_.is_function(name)) return named(c, name, order);
        }
      }
      return named(c, symbol_name(n));
    }
    case tex_node_kind::text: refuse("words inside a formula (\\text{" + n.text + "})", n);
    case tex_node_kind::label: break;
  }
  refuse("unexpected", n);
}

GiNaC::ex reader::atom(cursor& c, const std::vector<std::string>& closers) {
  const tex_node& n = c.node();
  if (n.text.size() == 1 && std::isdigit(static_cast<unsigned char>(n.text[0]))) return number(c);
  if (n.text == "O") {
    if (const auto landau = order_term(c)) return *landau;
    refuse("O without its argument in parentheses", n, "O(h^4)");
  }
  if (n.text == "\\pi") {
    ++c.k;
    return GiNaC::Pi;
  }
  if (is_greek_or_letter(n)) return named(c, symbol_name(n));
  if (n.atom_class == tex_class::open) {
    ++c.k;
    return parenthesised(c, n);
  }
  if (n.text == "|") {
    ++c.k;
    const GiNaC::ex inside = sum(c, {"|"});
    if (c.done() || !closes(c.node(), {"|"})) refuse("a '|' that is never closed", n);
    const tex_node& close = c.node();
    ++c.k;
    if (close.kind != tex_node_kind::scripts) return GiNaC::abs(inside);
    if (!close.sub.empty()) refuse("a subscript on a closing '|'", close);
    return power_of(GiNaC::abs(inside), whole_node(close.sup.front()));  // |r|^2
  }
  if (n.text == "\\partial") return slanted_derivative(c, closers);
  if (n.text == "\\ldots" || n.text == "\\cdots" || n.text == "\\dots") refuse("an ellipsis: what it stands for is not written", n);
  if (n.text == "\\infty") refuse("\\infty", n);
  if (n.text == "\\prime") refuse("a prime on no function (a prime is the derivative of a declared function: V'(x))", n);
  if (n.atom_class == tex_class::close) refuse("a '" + n.text + "' that closes nothing", n);
  refuse("unexpected '" + n.text + "'", n);
}

GiNaC::ex reader::number(cursor& c) {
  std::string digits;
  std::optional<GiNaC::ex> power;
  const tex_node& first = c.node();
  while (!c.done()) {
    const tex_node& n = c.node();
    const bool digit = n.kind == tex_node_kind::atom && n.text.size() == 1 && std::isdigit(static_cast<unsigned char>(n.text[0]));
    if (digit) {
      digits += n.text;
      ++c.k;
      continue;
    }
    if (n.kind == tex_node_kind::atom && n.text == "." && !digits.empty() && digits.find('.') == std::string::npos) {
      const tex_node* after = c.next_after();
      if (after && after->kind == tex_node_kind::atom && after->text.size() == 1 && std::isdigit(static_cast<unsigned char>(after->text[0]))) {
        digits += '.';
        ++c.k;
        continue;
      }
    }
    if (n.kind == tex_node_kind::scripts && n.children.front().kind == tex_node_kind::atom && n.children.front().text.size() == 1 &&
        std::isdigit(static_cast<unsigned char>(n.children.front().text[0]))) {
      if (!n.sub.empty()) refuse("a subscript on a number", n);
      digits += n.children.front().text;
      power = whole_node(n.sup.front());
      ++c.k;
    }
    break;
  }
  GiNaC::numeric value;
  const std::size_t point = digits.find('.');
  if (point == std::string::npos) {
    value = GiNaC::numeric(digits.c_str());
  } else {
    const std::string whole_digits = digits.substr(0, point) + digits.substr(point + 1);
    value = GiNaC::numeric(whole_digits.c_str()) / GiNaC::numeric(10).power(static_cast<long>(digits.size() - point - 1));
  }
  (void)first;
  return power ? power_of(value, *power) : GiNaC::ex(value);
}

GiNaC::ex reader::whole_node(const tex_node& n) {
  return n.kind == tex_node_kind::group ? whole(n.children) : whole({n});
}

GiNaC::ex reader::parenthesised(cursor& c, const tex_node& open) {
  static const std::map<std::string, std::string> pairs{{"(", ")"}, {"[", "]"}, {"\\{", "\\}"}, {"\\lbrace", "\\rbrace"}};
  const auto pair = pairs.find(open.text);
  if (pair == pairs.end()) refuse("the delimiter " + open.text, open);
  if (c.done()) refuse("a '" + open.text + "' that is never closed", open);
  GiNaC::ex inside = sum(c, {pair->second});
  if (c.done() || !closes(c.node(), {pair->second})) refuse("a '" + open.text + "' that is never closed", open);
  const tex_node& close = c.node();
  ++c.k;
  if (close.kind == tex_node_kind::scripts) {
    if (!close.sub.empty()) refuse("a subscript on a closing '" + pair->second + "'", close);
    inside = power_of(inside, whole_node(close.sup.front()));
  }
  return inside;
}

reader::application reader::arguments_and_power(cursor& c) {
  const tex_node& at = c.node();
  const tex_node& open = at.kind == tex_node_kind::scripts ? at.children.front() : at;
  application out;
  if (open.kind == tex_node_kind::delimited) {
    ++c.k;
    if (open.text != "(" || open.close != ")") refuse("an application in \\left" + open.text + " ... \\right" + open.close, open);
    if (at.kind == tex_node_kind::scripts) {
      if (!at.sub.empty()) refuse("a subscript on a function's argument", at);
      out.power = whole_node(at.sup.front());
    }
    tex_list part;
    int depth = 0;
    for (const tex_node& n : open.children) {
      depth += delimiter_depth_change(n);
      if (depth == 0 && is_atom(n, ",")) {
        out.args.push_back(whole(part));
        part.clear();
        continue;
      }
      part.push_back(n);
    }
    out.args.push_back(whole(part));
    return out;
  }
  ++c.k;  // '('
  for (;;) {
    out.args.push_back(sum(c, {")", ","}));
    if (c.done()) refuse("a '(' that is never closed", open);
    const tex_node& n = c.node();
    ++c.k;
    if (is_atom(n, ",")) continue;
    if (n.kind == tex_node_kind::scripts) {
      if (!n.sub.empty()) refuse("a subscript on a function's closing ')'", n);
      out.power = whole_node(n.sup.front());
    }
    return out;
  }
}

GiNaC::exvector reader::arguments(cursor& c) {
  const tex_node& at = c.node();
  application a = arguments_and_power(c);
  if (a.power) refuse("a power on the argument's closing delimiter where no power can stand", at);
  return a.args;
}

GiNaC::ex reader::raised(const GiNaC::ex& e, const std::optional<GiNaC::ex>& power) {
  return power ? power_of(e, *power) : e;
}

GiNaC::ex reader::power_of(const GiNaC::ex& base, const GiNaC::ex& exponent) {
  if (GiNaC::is_a<GiNaC::numeric>(exponent)) {
    const GiNaC::numeric& e = GiNaC::ex_to<GiNaC::numeric>(exponent);
    if (!e.is_rational() || GiNaC::abs(e.numer()) > 1000 || e.denom() > 1000) {
      throw tex_error("an exponent beyond the reader's exact arithmetic (" + canonical_text(exponent) + ")", 0);
    }
  }
  return GiNaC::pow(base, exponent);
}

bool reader::opens_application(const tex_node* n) {
  if (!n) return false;
  if (n->kind == tex_node_kind::atom && n->text == "(") return true;
  if (n->kind == tex_node_kind::scripts && n->children.front().kind == tex_node_kind::delimited) return n->children.front().text == "(";
  return n->kind == tex_node_kind::delimited && n->text == "(";
}

GiNaC::ex reader::named(cursor& c, const std::string& name, int derivative) {
  const tex_node& at = c.node();
  if (name == "O") refuse("O is Landau's symbol: O(h^k)", at);
  ++c.k;
  const bool applied = !c.done() && opens_application(&c.node());
  // A state is also written alone (θ for θ(t)): \theta\,(a + b) may be θ applied to a + b, or θ times
  // it; the space says the second to some, and the paper spaces its applications (H_d \, (p, q)).
  if (declared_.is_state(name) && applied && c.node().spaced) {
    refuse("a space between the state " + name + " and a parenthesis: whether " + name + " is applied to it or multiplies it is not written", c.node(),
           name + "(t_n), or " + name + " \\cdot (a + b)");
  }
  if (declared_.is_function(name) && applied) {
    application a = arguments_and_power(c);
    a.args = checked(name, a.args, at);
    if (derivative == 0) return raised(apply_function(name, a.args), a.power);
    if (a.args.size() != 1) refuse("a derivative of " + name + ", a function of " + std::to_string(a.args.size()) + " arguments: by which is not written", at);
    return raised(by_slots(name, std::vector<std::size_t>(static_cast<std::size_t>(derivative), 0), a.args), a.power);
  }
  // A function declared with its variables, written alone: at its variables (L, V' when V(q)).
  if (declared_.is_function(name) && !declared_.is_state(name) && declared_.variables_of(name)) {
    const GiNaC::exvector args = at_variables(name, at);
    if (derivative == 0) return apply_function(name, args);
    if (args.size() != 1) refuse("a derivative of " + name + ", a function of " + std::to_string(args.size()) + " arguments: by which is not written", at);
    return by_slots(name, std::vector<std::size_t>(static_cast<std::size_t>(derivative), 0), args);
  }
  if (derivative > 0) {
    if (!declared_.is_function(name)) {
      refuse("the derivative " + name + std::string(static_cast<std::size_t>(derivative), '\'') + " of " + name +
                 ", which the claims file does not declare a function",
             at, "declare " + name + " under [symbols] functions");
    }
    refuse("the derivative of " + name + " without its argument in parentheses", at);
  }
  // A function alone is no number: read as a symbol it would be a guess (V (h)^2 is not V h^2).
  if (declared_.is_function(name) && !declared_.is_state(name)) {
    refuse("the function " + name + " without its argument in parentheses", at, name + "(x)");
  }
  return symbols_[name];
}

}  // namespace simpson::verify::tex_reading

namespace simpson::verify {

using tex_reading::reader;

GiNaC::ex read_math(const tex_list& side, const tex_declarations& declared, tex_symbols& symbols) {
  try {
    return reader(declared, symbols).whole(side);
  } catch (const GiNaC::pole_error& e) {  // 1/0 as printed: undefined, not a formula
    throw tex_error(std::string("the formula divides by zero (") + e.what() + ")", side.empty() ? 0 : side.front().offset);
  }
}

GiNaC::ex read_tex(const std::string& tex, const tex_declarations& declared, tex_symbols& symbols, const tex_macros* macros) {
  std::vector<tex_token> tokens = tex_tokenize(tex);
  if (macros) tokens = expand_all(tokens, *macros);
  const tex_list list = parse_tex_tree(tokens);
  for (const tex_node& n : list) {
    if (n.kind == tex_node_kind::atom && n.atom_class == tex_class::rel) throw tex_error("a relation '" + n.text + "' in one side", n.offset, n.text);
  }
  return read_math(list, declared, symbols);
}

}  // namespace simpson::verify

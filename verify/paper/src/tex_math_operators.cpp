// The reader's fractions, derivatives, scripts, delimiters, environments, operators, sums and
// integrals: see tex_reader.hpp.

#include "tex_reader.hpp"

#include <simpson/verify/tex_macros.hpp>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>

namespace simpson::verify::tex_reading {

GiNaC::ex reader::fraction(cursor& c) {
  const tex_node& n = unwrapped(c.node());
  if (n.text == "\\binom" || n.text == "\\atop") refuse("a binomial coefficient or \\atop", n);
  if (const auto d = leibniz(c)) return *d;
  ++c.k;
  return whole(n.children[0].children) / whole(n.children[1].children);
}

std::optional<GiNaC::ex> reader::leibniz(cursor& c) {
  const tex_node& n = unwrapped(c.node());
  const tex_list top = unwrapped_list(n.children[0].children), bottom = unwrapped_list(n.children[1].children);
  if (top.empty() || bottom.size() < 2) return std::nullopt;
  const std::optional<differential> dt = differential_of(top.front()), db = differential_of(bottom.front());
  if (!dt || !db) return std::nullopt;
  if (dt->partial != db->partial) refuse("a derivative with d above and \\partial below, or the reverse", n);
  if (dt->plain_d && declared_.symbols.count("d")) {
    refuse("\\frac{d...}{d...} with d declared a symbol is ambiguous: a derivative, or a quotient of products of d", n,
           "write \\mathrm d, or do not declare d");
  }
  if (top.size() == 1) refuse("a derivative operator \\frac{d}{dt} applied to what follows", n, "write \\frac{dX}{dt}");
  if (top.size() != 2) refuse("a derivative of more than one name (the numerator after its d)", n);
  if (bottom.size() != 2 || db->order != 1) refuse("a derivative by more than one variable, or by a variable whose order is not written after it", n);
  const std::string of = symbol_name(top[1]);
  const tex_node& variable = unwrapped(bottom[1]);
  std::string by;
  int k = dt->order, order = 1;
  if (variable.kind == tex_node_kind::scripts && !variable.sup.empty()) {
    const tex_node& sup = unwrapped(variable.sup.front());
    if (sup.kind != tex_node_kind::atom || sup.text.size() != 1 || !std::isdigit(static_cast<unsigned char>(sup.text[0]))) {
      refuse("a derivative whose order is not a digit", variable);
    }
    order = sup.text[0] - '0';
    tex_node base = variable;
    base.sup.clear();
    by = base.sub.empty() ? symbol_name(base.children.front()) : symbol_name(base);
  } else {
    by = symbol_name(variable);
  }
  ++c.k;
  const bool applied = !c.done() && opens_application(&c.node());
  // A function's derivative: at its argument when one follows (a state's too: dq/dt(0) is q'(0)),
  // else at the variable below (dV/dq is V' at q); a state's without one is a quantity, dq/dt.
  if (declared_.is_function(of) && (applied || !declared_.is_state(of))) {
    if (k != order) refuse("the derivative d^" + std::to_string(k) + " " + of + " / d" + by + "^" + std::to_string(order) + ": the orders differ", n);
    const application a = applied ? arguments_and_power(c) : application{{symbols_[by]}, std::nullopt};
    if (a.args.size() != 1) refuse("a derivative of " + of + ", a function of " + std::to_string(a.args.size()) + " arguments, by name", n);
    const GiNaC::symbol x("derivative_variable");
    return raised(GiNaC::diff(apply_function(of, {x}), x, static_cast<unsigned>(k)).subs(x == a.args.front()), a.power);
  }
  if (applied) {
    refuse("\\frac{d" + of + "}{d" + by + "}(...) applies the derivative of " + of + " to an argument, and " + of + " is not declared a function", n,
           "declare " + of + " under [symbols] functions");
  }
  return GiNaC::ex(symbols_[derivative_name(of, by, k, order)]);
}

GiNaC::ex reader::scripts(cursor& c, const std::vector<std::string>& closers) {
  const tex_node& n = c.node();
  const tex_node& base = unwrapped(n.children.front());
  if (base.kind == tex_node_kind::op) return op(c, closers);
  if (base.kind == tex_node_kind::atom && base.text == "\\partial") {
    if (!n.sup.empty() || n.sub.empty()) refuse("\\partial with a superscript", n);
    const std::string by = subscript_text(n.sub.front());
    ++c.k;
    if (c.done()) refuse("\\partial_" + by + " of nothing", n);
    const std::string of = symbol_name(c.node());
    ++c.k;
    if (!c.done() && opens_application(&c.node())) refuse("\\partial_" + by + " " + of + "(...): a partial derivative of a function by name", n);
    return symbols_[derivative_name(of, by, 1, 1)];
  }
  if (base.kind == tex_node_kind::atom && (base.atom_class == tex_class::close || base.atom_class == tex_class::open)) {
    refuse("a script on the delimiter '" + base.text + "'", n);
  }
  // A name (with its subscript), and a superscript that is a power, or primes (a derivative).
  const bool nameable = is_greek_or_letter(base) || base.kind == tex_node_kind::accent ||
                        (base.kind == tex_node_kind::font && (base.text == "mathbf" || base.text == "boldsymbol" || base.text == "mathcal"));
  if (base.kind == tex_node_kind::atom && base.text.size() == 1 && std::isdigit(static_cast<unsigned char>(base.text[0]))) return number(c);
  if (nameable) {
    if (base.kind == tex_node_kind::atom && base.text == "O") refuse("a script on Landau's O", n);
    tex_node named_node = n;
    named_node.sup.clear();
    const std::string name = n.sub.empty() ? symbol_name(base) : symbol_name(named_node);
    if (n.sup.empty()) return named(c, name);
    const tex_list sup = n.sup.front().kind == tex_node_kind::group ? n.sup.front().children : tex_list{n.sup.front()};
    int primes = 0;
    while (primes < static_cast<int>(sup.size()) && sup[static_cast<std::size_t>(primes)].kind == tex_node_kind::atom &&
           sup[static_cast<std::size_t>(primes)].text == "\\prime") {
      ++primes;
    }
    if (primes > 0) {
      if (primes != static_cast<int>(sup.size())) refuse("a power on a derivative written with primes (V'^2)", n, "write (V'(x))^2");
      return named(c, name, primes);
    }
    if (const std::optional<int> k = parenthesised_order(sup)) {
      if (!declared_.is_function(name)) refuse(name + "^{(" + std::to_string(*k) + ")}: a derivative of a name not declared a function", n);
      return named(c, name, *k);
    }
    if (declared_.is_function(name) && !declared_.is_state(name)) {
      const tex_node* after = c.next_after();
      if (opens_application(after)) refuse("a superscript on the function " + name + " before its argument", n, "write (" + name + "(x))^k");
    }
    const GiNaC::ex exponent = whole(sup);
    return power_of(named(c, name), exponent);
  }
  if (!n.sub.empty()) refuse("a subscript on what is not a name", n);
  // A power of a group, a fraction, a root, a delimited expression, a matrix.
  tex_node inner = n.children.front();
  const GiNaC::ex exponent = whole_node(n.sup.front());
  tex_list alone{inner};
  cursor base_cursor{&alone, 0};
  const GiNaC::ex value = primary(base_cursor, {});
  if (!base_cursor.done()) refuse("unexpected", inner);
  ++c.k;
  return power_of(value, exponent);
}

std::optional<int> reader::parenthesised_order(const tex_list& sup) {
  if (sup.size() != 3 || !is_atom(sup[0], "(") || !is_atom(sup[2], ")")) return std::nullopt;
  if (sup[1].kind != tex_node_kind::atom || sup[1].text.size() != 1 || !std::isdigit(static_cast<unsigned char>(sup[1].text[0]))) return std::nullopt;
  return sup[1].text[0] - '0';
}

GiNaC::ex reader::delimited(const tex_node& n) {
  const tex_list body = n.children;
  if (n.text == "|" && n.close == "|") return GiNaC::abs(whole(body));
  if ((n.text == "(" && n.close == ")") || (n.text == "[" && n.close == "]") || (n.text == "\\{" && n.close == "\\}")) return whole(body);
  refuse("\\left" + n.text + " ... \\right" + n.close, n);
}

GiNaC::ex reader::environment(const tex_node& n) {
  static const std::set<std::string> matrices{"matrix", "pmatrix", "bmatrix", "Bmatrix", "smallmatrix", "array", "vmatrix"};
  if (!matrices.count(n.text)) refuse("the environment " + n.text + " inside an expression", n);
  const std::size_t columns = n.rows.front().size();
  GiNaC::matrix m(static_cast<unsigned>(n.rows.size()), static_cast<unsigned>(columns));
  for (std::size_t r = 0; r < n.rows.size(); ++r) {
    if (n.rows[r].size() != columns) refuse("a matrix whose rows have different lengths", n);
    for (std::size_t col = 0; col < columns; ++col) {
      const tex_list& cell = n.rows[r][col].children;
      if (std::any_of(cell.begin(), cell.end(), [](const tex_node& x) { return x.kind == tex_node_kind::atom && x.atom_class == tex_class::rel; })) {
        refuse("a relation inside a matrix", n);
      }
      m(static_cast<unsigned>(r), static_cast<unsigned>(col)) = whole(cell);
    }
  }
  if (n.text == "vmatrix") {
    if (m.rows() != m.cols()) refuse("a determinant of a matrix that is not square", n);
    return m.determinant();
  }
  return m;
}

std::optional<GiNaC::ex> reader::order_term(cursor& c) {
  const tex_node& n = c.node();
  const tex_node& u = unwrapped(n);
  const bool o = (u.kind == tex_node_kind::atom && u.text == "O") ||
                 (upright(u) && upright(u)->second == "O" && (upright(u)->first == "mathrm" || upright(u)->first == "mathcal"));
  if (!o) return std::nullopt;
  const tex_node* after = c.next_after();
  if (!opens_application(after)) refuse("Landau's O without its argument in parentheses", n, "O(h^4)");
  ++c.k;
  const GiNaC::exvector args = arguments(c);
  if (args.size() != 1) refuse("O of more than one argument", n);
  return GiNaC::Order(args.front());
}

std::optional<GiNaC::ex> reader::named_operator(cursor& c) {
  const auto u = upright(c.node());
  if (!u || (u->first != "mathrm" && u->first != "operatorname")) return std::nullopt;
  const tex_node& n = c.node();
  const std::string& name = u->second;
  if (name != "tr" && name != "Tr" && name != "trace" && name != "det") {
    refuse("the operator '" + name + "' is not one the reader knows", n, "\\det, \\operatorname{tr}");
  }
  ++c.k;
  if (c.done()) refuse("the operator " + name + " of nothing", n);
  const GiNaC::ex of = factor(c, {});
  return name == "det" ? determinant_of(of) : trace_of(of);
}

GiNaC::ex reader::op(cursor& c, const std::vector<std::string>& closers) {
  const tex_node& n = c.node();
  const tex_node& o = n.kind == tex_node_kind::scripts ? unwrapped(n.children.front()) : n;
  const std::string& name = o.text;
  if (name == "\\sum") return sum_of(c, closers);
  if (name == "\\int") return integral(c, closers);
  static const std::set<std::string> functions{"\\sin", "\\cos", "\\tan", "\\exp", "\\log", "\\ln", "\\det", "\\sinh", "\\cosh", "\\tanh"};
  if (!functions.count(name)) refuse("the operator " + name, n);
  if (n.kind == tex_node_kind::scripts && !n.sub.empty()) refuse(name + " with a subscript", n);
  std::optional<GiNaC::ex> power;
  if (n.kind == tex_node_kind::scripts) power = whole_node(n.sup.front());  // \sin^2 x
  ++c.k;
  if (c.done()) refuse(name + " of nothing", n);
  // Its argument: a parenthesised group alone (\sin(x) y is sin(x) y); else the product written
  // after it, as mathematics reads it (ISO 80000-2: \sin \omega t is sin(ωt)), up to +, -, a
  // relation, an explicit product (\cdot, \times) or the next operator (\sin x \cos y). A
  // parenthesis inside that product, or a '/' after it, leaves open what the argument is: refused.
  const auto opens = [](const tex_node& node) {
    const tex_node& core = node.kind == tex_node_kind::scripts ? node.children.front() : node;
    return core.kind == tex_node_kind::delimited || (core.kind == tex_node_kind::atom && core.atom_class == tex_class::open);
  };
  const bool parenthesised = opens(c.node());
  GiNaC::ex x = factor(c, {});
  while (!parenthesised && !ends_term(c, closers)) {
    const tex_node& next = c.node();
    const tex_node& core = next.kind == tex_node_kind::scripts ? unwrapped(next.children.front()) : next;
    if (core.kind == tex_node_kind::op) break;
    if (core.kind == tex_node_kind::atom && core.text == "/") {  // sin x/2: sin(x/2) to some, (sin x)/2 to others
      refuse("a '/' after " + name + "'s unparenthesised argument: whether it divides the argument is not written", next,
             name + "(x/2) or \\frac{" + name + " x}{2}");
    }
    if (core.kind == tex_node_kind::atom && (core.atom_class == tex_class::bin || core.text == "*")) break;
    if (opens(next)) {
      refuse("a parenthesis after " + name + "'s unparenthesised argument: whether it belongs to the argument is not written", next,
             name + "(x (1 + y)) or (" + name + " x)(1 + y)");
    }
    x *= factor(c, {});
  }
  GiNaC::ex value;
  if (name == "\\sin") value = GiNaC::sin(x);
  if (name == "\\cos") value = GiNaC::cos(x);
  if (name == "\\tan") value = GiNaC::tan(x);
  if (name == "\\exp") value = GiNaC::exp(x);
  if (name == "\\log" || name == "\\ln") value = GiNaC::log(x);
  if (name == "\\sinh") value = GiNaC::sinh(x);
  if (name == "\\cosh") value = GiNaC::cosh(x);
  if (name == "\\tanh") value = GiNaC::tanh(x);
  if (name == "\\det") value = determinant_of(x);
  return power ? power_of(value, *power) : value;
}

GiNaC::ex reader::sum_of(cursor& c, const std::vector<std::string>& closers) {
  const tex_node& n = c.node();
  if (n.kind != tex_node_kind::scripts || n.sub.empty() || n.sup.empty()) refuse("a \\sum without both its limits", n, "\\sum_{j=0}^{N-1}");
  const tex_list lower = unwrapped_list(n.sub.front().kind == tex_node_kind::group ? n.sub.front().children : tex_list{n.sub.front()});
  if (lower.size() < 3 || !is_atom(lower[1], "=")) refuse("a \\sum whose lower limit is not 'index = value'", n);
  const GiNaC::ex index = symbols_[symbol_name(lower[0])];
  const GiNaC::ex from = whole(tex_list(lower.begin() + 2, lower.end()));
  const GiNaC::ex to = whole_node(n.sup.front());
  ++c.k;
  const GiNaC::ex summand = term(c, closers);
  return apply_function("sum", {summand, index, from, to});
}

GiNaC::ex reader::integral(cursor& c, const std::vector<std::string>& closers) {
  const tex_node& n = c.node();
  if (n.kind != tex_node_kind::scripts || n.sub.empty() || n.sup.empty()) refuse("an integral without both its limits", n, "\\int_0^h");
  const GiNaC::ex lower = whole_node(n.sub.front()), upper = whole_node(n.sup.front());
  ++c.k;
  GiNaC::ex integrand = 1;
  bool any = false;
  for (;;) {
    if (c.done() || ends_term(c, closers)) refuse("an integral without its differential (d x)", n);
    const std::optional<differential> d = differential_of(c.node());
    if (d && !d->partial && d->order == 1 && !(d->plain_d && declared_.symbols.count("d"))) {
      const tex_node* variable = c.next_after();
      if (variable && any) {
        ++c.k;
        const std::string name = symbol_name(*variable);
        ++c.k;
        return GiNaC::integral(symbols_[name], lower, upper, integrand).hold();
      }
    }
    integrand *= factor(c, closers);
    any = true;
  }
}

}  // namespace simpson::verify::tex_reading

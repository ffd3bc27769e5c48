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

GiNaC::ex reader::fraction(cursor& c, const std::vector<std::string>& closers) {
  const tex_node& n = unwrapped(c.node());
  if (n.text == "\\binom" || n.text == "\\atop") refuse("a binomial coefficient or \\atop", n);
  if (const auto d = leibniz(c, closers)) return *d;
  ++c.k;
  return whole(n.children[0].children) / whole(n.children[1].children);
}

std::optional<GiNaC::ex> reader::leibniz(cursor& c, const std::vector<std::string>& closers) {
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
  if (const auto j = jacobian(n, top, bottom, *dt, *db)) {
    ++c.k;
    return *j;
  }
  if (top.size() > 2) refuse("a derivative of more than one name (the numerator after its d)", n);
  // The variables below, each after its own d: \partial q, \partial \dot q^2, \partial q \partial p.
  std::vector<std::pair<std::string, int>> by;
  int total = 0;
  for (std::size_t k = 0; k < bottom.size(); k += 2) {
    const std::optional<differential> d = differential_of(bottom[k]);
    if (!d || d->partial != db->partial || d->order != 1 || k + 1 >= bottom.size()) {
      refuse("a derivative by more than one variable, or by a variable whose order is not written after it", n);
    }
    const tex_node& variable = unwrapped(bottom[k + 1]);
    int order = 1;
    std::string name;
    if (variable.kind == tex_node_kind::scripts && !variable.sup.empty()) {
      const tex_node& sup = unwrapped(variable.sup.front());
      if (sup.kind != tex_node_kind::atom || sup.text.size() != 1 || !std::isdigit(static_cast<unsigned char>(sup.text[0]))) {
        refuse("a derivative whose order is not a digit", variable);
      }
      order = sup.text[0] - '0';
      tex_node base = variable;
      base.sup.clear();
      name = base.sub.empty() ? symbol_name(base.children.front()) : symbol_name(base);
    } else {
      name = symbol_name(variable);
    }
    by.emplace_back(name, order);
    total += order;
  }
  if (top.size() == 1) {  // \frac{d}{dt} X: an operator on what follows
    if (by.size() != 1) refuse("a derivative operator by more than one variable", n);
    if (dt->order != total) refuse("a derivative operator whose orders above and below differ", n);
    ++c.k;
    return derivative_operator(c, closers, by.front().first, total, dt->partial, n);
  }
  const std::string of = symbol_name(top[1]);
  const int k = dt->order;
  ++c.k;
  const bool applied = !c.done() && opens_application(&c.node());
  // A function's derivative: at its argument when one follows (a state's too: dq/dt(0) is q'(0)),
  // else at the variable below (dV/dq is V' at q, \partial L/\partial \dot q at L's variables); a
  // state's without one is a quantity, dq/dt.
  if (declared_.is_function(of) && (applied || !declared_.is_state(of))) {
    if (k != total) refuse("the derivative d^" + std::to_string(k) + " " + of + " / d" + by.front().first + "^" + std::to_string(total) + ": the orders differ", n);
    if (declared_.variables_of(of)) return partial_of(c, of, by, n);
    if (by.size() != 1) refuse("a derivative of " + of + " by more than one variable, and " + of + " declares no variables", n, "declare " + of + "(x, y) under [symbols] functions");
    const application a = applied ? arguments_and_power(c) : application{{symbols_[by.front().first]}, std::nullopt};
    if (a.args.size() != 1) {
      refuse("a derivative of " + of + ", a function of " + std::to_string(a.args.size()) + " arguments, by name, and " + of + " declares no variables", n,
             "declare " + of + "(x, y) under [symbols] functions");
    }
    return raised(by_slots(of, std::vector<std::size_t>(static_cast<std::size_t>(k), 0), a.args), a.power);
  }
  if (by.size() != 1) refuse("a derivative of " + of + ", which is not declared a function, by more than one variable", n);
  if (applied) {
    refuse("\\frac{d" + of + "}{d" + by.front().first + "}(...) applies the derivative of " + of + " to an argument, and " + of + " is not declared a function", n,
           "declare " + of + " under [symbols] functions");
  }
  return GiNaC::ex(symbols_[derivative_name(of, by.front().first, k, total)]);
}

std::optional<GiNaC::ex> reader::jacobian(const tex_node& n, const tex_list& top, const tex_list& bottom, const differential& dt, const differential& db) {
  // \partial(a, b) over \partial(c, d): names between the parentheses, as many above as below.
  const auto names = [&](const tex_list& part) -> std::optional<std::vector<GiNaC::symbol>> {
    if (part.size() < 2) return std::nullopt;
    tex_list inside;
    if (part.size() == 2 && part[1].kind == tex_node_kind::delimited && part[1].text == "(") {
      inside = part[1].children;
    } else if (is_atom(part[1], "(") && is_atom(part.back(), ")")) {
      inside = tex_list(part.begin() + 2, part.end() - 1);
    } else {
      return std::nullopt;
    }
    std::vector<GiNaC::symbol> out;
    tex_list name;
    const auto take = [&] {
      if (name.size() != 1) refuse("a Jacobian whose parentheses hold what is not names between commas", n);
      out.push_back(GiNaC::ex_to<GiNaC::symbol>(GiNaC::ex(symbols_[symbol_name(name.front())])));
      name.clear();
    };
    for (const tex_node& x : inside) {
      if (is_atom(x, ",")) {
        take();
      } else {
        name.push_back(x);
      }
    }
    take();
    return out;
  };
  const auto above = names(top), below = names(bottom);
  if (!above && !below) return std::nullopt;
  if (!above || !below || !dt.partial || !db.partial || dt.order != 1 || db.order != 1) refuse("a Jacobian is \\frac{\\partial(a, b)}{\\partial(c, d)}", n);
  if (above->size() != below->size()) refuse("a Jacobian with " + std::to_string(above->size()) + " names above and " + std::to_string(below->size()) + " below", n);
  return jacobian_of(*above, *below);
}

GiNaC::ex reader::scripts(cursor& c, const std::vector<std::string>& closers) {
  const tex_node& n = c.node();
  const tex_node& base = unwrapped(n.children.front());
  if (base.kind == tex_node_kind::op) return op(c, closers);
  if (base.kind == tex_node_kind::atom && base.text == "\\partial") {
    if (!n.sup.empty() || n.sub.empty()) refuse("\\partial with a superscript", n);
    // By a variable's name (\partial_q, \partial_{\dot q}) or by a slot (\partial_2).
    const tex_node& sub = unwrapped(n.sub.front());
    const bool slot = sub.kind == tex_node_kind::atom && sub.text.size() == 1 && std::isdigit(static_cast<unsigned char>(sub.text[0]));
    const std::string by = slot ? sub.text : symbol_name(sub);
    ++c.k;
    if (c.done()) refuse("\\partial_" + by + " of nothing", n);
    const std::string of = symbol_name(c.node());
    if (declared_.is_function(of) && !declared_.is_state(of)) {
      ++c.k;
      if (!slot) return partial_of(c, of, {{by, 1}}, n);
      const std::size_t k = static_cast<std::size_t>(sub.text[0] - '0');
      const GiNaC::exvector args = !c.done() && opens_application(&c.node()) ? checked(of, arguments(c), n) : at_variables(of, n);
      if (k == 0 || k > args.size()) refuse("\\partial_" + by + " " + of + ": " + of + " has " + std::to_string(args.size()) + " arguments", n);
      return by_slots(of, {k - 1}, args);
    }
    if (slot) refuse("\\partial_" + by + " " + of + ": a derivative by slot of what is not declared a function", n);
    ++c.k;
    if (!c.done() && opens_application(&c.node())) {
      refuse("\\partial_" + by + " " + of + "(...): a partial derivative of " + of + ", which is not declared a function", n,
             "declare " + of + "(x, y) under [symbols] functions");
    }
    return symbols_[derivative_name(of, by, 1, 1)];
  }
  if (base.kind == tex_node_kind::atom && base.text == "D" && !n.sub.empty() && n.sup.empty()) {
    if (const auto d = slot_operator(c)) return *d;
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

std::optional<GiNaC::ex> reader::named_operator(cursor& c, const std::vector<std::string>& closers) {
  const auto u = upright(c.node());
  if (!u || (u->first != "mathrm" && u->first != "operatorname")) return std::nullopt;
  const tex_node& n = c.node();
  const std::string& name = u->second;
  if (u->first == "operatorname" && is_known_function(name)) {  // \operatorname{sin} x: \sin x
    ++c.k;
    if (c.done()) refuse("the operator " + name + " of nothing", n);
    return *known_function(name, operand(c, closers, "\\operatorname{" + name + "}"));
  }
  if (name != "tr" && name != "Tr" && name != "trace" && name != "det") {
    refuse("the operator '" + name + "' is not one the reader knows", n, "\\det, \\operatorname{tr}, \\operatorname{sin}");
  }
  ++c.k;
  if (c.done()) refuse("the operator " + name + " of nothing", n);
  const GiNaC::ex of = factor(c, {});
  return name == "det" ? determinant_of(of) : trace_of(of);
}

bool reader::is_known_function(const std::string& name) {
  static const std::set<std::string> names{"sin", "cos", "tan", "exp", "log", "ln", "sinh", "cosh", "tanh"};
  return names.count(name) > 0;
}

std::optional<GiNaC::ex> reader::known_function(const std::string& name, const GiNaC::ex& x) {
  if (name == "sin") return GiNaC::sin(x);
  if (name == "cos") return GiNaC::cos(x);
  if (name == "tan") return GiNaC::tan(x);
  if (name == "exp") return GiNaC::exp(x);
  if (name == "log" || name == "ln") return GiNaC::log(x);
  if (name == "sinh") return GiNaC::sinh(x);
  if (name == "cosh") return GiNaC::cosh(x);
  if (name == "tanh") return GiNaC::tanh(x);
  return std::nullopt;
}

GiNaC::ex reader::op(cursor& c, const std::vector<std::string>& closers) {
  const tex_node& n = c.node();
  const tex_node& o = n.kind == tex_node_kind::scripts ? unwrapped(n.children.front()) : n;
  const std::string& name = o.text;
  if (name == "\\sum") return sum_of(c, closers);
  if (name == "\\int") return integral(c, closers);
  if (name != "\\det" && !is_known_function(name.substr(1))) refuse("the operator " + name, n);
  if (n.kind == tex_node_kind::scripts && !n.sub.empty()) refuse(name + " with a subscript", n);
  std::optional<GiNaC::ex> power;
  if (n.kind == tex_node_kind::scripts) power = whole_node(n.sup.front());  // \sin^2 x
  ++c.k;
  if (c.done()) refuse(name + " of nothing", n);
  const GiNaC::ex x = operand(c, closers, name);
  const GiNaC::ex value = name == "\\det" ? determinant_of(x) : *known_function(name.substr(1), x);
  return power ? power_of(value, *power) : value;
}

GiNaC::ex reader::operand(cursor& c, const std::vector<std::string>& closers, const std::string& name, bool differentiates) {
  // A parenthesised group alone (\sin(x) y is sin(x) y); else the product written after it, as
  // mathematics reads it (ISO 80000-2: \sin \omega t is sin(ωt)), up to +, -, a relation, an explicit
  // product (\cdot, \times) or the next operator (\sin x \cos y). What leaves open where the argument
  // ends is refused: a parenthesis inside that product, a '/' after it, a velocity in it (\sin\theta
  // \dot\phi is (sin θ) φ̇ to a physicist), or a space command after an unspaced first factor
  // (\sin^2\theta\,\dot\phi^2 ends the argument at the space to many, while the paper spaces every
  // factor of one argument: \sin \, \omega \, t, which reads as sin(ωt)).
  const auto opens = [](const tex_node& node) {
    const tex_node& core = node.kind == tex_node_kind::scripts ? node.children.front() : node;
    return core.kind == tex_node_kind::delimited || (core.kind == tex_node_kind::atom && core.atom_class == tex_class::open);
  };
  const bool parenthesised = opens(c.node());
  const bool spaced_factors = c.node().spaced;  // \sin \, \omega \, t: the writer spaces every factor
  GiNaC::ex x = factor(c, {});
  while (!parenthesised && !ends_term(c, closers)) {
    const tex_node& next = c.node();
    const tex_node& core = next.kind == tex_node_kind::scripts ? unwrapped(next.children.front()) : next;
    if (core.kind == tex_node_kind::op) break;
    if (next.spaced && !spaced_factors) {
      refuse("a space after " + name + "'s unparenthesised argument: whether what follows belongs to the argument is not written", next,
             name + "(x)\\, y or " + name + "(x\\, y)");
    }
    if (core.kind == tex_node_kind::atom && core.text == "/") {  // sin x/2: sin(x/2) to some, (sin x)/2 to others
      refuse("a '/' after " + name + "'s unparenthesised argument: whether it divides the argument is not written", next,
             name + "(x/2) or \\frac{" + name + " x}{2}");
    }
    if (core.kind == tex_node_kind::atom && (core.atom_class == tex_class::bin || core.text == "*")) break;
    if (opens(next)) {
      refuse("a parenthesis after " + name + "'s unparenthesised argument: whether it belongs to the argument is not written", next,
             name + "(x (1 + y)) or (" + name + " x)(1 + y)");
    }
    if (!differentiates && core.kind == tex_node_kind::accent && (core.text == "\\dot" || core.text == "\\ddot")) {  // \sin\theta\dot\phi: (sin θ) φ̇ to a physicist
      refuse("a velocity after " + name + "'s unparenthesised argument: whether it belongs to the argument is not written", next,
             name + "(\\theta)\\,\\dot\\phi or " + name + "(\\theta\\dot\\phi)");
    }
    x *= factor(c, {});
  }
  return x;
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

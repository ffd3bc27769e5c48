// The reader's functions of several arguments and their derivatives: by a variable's name
// (\frac{\partial L}{\partial \dot q}(a, b), \partial_q L), by slot (D_2 L_d(a, b), \partial_1 L), in
// slanted form (\partial L_h / \partial \psi_l), and along a trajectory (\frac{d}{dt} X). See
// tex_reader.hpp and tex_math.hpp.

#include "tex_reader.hpp"

#include <algorithm>
#include <cctype>
#include <set>

namespace simpson::verify::tex_reading {

namespace {

std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

GiNaC::exvector reader::checked(const std::string& name, GiNaC::exvector args, const tex_node& at) {
  const std::vector<std::string>* variables = declared_.variables_of(name);
  if (variables && variables->size() != args.size()) {
    refuse(name + ", a function of " + std::to_string(variables->size()) + " variables (" + listed(*variables) + "), applied to " +
               std::to_string(args.size()) + " argument" + (args.size() == 1 ? "" : "s"),
           at);
  }
  return args;
}

GiNaC::exvector reader::at_variables(const std::string& name, const tex_node& at) {
  const std::vector<std::string>* variables = declared_.variables_of(name);
  if (!variables) refuse("the function " + name + " without its argument in parentheses", at, name + "(x), or declare " + name + "(x, y) with its variables");
  GiNaC::exvector out;
  for (const std::string& v : *variables) out.push_back(symbols_[v]);
  return out;
}

std::size_t reader::slot_of(const std::string& of, const std::string& by, const tex_node& at) {
  const std::vector<std::string>* variables = declared_.variables_of(of);
  if (!variables) refuse("a derivative of " + of + " by name, and " + of + " declares no variables", at, "declare " + of + "(x, y) under [symbols] functions");
  const auto it = std::find(variables->begin(), variables->end(), by);
  if (it == variables->end()) refuse("a derivative of " + of + " by " + by + ", which is not one of its variables (" + listed(*variables) + ")", at);
  return static_cast<std::size_t>(it - variables->begin());
}

GiNaC::ex reader::by_slots(const std::string& of, const std::vector<std::size_t>& slots, const GiNaC::exvector& args) {
  GiNaC::exvector xs;
  GiNaC::lst at;
  for (std::size_t k = 0; k < args.size(); ++k) {
    const GiNaC::symbol x("slot_" + std::to_string(k));
    xs.push_back(x);
    at.append(x == args[k]);
  }
  GiNaC::ex e = apply_function(of, xs);
  for (const std::size_t s : slots) e = e.diff(GiNaC::ex_to<GiNaC::symbol>(xs[s]));
  return e.subs(at, GiNaC::subs_options::no_pattern);  // all slots at once: an argument may hold another slot's symbol
}

GiNaC::ex reader::partial_of(cursor& c, const std::string& of, const std::vector<std::pair<std::string, int>>& by, const tex_node& at) {
  std::vector<std::size_t> slots;
  for (const auto& [name, order] : by) {
    const std::size_t slot = slot_of(of, name, at);
    for (int k = 0; k < order; ++k) slots.push_back(slot);
  }
  if (!c.done() && opens_application(&c.node())) {
    application a = arguments_and_power(c);
    return raised(by_slots(of, slots, checked(of, a.args, at)), a.power);
  }
  return by_slots(of, slots, at_variables(of, at));
}

std::optional<GiNaC::ex> reader::slot_operator(cursor& c) {
  // D_k ... F: each D_k's digit, then the function; anything else leaves D_k a name.
  std::vector<std::size_t> slots;
  std::size_t k = c.k;
  const tex_node& first = c.node();
  const auto slot_at = [&](std::size_t j) -> std::optional<std::size_t> {
    if (j >= c.list->size()) return std::nullopt;
    const tex_node& n = (*c.list)[j];
    if (n.kind != tex_node_kind::scripts || !n.sup.empty() || n.sub.empty()) return std::nullopt;
    const tex_node& base = unwrapped(n.children.front());
    const tex_node& sub = unwrapped(n.sub.front());
    if (base.kind != tex_node_kind::atom || base.text != "D") return std::nullopt;
    if (sub.kind != tex_node_kind::atom || sub.text.size() != 1 || !std::isdigit(static_cast<unsigned char>(sub.text[0])) || sub.text == "0") return std::nullopt;
    return static_cast<std::size_t>(sub.text[0] - '1');
  };
  while (const auto s = slot_at(k)) {
    slots.push_back(*s);
    ++k;
  }
  if (k >= c.list->size()) return std::nullopt;
  std::string of;
  try {
    of = symbol_name((*c.list)[k]);
  } catch (const tex_error&) {
    return std::nullopt;
  }
  if (!declared_.is_function(of) || declared_.is_state(of)) return std::nullopt;
  const std::string written = "D_" + std::to_string(slots.front() + 1);
  if (declared_.symbols.count(written) || declared_.functions.count(written)) {
    refuse(written + " " + of + ": " + written + " is declared, so a derivative by slot and a product are both readings", first);
  }
  c.k = k;
  const tex_node& at = c.node();
  ++c.k;
  GiNaC::exvector args;
  std::optional<GiNaC::ex> power;
  if (!c.done() && opens_application(&c.node())) {
    application a = arguments_and_power(c);
    args = checked(of, a.args, at);
    power = a.power;
  } else {
    args = at_variables(of, at);
  }
  for (const std::size_t s : slots) {
    if (s >= args.size()) refuse(written + " " + of + ": " + of + " has " + std::to_string(args.size()) + " arguments", first);
  }
  return raised(by_slots(of, slots, args), power);
}

GiNaC::ex reader::slanted_derivative(cursor& c, const std::vector<std::string>& closers) {
  const tex_node& n = c.node();
  const auto at = [&](std::size_t j) -> const tex_node* { return c.k + j < c.list->size() ? &(*c.list)[c.k + j] : nullptr; };
  const tex_node* of = at(1);
  const tex_node* slash = at(2);
  const tex_node* d = at(3);
  const tex_node* by = at(4);
  if (!of || !slash || !d || !by || !is_atom(*slash, "/") || !is_atom(*d, "\\partial")) {
    refuse("a \\partial outside a derivative", n, "\\frac{\\partial L}{\\partial q}, \\partial_q L or \\partial L / \\partial q");
  }
  const std::string of_name = symbol_name(*of), by_name = symbol_name(*by);
  c.k += 5;
  GiNaC::ex value;
  if (declared_.is_function(of_name) && !declared_.is_state(of_name)) {
    value = partial_of(c, of_name, {{by_name, 1}}, n);
  } else {
    if (!c.done() && opens_application(&c.node())) {
      refuse("\\partial " + of_name + " / \\partial " + by_name + "(...): a derivative of " + of_name + ", which is not declared a function, applied", n);
    }
    value = symbols_[derivative_name(of_name, by_name, 1, 1)];
  }
  if (!ends_term(c, closers)) {
    refuse("a slanted derivative \\partial " + of_name + " / \\partial " + by_name + " followed by more factors: whether they divide or multiply is not written", n,
           "\\frac{\\partial " + of_name + "}{\\partial " + by_name + "} ...");
  }
  return value;
}

GiNaC::ex reader::derivative_operator(cursor& c, const std::vector<std::string>& closers, const std::string& by, int order, bool partial,
                                      const tex_node& at) {
  const std::string name = partial ? "\\frac{\\partial}{\\partial " + by + "}" : "\\frac{d}{d" + by + "}";
  if (c.done() || ends_term(c, closers)) refuse("the derivative operator " + name + " of nothing", at, "write \\frac{dX}{d" + by + "}");
  GiNaC::ex e = operand(c, closers, name, true);
  for (int k = 0; k < order; ++k) {
    e = partial ? e.diff(symbols_[by]) : along_trajectory(e, by, at);
  }
  return e;
}

GiNaC::ex reader::along_trajectory(const GiNaC::ex& e, const std::string& by, const tex_node& at) {
  // The states (names declared both a function and a symbol) and their derivatives in `by` move
  // along the trajectory; `by` itself; every other symbol must be declared, and is a constant.
  std::set<std::string> states;
  for (const std::string& f : declared_.functions) {
    if (declared_.is_state(f)) states.insert(f);
  }
  std::set<GiNaC::ex, GiNaC::ex_is_less> symbols;
  for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i) {
    if (GiNaC::is_a<GiNaC::symbol>(*i)) symbols.insert(*i);
  }
  GiNaC::ex out = 0;
  for (const GiNaC::ex& s : symbols) {
    const std::string name = GiNaC::ex_to<GiNaC::symbol>(s).get_name();
    const GiNaC::ex partial = e.diff(GiNaC::ex_to<GiNaC::symbol>(s));
    if (name == by) {
      out += partial;
      continue;
    }
    bool moving = false;
    for (const std::string& x : states) {
      for (int k = 0; k <= 8 && !moving; ++k) {
        if (name != (k == 0 ? x : derivative_name(x, by, k, k))) continue;
        out += partial * symbols_[derivative_name(x, by, k + 1, k + 1)];
        moving = true;
      }
    }
    if (moving) continue;
    if (!declared_.symbols.count(name)) {
      refuse("the derivative along a trajectory of an expression in " + name + ", which is neither a state nor declared a constant symbol", at,
             "declare " + name + " a state (under functions and real) or a symbol");
    }
  }
  return out;
}

}  // namespace simpson::verify::tex_reading

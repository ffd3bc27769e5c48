// What a document's math means: see tex_math.hpp. One function per construct; a node no function
// takes is refused, named.

#include <simpson/verify/tex_math.hpp>

#include "tex_math_parts.hpp"

#include <simpson/verify/tex_macros.hpp>

#include <algorithm>
#include <cctype>
#include <optional>

namespace simpson::verify {
namespace {

using namespace tex_reading;

// --- the reader: the tree read into GiNaC

class reader {
 public:
  reader(const tex_declarations& declared, tex_symbols& symbols) : declared_(declared), symbols_(symbols) {}

  GiNaC::ex whole(const tex_list& list) {
    cursor c{&list, 0};
    GiNaC::ex e = sum(c, {});
    if (!c.done()) refuse("unexpected '" + c.node().text + "'", c.node());
    return e;
  }

 private:
  struct cursor {
    const tex_list* list;
    std::size_t k;
    void skip() {
      while (k < list->size() && ((*list)[k].kind == tex_node_kind::label || ((*list)[k].kind == tex_node_kind::group && (*list)[k].children.empty()))) ++k;
    }
    bool done() {
      skip();
      return k >= list->size();
    }
    const tex_node& node() {
      skip();
      return (*list)[k];
    }
    const tex_node* next_after() {  // the node after the current one
      skip();
      std::size_t j = k + 1;
      while (j < list->size() && (*list)[j].kind == tex_node_kind::label) ++j;
      return j < list->size() ? &(*list)[j] : nullptr;
    }
  };

  static bool is_atom(const tex_node& n, const std::string& text) { return n.kind == tex_node_kind::atom && n.text == text; }

  /// A closing atom (or one carrying scripts, \Big)^2) of `closers`.
  static bool closes(const tex_node& n, const std::vector<std::string>& closers) {
    const tex_node& atom = n.kind == tex_node_kind::scripts ? n.children.front() : n;
    return atom.kind == tex_node_kind::atom && std::find(closers.begin(), closers.end(), atom.text) != closers.end();
  }

  static bool ends_term(cursor& c, const std::vector<std::string>& closers) {
    if (c.done()) return true;
    const tex_node& n = c.node();
    if (closes(n, closers)) return true;
    if (n.kind == tex_node_kind::atom && (n.text == "+" || n.text == "-" || n.atom_class == tex_class::rel || n.atom_class == tex_class::punct)) {
      return true;
    }
    return false;
  }

  // sum := [+-] term {+- term}
  GiNaC::ex sum(cursor& c, const std::vector<std::string>& closers) {
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

  // term := factor {[\cdot \times * /] factor}
  GiNaC::ex term(cursor& c, const std::vector<std::string>& closers) {
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

  GiNaC::ex factor(cursor& c, const std::vector<std::string>& closers) {
    GiNaC::ex f = primary(c, closers);
    while (!c.done() && is_atom(c.node(), "!")) {  // n!
      const tex_node& bang = c.node();
      ++c.k;
      if (GiNaC::is_a<GiNaC::numeric>(f) && GiNaC::ex_to<GiNaC::numeric>(f) > 1000) refuse("a factorial beyond the reader's exact arithmetic", bang);
      f = GiNaC::factorial(f);
    }
    return f;
  }

  GiNaC::ex primary(cursor& c, const std::vector<std::string>& closers) {
    if (c.done()) throw tex_error("a factor missing at the end of the formula (after \\cdot, \\times or an operator)", c.list->empty() ? 0 : c.list->back().offset);
    const tex_node& n = c.node();
    switch (n.kind) {
      case tex_node_kind::atom: return atom(c);
      case tex_node_kind::group: {
        if (const auto landau = order_term(c)) return *landau;
        if (const auto op = named_operator(c)) return *op;
        // {{dV}\over{dq}}(x): a fraction alone in its group (\over's braces) is read where the group
        // is, so that an application after it applies to it.
        if (unwrapped(n).kind == tex_node_kind::fraction) return fraction(c);
        if (differential_of(n)) refuse("an upright d outside a derivative or an integral", n);
        ++c.k;
        return whole(n.children);
      }
      case tex_node_kind::fraction: return fraction(c);
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
        if (const auto op = named_operator(c)) return *op;
        if (n.text == "mathbf" || n.text == "boldsymbol" || n.text == "mathcal" || n.text == "mathbb") return named(c, symbol_name(n));
        if (differential_of(n)) refuse("an upright d outside a derivative or an integral", n);
        refuse("the font " + n.text + " on '" + normal_form(n.children) + "': an upright name the reader gives no meaning to", n,
               "\\operatorname{tr}, \\det, \\mathrm d in a derivative, \\mathcal O(h^k)");
      }
      case tex_node_kind::op: return op(c, closers);
      case tex_node_kind::accent: return named(c, symbol_name(n));
      case tex_node_kind::text: refuse("words inside a formula (\\text{" + n.text + "})", n);
      case tex_node_kind::label: break;
    }
    refuse("unexpected", n);
  }

  GiNaC::ex atom(cursor& c) {
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
    if (n.text == "\\partial") refuse("a \\partial outside a derivative", n, "\\frac{\\partial L}{\\partial q} or \\partial_q L");
    if (n.text == "\\ldots" || n.text == "\\cdots" || n.text == "\\dots") refuse("an ellipsis: what it stands for is not written", n);
    if (n.text == "\\infty") refuse("\\infty", n);
    if (n.text == "\\prime") refuse("a prime on no function (a prime is the derivative of a declared function: V'(x))", n);
    if (n.atom_class == tex_class::close) refuse("a '" + n.text + "' that closes nothing", n);
    refuse("unexpected '" + n.text + "'", n);
  }

  /// Digits (and a decimal point between digits): an exact number; a superscript on its last digit
  /// is on the number (12^2).
  GiNaC::ex number(cursor& c) {
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

  GiNaC::ex whole_node(const tex_node& n) { return n.kind == tex_node_kind::group ? whole(n.children) : whole({n}); }

  /// After an opening atom: the expression to its closing one (which may carry a superscript:
  /// \Big( ... \Big)^2 squares the whole).
  GiNaC::ex parenthesised(cursor& c, const tex_node& open) {
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

  /// The arguments of an application: after '(' (an atom) up to its ')', split at commas, or a
  /// \left( ... \right); and a power on its closing delimiter (V(x)^2 squares the application).
  struct application {
    GiNaC::exvector args;
    std::optional<GiNaC::ex> power;
  };
  application arguments_and_power(cursor& c) {
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
        if (n.kind == tex_node_kind::atom && n.atom_class == tex_class::open) ++depth;
        if (n.kind == tex_node_kind::atom && n.atom_class == tex_class::close) --depth;
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

  GiNaC::exvector arguments(cursor& c) {
    const tex_node& at = c.node();
    application a = arguments_and_power(c);
    if (a.power) refuse("a power on the argument's closing delimiter where no power can stand", at);
    return a.args;
  }

  GiNaC::ex raised(const GiNaC::ex& e, const std::optional<GiNaC::ex>& power) { return power ? power_of(e, *power) : e; }

  /// base^exponent, an exponent whose numerator or denominator exceeds 1000 refused: exact arithmetic
  /// on 9^{9^9} would take what no formula of a derivation needs.
  GiNaC::ex power_of(const GiNaC::ex& base, const GiNaC::ex& exponent) {
    if (GiNaC::is_a<GiNaC::numeric>(exponent)) {
      const GiNaC::numeric& e = GiNaC::ex_to<GiNaC::numeric>(exponent);
      if (!e.is_rational() || GiNaC::abs(e.numer()) > 1000 || e.denom() > 1000) {
        throw tex_error("an exponent beyond the reader's exact arithmetic (" + canonical_text(exponent) + ")", 0);
      }
    }
    return GiNaC::pow(base, exponent);
  }

  static bool opens_application(const tex_node* n) {
    if (!n) return false;
    if (n->kind == tex_node_kind::atom && n->text == "(") return true;
    if (n->kind == tex_node_kind::scripts && n->children.front().kind == tex_node_kind::delimited) return n->children.front().text == "(";
    return n->kind == tex_node_kind::delimited && n->text == "(";
  }

  /// A name: a symbol, or a declared function applied to what follows in parentheses.
  GiNaC::ex named(cursor& c, const std::string& name, int derivative = 0) {
    const tex_node& at = c.node();
    if (name == "O") refuse("O is Landau's symbol: O(h^k)", at);
    ++c.k;
    const bool applied = !c.done() && opens_application(&c.node());
    if (declared_.is_function(name) && applied) {
      const application a = arguments_and_power(c);
      if (derivative == 0) return raised(apply_function(name, a.args), a.power);
      if (a.args.size() != 1) refuse("a derivative of " + name + ", a function of " + std::to_string(a.args.size()) + " arguments: by which is not written", at);
      const GiNaC::symbol x("derivative_variable");
      return raised(GiNaC::diff(apply_function(name, {x}), x, static_cast<unsigned>(derivative)).subs(x == a.args.front()), a.power);
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

  // --- fractions and derivatives

  GiNaC::ex fraction(cursor& c) {
    const tex_node& n = unwrapped(c.node());
    if (n.text == "\\binom" || n.text == "\\atop") refuse("a binomial coefficient or \\atop", n);
    if (const auto d = leibniz(c)) return *d;
    ++c.k;
    return whole(n.children[0].children) / whole(n.children[1].children);
  }

  /// \frac{d^k X}{d y^k}, {\rm d}, \mathrm d, \partial: the derivative, or none when the fraction
  /// is not one.
  std::optional<GiNaC::ex> leibniz(cursor& c) {
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

  // --- scripts

  GiNaC::ex scripts(cursor& c, const std::vector<std::string>& closers) {
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

  static std::optional<int> parenthesised_order(const tex_list& sup) {  // ^{(3)}
    if (sup.size() != 3 || !is_atom(sup[0], "(") || !is_atom(sup[2], ")")) return std::nullopt;
    if (sup[1].kind != tex_node_kind::atom || sup[1].text.size() != 1 || !std::isdigit(static_cast<unsigned char>(sup[1].text[0]))) return std::nullopt;
    return sup[1].text[0] - '0';
  }

  // --- delimiters, matrices

  GiNaC::ex delimited(const tex_node& n) {
    const tex_list body = n.children;
    if (n.text == "|" && n.close == "|") return GiNaC::abs(whole(body));
    if ((n.text == "(" && n.close == ")") || (n.text == "[" && n.close == "]") || (n.text == "\\{" && n.close == "\\}")) return whole(body);
    refuse("\\left" + n.text + " ... \\right" + n.close, n);
  }

  GiNaC::ex environment(const tex_node& n) {
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

  // --- operators

  /// {\rm O}(h^k), \mathcal O(h^k), O(h^k): GiNaC's order term.
  std::optional<GiNaC::ex> order_term(cursor& c) {
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

  /// \det, \operatorname{tr}, \mathrm{tr}, {\rm det}: of the factor that follows.
  std::optional<GiNaC::ex> named_operator(cursor& c) {
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

  GiNaC::ex op(cursor& c, const std::vector<std::string>& closers) {
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
    // relation, an explicit operation (\cdot, \times, /) or the next operator (\sin x \cos y). A
    // parenthesis inside that product leaves open whether it belongs to the argument: refused.
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
      if (core.kind == tex_node_kind::atom && (core.atom_class == tex_class::bin || core.text == "/" || core.text == "*")) break;
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

  /// \sum_{j=a}^{b} s: the summand is the rest of the term.
  GiNaC::ex sum_of(cursor& c, const std::vector<std::string>& closers) {
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

  /// \int_a^b f \, dx: held (an integrand written in the state and its derivative must not be
  /// taken for a constant of x).
  GiNaC::ex integral(cursor& c, const std::vector<std::string>& closers) {
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

  const tex_declarations& declared_;
  tex_symbols& symbols_;
};

}  // namespace

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

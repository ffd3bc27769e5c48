#include <simpson/verify/tex_math.hpp>

#include <algorithm>
#include <cctype>
#include <sstream>
#include <set>

namespace simpson::verify {

const GiNaC::symbol& tex_symbols::operator[](const std::string& name) {
  auto it = symbols_.find(name);
  if (it == symbols_.end()) it = symbols_.emplace(name, GiNaC::symbol(name)).first;
  return it->second;
}

tex_symbols& paper_symbols() {
  static tex_symbols symbols;
  return symbols;
}

namespace {

std::vector<std::string>& function_registry() {
  static std::vector<std::string> names{"V", "L_d", "L_h", "H_d", "Q", "Q_c", "q", "varphi_0", "varphi_1/2", "varphi_1", "psi"};
  return names;
}

}  // namespace

const std::vector<std::string>& function_names() { return function_registry(); }

void declare_function(const std::string& name) {
  std::vector<std::string>& names = function_registry();
  if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
}

std::string function_name(const std::string& name, std::size_t arity) {
  // One of GiNaC's own (psi, the digamma function; beta; zeta): ours is registered apart under a
  // marked name, so that GiNaC never evaluates it as its own. Decided once, before ours exists.
  static std::map<std::pair<std::string, std::size_t>, std::string> names;
  const auto key = std::make_pair(name, arity);
  const auto it = names.find(key);
  if (it != names.end()) return it->second;
  std::string registered = name + "_f";
  try {
    (void)GiNaC::function::find_function(name, static_cast<unsigned>(arity));
  } catch (const std::runtime_error&) {
    registered = name;
  }
  return names.emplace(key, registered).first->second;
}

GiNaC::ex apply_function(const std::string& name, const GiNaC::exvector& args) {
  static std::map<std::pair<std::string, std::size_t>, unsigned> serials;
  const auto key = std::make_pair(name, args.size());
  auto it = serials.find(key);
  if (it == serials.end()) {
    const std::string registered = function_name(name, args.size());
    it = serials.emplace(key, GiNaC::function::register_new(GiNaC::function_options(registered, static_cast<unsigned>(args.size())))).first;
  }
  return GiNaC::function(it->second, args);
}

std::string derivative_name(const std::string& of, const std::string& by, int k, int n) {
  const auto power = [](int e) { return e == 1 ? std::string() : "^" + std::to_string(e); };
  return "d" + power(k) + of + "/d" + by + power(n);
}

bool is_sum(const GiNaC::ex& e) {
  return GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == "sum" && e.nops() == 4;
}

namespace {

struct token {
  enum class kind { command, character, end } what;
  std::string text;  // "\omega", "(", "4", "q"
  std::size_t offset;
};

std::vector<token> tokenize(const std::string& tex) {
  std::vector<token> out;
  for (std::size_t k = 0; k < tex.size();) {
    const char c = tex[k];
    if (std::isspace(static_cast<unsigned char>(c)) || c == '~') {
      ++k;
    } else if (c == '\\') {
      std::size_t j = k + 1;
      while (j < tex.size() && std::isalpha(static_cast<unsigned char>(tex[j]))) ++j;
      if (j == k + 1 && j < tex.size()) ++j;  // a one-character command: \, \! \; \\ \{
      out.push_back({token::kind::command, tex.substr(k, j - k), k});
      k = j;
    } else {
      out.push_back({token::kind::character, std::string(1, c), k});
      ++k;
    }
  }
  out.push_back({token::kind::end, "end of formula", tex.size()});
  return out;
}

// The tables of the subset.
const std::set<std::string>& ignored_commands() {
  static const std::set<std::string> names{"\\,", "\\!", "\\;", "\\:", "\\ ", "\\quad", "\\qquad", "\\displaystyle",
                                           "\\big", "\\Big", "\\bigg", "\\Bigg", "\\bigl", "\\bigr", "\\Bigl", "\\Bigr",
                                           "\\left", "\\right", "\\textstyle", "\\limits"};
  return names;
}

const std::map<std::string, std::string>& greek() {
  static const std::map<std::string, std::string> names{
      {"\\omega", "omega"}, {"\\theta", "theta"}, {"\\alpha", "alpha"}, {"\\beta", "beta"},     {"\\gamma", "gamma"},
      {"\\delta", "delta"}, {"\\xi", "xi"},       {"\\eta", "eta"},     {"\\zeta", "zeta"},     {"\\varphi", "varphi"},
      {"\\phi", "phi"},     {"\\psi", "psi"},     {"\\Delta", "Delta"}, {"\\Phi", "Phi"},       {"\\Gamma", "Gamma"},
      {"\\Sigma", "Sigma"}, {"\\ell", "l"},       {"\\pi", "pi"}};
  return names;
}

class parser {
 public:
  parser(const std::string& tex, tex_symbols& symbols) : tokens_(tokenize(tex)), symbols_(symbols) {}

  GiNaC::ex parse_all() {
    GiNaC::ex e = expression();
    if (peek().what != token::kind::end) fail("unexpected token");
    return e;
  }

 private:
  const token& peek() {
    while (tokens_[at_].what == token::kind::command && ignored_commands().count(tokens_[at_].text)) ++at_;
    return tokens_[at_];
  }
  token next() {
    const token t = peek();
    if (t.what != token::kind::end) ++at_;
    return t;
  }
  bool accept(const std::string& text) {
    if (peek().text == text && peek().what != token::kind::end) {
      ++at_;
      return true;
    }
    return false;
  }
  void expect(const std::string& text) {
    if (!accept(text)) fail("expected '" + text + "'");
  }
  [[noreturn]] void fail(const std::string& why) {
    const token& t = peek();
    throw tex_parse_error(why + " at token '" + t.text + "'", t.text, t.offset);
  }

  bool ends_product(const token& t) {
    if (t.what == token::kind::end) return true;
    if (integrands_ > 0 && at_differential()) return true;  // \int ... \dd x: the integrand ends at its differential
    static const std::set<std::string> stops{"+", "-", ")", "]", "}", "&", "\\\\", "\\over", ",", ".", "=", "<",
                                             "\\equiv", "\\end"};
    return stops.count(t.text) > 0;
  }

  // expression := [±] product {± product}
  GiNaC::ex expression() {
    GiNaC::ex sum = 0;
    bool negative = false;
    if (accept("-")) negative = true;
    else accept("+");
    sum = negative ? -product() : product();
    for (;;) {
      if (accept("+")) {
        sum += product();
      } else if (accept("-")) {
        sum -= product();
      } else {
        return sum;
      }
    }
  }

  // product := power {power | \cdot power}: implicit multiplication
  GiNaC::ex product() {
    GiNaC::ex p = power();
    while (!ends_product(peek())) {
      if (accept("\\cdot") || accept("\\times")) continue;
      p = p * power();
    }
    return p;
  }

  // power := atom [^ script]
  GiNaC::ex power() {
    GiNaC::ex base = atom();
    if (accept("^")) base = GiNaC::pow(base, script());
    return base;
  }

  // A script takes one token, or a group: h^24 is h² · 4, as in TeX.
  GiNaC::ex script() {
    if (accept("{")) {
      GiNaC::ex e = group_body();
      expect("}");
      return e;
    }
    const token t = next();
    if (t.what == token::kind::character && std::isdigit(static_cast<unsigned char>(t.text[0]))) return GiNaC::numeric(t.text[0] - '0');
    if (t.what == token::kind::character && std::isalpha(static_cast<unsigned char>(t.text[0]))) return symbols_[t.text];
    if (greek().count(t.text)) return symbols_[greek().at(t.text)];
    --at_;
    fail("expected a one-token script");
  }

  // The text of a subscript: q_\ell → "l", q_{j+1} → "j+1".
  std::string subscript_text() {
    if (accept("{")) {
      std::string text;
      int depth = 1;
      for (;;) {
        const token t = next();
        if (t.what == token::kind::end) fail("unclosed subscript");
        if (t.text == "{") ++depth;
        if (t.text == "}" && --depth == 0) break;
        text += greek().count(t.text) ? greek().at(t.text) : t.text;
      }
      return text;
    }
    const token t = next();
    if (greek().count(t.text)) return greek().at(t.text);
    if (t.what == token::kind::character) return t.text;
    --at_;
    fail("expected a subscript");
  }

  // A group's body: an expression, or a fraction {a \over b}.
  GiNaC::ex group_body() {
    GiNaC::ex e = peek().text == "}" ? GiNaC::ex(1) : expression();
    if (accept("\\over")) e = e / expression();
    return e;
  }

  GiNaC::ex symbol_with_subscript(std::string name) {
    if (accept("_")) name += "_" + subscript_text();
    const auto& functions = function_names();
    if (peek().text == "(" && std::find(functions.begin(), functions.end(), name) != functions.end()) {
      return apply_function(name, arguments());
    }
    return symbols_[name];
  }

  // ( a, b, ... ) after a function name.
  GiNaC::exvector arguments() {
    expect("(");
    GiNaC::exvector args{expression()};
    while (accept(",")) args.push_back(expression());
    expect(")");
    return args;
  }

  // A name in a derivative: a letter or a Greek letter, with its subscript.
  std::string derivative_operand() {
    const token t = next();
    std::string name;
    if (t.what == token::kind::character && std::isalpha(static_cast<unsigned char>(t.text[0]))) name = t.text;
    else if (greek().count(t.text)) name = greek().at(t.text);
    else fail("expected a name in the derivative");
    if (accept("_")) name += "_" + subscript_text();
    return name;
  }

  int derivative_order() {
    if (!accept("^")) return 1;
    const token t = next();
    if (t.what != token::kind::character || !std::isdigit(static_cast<unsigned char>(t.text[0]))) fail("expected an order");
    return t.text[0] - '0';
  }

  // The differential: \dd, \partial, or {\rm d} and \mathrm{d} (what a document's own \dd
  // expands to), consumed when there; nothing consumed otherwise.
  bool accept_differential() {
    if (accept("\\dd") || accept("\\partial")) return true;
    const std::size_t saved = at_;
    if (accept("{") && accept("\\rm") && accept("d") && accept("}")) return true;
    at_ = saved;
    if (accept("\\mathrm") && accept("{") && accept("d") && accept("}")) return true;
    at_ = saved;
    return false;
  }

  bool at_differential() {
    const std::size_t saved = at_;
    const bool is = accept_differential();
    at_ = saved;
    return is;
  }

  // \int_a^b f \dd x: GiNaC's integral of f in x over [a, b], unevaluated.
  GiNaC::ex integral() {
    expect("_");
    const GiNaC::ex lower = script();
    expect("^");
    const GiNaC::ex upper = script();
    ++integrands_;
    const GiNaC::ex integrand = expression();
    --integrands_;
    if (!accept_differential()) fail("expected the differential of the integral");
    const GiNaC::ex variable = symbols_[derivative_operand()];
    // Held: an integrand written in the state q and dq/dt, not in the variable, must not be taken
    // for a constant (GiNaC would return (b - a) f).
    return GiNaC::integral(variable, lower, upper, integrand).hold();
  }

  // After the outer '{': {\dd^k x}\over{\dd t^n}} (or \partial, {\rm d}). Only when the group starts
  // so; otherwise nothing is consumed.
  bool starts_derivative() {
    const std::size_t saved = at_;
    const bool is = accept("{") && accept_differential();
    at_ = saved;
    return is;
  }
  GiNaC::ex derivative() {
    expect("{");
    accept_differential();
    const int k = derivative_order();
    const std::string of = derivative_operand();
    expect("}");
    expect("\\over");
    expect("{");
    if (!accept_differential()) fail("expected \\dd in the denominator of a derivative");
    const std::string by = derivative_operand();
    const int n = derivative_order();
    expect("}");
    expect("}");
    const auto& functions = function_names();
    // The state q is a function of t whose derivatives the paper writes without an argument:
    // {{\dd^k q}\over{\dd t^n}} stays a named symbol (a misprinted order stays visible).
    const bool state = of == "q" && peek().text != "(";
    if (!state && std::find(functions.begin(), functions.end(), of) != functions.end()) {
      if (k != n) fail("derivative of " + of + " of order " + std::to_string(k) + " over d" + by + "^" + std::to_string(n));
      // {{\dd V}\over{\dd q}} alone is V' at q; followed by (x), at x.
      const GiNaC::exvector args = peek().text == "(" ? arguments() : GiNaC::exvector{symbols_[by]};
      if (args.size() != 1) fail("a derivative of a function of one argument");
      const GiNaC::symbol x("derivative_variable");
      return GiNaC::diff(apply_function(of, {x}), x, static_cast<unsigned>(k)).subs(x == args.front());
    }
    return symbols_[derivative_name(of, by, k, n)];
  }

  // \sum_{j=a}^{b} s: the summand is the product that follows.
  GiNaC::ex sum() {
    expect("_");
    expect("{");
    const GiNaC::ex index = symbols_[derivative_operand()];
    expect("=");
    const GiNaC::ex lower = expression();
    expect("}");
    expect("^");
    const GiNaC::ex upper = script();
    const GiNaC::ex summand = product();
    return apply_function("sum", {summand, index, lower, upper});
  }

  GiNaC::ex atom() {
    const token t = next();
    if (t.what == token::kind::end) fail("unexpected end of formula");
    if (t.what == token::kind::character) {
      const char c = t.text[0];
      if (std::isdigit(static_cast<unsigned char>(c))) {
        std::string digits = t.text;
        while (peek().what == token::kind::character && std::isdigit(static_cast<unsigned char>(peek().text[0]))) digits += next().text;
        return GiNaC::numeric(digits.c_str());
      }
      if (std::isalpha(static_cast<unsigned char>(c))) return symbol_with_subscript(t.text);
      if (c == '(' || c == '[') {
        GiNaC::ex e = expression();
        expect(c == '(' ? ")" : "]");
        return e;
      }
      if (c == '{' && peek().text == "\\rm") {  // {\rm O}(h^k): the order term; {\rm d}: upright letters
        next();
        std::string name;
        while (peek().what == token::kind::character && std::isalpha(static_cast<unsigned char>(peek().text[0]))) name += next().text;
        expect("}");
        if (name == "O") {
          expect("(");
          GiNaC::ex e = expression();
          expect(")");
          return GiNaC::Order(e);
        }
        return symbols_[name];
      }
      if (c == '{' && starts_derivative()) return derivative();
      if (c == '{') {
        GiNaC::ex e = group_body();
        expect("}");
        // {\Phi}_3: a subscript on a braced symbol.
        if (peek().text == "_" && GiNaC::is_a<GiNaC::symbol>(e)) return symbol_with_subscript(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
        return e;
      }
    }
    if (greek().count(t.text)) return symbol_with_subscript(greek().at(t.text));
    if (t.text == "\\frac" || t.text == "\\tfrac" || t.text == "\\dfrac") {
      expect("{");
      GiNaC::ex num = group_body();
      expect("}");
      expect("{");
      GiNaC::ex den = group_body();
      expect("}");
      return num / den;
    }
    if (t.text == "\\sqrt") {
      expect("{");
      GiNaC::ex e = group_body();
      expect("}");
      return GiNaC::sqrt(e);
    }
    if (t.text == "\\begin") return matrix_environment();
    if (t.text == "\\sum") return sum();
    if (t.text == "\\int") return integral();
    --at_;
    fail("unsupported token");
  }

  // \begin{array}{cc} a & b \\ c & d \end{array}, or pmatrix.
  GiNaC::ex matrix_environment() {
    expect("{");
    std::string name;
    while (peek().text != "}" && peek().what != token::kind::end) name += next().text;
    expect("}");
    if (name != "array" && name != "pmatrix") fail("unsupported environment '" + name + "'");
    if (name == "array") {  // the column specification
      expect("{");
      while (peek().text != "}" && peek().what != token::kind::end) next();
      expect("}");
    }
    std::vector<std::vector<GiNaC::ex>> rows(1);
    for (;;) {
      rows.back().push_back(expression());
      if (accept("&")) continue;
      if (accept("\\\\")) {
        if (peek().text == "\\end") break;
        rows.emplace_back();
        continue;
      }
      break;
    }
    expect("\\end");
    expect("{");
    while (peek().text != "}" && peek().what != token::kind::end) next();
    expect("}");
    const std::size_t columns = rows.front().size();
    GiNaC::matrix m(static_cast<unsigned>(rows.size()), static_cast<unsigned>(columns));
    for (std::size_t r = 0; r < rows.size(); ++r) {
      if (rows[r].size() != columns) fail("rows of different lengths");
      for (std::size_t c = 0; c < columns; ++c) m(static_cast<unsigned>(r), static_cast<unsigned>(c)) = rows[r][c];
    }
    return m;
  }

  std::vector<token> tokens_;
  std::size_t at_ = 0;
  int integrands_ = 0;  // integrals being read: their integrands end at a differential
  tex_symbols& symbols_;
};

}  // namespace

std::vector<std::string> relation_sides(const std::string& tex) {
  std::vector<std::string> sides(1);
  int depth = 0;
  for (std::size_t k = 0; k < tex.size(); ++k) {
    const char c = tex[k];
    if (c == '{' || c == '(' || c == '[') ++depth;
    if (c == '}' || c == ')' || c == ']') --depth;
    if (depth == 0 && (c == '=' || c == '<')) {
      sides.emplace_back();
      continue;
    }
    if (depth == 0 && tex.compare(k, 6, "\\equiv") == 0) {
      sides.emplace_back();
      k += 5;
      continue;
    }
    if (depth == 0 && tex.compare(k, 6, "\\simeq") == 0) {  // an approximation: a quadrature rule against its integral
      sides.emplace_back();
      k += 5;
      continue;
    }
    if (depth == 0 && tex.compare(k, 4, "\\leq") == 0 && (k + 4 == tex.size() || !std::isalpha(static_cast<unsigned char>(tex[k + 4])))) {
      sides.emplace_back();  // a range 0 \leq t \leq T, as 0 < t < T is
      k += 3;
      continue;
    }
    sides.back() += c;
  }
  for (std::string& s : sides) {
    // Trailing punctuation and spacing of the display: "... \, ." or "... :".
    for (;;) {
      while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
      if (s.size() >= 2 && s[s.size() - 2] == '\\' && (s.back() == ',' || s.back() == ';' || s.back() == '!')) {
        s.resize(s.size() - 2);  // spacing: \, \; \! (before the punctuation test, which would take its comma)
      } else if (!s.empty() && (s.back() == '.' || s.back() == ',' || s.back() == ':')) {
        s.pop_back();
      } else {
        break;
      }
    }
  }
  return sides;
}

namespace {

/// `tex` without \vspace{...} and \vspace*{...}.
std::string without_vspace(std::string tex) {
  for (std::size_t at; (at = tex.find("\\vspace")) != std::string::npos;) {
    const std::size_t close = tex.find('}', at);
    tex.erase(at, close == std::string::npos ? std::string::npos : close + 1 - at);
  }
  return tex;
}

/// True when `tex` holds nothing but spacing commands and white space.
bool only_spacing(const std::string& tex) {
  std::size_t k = 0;
  while (k < tex.size()) {
    if (std::isspace(static_cast<unsigned char>(tex[k]))) {
      ++k;
    } else if (tex[k] == '\\' && k + 1 < tex.size() && std::string(",;!: ").find(tex[k + 1]) != std::string::npos) {
      k += 2;
    } else if (tex.compare(k, 6, "\\quad") == 0) {
      k += 5;
    } else if (tex.compare(k, 13, "\\displaystyle") == 0) {
      k += 13;
    } else {
      return false;
    }
  }
  return true;
}

/// `tex` with leading spacing commands removed.
std::string trimmed(const std::string& tex) {
  std::size_t k = 0;
  for (;;) {
    while (k < tex.size() && std::isspace(static_cast<unsigned char>(tex[k]))) ++k;
    std::size_t next = k;
    for (const char* s : {"\\displaystyle", "\\quad", "\\,", "\\;", "\\!", "\\left\\{"}) {
      if (tex.compare(k, std::string(s).size(), s) == 0) next = k + std::string(s).size();
    }
    if (next == k) return tex.substr(k);
    k = next;
  }
}

/// Splits at `separator` where it is outside every group; escaped braces \{ \} are not groups.
std::vector<std::string> split_top_level(const std::string& tex, const std::string& separator) {
  std::vector<std::string> parts(1);
  int depth = 0;
  for (std::size_t k = 0; k < tex.size(); ++k) {
    const char c = tex[k];
    if (c == '\\' && k + 1 < tex.size() && !(depth == 0 && tex.compare(k, separator.size(), separator) == 0)) {
      parts.back() += tex.substr(k, 2);  // \, \{ \} and the first letter of a command are never separators or groups
      ++k;
      continue;
    }
    if (c == '{' || c == '(' || c == '[') ++depth;
    if (c == '}' || c == ')' || c == ']') --depth;
    if (depth == 0 && tex.compare(k, separator.size(), separator) == 0) {
      parts.emplace_back();
      k += separator.size() - 1;
      continue;
    }
    parts.back() += c;
  }
  return parts;
}

}  // namespace

std::vector<std::string> display_equations(const std::string& display) {
  const std::string tex = trimmed(without_vspace(display));
  std::vector<std::string> equations;
  if (tex.compare(0, 13, "\\begin{array}") == 0) {
    const std::size_t body = tex.find('}', 13);  // the end of the column specification
    const std::size_t end = tex.rfind("\\end{array}");
    const std::string rows = tex.substr(body + 1, end == std::string::npos ? std::string::npos : end - body - 1);
    for (const std::string& row : split_top_level(rows, "\\\\")) {
      if (only_spacing(row)) continue;
      if (!equations.empty() && trimmed(row).compare(0, 1, "=") == 0) {
        equations.back() += " " + row;  // "\quad = ..." continues the equation above
      } else {
        equations.push_back(row);
      }
    }
    return equations;
  }
  for (const std::string& part : split_top_level(tex, ",")) {
    if (!only_spacing(part) && trimmed(part) != ".") equations.push_back(part);
  }
  return equations;
}

GiNaC::ex parse_tex_math(const std::string& tex, tex_symbols& symbols) { return parser(tex, symbols).parse_all(); }

namespace {

std::string numeric_text(const GiNaC::numeric& n) {
  std::ostringstream out;
  out << n;
  return out.str();
}

/// A polynomial (expanded) as a sum of monomials: coefficients exact, symbols in name order,
/// terms by decreasing total degree, then by text.
std::string polynomial_text(const GiNaC::ex& poly, const std::vector<GiNaC::symbol>& symbols) {
  const GiNaC::ex expanded = GiNaC::expand(poly);
  std::vector<GiNaC::ex> terms;
  if (GiNaC::is_a<GiNaC::add>(expanded)) {
    for (std::size_t k = 0; k < expanded.nops(); ++k) terms.push_back(expanded.op(k));
  } else {
    terms.push_back(expanded);
  }
  std::vector<std::pair<int, std::string>> texts;
  for (const GiNaC::ex& term : terms) {
    GiNaC::ex rest = term;
    std::string monomial;
    int total = 0;
    for (const GiNaC::symbol& x : symbols) {
      const int d = term.degree(x);
      if (d == 0) continue;
      rest = rest / GiNaC::pow(x, d);
      total += d;
      monomial += "*" + x.get_name() + (d == 1 ? "" : "^" + std::to_string(d));
    }
    rest = GiNaC::normal(rest);
    // A numeric coefficient, or a function of one symbol such as Order(h^6), whose printing is fixed.
    std::ostringstream other;
    other << rest;
    std::string coefficient = GiNaC::is_a<GiNaC::numeric>(rest) ? numeric_text(GiNaC::ex_to<GiNaC::numeric>(rest)) : other.str();
    std::string text;
    if (monomial.empty()) {
      text = coefficient;
    } else if (coefficient == "1") {
      text = monomial.substr(1);
    } else if (coefficient == "-1") {
      text = "-" + monomial.substr(1);
    } else {
      text = coefficient + monomial;
    }
    texts.emplace_back(-total, text);
  }
  std::sort(texts.begin(), texts.end());
  std::string out;
  for (const auto& t : texts) out += (out.empty() || t.second[0] == '-' ? "" : "+") + t.second;
  return out.empty() ? "0" : out;
}

/// Every function application (V(x), D[0](V)(x), Order(h^6), sum(...)) replaced by a symbol named
/// by its canonical text, so that its arguments print in name order and equal applications are one
/// symbol: GiNaC orders the terms of an argument by serial numbers, which depend on the process.
struct functions_as_symbols : GiNaC::map_function {
  std::map<std::string, GiNaC::symbol> named;
  GiNaC::ex operator()(const GiNaC::ex& e) override {
    if (GiNaC::is_a<GiNaC::integral>(e)) {  // integral(x, a, b, f), unevaluated
      return symbol_named("integral(" + canonical_text(e.op(0)) + ", " + canonical_text(e.op(1)) + ", " + canonical_text(e.op(2)) + ", " +
                          canonical_text(e.op(3)) + ")");
    }
    if (!GiNaC::is_a<GiNaC::function>(e) && !GiNaC::is_a<GiNaC::fderivative>(e)) return e.map(*this);
    GiNaC::ex shape = e;
    std::vector<std::string> arguments;
    for (std::size_t k = 0; k < e.nops(); ++k) {
      arguments.push_back(canonical_text(e.op(k)));
      shape.let_op(k) = GiNaC::symbol("#" + std::to_string(k) + "#");
    }
    std::ostringstream out;
    out << shape;
    std::string name = out.str();
    for (std::size_t k = 0; k < arguments.size(); ++k) {
      const std::string mark = "#" + std::to_string(k) + "#";
      for (std::size_t at; (at = name.find(mark)) != std::string::npos;) name.replace(at, mark.size(), arguments[k]);
    }
    // Ours registered apart from one of GiNaC's (psi_f): printed under the name the text gives it.
    const std::string registered = GiNaC::ex_to<GiNaC::function>(e).get_name();
    const std::string base = registered.size() > 2 ? registered.substr(0, registered.size() - 2) : "";
    if (!base.empty() && registered.compare(registered.size() - 2, 2, "_f") == 0 && function_name(base, e.nops()) == registered) {
      for (std::size_t at; (at = name.find(registered)) != std::string::npos;) name.replace(at, registered.size(), base);
    }
    return symbol_named(name);
  }

  GiNaC::ex symbol_named(const std::string& name) {
    auto it = named.find(name);
    if (it == named.end()) it = named.emplace(name, GiNaC::symbol(name)).first;
    return it->second;
  }
};

}  // namespace

std::string canonical_text(const GiNaC::ex& given) {
  functions_as_symbols rename;
  const GiNaC::ex e = rename(given);
  if (GiNaC::is_a<GiNaC::matrix>(e)) {
    const GiNaC::matrix& m = GiNaC::ex_to<GiNaC::matrix>(e);
    std::string out = "[";
    for (unsigned r = 0; r < m.rows(); ++r) {
      out += r ? ", [" : "[";
      for (unsigned c = 0; c < m.cols(); ++c) out += (c ? ", " : "") + canonical_text(m(r, c));
      out += "]";
    }
    return out + "]";
  }
  std::vector<GiNaC::symbol> symbols;
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::symbol>(*it)) symbols.push_back(GiNaC::ex_to<GiNaC::symbol>(*it));
  }
  std::sort(symbols.begin(), symbols.end(), [](const GiNaC::symbol& a, const GiNaC::symbol& b) { return a.get_name() < b.get_name(); });
  symbols.erase(std::unique(symbols.begin(), symbols.end(),
                            [](const GiNaC::symbol& a, const GiNaC::symbol& b) { return a.get_name() == b.get_name(); }),
                symbols.end());
  const GiNaC::ex n = GiNaC::normal(e);
  GiNaC::ex num = GiNaC::numer(n), den = GiNaC::denom(n);
  if (den.is_equal(GiNaC::ex(1))) return polynomial_text(num, symbols);
  // GiNaC makes the denominator's leading coefficient positive in its own order of the symbols, which
  // depends on the order they were made in: a quotient may come out as (-a)/(-b) in one run and a/b
  // in another. The text's denominator starts with a positive term, in the text's order.
  std::string denominator = polynomial_text(den, symbols);
  if (!denominator.empty() && denominator.front() == '-') {
    num = -num;
    den = -den;
    denominator = polynomial_text(den, symbols);
  }
  return "(" + polynomial_text(num, symbols) + ")/(" + denominator + ")";
}

}  // namespace simpson::verify

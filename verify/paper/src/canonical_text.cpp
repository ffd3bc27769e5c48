// The canonical text of an expression: see tex_math.hpp.

#include <simpson/verify/tex_math.hpp>

#include <algorithm>
#include <regex>
#include <set>
#include <sstream>

namespace simpson::verify {

namespace {

std::string numeric_text(const GiNaC::numeric& n) {
  std::ostringstream out;
  out << n;
  return out.str();
}

/// How a text is spelled: the canonical plain text ("h^2*omega^2"), or TeX ("h^{2} \\omega^{2}").
enum class spelling { plain, tex };

/// A symbol's name in TeX: a Greek letter's macro, a subscript in braces, a derivative's name
/// (d^6q/dt^5) as the fraction it was read from; other names as they are.
std::string tex_name(const std::string& name) {
  static const std::set<std::string> greek{"alpha", "beta",    "gamma", "delta", "epsilon", "zeta",  "eta",   "theta", "iota",  "kappa",
                                           "lambda", "mu",     "nu",    "xi",    "pi",      "rho",   "sigma", "tau",   "upsilon", "phi",
                                           "chi",   "psi",     "omega", "Gamma", "Delta",   "Theta", "Lambda", "Xi",   "Pi",    "Sigma",
                                           "Phi",   "Psi",     "Omega"};
  std::smatch m;
  static const std::regex derivative(R"(d(\^(\d+))?(\w+)/d(\w+)(\^(\d+))?)");
  if (std::regex_match(name, m, derivative)) {
    const auto power = [](const std::string& e) { return e.empty() ? std::string() : "^{" + e + "}"; };
    return "\\frac{d" + power(m[2]) + tex_name(m[3]) + "}{d" + tex_name(m[4]) + power(m[6]) + "}";
  }
  const std::size_t under = name.find('_');
  if (under != std::string::npos && under > 0) {
    std::string sub = name.substr(under + 1);
    if (sub.size() > 1 && sub.front() == '{' && sub.back() == '}') sub = sub.substr(1, sub.size() - 2);
    return tex_name(name.substr(0, under)) + "_{" + sub + "}";
  }
  return greek.count(name) ? "\\" + name : name;
}

/// A symbol's name in plain text: as it is, but a subscript that is not one word in braces, so that
/// q_{n+1/2} does not read as q_n + 1/2 in a sum (q_n+1/2 would).
std::string plain_name(const std::string& name) {
  const std::size_t under = name.find('_');
  if (under == std::string::npos || under == 0 || (name.front() == 'd' && name.find("/d") != std::string::npos)) return name;
  // A function application spelled as one symbol (L_d(q_j,q_j+1), functions_as_symbols) is no name.
  if (name.find_first_of("() ") != std::string::npos) return name;
  const std::string sub = name.substr(under + 1);
  if (sub.empty() || sub.front() == '{' || sub.find_first_of("+-/*") == std::string::npos) return name;
  return name.substr(0, under) + "_{" + sub + "}";
}

/// A coefficient: an integer as it is, a fraction as \frac in TeX.
std::string coefficient_text(const GiNaC::numeric& n, spelling how) {
  if (how == spelling::plain || n.is_integer()) return numeric_text(n);
  const GiNaC::numeric a = GiNaC::abs(n);
  return (n < 0 ? "-" : "") + std::string("\\frac{") + numeric_text(a.numer()) + "}{" + numeric_text(a.denom()) + "}";
}

/// A polynomial (expanded) as a sum of monomials: coefficients exact, symbols in name order,
/// terms by decreasing total degree, then by text.
std::string polynomial_text(const GiNaC::ex& poly, const std::vector<GiNaC::symbol>& symbols, spelling how = spelling::plain) {
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
      if (how == spelling::plain) {
        monomial += "*" + plain_name(x.get_name()) + (d == 1 ? "" : "^" + std::to_string(d));
      } else {
        monomial += " " + tex_name(x.get_name()) + (d == 1 ? "" : "^{" + std::to_string(d) + "}");
      }
    }
    rest = GiNaC::normal(rest);
    // A numeric coefficient, or a function of one symbol such as Order(h^6), whose printing is fixed.
    std::ostringstream other;
    other << rest;
    std::string coefficient = GiNaC::is_a<GiNaC::numeric>(rest) ? coefficient_text(GiNaC::ex_to<GiNaC::numeric>(rest), how) : other.str();
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

std::vector<GiNaC::symbol> symbols_by_name(const GiNaC::ex& e) {
  std::vector<GiNaC::symbol> symbols;
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::symbol>(*it)) symbols.push_back(GiNaC::ex_to<GiNaC::symbol>(*it));
  }
  std::sort(symbols.begin(), symbols.end(), [](const GiNaC::symbol& a, const GiNaC::symbol& b) { return a.get_name() < b.get_name(); });
  symbols.erase(std::unique(symbols.begin(), symbols.end(),
                            [](const GiNaC::symbol& a, const GiNaC::symbol& b) { return a.get_name() == b.get_name(); }),
                symbols.end());
  return symbols;
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

/// The one canonical form, spelled plain or in TeX: a matrix entry by entry; otherwise numerator over
/// denominator, each a polynomial in the symbols' name order.
std::string canonical(const GiNaC::ex& given, spelling how) {
  functions_as_symbols rename;
  const GiNaC::ex e = rename(given);
  const bool tex = how == spelling::tex;
  if (GiNaC::is_a<GiNaC::matrix>(e)) {
    const GiNaC::matrix& m = GiNaC::ex_to<GiNaC::matrix>(e);
    std::string out = tex ? "\\begin{pmatrix}" : "[";
    for (unsigned r = 0; r < m.rows(); ++r) {
      out += tex ? (r ? " \\\\ " : "") : (r ? ", [" : "[");
      for (unsigned c = 0; c < m.cols(); ++c) out += (c ? (tex ? " & " : ", ") : "") + canonical(m(r, c), how);
      out += tex ? "" : "]";
    }
    return out + (tex ? "\\end{pmatrix}" : "]");
  }
  const std::vector<GiNaC::symbol> symbols = symbols_by_name(e);
  const GiNaC::ex n = GiNaC::normal(e);
  GiNaC::ex num = GiNaC::numer(n), den = GiNaC::denom(n);
  // A TeX monomial starts with the space that separates it from its coefficient: none at the front.
  const auto spelled = [&](const GiNaC::ex& p) {
    const std::string t = polynomial_text(p, symbols, how);
    return !t.empty() && t.front() == ' ' ? t.substr(1) : t;
  };
  if (den.is_equal(GiNaC::ex(1))) return spelled(num);
  // GiNaC makes the denominator's leading coefficient positive in its own order of the symbols, which
  // depends on the order they were made in: a quotient may come out as (-a)/(-b) in one run and a/b
  // in another. The denominator starts with a positive term, in the canonical order.
  if (polynomial_text(den, symbols).front() == '-') {
    num = -num;
    den = -den;
  }
  return tex ? "\\frac{" + spelled(num) + "}{" + spelled(den) + "}" : "(" + spelled(num) + ")/(" + spelled(den) + ")";
}

}  // namespace

std::string canonical_text(const GiNaC::ex& e) { return canonical(e, spelling::plain); }

std::string canonical_tex(const GiNaC::ex& e) { return canonical(e, spelling::tex); }

}  // namespace simpson::verify

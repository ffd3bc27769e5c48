// See one_variable.hpp.

#include <simpson/shapes/one_variable.hpp>

#include <simpson/prove/printed_check_support.hpp>

#include <simpson/verify/tex_math.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <sstream>

namespace simpson::verify::detail {

using GiNaC::ex;

/// GiNaC's polynomial in t (rational coefficients) as our kernel's.
polynomial as_polynomial(const ex& p, const GiNaC::symbol& t) {
  const ex expanded = GiNaC::expand(p);
  std::vector<rational> c;
  for (int k = 0; k <= expanded.degree(t); ++k) {
    const ex coefficient = expanded.coeff(t, k);
    if (!GiNaC::is_a<GiNaC::numeric>(coefficient) || !GiNaC::ex_to<GiNaC::numeric>(coefficient).is_rational()) {
      throw std::invalid_argument("a coefficient that is not a rational number: " + text_of(coefficient));
    }
    std::ostringstream num, den;
    num << GiNaC::ex_to<GiNaC::numeric>(coefficient).numer();
    den << GiNaC::ex_to<GiNaC::numeric>(coefficient).denom();
    c.emplace_back(boost::multiprecision::cpp_int(num.str()), boost::multiprecision::cpp_int(den.str()));
  }
  return make_polynomial(c);
}

namespace {

bool even(const polynomial& p) {
  for (long k = 1; k <= degree(p); k += 2) {
    if (p[static_cast<std::size_t>(k)] != 0) return false;
  }
  return true;
}

}  // namespace

/// Our kernel's rational as GiNaC's.
GiNaC::numeric as_numeric(const rational& r) {
  std::ostringstream num, den;
  num << boost::multiprecision::numerator(r);
  den << boost::multiprecision::denominator(r);
  return GiNaC::numeric(num.str().c_str()) / GiNaC::numeric(den.str().c_str());
}

/// Our kernel's polynomial as GiNaC's, in `x`.
ex as_ginac(const polynomial& p, const GiNaC::symbol& x) {
  ex out = 0;
  for (long k = 0; k <= degree(p); ++k) out += as_numeric(p[static_cast<std::size_t>(k)]) * GiNaC::pow(x, k);
  return out;
}

int one_variable::sign_at(const rational& x) const {
  const rational value = numerator.evaluate(x) / denominator.evaluate(x);
  return value < 0 ? -1 : value > 0 ? 1 : 0;
}

std::string one_variable::text(const positive_root& r) const { return in_square ? omega_h_text(r) : root_text(r); }

one_variable::inside_of one_variable::first_inside(const rational& c) const {
  for (const positive_root& e : ends) {
    if (e.exact() ? e.low < c : e.high < c) return {e, false};
    if (!e.exact() && e.low < c && numerator.evaluate(c) != 0 && denominator.evaluate(c) != 0) return {std::nullopt, true};
  }
  return {};
}

proof_goal one_variable::sign_goal_on(const std::string& name, int sign, const rational& end) const {
  static const GiNaC::symbol x("x"), t("t");
  const GiNaC::symbol& u = in_square ? x : t;
  const GiNaC::numeric c = as_numeric(end);
  return sign_goal(name, as_ginac(numerator, u) / as_ginac(denominator, u), sign, {u, c - u}, GiNaC::exmap{{u, c / 2}});
}

proof_goal one_variable::sign_goal_between(const std::string& name, int sign, const rational& from, const rational& to) const {
  static const GiNaC::symbol x("x"), t("t");
  const GiNaC::symbol& u = in_square ? x : t;
  const GiNaC::numeric a = as_numeric(from), b = as_numeric(to);
  return sign_goal(name, as_ginac(numerator, u) / as_ginac(denominator, u), sign, {u - a, b - u}, GiNaC::exmap{{u, (a + b) / 2}});
}

std::optional<rational> one_variable::exact(const ex& c) const {
  const ex value = GiNaC::expand(in_square ? c * c : c);
  if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_rational()) return std::nullopt;
  const polynomial p = as_polynomial(value, t);
  return degree(p) < 0 ? rational(0) : p[0];
}

/// `f` as a function of v alone, or nothing when it is not one.
std::optional<one_variable> in_variable(const ex& f, const ex& v) {
  one_variable out;
  std::optional<ex> of_t;
  for (const std::string& name : symbol_names(v)) {
    const GiNaC::symbol s = paper_symbols()[name];
    if (v.degree(s) != 1 || v.ldegree(s) != 1 || GiNaC::normal(v / s).has(s)) continue;
    of_t = GiNaC::normal(f.subs(s == out.t / GiNaC::normal(v / s)));
    break;
  }
  if (!of_t) return std::nullopt;
  for (const std::string& name : symbol_names(*of_t)) {
    if (name != out.t.get_name()) return std::nullopt;
  }
  out.of_t = *of_t;
  out.numerator = as_polynomial(GiNaC::numer(out.of_t), out.t);
  out.denominator = as_polynomial(GiNaC::denom(out.of_t), out.t);
  out.in_square = even(out.numerator) && even(out.denominator);
  if (out.in_square) {
    out.numerator = even_in_theta_to_x(out.numerator);
    out.denominator = even_in_theta_to_x(out.denominator);
  }
  out.ends = positive_roots(out.numerator);
  for (const positive_root& pole : positive_roots(out.denominator)) out.ends.push_back(pole);
  std::sort(out.ends.begin(), out.ends.end(), [](const positive_root& a, const positive_root& b) { return a.low < b.low; });
  return out;
}

/// The printed condition 0 < v < c: c, or an exception naming the condition when it is not so.
ex interval_end(const referenced_formula& condition, const ex& v, const tex_declarations& declared) {
  if (condition.sides.size() != 3) throw std::invalid_argument(condition.locator + ": not a condition '0 < ... < c'");
  const ex low = read_side(condition, 0, declared), middle = read_side(condition, 1, declared), high = read_side(condition, 2, declared);
  if (!GiNaC::normal(low).is_zero() || !GiNaC::normal(middle - v).is_zero()) {
    throw std::invalid_argument(condition.locator + ": the condition is not '0 < " + text_of(v) + " < c'");
  }
  return high;
}


/// GiNaC's own decision of the sign of f(v) on 0 < v < end, without our kernel: f as G(u) (u = v,
/// or u = v² when f is even, G = f(sqrt(u)) in normal form), u = E s/(1 + s) mapping s > 0 onto
/// the interval (E = end, or end²); the numerator and the denominator of G, times (1 + s)^degree,
/// have coefficients of one sign each. Sufficient, not necessary: 0 when the coefficients do not
/// decide, with why in `proof`.
int ginac_sign_on(const one_variable& g, const ex& v, const ex& end, std::string& proof) {
  const GiNaC::symbol u("u"), s("s");
  const ex G = g.in_square ? GiNaC::normal(g.of_t.subs(g.t == GiNaC::sqrt(u))) : g.of_t.subs(g.t == u);
  const ex E = GiNaC::normal(g.in_square ? end * end : end);
  if (G.has(g.t) || !GiNaC::is_a<GiNaC::numeric>(E) || !GiNaC::ex_to<GiNaC::numeric>(E).is_rational()) {
    proof = "not a rational function of " + std::string(g.in_square ? "(" + text_of(v) + ")^2" : text_of(v)) + " with a rational end: not decided";
    return 0;
  }
  int sign = 1;
  std::string parts;
  for (const ex& part : {ex(GiNaC::numer(G)), ex(GiNaC::denom(G))}) {
    const int degree = part.degree(u);
    const ex mapped = GiNaC::expand(GiNaC::normal(part.subs(u == E * s / (1 + s)) * GiNaC::pow(1 + s, degree)));
    bool positive = true, negative = true, nonzero = false;
    for (int k = 0; k <= mapped.degree(s); ++k) {
      const ex c = mapped.coeff(s, k);
      if (!GiNaC::is_a<GiNaC::numeric>(c)) return proof = "a coefficient that is not a number: not decided", 0;
      const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(c);
      if (n.is_zero()) continue;
      nonzero = true;
      positive = positive && n.is_positive();
      negative = negative && n.is_negative();
    }
    parts += (parts.empty() ? "" : "; ") + text_of(mapped);
    sign *= !nonzero ? 0 : positive ? 1 : negative ? -1 : 0;
  }
  proof = fmt::format("u = {} s/(1 + s), s > 0: numerator and denominator times (1 + s)^degree: {}{}", text_of(E), parts,
                      sign == 0 ? " (coefficients of both signs: not decided)" : sign > 0 ? " (one sign each: positive)" : " (one sign each: negative)");
  return sign;
}

}  // namespace simpson::verify::detail

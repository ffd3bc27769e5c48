// The interval shapes (shape_support.hpp): a map's first stability band, a sign on a printed interval,
// and the signs of a printed product's factors there, decided by our kernel's Sturm sequences with the
// printed end compared exactly.

#include "shape_support.hpp"

#include "coq_export.hpp"
#include "printed_check_support.hpp"

#include <simpson/verify/quoted_words.hpp>
#include <simpson/verify/stability_analysis.hpp>
#include <simpson/verify/tex_math.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <sstream>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

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

bool even(const polynomial& p) {
  for (long k = 1; k <= degree(p); k += 2) {
    if (p[static_cast<std::size_t>(k)] != 0) return false;
  }
  return true;
}

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

/// A function of the condition's variable v alone, for our kernel: every symbol of v but one
/// eliminated by v's scaling (s = t / (v / s) for a symbol s of v with exponent 1), its numerator
/// and denominator as polynomials in t = v, or in x = v² when both are even (roots exact more often).
struct one_variable {
  GiNaC::symbol t{"interval_variable"};
  ex of_t;  // normal form in t
  polynomial numerator, denominator;
  bool in_square = false;
  std::vector<positive_root> ends;  // positive roots of both, increasing

  int sign_at(const rational& x) const {
    const rational value = numerator.evaluate(x) / denominator.evaluate(x);
    return value < 0 ? -1 : value > 0 ? 1 : 0;
  }
  std::string text(const positive_root& r) const { return in_square ? omega_h_text(r) : root_text(r); }
  /// The first root or pole inside (0, c), if any; `ambiguous` when one's isolating interval holds c
  /// without c being a root or pole (it lies within 2^-40 of the end, on a side not known).
  struct inside_of {
    std::optional<positive_root> first;
    bool ambiguous = false;
  };
  inside_of first_inside(const rational& c) const {
    for (const positive_root& e : ends) {
      if (e.exact() ? e.low < c : e.high < c) return {e, false};
      if (!e.exact() && e.low < c && numerator.evaluate(c) != 0 && denominator.evaluate(c) != 0) return {std::nullopt, true};
    }
    return {};
  }
  /// What Coq is asked (coq_export.hpp): `sign` times the function is positive on 0 < v < c, stated
  /// in the kernel's variable (x = v² when both polynomials are even, else t = v) with the end
  /// `end` (c² or c) rational. The reduction of the printed expression to this one-variable function
  /// (v's scaling) is GiNaC's; nra proves each factor's sign from the two bounds.
  proof_goal sign_goal_on(const std::string& name, int sign, const rational& end) const {
    static const GiNaC::symbol x("x"), t("t");
    const GiNaC::symbol& u = in_square ? x : t;
    const GiNaC::numeric c = as_numeric(end);
    return sign_goal(name, as_ginac(numerator, u) / as_ginac(denominator, u), sign, {u, c - u}, GiNaC::exmap{{u, c / 2}});
  }
  /// The printed end c as our kernel's rational (c, or c² in x), when it is one.
  std::optional<rational> exact(const ex& c) const {
    const ex value = GiNaC::expand(in_square ? c * c : c);
    if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_rational()) return std::nullopt;
    const polynomial p = as_polynomial(value, t);
    return degree(p) < 0 ? rational(0) : p[0];
  }
};

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
ex interval_end(const referenced_formula& condition, const ex& v) {
  if (condition.sides.size() != 3) throw std::invalid_argument(condition.locator + ": not a condition '0 < ... < c'");
  ex low, middle, high;
  try {
    low = parse_tex_math(condition.sides[0], paper_symbols());
    middle = parse_tex_math(condition.sides[1], paper_symbols());
    high = parse_tex_math(condition.sides[2], paper_symbols());
  } catch (const tex_parse_error& e) {
    throw std::invalid_argument(condition.locator + ": " + e.what());
  }
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

/// The factors of a printed product as the text writes them: each sum (or power of one), and the
/// rest (numbers, symbols and their powers) multiplied into one prefactor, listed first; the sums by
/// their text (GiNaC orders a product by hash, which differs from run to run).
std::vector<ex> printed_factors(const ex& product) {
  std::vector<ex> sums;
  ex prefactor = 1;
  for (const ex& f : GiNaC::is_a<GiNaC::mul>(product) ? GiNaC::exvector(product.begin(), product.end()) : GiNaC::exvector{product}) {
    const bool sum = GiNaC::is_a<GiNaC::add>(f) || (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::add>(f.op(0)));
    if (sum) {
      sums.push_back(f);
    } else {
      prefactor *= f;
    }
  }
  std::sort(sums.begin(), sums.end(), [](const ex& a, const ex& b) { return text_of(a) < text_of(b); });
  std::vector<ex> out;
  if (!(GiNaC::is_a<GiNaC::numeric>(prefactor) && prefactor == 1)) out.push_back(prefactor);
  out.insert(out.end(), sums.begin(), sums.end());
  return out;
}

std::string sign_word(int sign) { return sign > 0 ? "positive" : sign < 0 ? "negative" : "of no one sign"; }

}  // namespace

claim_result stability_interval_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const referenced_formula condition = read.raw("condition");
  const bool of_map = read.has("map");
  const std::string what = reference_of(call, of_map ? "map" : "scheme");
  claim_result result;
  // The trace of the map, or −b/a of the reversible scheme's a r² + b r + a (its roots' sum, their
  // product 1): either way power-bounded exactly where |trace| < 2. The premise (det = 1, or a = c)
  // in both kernels.
  ex trace;
  std::string premise;
  proof_goal premise_goal;
  if (of_map) {
    const GiNaC::matrix m = as_square_matrix(read.formula("map"), what);
    if (m.rows() != 2) throw std::invalid_argument(what + " is not a 2 x 2 map");
    const ex det = m.determinant();
    const kernel_decision det_own = kernel_decides_zero(det - 1);
    if (!GiNaC::normal(det - 1).is_zero() || det_own.outcome == kernel_decision::result::nonzero) {
      result.printed = read.printed();
      result.outcome = verdict::fails;
      result.note = "The shape decides maps with det 1; det (" + what + ") = " + text_of(GiNaC::normal(det)) + ".";
      return result;
    }
    trace = m(0, 0) + m(1, 1);
    premise = "det = 1 (GiNaC normal form; our kernel: " + det_own.evidence + ")";
    premise_goal = decided("det", determinant_2x2(m), 1);  // a d − b c as written, not GiNaC's value
  } else {
    const ex scheme = read.formula("scheme");
    const std::vector<GiNaC::symbol> q = read.symbols("sequence");
    const std::optional<three_term_coefficients> terms = linear_three_term(scheme, q);
    const kernel_decision reversible_own = terms ? kernel_decides_zero(terms->next - terms->previous) : kernel_decision{};
    if (!terms || !GiNaC::normal(terms->next - terms->previous).is_zero() || reversible_own.outcome == kernel_decision::result::nonzero) {
      result.printed = read.printed();
      result.outcome = verdict::fails;
      result.note = "The shape decides linear three-term schemes whose " + q[2].get_name() + " and " + q[0].get_name() + " coefficients are equal; (" +
                    what + ") " + (terms ? "has " + text_of(GiNaC::normal(terms->next)) + " and " + text_of(GiNaC::normal(terms->previous)) : "is not linear in its states") + ".";
      return result;
    }
    trace = -terms->current / terms->next;
    premise = fmt::format("the scheme is linear, its {} and {} coefficients equal: the characteristic roots' product is 1 (GiNaC normal form; our kernel: {})",
                          q[2].get_name(), q[0].get_name(), reversible_own.evidence);
    premise_goal = decided("reversible", terms->next, terms->previous);
  }
  const ex v = read.formula("variable");
  result.printed = read.printed();
  const ex high = interval_end(condition, v);
  const std::optional<one_variable> excess = in_variable(trace * trace - 4, v);  // < 0 exactly on the stable set
  if (!excess) {
    result.outcome = verdict::fails;
    result.note = "The trace of " + what + " is not a function of " + text_of(v) + " alone.";
    return result;
  }
  const std::string var = text_of(v);
  // The stable bands: between consecutive ends, where trace² − 4 < 0 at a point inside.
  std::vector<std::string> bands;
  rational from = 0;
  std::string from_text = "0";
  for (std::size_t k = 0; k <= excess->ends.size(); ++k) {
    const rational inside = k < excess->ends.size() ? rational((from + excess->ends[k].low) / 2) : rational(from + 1);
    if (excess->sign_at(inside) < 0) {
      bands.push_back(k < excess->ends.size() ? fmt::format("{} < {} < {}", from_text, var, excess->text(excess->ends[k]))
                                              : fmt::format("{} > {}", var, from_text));
    }
    if (k < excess->ends.size()) {
      from = excess->ends[k].high;
      from_text = excess->text(excess->ends[k]);
    }
  }
  const bool stable_near_zero = !excess->ends.empty() && excess->sign_at(excess->ends.front().low / 2) < 0;
  // Is the printed c the first end? Exactly: c (or c² in x) is rational and equal to an exact root,
  // or a root of the numerator inside the first end's isolating interval.
  bool equal = false;
  std::string how;
  if (stable_near_zero) {
    const positive_root& first = excess->ends.front();
    if (const std::optional<rational> value = excess->exact(high)) {
      equal = first.exact() ? *value == first.low : (*value >= first.low && *value <= first.high && excess->numerator.evaluate(*value) == 0);
      how = fmt::format("{} = {} (exact)", excess->in_square ? "c^2" : "c", value->str());
    } else {
      how = "c = " + text_of(high) + " is not rational" + std::string(excess->in_square ? " in its square" : "") + ": not compared";
    }
  }
  const ex trace_in_v = GiNaC::normal(trace);
  result.evidence["exact"] = {
      {"statement", fmt::format("the stable set of ({}) in {} > 0 begins with 0 < {} < {}", what, var, var, text_of(high))},
      {of_map ? "det" : "reversible", premise},
      {of_map ? "trace" : "roots_sum", text_of(trace_in_v)},
      {"boundary_polynomial", to_string(excess->numerator, excess->in_square ? "x" : "t") + (excess->in_square ? " (x = (" + var + ")^2)" : "")},
      {"stable_bands", bands},
      {"printed_end", how}};
  // Who decided what: GiNaC the premise and the reduction to one variable, our kernel the premise
  // again and the bands (Sturm sequences), the printed end compared exactly.
  const std::string verdict_word = stable_near_zero && equal ? "holds" : "fails";
  result.evidence["exact"]["ginac"] = verdict_word + ": the premise in normal form, and " + std::string(of_map ? "the trace" : "the roots' sum") +
                                      " as a function of " + var + " alone; the bands are our kernel's";
  result.evidence["exact"]["own"] = verdict_word + ": the premise on its grid, and the stable bands by Sturm sequences: " +
                                    (bands.empty() ? std::string("none") : fmt::format("{}", fmt::join(bands, ", "))) + "; " + how;
  // Coq: det = 1, and trace² − 4 < 0 on the printed band (holds) or on the first band (the
  // correction's), when its end is rational. That the band ends there is our kernel's alone.
  std::vector<proof_goal> goals{premise_goal};
  if (stable_near_zero && equal) {
    goals.push_back(excess->sign_goal_on("stable_band", -1, *excess->exact(high)));
    record_certificate(result, coq_certificate(call.claim_id, call.statement, goals));
    result.outcome = verdict::holds;
    // What the condition leaves out: the other bands, and the ends, where |trace| = 2 (a double root ±1).
    if (bands.size() > 1) {
      std::vector<std::string> ends;
      for (const positive_root& end : positive_roots(excess->numerator)) ends.push_back(excess->text(end));  // not its poles
      result.note = fmt::format("Sufficient, not necessary: ({}) is stable exactly for {}. At {} = {} the characteristic roots are double (|trace| = 2).",
                                what, fmt::join(bands, ", "), var, fmt::join(ends, ", "));
    }
    return result;
  }
  if (stable_near_zero && excess->ends.front().exact()) goals.push_back(excess->sign_goal_on("first_band", -1, excess->ends.front().low));
  record_certificate(result, coq_certificate(call.claim_id, call.statement, goals));
  result.outcome = verdict::erratum;
  result.correction = bands.empty() ? "never stable for " + var + " > 0" : "stable exactly for " + fmt::format("{}", fmt::join(bands, ", "));
  result.note = "As printed: " + folded_space(condition.tex) + " is not the first stable band of " + what +
                " (trace = " + text_of(trace_in_v) + ", stable where |trace| < 2).";
  return result;
}

/// The claimed sign of a function of v on the printed interval 0 < v < c: no root or pole of it
/// inside (our kernel's Sturm sequences, the end compared exactly), and the sign at a point inside.
claim_result sign_on_interval_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex f = read.formula("expression");
  const referenced_formula condition = read.raw("condition");
  const ex v = read.formula("variable");
  const std::string claimed = call.with.at("sign").values.front();
  const int want = claimed == "positive" ? 1 : -1;
  claim_result result;
  result.printed = read.printed();
  const ex high = interval_end(condition, v);
  const std::optional<one_variable> g = in_variable(f, v);
  if (!g) {
    result.outcome = verdict::fails;
    result.note = "(" + reference_of(call, "expression") + ") is not a function of " + text_of(v) + " alone.";
    return result;
  }
  const std::string var = text_of(v);
  const std::optional<rational> c = g->exact(high);
  if (!c || *c <= 0) {
    result.outcome = verdict::undecided;
    result.note = "The interval's end " + text_of(high) + " is not a positive rational" + (g->in_square ? " in its square" : "") +
                  ": our kernel compares ends exactly, and cannot here.";
    return result;
  }
  // The first root or pole of f inside (0, c), if any.
  const one_variable::inside_of found = g->first_inside(*c);
  if (found.ambiguous) {
    result.outcome = verdict::undecided;
    result.note = "A root of " + text_of(f) + " lies within 2^-40 of the interval's end; its isolating interval holds the end.";
    return result;
  }
  const std::optional<positive_root> inside = found.first;
  const rational probe = inside ? rational(inside->low / 2) : rational(*c / 2);
  const int sign = g->sign_at(probe);
  const std::string expression = text_of(f);
  result.evidence["exact"] = {
      {"statement", fmt::format("({}) is {} for 0 < {} < {}", reference_of(call, "expression"), claimed, var, text_of(high))},
      {"in_variable", text_of(g->of_t.subs(g->t == v))},
      {"roots_and_poles", [&] {
         json all = json::array();
         for (const positive_root& e : g->ends) all.push_back(g->text(e));
         return all;
       }()},
      {"interval_end", fmt::format("{} = {} (exact)", g->in_square ? "c^2" : "c", c->str())}};
  // Coq: the sign on the printed interval (holds), or the correction's: the sign found on (0, c),
  // or on (0, r) up to the first root or pole r when it is rational.
  if (!inside && sign == want) {
    record_certificate(result, coq_certificate(call.claim_id, call.statement, {g->sign_goal_on("sign", want, *c)}));
    result.outcome = verdict::holds;
    return result;
  }
  if (!inside) {
    record_certificate(result, coq_certificate(call.claim_id, call.statement, {g->sign_goal_on("sign", sign, *c)}));
  } else if (inside->exact()) {
    record_certificate(result, coq_certificate(call.claim_id, call.statement, {g->sign_goal_on("sign_before_root", sign, inside->low)}));
  } else {
    result.certificate_missing = "the sign changes at an irrational root, which the certificate cannot name as a bound; our kernel's Sturm sequences decide it";
  }
  result.outcome = verdict::erratum;
  const std::string sign_text = sign > 0 ? "positive" : "negative";
  result.correction = inside ? fmt::format("{} is {} for 0 < {} < {} only, and changes sign there", expression, sign_text, var, g->text(*inside))
                             : fmt::format("{} is {} for 0 < {} < {}", expression, sign_text, var, text_of(high));
  result.note = "As printed: (" + reference_of(call, "expression") + ") is said to be " + claimed + " for " + folded_space(condition.tex) + ".";
  return result;
}

/// "Under (condition), all the factors of the expression are {sign} and Δ {relation}": each factor of
/// the printed product (printed_factors) has its sign on the printed interval decided by our
/// kernel's Sturm sequences and again by GiNaC's coefficient test; the words are judged against
/// them: every factor of the stated sign, and the product in the stated relation to 0 (when the
/// sentence has a hole {relation}). The product's relation true with a factor of another sign is a
/// wording erratum; the correction gives each factor's proved sign, and so does the certificate.
claim_result factor_signs_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex product = read.formula("expression");
  const referenced_formula condition = read.raw("condition");
  const ex v = read.formula("variable");
  const std::string pattern = call.with.at("sentence").values.front();
  const quoted_sentence said = quote(ctx, pattern);
  const int stated = said.choice("sign", {{"negative", "-1"}, {"positive", "1"}}) == "-1" ? -1 : 1;
  const bool has_relation = pattern.find("{relation}") != std::string::npos;
  std::optional<stated_bound> relation;
  if (has_relation) {
    relation = said.bound("relation");
    if (relation->value != 0 || !relation->rest.empty()) said.unparsed("relation", "a relation to 0");
  }
  claim_result result;
  result.printed = read.printed();
  const ex high = interval_end(condition, v);
  const std::string var = text_of(v), expression = reference_of(call, "expression");
  json factors = json::array();
  std::vector<int> signs;
  std::vector<proof_goal> goals;
  std::vector<std::string> proved, unlike;
  bool kernels_agree = true, sums_as_stated = true, ginac_decided = true;
  int product_sign = 1;
  const std::vector<ex> all_factors = printed_factors(product);
  for (const ex& f : all_factors) {
    const std::optional<one_variable> g = in_variable(f, v);
    const std::optional<rational> c = g ? g->exact(high) : std::nullopt;
    if (!g || !c || *c <= 0) {
      result.outcome = verdict::undecided;
      result.note = "The factor " + text_of(f) + (g ? " on an interval whose end is not a positive rational" + std::string(g->in_square ? " in its square" : "")
                                                     : " is not a function of " + var + " alone") + ": our kernel cannot decide its sign.";
      return result;
    }
    // Our kernel: no root or pole inside (0, c), and the sign at c/2.
    const one_variable::inside_of found = g->first_inside(*c);
    if (found.ambiguous) {
      result.outcome = verdict::undecided;
      result.note = "A root or pole of " + text_of(f) + " lies within 2^-40 of the interval's end; its isolating interval holds the end.";
      return result;
    }
    const bool inside = found.first.has_value();
    const int own = inside ? 0 : g->sign_at(*c / 2);
    std::string ginac_proof;
    const int theirs = ginac_sign_on(*g, v, high, ginac_proof);
    kernels_agree = kernels_agree && (theirs == 0 || theirs == own);
    ginac_decided = ginac_decided && theirs != 0;
    signs.push_back(own);
    product_sign *= own;
    const std::string text = text_of(f);
    factors.push_back({{"factor", text}, {"own", sign_word(own) + (inside ? ": a root or pole inside" : "")}, {"ginac", ginac_proof}});
    proved.push_back(text + " " + sign_word(own));
    if (own != stated) unlike.push_back(text);
    const bool prefactor = &f == &all_factors.front() && !GiNaC::is_a<GiNaC::add>(f) && !(GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::add>(f.op(0)));
    if (own != stated && !prefactor) sums_as_stated = false;
    if (own != 0) goals.push_back(g->sign_goal_on("factor_" + std::to_string(goals.size() + 1), own, *c));
  }
  const bool factors_as_stated = unlike.empty();
  const bool relation_as_stated = !relation || (product_sign != 0 && relation->admits(product_sign));
  result.evidence["exact"] = {
      {"statement", fmt::format("the factors of ({}) on 0 < {} < {}", expression, var, text_of(high))},
      {"stated", {{"factors", said.words("sign")}, {"relation", has_relation ? said.words("relation") : std::string("(not stated)")}}},
      {"factors", factors},
      {"product", sign_word(product_sign)},
      {"own", std::string(product_sign != 0 ? "holds: every factor's sign decided" : "fails: a factor changes sign inside") +
                  " (Sturm count of the roots and poles of each factor in (0, c), c compared exactly, and its sign at c/2)"},
      {"ginac", std::string(ginac_decided ? "holds: every factor's sign decided" : "not decided for every factor") +
                    " (the coefficients of its numerator and denominator after u = E s/(1 + s))"}};
  record_certificate(result, coq_certificate(call.claim_id, call.statement, goals));
  if (!kernels_agree) {
    result.outcome = verdict::kernels_disagree;
    result.note = "Our kernel's (Sturm) and GiNaC's (coefficients) signs of a factor differ: a bug in one of them.";
    return result;
  }
  const std::string facts = fmt::format("on 0 < {} < {}: {}; the product is {}", var, text_of(high), fmt::join(proved, ", "), sign_word(product_sign));
  if (factors_as_stated && relation_as_stated) {
    result.outcome = verdict::holds;
    result.note = "Proved in both kernels, each factor's sign on the whole interval (no sample): " + facts + ".";
    return result;
  }
  result.outcome = verdict::erratum;
  result.correction = "As proved: " + facts;
  // Wording when only the monomial prefactor differs and the product's relation holds: the sums are
  // what a reader may take for "the factors"; the words' "all" takes in the prefactor too.
  result.note = relation_as_stated && sums_as_stated
                    ? fmt::format("Wording: 'all the factors' are said to be {}, which the prefactor {} is not; the factors that are sums are {}, and "
                                  "the product's sign is as stated.", said.words("sign"), fmt::join(unlike, ", "), said.words("sign"))
                    : "As printed, the factors' signs are not the sentence's: " + fmt::format("{}", fmt::join(unlike, ", ")) + ".";
  return result;
}

}  // namespace simpson::verify::detail

// The interval shapes (shape_support.hpp): a map's first stability band, and a sign on a printed interval,
// decided by our kernel's Sturm sequences with the printed end compared exactly.

#include "shape_support.hpp"

#include "coq_export.hpp"
#include "printed_check_support.hpp"

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
    const ex previous = GiNaC::diff(scheme, q[0]), current = GiNaC::diff(scheme, q[1]), next = GiNaC::diff(scheme, q[2]);
    const ex linear = scheme - (previous * q[0] + current * q[1] + next * q[2]);
    bool linear_three_term = GiNaC::normal(linear).is_zero();
    for (const GiNaC::symbol& state : q) {
      linear_three_term = linear_three_term && !GiNaC::normal(previous).has(state) && !GiNaC::normal(current).has(state) && !GiNaC::normal(next).has(state);
    }
    const kernel_decision reversible_own = kernel_decides_zero(next - previous);
    if (!linear_three_term || !GiNaC::normal(next - previous).is_zero() || reversible_own.outcome == kernel_decision::result::nonzero) {
      result.printed = read.printed();
      result.outcome = verdict::fails;
      result.note = "The shape decides linear three-term schemes whose " + q[2].get_name() + " and " + q[0].get_name() + " coefficients are equal; (" +
                    what + ") " + (linear_three_term ? "has " + text_of(GiNaC::normal(next)) + " and " + text_of(GiNaC::normal(previous)) : "is not linear in its states") + ".";
      return result;
    }
    trace = -current / next;
    premise = fmt::format("the scheme is linear, its {} and {} coefficients equal: the characteristic roots' product is 1 (GiNaC normal form; our kernel: {})",
                          q[2].get_name(), q[0].get_name(), reversible_own.evidence);
    premise_goal = decided("reversible", next, previous);
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
  std::optional<positive_root> inside;
  for (const positive_root& e : g->ends) {
    if (e.exact() ? e.low < *c : e.high < *c) {
      inside = e;
      break;
    }
    if (!e.exact() && e.low < *c && g->numerator.evaluate(*c) != 0 && g->denominator.evaluate(*c) != 0) {
      result.outcome = verdict::undecided;
      result.note = "A root of " + text_of(f) + " lies within 2^-40 of the interval's end; its isolating interval holds the end.";
      return result;
    }
  }
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

}  // namespace simpson::verify::detail

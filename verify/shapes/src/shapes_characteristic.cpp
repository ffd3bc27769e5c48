// The characteristic-polynomial shapes (shape_support.hpp) of a linear three-term scheme, the scheme
// taken at the geometric sequence q_{j-1} = 1, q_j = r, q_{j+1} = r²: a printed polynomial in r is
// it up to a factor free of r (characteristic), the printed value of its discriminant (discriminant), and what a sentence says of its roots on a printed
// interval (characteristic-roots); a criterion on their modulus and stability for every step are
// shapes_stability_criteria.cpp's.

#include <simpson/shapes/shape_support.hpp>

#include <simpson/shapes/one_variable.hpp>
#include <simpson/prove/printed_check_support.hpp>
#include <simpson/shapes/stability_regions.hpp>

#include <simpson/verify/sentence_holes.hpp>
#include <simpson/verify/quoted_words.hpp>

#include <fmt/format.h>

#include <array>
#include <map>
#include <optional>
#include <vector>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

/// p's coefficients of r⁰, r¹, r² when p is a polynomial of degree at most 2 in r with
/// coefficients free of r; none otherwise.
std::optional<std::array<ex, 3>> quadratic_coefficients(const ex& p, const GiNaC::symbol& r) {
  const ex expanded = GiNaC::expand(p);
  if (!expanded.is_polynomial(r) || expanded.degree(r) > 2) return std::nullopt;
  std::array<ex, 3> c;
  for (int k = 0; k <= 2; ++k) c[static_cast<std::size_t>(k)] = GiNaC::normal(expanded.coeff(r, k));
  for (const ex& coefficient : c) {
    if (coefficient.has(r)) return std::nullopt;
  }
  if (!GiNaC::normal(p - (c[0] + c[1] * r + c[2] * r * r)).is_zero()) return std::nullopt;
  return c;
}

/// r^k as a term's factor ("" for k = 0, "r", "r^2").
std::string power_text(const GiNaC::symbol& r, std::size_t k) {
  return k == 0 ? std::string() : k == 1 ? r.get_name() : r.get_name() + "^" + std::to_string(k);
}

/// The name of the coefficient of r^k: "r^0", "r", "r^2".
std::string coefficient_name(const GiNaC::symbol& r, std::size_t k) { return k == 0 ? r.get_name() + "^0" : power_text(r, k); }

}  // namespace

namespace {

/// A printed polynomial in the root against a linear three-term scheme at (1, r, r²): both sets of
/// coefficients, the printed one that sets the scale (the highest power's that is printed), and
/// the unprinted coefficients (`unprinted`, each one whole coefficient) solved at that scale; or why
/// the two cannot be compared.
struct characteristic_reading {
  ex polynomial, scheme;  // as read, the definitions put in
  std::vector<GiNaC::symbol> sequence;
  GiNaC::symbol root;
  std::string polynomial_ref, scheme_ref;
  std::array<ex, 3> derived, stated;  // of r^0, r^1, r^2
  std::map<std::size_t, GiNaC::symbol> holes;
  std::size_t lead = 2;
  ex scale;  // printed over derived
  GiNaC::exmap solved;
  json solved_text = json::object();
  std::string why_not;
};

characteristic_reading read_characteristic(shape_reader& read, const shape_call& call, const std::string& polynomial) {
  characteristic_reading c;
  c.polynomial = read.formula(polynomial);
  c.scheme = read.formula("scheme");
  c.sequence = read.symbols("sequence");
  c.root = read.symbols("root").front();
  c.polynomial_ref = reference_of(call, polynomial);
  c.scheme_ref = reference_of(call, "scheme");
  const std::vector<GiNaC::symbol> unprinted = read.has("unprinted") ? read.symbols("unprinted") : std::vector<GiNaC::symbol>{};
  const ex& printed = c.polynomial;
  const ex& scheme = c.scheme;
  const std::vector<GiNaC::symbol>& q = c.sequence;
  const GiNaC::symbol& r = c.root;
  const std::string& scheme_ref = c.scheme_ref;
  const std::string& printed_ref = c.polynomial_ref;
  const std::optional<three_term_coefficients> terms = linear_three_term(scheme, q);
  if (!terms) {
    c.why_not = "The shape decides linear three-term schemes; (" + scheme_ref + ") is not linear in " + q[0].get_name() + ", " + q[1].get_name() +
                ", " + q[2].get_name() + ".";
    return c;
  }
  c.derived = {GiNaC::normal(terms->previous), GiNaC::normal(terms->current), GiNaC::normal(terms->next)};
  const std::optional<std::array<ex, 3>> stated = quadratic_coefficients(printed, r);
  if (!stated) {
    c.why_not = "(" + printed_ref + ") is not a polynomial of degree at most 2 in " + r.get_name() + ".";
    return c;
  }
  c.stated = *stated;
  // Each unprinted coefficient is one whole coefficient of the printed polynomial, and in no other.
  for (const GiNaC::symbol& u : unprinted) {
    std::optional<std::size_t> at;
    for (std::size_t k = 0; k < 3; ++k) {
      if (GiNaC::normal(c.stated[k] - u).is_zero()) {
        at = k;
      } else if (c.stated[k].has(u)) {
        at.reset();
        break;
      }
    }
    if (!at || c.holes.count(*at)) {
      c.why_not = "The unprinted " + u.get_name() + " is not one whole coefficient of (" + printed_ref + ") = " + text_of(printed) + ".";
      return c;
    }
    c.holes.emplace(*at, u);
  }
  std::optional<std::size_t> lead;
  for (std::size_t k = 3; k-- > 0;) {
    if (!c.holes.count(k) && !c.stated[k].is_zero() && !c.derived[k].is_zero()) {
      lead = k;
      break;
    }
  }
  if (!lead) {
    c.why_not = "(" + printed_ref + ") and (" + scheme_ref + ") share no nonzero printed coefficient to compare by.";
    return c;
  }
  c.lead = *lead;
  c.scale = GiNaC::normal(c.stated[c.lead] / c.derived[c.lead]);
  for (const auto& [k, u] : c.holes) {
    c.solved[u] = GiNaC::normal(c.derived[k] * c.scale);
    c.solved_text[u.get_name()] = fmt::format("{} (the {} coefficient of ({}) at (1, {}, {}^2), times {})", text_of(c.solved[u]),
                                              coefficient_name(r, k), scheme_ref, r.get_name(), r.get_name(), text_of(c.scale));
  }
  return c;
}

/// The coefficients compared, and the unprinted ones solved ("Not printed, solved from the scheme:
/// c = ..., the printed r^2 coefficient." in the note), in a verdict's evidence.
void record_coefficients(claim_result& result, const characteristic_reading& c) {
  const GiNaC::symbol& r = c.root;
  result.evidence["exact"]["characteristic_coefficients"] = {
      {"derived", {text_of(c.derived[0]), text_of(c.derived[1]), text_of(c.derived[2])}},
      {"printed", {text_of(c.stated[0]), text_of(c.stated[1]), text_of(c.stated[2])}}};
  if (c.holes.empty()) return;
  result.evidence["exact"]["unprinted"] = c.solved_text;
  std::string named;
  for (const auto& [k, u] : c.holes) {
    named += (named.empty() ? "" : ", ") + u.get_name() + " = " + text_of(c.solved.at(u));
    for (std::size_t other = 3; other-- > 0;) {  // equal to a printed one (c = a: the roots' product is 1)
      if (!c.holes.count(other) && GiNaC::normal(c.solved.at(u) - c.stated[other]).is_zero()) {
        named += ", the printed " + coefficient_name(r, other) + " coefficient";
        break;
      }
    }
  }
  const std::string said = "Not printed, solved from the scheme: " + named + ".";
  result.note = result.note.empty() ? said : result.note + " " + said;
}

}  // namespace

/// "This equation can be written a r² + b r + c = 0 with a = ..., b = ...": the printed polynomial
/// (its coefficients by `where`) is the scheme's at (1, r, r²) times a factor free of r. A
/// coefficient the text names without printing it (`unprinted`, c) is solved for: it is what makes
/// the two proportional, and the evidence gives it. The scale is the printed coefficient of the
/// highest power: Q_k P(r) = P_k Q(r), decided in both kernels as written, is the statement.
decider_evidence characteristic_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const characteristic_reading c = read_characteristic(read, call, "printed");
  const ex& printed = c.polynomial;
  const std::vector<GiNaC::symbol>& q = c.sequence;
  const GiNaC::symbol& r = c.root;
  const std::string &scheme_ref = c.scheme_ref, &printed_ref = c.polynomial_ref;
  claim_result result;
  result.printed = read.printed();
  if (!c.why_not.empty()) {
    result.note = c.why_not;
    return beyond_reach(std::move(result));  // a tool's limit, never a finding
  }
  // The statement: Q_lead · scheme(1, r, r²) = P_lead · printed, the unprinted coefficients put in.
  const GiNaC::lst geometric{q[0] == 1, q[1] == r, q[2] == r * r};
  const ex lhs = c.stated[c.lead] * c.scheme.subs(geometric);
  const ex rhs = c.derived[c.lead] * printed.subs(c.solved);
  const std::string what = fmt::format("({}) at {} = 1, {} = {}, {} = {}^2 is ({}) times {}", scheme_ref, q[0].get_name(), q[1].get_name(), r.get_name(),
                                       q[2].get_name(), r.get_name(), printed_ref, text_of(GiNaC::normal(1 / c.scale)));
  std::string correction = "as derived from (" + scheme_ref + "), scaled to the printed " + coefficient_name(r, c.lead) + " coefficient:";
  for (std::size_t k = 3; k-- > 0;) {
    correction += fmt::format(" ({}){}{}", text_of(GiNaC::normal(c.derived[k] * c.scale)), k > 0 ? " " + power_text(r, k) : std::string(), k > 0 ? " +" : "");
  }
  decider_evidence e = identity_evidence(read, "characteristic", what, lhs, rhs, correction);
  record_coefficients(e.found, c);
  return e;
}

/// "The discriminant Δ ≡ b² − 4ac can be factorized: Δ = ...": the printed value of the discriminant
/// of the printed polynomial a r² + b r + c, its coefficients as printed (`where`) and the unprinted
/// ones solved from the scheme at the printed scale (as `characteristic` does), decided in both
/// kernels. The printed definition (`definition`, b² − 4ac), when given, is first checked to be the
/// printed polynomial's discriminant, its symbols as printed; its value is then the one compared.
decider_evidence discriminant_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex printed = read.formula("printed");
  const characteristic_reading c = read_characteristic(read, call, "polynomial");
  const GiNaC::symbol& r = c.root;
  const std::string &polynomial_ref = c.polynomial_ref, printed_ref = reference_of(call, "printed");
  claim_result result;
  result.printed = read.printed();
  const auto cannot = [&](const std::string& why) {
    result.note = why;
    return beyond_reach(std::move(result));  // a tool's limit, never a finding
  };
  if (!c.why_not.empty()) return cannot(c.why_not);
  const ex discriminant = c.stated[1] * c.stated[1] - 4 * c.stated[2] * c.stated[0];  // b² − 4ac of the printed coefficients
  ex value = discriminant.subs(c.solved);
  std::string of = "b^2 - 4ac of (" + polynomial_ref + ")";
  if (read.has("definition")) {
    // As printed, before any definition: b² − 4ac of a r² + b r + c, in the printed symbols.
    const std::optional<std::array<ex, 3>> as_printed = quadratic_coefficients(read.raw("polynomial").value, r);
    const ex defined = read.raw("definition").value;
    if (!as_printed) return cannot("(" + polynomial_ref + ") as printed is not a polynomial of degree at most 2 in " + r.get_name() + ".");
    const ex expected = (*as_printed)[1] * (*as_printed)[1] - 4 * (*as_printed)[2] * (*as_printed)[0];
    if (!is_zero_expression(normal_difference(defined, expected))) {
      decider_evidence e;
      e.statement = fmt::format("({}) is the discriminant of ({})", reference_of(call, "definition"), polynomial_ref);
      e.ginac = answer::fails;
      result.correction = fmt::format("the discriminant of ({}) is {}", polynomial_ref, text_of(expected));
      result.note = fmt::format("As printed: ({}) = {} is not the discriminant of ({}), {}.", reference_of(call, "definition"), text_of(defined),
                                polynomial_ref, text_of(expected));
      result.evidence["exact"] = {{"statement", fmt::format("({}) is the discriminant of ({})", reference_of(call, "definition"), polynomial_ref)},
                                  {"ginac", "fails: " + text_of(normal_difference(defined, expected)) + " ≠ 0"}};
      e.found = std::move(result);
      return e;
    }
    value = read.formula("definition").subs(c.solved);
    of = "(" + reference_of(call, "definition") + ")";
  }
  const std::string what = fmt::format("{} = ({}), the unprinted coefficients solved from ({})", of, printed_ref, c.scheme_ref);
  decider_evidence e = identity_evidence(read, "discriminant", what, value, printed,
                                         fmt::format("as derived: {} = {}", of, text_of(GiNaC::factor(GiNaC::normal(value)))));
  record_coefficients(e.found, c);
  return e;
}

/// "has two {roots} roots r and r̄. Their product r r̄ = |r|² is {product} and the scheme is
/// {conclusion}", on the printed interval 0 < v < c: the discriminant (P₁² − 4P₀P₂)/P₂² of the scheme's
/// characteristic polynomial has one sign on the whole interval (our kernel's Sturm sequences, the
/// end compared exactly, and GiNaC's coefficients again), so the roots are complex conjugate (Δ < 0)
/// or real (Δ > 0) throughout; their product is P₀/P₂, a number (both kernels); the scheme is
/// power-bounded when the roots are complex with a product at most 1 (|r|² is the product, and a pair
/// of modulus 1 is simple since Δ ≠ 0), and not when they are real with product 1 (r and 1/r, one
/// outside the unit circle) on all or part of the interval. The words are judged against these facts; holes {product} and
/// {conclusion} are optional.
decider_evidence characteristic_roots_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex scheme = read.formula("scheme");
  const std::vector<GiNaC::symbol> q = read.symbols("sequence");
  const referenced_formula condition = read.raw("condition");
  const ex v = read.formula("variable");
  const std::string pattern = call.with.at("sentence").values.front();
  const quoted_sentence said = quote(ctx, pattern);
  const std::string roots_said = said.choice("roots", hole_named("roots").phrases);
  std::optional<stated_bound> product_said;
  if (pattern.find("{product}") != std::string::npos) {
    product_said = said.bound("product");
    if (!product_said->rest.empty()) said.unparsed("product", "a relation and a number");
  }
  std::optional<std::string> conclusion_said;
  if (pattern.find("{conclusion}") != std::string::npos) {
    conclusion_said = said.choice("conclusion", hole_named("conclusion").phrases);
  }
  const std::string scheme_ref = reference_of(call, "scheme");
  claim_result result;
  result.printed = read.printed();
  const auto cannot = [&](const std::string& why) {
    result.note = why;
    return beyond_reach(std::move(result));
  };
  const std::optional<three_term_coefficients> terms = linear_three_term(scheme, q);
  if (!terms) return cannot("The shape decides linear three-term schemes; (" + scheme_ref + ") is not linear in its states.");
  // The product of the roots, P₀/P₂: a number, in both kernels.
  const ex product = GiNaC::normal(terms->previous / terms->next);
  if (!GiNaC::is_a<GiNaC::numeric>(product) || !GiNaC::ex_to<GiNaC::numeric>(product).is_rational()) {
    return cannot("The roots' product " + text_of(product) + " of (" + scheme_ref + ") is not a number: the shape does not judge it.");
  }
  const kernel_decision product_own = kernel_decides_zero(terms->previous - product * terms->next);
  // The discriminant's sign on the interval, in both kernels.
  const ex high = interval_end(condition, v, read.reading());
  const ex delta = monic_discriminant(*terms);
  const std::optional<one_variable> g = in_variable(delta, v);
  const std::optional<rational> c = g ? g->exact(high) : std::nullopt;
  if (!g || !c || *c <= 0) {
    return cannot("The discriminant " + text_of(delta) + (g ? " on an interval whose end is not a positive rational" : " is not a function of " + text_of(v) + " alone") +
                  ": our kernel cannot decide its sign.");
  }
  const one_variable::inside_of found = g->first_inside(*c);
  if (found.ambiguous) return cannot("A root of the discriminant lies within 2^-40 of the interval's end.");
  const int sign = found.first ? 0 : g->sign_at(*c / 2);
  std::string ginac_proof;
  const int ginac_sign = ginac_sign_on(*g, v, high, ginac_proof);
  // The facts are our kernel's (the sign by Sturm sequences) and GiNaC's (the sign from its
  // coefficients, where they decide it, and the product in normal form): the words are judged once,
  // and the kernels differ on them only through a fact.
  decider_evidence e;
  e.statement = "the discriminant's sign or the roots' product";
  e.parts_differ = (ginac_sign != 0 && ginac_sign != sign) || product_own.outcome == kernel_decision::result::nonzero;
  const GiNaC::numeric p = GiNaC::ex_to<GiNaC::numeric>(product);
  const std::string nature = sign < 0 ? "complex conjugate" : sign > 0 ? "real" : "complex conjugate on part of the interval, real on the rest";
  std::optional<std::string> stability;  // "stable" or "unstable", when the facts decide it
  if (sign < 0) stability = p <= 1 ? "stable" : "unstable";
  if (sign >= 0 && p == 1) stability = "unstable";  // real r and 1/r where the discriminant is positive: on all or part of it
  const std::string var = text_of(v);
  const std::string stability_text =
      !stability ? std::string() : sign == 0 ? ", and the scheme is not stable on all of it" : ", and the scheme is " + *stability;
  const std::string facts = fmt::format("on 0 < {} < {} the discriminant is {}: the roots are {}, their product {}{}", var, text_of(high),
                                        sign < 0 ? "negative" : sign > 0 ? "positive" : "of both signs", nature, text_of(product), stability_text);
  result.evidence["exact"] = {
      {"statement", fmt::format("the roots of ({}) at (1, r, r^2) on 0 < {} < {}", scheme_ref, var, text_of(high))},
      {"stated", {{"roots", roots_said}, {"product", product_said ? said.words("product") : "(not stated)"},
                  {"conclusion", conclusion_said ? *conclusion_said : "(not stated)"}}},
      {"discriminant", text_of(delta)},
      {"product", text_of(product) + " = P0/P2"},
      {"own", std::string(sign != 0 ? "holds" : "fails") + ": the discriminant's roots in (0, c) by Sturm sequences, c compared exactly; the product: " +
                  product_own.evidence},
      {"ginac", std::string(ginac_sign != 0 ? "holds: " : "not decided: ") + ginac_proof + "; the product in normal form"}};
  std::vector<proof_goal> goals{decided("product", terms->previous, product * terms->next)};
  if (sign != 0) goals.push_back(g->sign_goal_on("discriminant", sign, *c));
  const bool product_right = !product_said || (p.is_integer() && product_said->admits(static_cast<int>(p.to_long())));
  const bool words_hold = roots_said == nature && product_right && (!conclusion_said || (stability && *conclusion_said == *stability));
  e.own = answer_of(words_hold);
  e.ginac = ginac_sign != 0 ? answer_of(words_hold) : answer::none;
  if (words_hold) {
    result.note = "Proved in both kernels on the whole interval (no sample): " + facts + ".";
  } else if (conclusion_said && !stability) {
    e.reached = decider_evidence::reach::beyond_reach;
    result.note = "The facts do not decide stability here (" + facts + "): the words' '" + *conclusion_said + "' is not judged.";
  } else {
    result.correction = "As proved: " + facts;
    result.note = "As printed, the sentence's words are not the facts proved on the interval.";
  }
  e.found = std::move(result);
  e.goals = std::move(goals);
  return e;
}


/// The shapes of this file, each one's name, summary, principal argument and parameters beside the
/// function that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> characteristic_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  add({"characteristic", "the printed polynomial in the root is the scheme at (1, r, r^2), up to a factor free of r; unprinted coefficients solved for",
       "printed",
       with_where({{"printed", argument_kind::formula, true, "the printed polynomial (its side that is 0), of degree at most 2 in the root"},
                   {"scheme", argument_kind::formula, true, "a linear three-term scheme (= 0)"},
                   {"sequence", argument_kind::symbols, true, "its three states q_{j-1}, q_j, q_{j+1}", 3},
                   {"root", argument_kind::symbols, true, "the root r: q_{j-1} = 1, q_j = r, q_{j+1} = r^2", 1},
                   {"unprinted", argument_kind::symbols, false, "coefficients the text names but does not print (c), each one whole coefficient"}}),
       characteristic_shape});
  add({"discriminant", "the printed value of the discriminant b^2 - 4ac of the printed polynomial a r^2 + b r + c, its unprinted coefficients solved from the scheme",
       "printed",
       with_where({{"printed", argument_kind::formula, true, "the printed value of the discriminant"},
                   {"polynomial", argument_kind::formula, true, "the printed polynomial in the root (its side that is 0)"},
                   {"definition", argument_kind::formula, false, "the printed definition of the discriminant, b^2 - 4ac, in the polynomial's symbols"},
                   {"scheme", argument_kind::formula, true, "a linear three-term scheme (= 0)"},
                   {"sequence", argument_kind::symbols, true, "the scheme's three states q_{j-1}, q_j, q_{j+1}", 3},
                   {"root", argument_kind::symbols, true, "the polynomial's variable", 1},
                   {"unprinted", argument_kind::symbols, false, "coefficients the text names but does not print, solved from the scheme"}}),
       discriminant_shape});
  add({"characteristic-roots", "what a sentence says of the roots of the scheme's characteristic polynomial on the printed interval: complex or real, their product, stability",
       "scheme",
       with_where({{"scheme", argument_kind::formula, true, "a linear three-term scheme (= 0)"},
                   {"sequence", argument_kind::symbols, true, "its three states q_{j-1}, q_j, q_{j+1}", 3},
                   {"variable", argument_kind::formula, true, "the variable of the condition, a product of positive symbols", 0, "", true},
                   {"condition", argument_kind::condition, true, "the printed interval 0 < variable < c"},
                   pattern_with_hole("sentence", "the sentence's pattern: the hole {roots} (complex conjugate, real), optionally {product} and {conclusion} (stable, unstable)",
                                     "roots")}),
       characteristic_roots_shape});
  return all;
}

}  // namespace simpson::verify::detail

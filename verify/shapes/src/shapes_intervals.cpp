// The interval shapes (shape_support.hpp): a map's first stability band, a sign on a printed interval,
// and the signs of a printed product's factors there, decided by our kernel's Sturm sequences with the
// printed end compared exactly.

#include <simpson/shapes/shape_support.hpp>

#include <simpson/prove/coq_export.hpp>
#include <simpson/shapes/one_variable.hpp>
#include <simpson/prove/printed_check_support.hpp>

#include <simpson/verify/sentence_holes.hpp>
#include <simpson/verify/quoted_words.hpp>
#include <simpson/verify/stability_analysis.hpp>
#include <simpson/verify/tex_math.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <optional>
#include <sstream>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

/// A factor the text writes as a sum, or a power of one.
bool written_as_sum(const ex& f) { return GiNaC::is_a<GiNaC::add>(f) || (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::add>(f.op(0))); }

/// The factors of a printed product as the text writes them: each sum (written_as_sum), and the rest
/// (numbers, symbols and their powers) multiplied into one prefactor, listed first; the sums by
/// their text (GiNaC orders a product by hash, which differs from run to run). Each parenthesised
/// factor is read on its own from the printed tree, so that it keeps its printed orientation: GiNaC's
/// product of (4 - x)(8 - x) is (x - 4)(x - 8), whose factors have the other sign. When the printed
/// side is not a product of its top-level parts (a sum, or parts whose product is not the formula),
/// the factors are GiNaC's.
std::vector<ex> printed_factors(const ex& product, const referenced_formula& printed, const shape_reader& read) {
  std::vector<ex> sums;
  ex prefactor = 1;
  const auto add_factor = [&](const ex& f) {
    if (written_as_sum(f)) {
      sums.push_back(f);
    } else {
      prefactor *= f;
    }
  };
  const auto as_read = [&]() {
    sums.clear();
    prefactor = 1;
    for (const ex& f : GiNaC::is_a<GiNaC::mul>(product) ? GiNaC::exvector(product.begin(), product.end()) : GiNaC::exvector{product}) add_factor(f);
  };
  const auto read_part = [&](const tex_list& part) { return read.defined(read_math(part, read.reading(), paper_symbols())); };
  bool from_tree = printed.side < printed.side_trees.size();
  if (from_tree) {
    const tex_list& side = printed.side_trees[printed.side];
    tex_list rest;
    for (std::size_t k = 0; k < side.size() && from_tree; ++k) {
      const tex_node& n = side[k];
      if (n.kind == tex_node_kind::atom && n.atom_class == tex_class::bin) from_tree = false;  // a sum, not a product
      const bool parenthesised = (n.kind == tex_node_kind::delimited && n.text == "(") ||
                                 (n.kind == tex_node_kind::scripts && !n.children.empty() && n.children.front().kind == tex_node_kind::delimited &&
                                  n.children.front().text == "(");
      if (parenthesised) {
        add_factor(read_part({n}));
      } else if (delimiter_depth_change(n) > 0) {
        tex_list group{n};
        int depth = 1;
        while (depth > 0 && ++k < side.size()) {
          depth += delimiter_depth_change(side[k]);
          group.push_back(side[k]);
        }
        if (depth != 0) from_tree = false;
        else add_factor(read_part(group));
      } else {
        rest.push_back(n);
      }
    }
    if (from_tree && !rest.empty()) prefactor *= read_part(rest);
    from_tree = from_tree && GiNaC::normal(GiNaC::expand(prefactor) * [&] {
                  ex all = 1;
                  for (const ex& f : sums) all *= f;
                  return all;
                }() - product).is_zero();
  }
  if (!from_tree) as_read();
  std::sort(sums.begin(), sums.end(), [](const ex& a, const ex& b) { return text_of(a) < text_of(b); });
  std::vector<ex> out;
  if (!(GiNaC::is_a<GiNaC::numeric>(prefactor) && prefactor == 1)) out.push_back(prefactor);
  out.insert(out.end(), sums.begin(), sums.end());
  return out;
}

std::string sign_word(int sign) { return sign > 0 ? "positive" : sign < 0 ? "negative" : "of no one sign"; }

}  // namespace

decider_evidence stability_interval_shape(const shape_call& call, const run_context& ctx) {
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
      // Not symplectic: the premise of the band's criterion (|trace| < 2 for det 1) fails, decided in
      // both kernels; a finding without a correction (what its stable set is, the shape does not say).
      result.printed = read.printed();
      result.evidence["exact"] = {{"statement", "det (" + what + ") = 1: the map is symplectic, the premise of the criterion |trace| < 2"},
                                  {"ginac", "fails: det = " + text_of(GiNaC::normal(det))},
                                  {"own", std::string(det_own.outcome == kernel_decision::result::nonzero ? "fails: " : "not decided: ") + det_own.evidence}};
      result.note = "(" + what + ") is not symplectic: its determinant is " + text_of(GiNaC::factor(GiNaC::normal(det))) +
                    ", not 1, so its stability is not the band where |trace| < 2 that this shape decides.";
      result.certificate_missing = "a determinant that is not 1: nothing to certify of the band";
      decider_evidence e;
      e.statement = "det = 1, the map's premise";
      e.ginac = answer::fails;
      e.own = det_own.outcome == kernel_decision::result::nonzero ? answer::fails : answer::none;
      e.if_false = verdict::fails;
      e.found = std::move(result);
      return e;
    }
    trace = m(0, 0) + m(1, 1);
    premise = "det = 1 (GiNaC normal form; our kernel: " + det_own.evidence + ")";
    premise_goal = decided("det", determinant_2x2(m), 1);  // a d − b c as written, not GiNaC's value
  } else {
    const ex scheme = read.formula("scheme");
    const std::vector<GiNaC::symbol> q = read.symbols("sequence");
    const std::optional<three_term_coefficients> terms = linear_three_term(scheme, q);
    kernel_decision reversible_own;
    if (!terms || !reversible(*terms, reversible_own)) {
      result.printed = read.printed();
      result.note = "The shape decides linear three-term schemes whose " + q[2].get_name() + " and " + q[0].get_name() + " coefficients are equal; (" +
                    what + ") " + (terms ? "has " + text_of(GiNaC::normal(terms->next)) + " and " + text_of(GiNaC::normal(terms->previous)) : "is not linear in its states") + ".";
      return beyond_reach(std::move(result));
    }
    trace = -terms->current / terms->next;
    premise = fmt::format("the scheme is linear, its {} and {} coefficients equal: the characteristic roots' product is 1 (GiNaC normal form; our kernel: {})",
                          q[2].get_name(), q[0].get_name(), reversible_own.evidence);
    premise_goal = decided("reversible", terms->next, terms->previous);
  }
  const ex v = read.formula("variable");
  result.printed = read.printed();
  const ex high = interval_end(condition, v, read.reading());
  const std::optional<one_variable> excess = in_variable(trace * trace - 4, v);  // < 0 exactly on the stable set
  if (!excess) {
    result.note = "The trace of " + what + " is not a function of " + text_of(v) + " alone.";
    return beyond_reach(std::move(result));
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
  // The bands and the end's comparison are our kernel's (Sturm sequences, exact): its answer decides.
  decider_evidence e;
  e.statement = "the first stable band";
  e.own = answer_of(stable_near_zero && equal);
  if (stable_near_zero && equal) {
    goals.push_back(excess->sign_goal_on("stable_band", -1, *excess->exact(high)));
    e.goals = std::move(goals);
    // What the condition leaves out: the other bands, and the ends, where |trace| = 2 (a double root ±1).
    if (bands.size() > 1) {
      std::vector<std::string> ends;
      for (const positive_root& end : positive_roots(excess->numerator)) ends.push_back(excess->text(end));  // not its poles
      result.note = fmt::format("Sufficient, not necessary: ({}) is stable exactly for {}. At {} = {} the characteristic roots are double (|trace| = 2).",
                                what, fmt::join(bands, ", "), var, fmt::join(ends, ", "));
    }
    e.found = std::move(result);
    return e;
  }
  if (stable_near_zero && excess->ends.front().exact()) goals.push_back(excess->sign_goal_on("first_band", -1, excess->ends.front().low));
  e.goals = std::move(goals);
  result.correction = bands.empty() ? "never stable for " + var + " > 0" : "stable exactly for " + fmt::format("{}", fmt::join(bands, ", "));
  result.note = "As printed: " + folded_space(condition.tex) + " is not the first stable band of " + what +
                " (trace = " + text_of(trace_in_v) + ", stable where |trace| < 2).";
  e.found = std::move(result);
  return e;
}

/// The sign a claim states: the words of its sentence's hole {sign}, or, with no sentence, the
/// record's `sign`.
std::string stated_sign(const shape_call& call, const run_context& ctx) {
  if (!call.with.count("sentence")) return call.with.at("sign").values.front();
  return quote(ctx, call.with.at("sentence").values.front()).choice("sign", hole_named("sign").phrases);
}

/// What the sign shapes read: the expression as a function of the variable alone, the printed
/// interval 0 < v < c with c exact, and the sign the claim states. None when our kernel cannot decide
/// (the expression not a function of v alone, or c not a positive rational): `result`'s note then
/// says why (beyond the shape's reach).
struct sign_claim {
  ex f, v, high;
  referenced_formula condition;
  std::string claimed;
  int want = 0;
  std::optional<one_variable> g;
  rational c;
};

std::optional<sign_claim> read_sign_claim(shape_reader& read, const shape_call& call, const run_context& ctx, claim_result& result) {
  sign_claim s;
  s.f = read.formula("expression");
  s.condition = read.raw("condition");
  s.v = read.formula("variable");
  s.claimed = stated_sign(call, ctx);
  s.want = s.claimed == "positive" ? 1 : -1;
  result.printed = read.printed();
  s.high = interval_end(s.condition, s.v, read.reading());
  s.g = in_variable(s.f, s.v);
  if (!s.g) {
    result.note = "(" + reference_of(call, "expression") + ") is not a function of " + text_of(s.v) + " alone.";
    return std::nullopt;
  }
  const std::optional<rational> c = s.g->exact(s.high);
  if (!c || *c <= 0) {
    result.note = "The interval's end " + text_of(s.high) + " is not a positive rational" + (s.g->in_square ? " in its square" : "") +
                  ": our kernel compares ends exactly, and cannot here.";
    return std::nullopt;
  }
  s.c = *c;
  return s;
}

/// The claimed sign of a function of v on the printed interval 0 < v < c: no root or pole of it
/// inside (our kernel's Sturm sequences, the end compared exactly), and the sign at a point inside.
decider_evidence sign_on_interval_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  claim_result result;
  const std::optional<sign_claim> claim = read_sign_claim(read, call, ctx, result);
  if (!claim) return beyond_reach(std::move(result));
  const ex &f = claim->f, &v = claim->v, &high = claim->high;
  const referenced_formula& condition = claim->condition;
  const std::string& claimed = claim->claimed;
  const int want = claim->want;
  const std::optional<one_variable>& g = claim->g;
  const std::optional<rational> c = claim->c;
  const std::string var = text_of(v);
  // The first root or pole of f inside (0, c), if any.
  const one_variable::inside_of found = g->first_inside(*c);
  if (found.ambiguous) {
    result.note = "A root of " + text_of(f) + " lies within 2^-40 of the interval's end; its isolating interval holds the end.";
    return beyond_reach(std::move(result));
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
      {"interval_end", fmt::format("{} = {} (exact)", g->in_square ? "c^2" : "c", c->str())},
      {"own", std::string(!inside && sign == want ? "holds" : "fails") + ": our kernel's Sturm sequences, no root or pole of the function of " + var +
                  " inside, and its sign at a point inside"},
      {"ginac", "holds: the expression reduced to a function of " + var + " alone, " + text_of(g->of_t.subs(g->t == v)) +
                    " (normal form); the sign is our kernel's"}};
  // Coq: the sign on the printed interval (holds), or the correction's: the sign found on (0, c),
  // or on (0, r) up to the first root or pole r when it is rational.
  // The roots, poles and sign are our kernel's: its answer decides.
  decider_evidence e;
  e.statement = "the sign on the interval";
  e.own = answer_of(!inside && sign == want);
  if (!inside && sign == want) {
    e.goals = std::vector<proof_goal>{g->sign_goal_on("sign", want, *c)};
    e.found = std::move(result);
    return e;
  }
  if (!inside) {
    e.goals = std::vector<proof_goal>{g->sign_goal_on("sign", sign, *c)};
  } else if (inside->exact()) {
    e.goals = std::vector<proof_goal>{g->sign_goal_on("sign_before_root", sign, inside->low)};
  } else {
    result.certificate_missing = "the sign changes at an irrational root, which the certificate cannot name as a bound; our kernel's Sturm sequences decide it";
  }
  const std::string sign_text = sign > 0 ? "positive" : "negative";
  result.correction = inside ? fmt::format("{} is {} for 0 < {} < {} only, and changes sign there", expression, sign_text, var, g->text(*inside))
                             : fmt::format("{} is {} for 0 < {} < {}", expression, sign_text, var, text_of(high));
  result.note = "As printed: (" + reference_of(call, "expression") + ") is said to be " + claimed + " for " + folded_space(condition.tex) + ".";
  e.found = std::move(result);
  return e;
}

/// "Under (condition), all the factors of the expression are {sign} and Δ {relation}": each factor of
/// the printed product (printed_factors) has its sign on the printed interval decided by our
/// kernel's Sturm sequences and again by GiNaC's coefficient test; the words are judged against
/// them: every factor of the stated sign, and the product in the stated relation to 0 (when the
/// sentence has a hole {relation}). The product's relation true with a factor of another sign is a
/// wording erratum; the correction gives each factor's proved sign, and so does the certificate.
decider_evidence factor_signs_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const referenced_formula printed_product = read.raw("expression");  // read once: its value, and its tree for the factors
  const ex product = read.defined(printed_product.value);
  const referenced_formula condition = read.raw("condition");
  const ex v = read.formula("variable");
  const std::string pattern = call.with.at("sentence").values.front();
  const quoted_sentence said = quote(ctx, pattern);
  const int stated = said.choice("sign", hole_named("sign").phrases) == "negative" ? -1 : 1;
  const bool has_relation = pattern.find("{relation}") != std::string::npos;
  std::optional<stated_bound> relation;
  if (has_relation) {
    relation = said.bound("relation");
    if (relation->value != 0 || !relation->rest.empty()) said.unparsed("relation", "a relation to 0");
  }
  claim_result result;
  result.printed = read.printed();
  const ex high = interval_end(condition, v, read.reading());
  const std::string var = text_of(v), expression = reference_of(call, "expression");
  json factors = json::array();
  std::vector<proof_goal> goals;
  std::vector<std::string> proved, unlike;
  bool kernels_agree = true, sums_as_stated = true, ginac_decided = true;
  int product_sign = 1;
  for (const ex& f : printed_factors(product, printed_product, read)) {
    const std::optional<one_variable> g = in_variable(f, v);
    const std::optional<rational> c = g ? g->exact(high) : std::nullopt;
    if (!g || !c || *c <= 0) {
      result.note = "The factor " + text_of(f) + (g ? " on an interval whose end is not a positive rational" + std::string(g->in_square ? " in its square" : "")
                                                     : " is not a function of " + var + " alone") + ": our kernel cannot decide its sign.";
      return beyond_reach(std::move(result));
    }
    // Our kernel: no root or pole inside (0, c), and the sign at c/2.
    const one_variable::inside_of found = g->first_inside(*c);
    if (found.ambiguous) {
      result.note = "A root or pole of " + text_of(f) + " lies within 2^-40 of the interval's end; its isolating interval holds the end.";
      return beyond_reach(std::move(result));
    }
    const bool inside = found.first.has_value();
    const int own = inside ? 0 : g->sign_at(*c / 2);
    std::string ginac_proof;
    const int theirs = ginac_sign_on(*g, v, high, ginac_proof);
    kernels_agree = kernels_agree && (theirs == 0 || theirs == own);
    ginac_decided = ginac_decided && theirs != 0;
    product_sign *= own;
    const std::string text = text_of(f);
    factors.push_back({{"factor", text}, {"own", sign_word(own) + (inside ? ": a root or pole inside" : "")}, {"ginac", ginac_proof}});
    proved.push_back(text + " " + sign_word(own));
    if (own != stated) unlike.push_back(text);
    if (own != stated && written_as_sum(f)) sums_as_stated = false;  // the prefactor is the one factor that is not a sum
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
  // The words are judged on our kernel's signs; GiNaC's coefficient test agrees factor by factor
  // where it decides, and answers on the words only where it decided every factor.
  decider_evidence e;
  e.statement = "the factors' signs";
  e.parts_differ = !kernels_agree;
  e.disagreement = "Our kernel's (Sturm) and GiNaC's (coefficients) signs of a factor differ: a bug in one of them.";
  e.own = answer_of(factors_as_stated && relation_as_stated);
  e.ginac = ginac_decided ? e.own : answer::none;
  e.goals = std::move(goals);
  const std::string facts = fmt::format("on 0 < {} < {}: {}; the product is {}", var, text_of(high), fmt::join(proved, ", "), sign_word(product_sign));
  if (factors_as_stated && relation_as_stated) {
    result.note = "Proved in both kernels, each factor's sign on the whole interval (no sample): " + facts + ".";
    e.found = std::move(result);
    return e;
  }
  // Only the monomial prefactor differs, and the sentence states the product's sign, which holds:
  // the sentence is consistent under one reading alone, "all the factors" being the sums (all of them
  // of the stated sign would give the product the other one). As an expert reads it, it holds: a
  // wording remark (the policy: an erratum is false under every reasonable reading).
  if (has_relation && relation_as_stated && sums_as_stated) {
    e.own = answer::holds;
    e.ginac = ginac_decided ? answer::holds : answer::none;
    result.remark_kind = finding::wording;
    result.remark = fmt::format("'All the factors' can only be the factors that are sums: they are {}, and the product {} as stated; the prefactor {} is {} "
                                "(were it {} too, the product would have the other sign). As proved: {}.",
                                said.words("sign"), sign_word(product_sign) == "negative" ? "is negative" : "is positive", fmt::join(unlike, ", "),
                                stated < 0 ? "positive" : "negative", said.words("sign"), facts);
    result.amendments.push_back(amendment_in_words("the sign said of all the factors", said.words("sign"),
                                                   fmt::format("{} for the factors that are sums; {} for the prefactor {}", said.words("sign"),
                                                               stated < 0 ? "positive" : "negative", fmt::join(unlike, ", "))));
    e.found = std::move(result);
    return e;
  }
  result.correction = "As proved: " + facts;
  // Wording when only the monomial prefactor differs and the product's relation holds: the sums are
  // what a reader may take for "the factors"; the words' "all" takes in the prefactor too.
  result.note = relation_as_stated && sums_as_stated
                    ? fmt::format("Wording: 'all the factors' are said to be {}, which the prefactor {} is not; the factors that are sums are {}, and "
                                  "the product's sign is as stated.", said.words("sign"), fmt::join(unlike, ", "), said.words("sign"))
                    : "As printed, the factors' signs are not the sentence's: " + fmt::format("{}", fmt::join(unlike, ", ")) + ".";
  result.amendments.push_back(amendment_in_words(
      "the sign said of all the factors", said.words("sign"),
      relation_as_stated && sums_as_stated
          ? fmt::format("{} for the factors that are sums; {} for the prefactor {}", said.words("sign"), stated < 0 ? "positive" : "negative", fmt::join(unlike, ", "))
          : fmt::format("on 0 < {} < {}: {}; the product {}", var, text_of(high), fmt::join(proved, ", "), sign_word(product_sign))));
  e.found = std::move(result);
  return e;
}

}  // namespace simpson::verify::detail

namespace simpson::verify::detail {

/// "positive if and only if 0 < v < c": the function has the stated sign on the printed interval and
/// nowhere else for v > 0 (but at isolated points). Our kernel's Sturm sequences find every positive
/// root and pole; the sign is probed on each interval between them: the printed end must be one of
/// them, the sign the stated one before it and never after it. Coq certifies the sign on the printed
/// interval, and on each bounded interval beyond it between rational ends; the unbounded last one is
/// our kernel's alone.
decider_evidence sign_iff_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  claim_result result;
  const std::optional<sign_claim> claim = read_sign_claim(read, call, ctx, result);
  if (!claim) return beyond_reach(std::move(result));
  const ex &f = claim->f, &v = claim->v, &high = claim->high;
  const referenced_formula& condition = claim->condition;
  const std::string& claimed = claim->claimed;
  const int want = claim->want;
  const std::optional<one_variable>& g = claim->g;
  const std::optional<rational> c = claim->c;
  // The intervals of v > 0 between the roots and poles, each with its sign (probed inside it).
  struct band {
    rational from, to;  // to < 0: unbounded
    bool from_exact = true, to_exact = true;
    std::string from_text, to_text;
    int sign = 0;
  };
  std::vector<band> bands;
  rational from(0);
  std::string from_text = "0";
  bool from_exact = true;
  for (const positive_root& e : g->ends) {
    const rational probe = (from + e.low) / 2;
    bands.push_back({from, e.low, from_exact, e.exact(), from_text, g->text(e), g->sign_at(probe)});
    from = e.high;
    from_text = g->text(e);
    from_exact = e.exact();
  }
  bands.push_back({from, rational(-1), from_exact, true, from_text, "", g->sign_at(from + rational(1))});
  // Where the function has the stated sign, as bands of v.
  const std::string var = text_of(v);
  std::vector<std::string> where;
  for (const band& b : bands) {
    if (b.sign != want) continue;
    where.push_back(b.to < 0 ? fmt::format("{} > {}", var, b.from_text) : fmt::format("{} < {} < {}", b.from_text, var, b.to_text));
  }
  // The printed statement: the first band ends exactly at c, with the stated sign, and no other band has it.
  const bool first_is_printed = !bands.empty() && bands.front().sign == want && bands.front().to_exact && bands.front().to == *c;
  bool others_opposite = true;
  for (std::size_t k = 1; k < bands.size(); ++k) others_opposite = others_opposite && bands[k].sign != want;
  const bool holds = first_is_printed && others_opposite;
  result.evidence["exact"] = {
      {"statement", fmt::format("({}) is {} exactly for 0 < {} < {}", reference_of(call, "expression"), claimed, var, text_of(high))},
      {"in_variable", text_of(g->of_t.subs(g->t == v))},
      {"bands", [&] {
         json all = json::array();
         for (const band& b : bands) {
           all.push_back(fmt::format("{} on ({}, {})", b.sign > 0 ? "positive" : "negative", b.from_text, b.to < 0 ? "infinity" : b.to_text));
         }
         return all;
       }()},
      {"interval_end", fmt::format("{} = {} (exact)", g->in_square ? "c^2" : "c", c->str())},
      {"own", std::string(holds ? "holds" : "fails") + ": our kernel's Sturm sequences, every positive root and pole of the function of " + var +
                  ", the sign probed between them"},
      {"ginac", "holds: the expression reduced to a function of " + var + " alone, " + text_of(g->of_t.subs(g->t == v)) +
                    " (normal form); the bands are our kernel's"}};
  std::vector<proof_goal> goals;
  if (first_is_printed) goals.push_back(g->sign_goal_on("sign_before", want, *c));
  for (std::size_t k = 1; k < bands.size(); ++k) {
    if (bands[k].to < 0 || !bands[k].from_exact || !bands[k].to_exact) continue;
    goals.push_back(g->sign_goal_between("sign_band_" + std::to_string(k), bands[k].sign, bands[k].from, bands[k].to));
  }
  // The bands are our kernel's (Sturm sequences): its answer decides.
  decider_evidence e;
  e.statement = "the sign's bands";
  e.own = answer_of(holds);
  if (goals.empty()) {
    result.certificate_missing = "no band with rational ends to state; our kernel's Sturm sequences decide it";
  } else {
    e.goals = std::move(goals);
  }
  if (holds) {
    e.found = std::move(result);
    return e;
  }
  result.correction = where.empty() ? fmt::format("{} is never {} for {} > 0", text_of(f), claimed, var)
                                    : fmt::format("{} is {} exactly for {}", text_of(f), claimed, fmt::join(where, " and for "));
  result.note = "As printed: (" + reference_of(call, "expression") + ") is said to be " + claimed + " if and only if " + folded_space(condition.tex) + ".";
  e.found = std::move(result);
  return e;
}

/// The shapes of this file, each one's name, summary, principal argument and parameters beside the
/// function that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> intervals_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  add({"stability-interval", "the printed 0 < variable < c is the first band where the map (det 1), or the three-term scheme (reversible), is power-bounded",
       "condition",
       with_where({{"map", argument_kind::matrix, false, "a 2 x 2 one-step map with det 1", 2},
                   {"scheme", argument_kind::formula, false,
                    "instead of a map: a linear three-term scheme (= 0) whose q_{j+1} and q_{j-1} coefficients are equal", 0, "", false, {}, "",
                    "map"},
                   {"sequence", argument_kind::symbols, false, "the scheme's three states q_{j-1}, q_j, q_{j+1}", 3, "", false, {}, "", "",
                    "scheme"},
                   {"variable", argument_kind::formula, true, "the variable of the condition, a product of positive symbols", 0, "", true},
                   {"condition", argument_kind::condition, true, "the printed condition 0 < variable < c"}}),
       stability_interval_shape});
  add({"sign-on-interval", "expression has the stated sign on the printed interval 0 < variable < c", "expression",
       with_where({{"expression", argument_kind::formula, true, "a function of the variable alone once scaled"},
                   {"variable", argument_kind::formula, true, "the variable of the condition, a product of positive symbols", 0, "", true},
                   {"condition", argument_kind::condition, true, "the printed interval 0 < variable < c"},
                   {"sign", argument_kind::word, false, "positive or negative, when no sentence states it", 0, "", false, {"positive", "negative"}, "", "sentence"},
                   pattern_with_hole("sentence", "the sentence that states the sign, with the hole {sign}: '... is {sign} for'", "sign", false)}),
       sign_on_interval_shape});
  add({"sign-iff", "expression has the stated sign if and only if 0 < variable < c: on the printed interval, and nowhere else for variable > 0",
       "expression",
       with_where({{"expression", argument_kind::formula, true, "a function of the variable alone once scaled"},
                   {"variable", argument_kind::formula, true, "the variable of the condition, a product of positive symbols", 0, "", true},
                   {"condition", argument_kind::condition, true, "the printed interval 0 < variable < c"},
                   {"sign", argument_kind::word, false, "positive or negative, when no sentence states it", 0, "", false, {"positive", "negative"}, "", "sentence"},
                   pattern_with_hole("sentence", "the sentence that states the sign, with the hole {sign}: '... is {sign} if and only if'", "sign", false)}),
       sign_iff_shape});
  add({"factor-signs", "each factor of the printed product, and the product, have the signs a sentence states on the printed interval 0 < variable < c",
       "expression",
       with_where({{"expression", argument_kind::formula, true, "the printed product: its sums are its factors, the rest one prefactor"},
                   {"variable", argument_kind::formula, true, "the variable of the condition, a product of positive symbols", 0, "", true},
                   {"condition", argument_kind::condition, true, "the printed interval 0 < variable < c"},
                   pattern_with_hole("sentence", "the sentence's pattern: the hole {sign} (the factors' sign), optionally {relation} (the product's, to 0)",
                                     "sign")}),
       factor_signs_shape});
  return all;
}

}  // namespace simpson::verify::detail

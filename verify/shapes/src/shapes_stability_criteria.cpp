// The stability shapes of a linear three-term scheme (shape_support.hpp), stated in words: a criterion
// on the modulus of its characteristic roots (root-criterion) and stability for every step
// (unconditional-stability), each against the root condition on every region of the variable > 0.
// The characteristic polynomial, its discriminant and its roots: shapes_characteristic.cpp.

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

/// "The scheme is stable when the roots of the corresponding equation are of modulus {modulus}": the
/// stated criterion against the root condition (every root of modulus at most 1, those of modulus 1
/// simple) on every region of v > 0, for a reversible scheme (P₀ = P₂: the roots' product is 1). The
/// regions are cut at the roots and poles of the discriminant (Sturm sequences): where it is negative,
/// a simple conjugate pair of modulus 1 (stable); where positive, ρ and 1/ρ with ρ > 1 taking every
/// value near 1 at the region's ends (unstable); at its roots, a double root ±1 (unstable: linear
/// growth). "{modulus}" is a bound ("smaller than 1", "at most 1"), optionally with "simple".
decider_evidence root_criterion_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex scheme = read.formula("scheme");
  const std::vector<GiNaC::symbol> q = read.symbols("sequence");
  const ex v = read.formula("variable");
  const quoted_sentence said = quote(ctx, call.with.at("sentence").values.front());
  const stated_bound bound = said.bound("modulus");
  const bool simple_required = !bound.rest.empty();
  if (simple_required && bound.rest.find("simple") == std::string::npos) said.unparsed("modulus", "a bound, optionally with 'simple'");
  const std::string scheme_ref = reference_of(call, "scheme");
  claim_result result;
  result.printed = read.printed();
  const std::optional<reversible_scheme> premise = reversible_premise(scheme, q, v, scheme_ref, result);
  if (!premise) return beyond_reach(std::move(result));
  const ex& delta = premise->delta;
  const std::optional<one_variable>& g = premise->g;
  const kernel_decision& reversible_own = premise->reversible_own;
  // What the criterion calls stable: a simple pair of modulus 1; real ρ, 1/ρ with ρ near 1; a double root ±1.
  const bool says_unit_pair = bound.admits(1);
  const bool says_real_pair = (bound.relation == "<" || bound.relation == "<=") ? bound.value > 1
                              : (bound.relation == ">" || bound.relation == ">=") ? bound.value < 1
                                                                                  : false;
  const bool says_double = bound.admits(1) && !simple_required;
  const std::string var = text_of(v), var_in = g->in_square ? "(" + var + ")^2" : var;
  json regions = json::array();
  std::vector<std::string> stable_bands;
  std::vector<proof_goal> goals{decided("reversible", premise->terms.next, premise->terms.previous)};
  bool agrees = true, said_any_stable = false, only_too_strict = true;
  std::vector<std::string> disagreements;  // where the stated criterion and the root condition differ, in words
  const auto differ = [&](const std::string& where, const std::string& roots, bool stable) {
    only_too_strict = only_too_strict && stable;  // a stable region the criterion calls unstable
    disagreements.push_back(fmt::format("for {} {} the roots are {}: {} by the root condition, {} by '{}'", var, where, roots, stable ? "stable" : "unstable",
                                        stable ? "unstable" : "stable", said.words("modulus")));
  };
  for (const discriminant_region& region : regions_of(*g)) {
    const bool stable = region.negative;
    const bool said_stable = stable ? says_unit_pair : says_real_pair;
    agrees = agrees && said_stable == stable;
    said_any_stable = said_any_stable || said_stable;
    if (said_stable != stable) differ("in " + region.text(), stable ? "conjugate, simple, of modulus 1" : "real, rho and 1/rho with rho > 1", stable);
    regions.push_back({{var, region.text()},
                       {"roots", stable ? "conjugate, simple, modulus 1" : "real, rho and 1/rho, rho > 1"},
                       {"root_condition", stable ? "stable" : "unstable"},
                       {"stated_criterion", said_stable ? "stable" : "unstable"}});
    if (stable) {
      stable_bands.push_back(region.text());
      if (auto goal = stable_band_goal(*g, region, stable_bands.size())) goals.push_back(std::move(*goal));
    }
    if (!region.last) {
      const positive_root& end = g->ends[region.index];  // a root of the numerator (a double root ±1), or a pole
      const bool root = end.exact() ? g->numerator.evaluate(end.low) == 0
                                    : (g->numerator.evaluate(end.low) < 0) != (g->numerator.evaluate(end.high) < 0);
      if (root) {
        agrees = agrees && !says_double;
        said_any_stable = said_any_stable || says_double;
        if (says_double) differ("= " + region.to_text, "a double root of modulus 1", false);
        regions.push_back({{var, region.to_text}, {"roots", "double, modulus 1"}, {"root_condition", "unstable (linear growth)"},
                           {"stated_criterion", says_double ? "stable" : "unstable"}});
      }
    }
  }
  result.evidence["exact"] = {
      {"statement", fmt::format("the criterion '{}' against the root condition on every region of {} > 0, for ({})", said.words("modulus"), var, scheme_ref)},
      {"stated", said.words("modulus")},
      {"reversible", "the first and last coefficients are equal, so the roots' product is 1 (GiNaC normal form; our kernel: " + reversible_own.evidence + ")"},
      {"discriminant", text_of(delta) + " (over the leading coefficient squared)"},
      {"regions", regions},
      {"own", std::string("holds: the regions by Sturm sequences of the discriminant, in ") + var_in},
      {"ginac", "holds: the premise in normal form, and the discriminant as a function of " + var + " alone; the regions are our kernel's"}};
  // The regions are our kernel's; GiNaC's part is the premise and the reduction to one variable.
  decider_evidence e;
  e.statement = "the stated criterion against the root condition";
  e.own = answer_of(agrees);
  e.goals = std::move(goals);
  if (agrees) {
    e.found = std::move(result);
    return e;
  }
  // "Modulus smaller than 1", where the stable roots have modulus 1: read literally, a sufficient
  // condition (true, and met by no step here); read as meant ("smaller than" for at most 1, as the
  // French "inférieur à"), the root condition without its clause on simple roots, which the roots here
  // are. The conclusion the text draws from it holds: as an expert reads it, a wording remark.
  if (only_too_strict && bound.relation == "<" && bound.value == 1 && !simple_required) {
    e.own = answer::holds;
    result.remark_kind = finding::wording;
    result.remark = fmt::format("'{}' should read 'at most 1, those of modulus 1 simple' (the root condition). Read literally it is a sufficient "
                                "condition that no {} > 0 meets here; the conclusion, drawn from roots of modulus 1, holds because the negative "
                                "discriminant makes them simple and conjugate: stable for {} in {}.",
                                said.words("modulus"), var, var, fmt::join(stable_bands, " and "));
    result.amendments.push_back(amendment_in_words("the stability criterion", said.words("modulus"),
                                                   "modulus at most 1, those of modulus 1 simple (the root condition)"));
    e.found = std::move(result);
    return e;
  }
  result.correction = fmt::format("The scheme is stable when the roots have modulus <= 1 and the roots of modulus 1 are simple (root condition); here they "
                                  "are simple, conjugate and of modulus 1 for {} in {}.", var, fmt::join(stable_bands, " and "));
  result.amendments.push_back(amendment_in_words("the stability criterion", said.words("modulus"),
                                                 fmt::format("modulus at most 1, those of modulus 1 simple (the root condition): stable for {} in {}", var,
                                                             fmt::join(stable_bands, " and "))));
  result.note = fmt::format("As printed, '{}' and the root condition disagree: {}{}.", said.words("modulus"), fmt::join(disagreements, "; "),
                            said_any_stable ? ""
                                            : fmt::format("; read literally, '{}' is a sufficient condition that no {} > 0 meets here, and the text "
                                                          "then applies it to roots of modulus 1: what the conclusion needs is the root condition, "
                                                          "which the negative discriminant gives, so the conclusion stands",
                                                          said.words("modulus"), var));
  e.found = std::move(result);
  return e;
}

/// "the scheme is {stability}" (stable, linearly stable, unstable; "conditionally stable" or
/// "unconditionally stable" in the hole itself), optionally with "{qualifier} stable" (unconditionally,
/// or the paper's French "inconditionally"; conditionally): against the root condition on every
/// variable > 0 of a reversible linear three-term scheme. Stable where its discriminant is negative:
/// unconditionally when it has no root or pole on variable > 0 and is negative there (Sturm sequences;
/// Coq: the sign for every positive symbol), conditionally when it is negative on some band between
/// them (Coq: the sign on each band with rational ends), unstable when on none. Unqualified, "stable"
/// is read as the field reads it of a scheme, stable for every step small enough: it holds on a first
/// band from 0, with a wording remark when the scheme is not stable for every step.
decider_evidence unconditional_stability_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex scheme = read.formula("scheme");
  const std::vector<GiNaC::symbol> q = read.symbols("sequence");
  const ex v = read.formula("variable");
  const quoted_sentence said = quote(ctx, call.with.at("sentence").values.front());
  // The qualifier may be in the hole itself; else the qualifying sentence gives it, or the default
  // (for every step).
  const std::string stated_words = said.choice("stability", hole_named("stability").phrases);
  const std::string stated = stated_words == "unstable" ? "unstable" : "stable";
  std::string qualifier = stated_words == "unconditionally stable" ? "unconditional" : stated_words == "conditionally stable" ? "conditional" : "";
  // A plain "stable", with no qualifying words, is read as the field reads it of a scheme: stable for
  // every step small enough (a first stable band from 0); not for every step, a wording remark.
  const bool plain = qualifier.empty() && !call.with.count("qualifier") && stated_words == "stable";
  if (qualifier.empty()) {
    qualifier = "unconditional";  // no qualifying words: stable means for every step
    if (call.with.count("qualifier")) {
      qualifier = quote(ctx, call.with.at("qualifier").values.front())
                      .choice("qualifier", hole_named("qualifier").phrases);
    }
  }
  const std::string scheme_ref = reference_of(call, "scheme");
  claim_result result;
  result.printed = read.printed();
  const std::optional<reversible_scheme> premise = reversible_premise(scheme, q, v, scheme_ref, result);
  if (!premise) return beyond_reach(std::move(result));
  const ex& delta = premise->delta;
  const std::optional<one_variable>& g = premise->g;
  const kernel_decision& reversible_own = premise->reversible_own;
  const std::string var = text_of(v);
  const bool unconditional = g->ends.empty() && g->sign_at(1) < 0;
  std::vector<ex> positive;
  GiNaC::exmap inside;
  for (const std::string& name : symbol_names(delta)) {
    positive.push_back(paper_symbols()[name]);
    inside[paper_symbols()[name]] = 1;
  }
  // The stable bands: the regions between the discriminant's positive roots and poles where it is
  // negative (the sign at an inner point; the last region reaches infinity).
  std::vector<std::string> stable_bands;
  std::vector<proof_goal> band_goals;
  for (const discriminant_region& region : regions_of(*g)) {
    if (!region.negative) continue;
    stable_bands.push_back(region.text());
    if (auto goal = stable_band_goal(*g, region, stable_bands.size())) band_goals.push_back(std::move(*goal));
  }
  const std::string computed = unconditional          ? "unconditional"
                               : stable_bands.empty() ? "unstable"
                                                      : "conditional";
  const std::vector<discriminant_region> regions = regions_of(*g);
  const bool stable_from_zero = !regions.empty() && regions.front().negative;
  const bool small_steps = plain && computed == "conditional" && stable_from_zero;  // stable for h small enough
  const bool holds = stated == "stable" ? (qualifier == computed || small_steps) : computed == "unstable";
  // The signs are our kernel's (Sturm sequences); Coq checks them where the statement holds.
  decider_evidence e;
  e.statement = "the stated stability against the root condition";
  e.own = answer_of(holds);
  if (holds && unconditional) e.goals = std::vector<proof_goal>{sign_goal("discriminant", delta, -1, positive, inside)};
  if (holds && computed == "conditional" && !band_goals.empty()) e.goals = band_goals;
  std::string where;
  for (const positive_root& end : g->ends) where += (where.empty() ? "" : ", ") + g->text(end);
  const std::string bands_text = fmt::format("{} in {}", var, fmt::join(stable_bands, " and "));
  result.evidence["exact"] = {
      {"statement", fmt::format("the stated stability of ({}) against its root condition, region by region of {} > 0", scheme_ref, var)},
      {"stated", {{"scheme", stated}, {"qualifier", plain ? std::string("none (a plain 'stable': for steps small enough)") : qualifier}}},
      {"reversible", "the first and last coefficients are equal (GiNaC normal form; our kernel: " + reversible_own.evidence + ")"},
      {"discriminant", text_of(delta) + " (over the leading coefficient squared)"},
      {"computed", unconditional ? fmt::format("negative for every {} > 0: simple conjugate roots of modulus 1, stable for every step", var)
                   : stable_bands.empty() ? fmt::format("roots or poles at {} = {}, and negative on no region between them: stable for no step", var, where)
                                          : fmt::format("roots or poles at {} = {}: stable (negative) exactly for {}", var, where, bands_text)},
      {"own", "holds: the discriminant's roots and poles on " + var + " > 0 by Sturm sequences, in " + (g->in_square ? "(" + var + ")^2" : var) +
                  ", and its sign between them"},
      {"ginac", "holds: the premise in normal form, and the discriminant as a function of " + var + " alone; its sign is our kernel's"}};
  if (holds) {
    if (small_steps) {
      result.remark_kind = finding::wording;
      result.remark = fmt::format("Stable for every step small enough, as a plain \"stable\" of a scheme is read; not for every step: ({}) is "
                                  "stable for {} only, so conditionally stable.",
                                  scheme_ref, bands_text);
      result.amendments.push_back(amendment_in_words("the stated stability", stated_words, "conditionally stable: for " + bands_text + " only"));
    }
    e.found = std::move(result);
    return e;
  }
  result.correction = unconditional ? fmt::format("The scheme ({}) is stable for every {} > 0 (unconditionally): its discriminant is negative on the whole half-line", scheme_ref, var)
                      : stable_bands.empty()
                          ? (where.empty() ? fmt::format("The scheme ({}) is stable for no {} > 0: its discriminant is positive on the whole half-line", scheme_ref, var)
                                           : fmt::format("The scheme ({}) is stable for no {} > 0: its discriminant changes sign at {} = {} and is negative on no region between",
                                                         scheme_ref, var, var, where))
                          : fmt::format("The scheme ({}) is not stable for every {} > 0 but conditionally: its discriminant changes sign at {} = {}, and it is stable exactly for {}",
                                        scheme_ref, var, var, where, bands_text);
  const std::string printed_words = stated_words == "unconditionally stable" || stated_words == "conditionally stable" || !call.with.count("qualifier")
                                        ? stated_words
                                        : qualifier + " … " + stated_words;
  result.amendments.push_back(amendment_in_words("the stated stability", printed_words,
                                                 unconditional ? "stable for every step (unconditionally)"
                                                 : stable_bands.empty() ? "stable for no step"
                                                                        : "conditionally stable: for " + bands_text + " only"));
  e.found = std::move(result);
  return e;
}

/// The shapes of this file, each one's name, summary, principal argument and parameters beside the
/// function that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> stability_criteria_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  add({"unconditional-stability", "what a sentence says of the scheme's stability ({stability}, optionally {qualifier}) against the root condition for every variable > 0",
       "scheme",
       with_where({{"scheme", argument_kind::formula, true, "a linear three-term scheme (= 0) whose first and last coefficients are equal"},
                   {"sequence", argument_kind::symbols, true, "its three states q_{j-1}, q_j, q_{j+1}", 3},
                   {"variable", argument_kind::formula, true, "the variable the scheme's roots depend on, a product of positive symbols", 0, "", true},
                   pattern_with_hole("sentence", "the sentence's pattern: the hole {stability} (stable, linearly stable, conditionally or unconditionally stable, unstable)", "stability"),
                   pattern_with_hole("qualifier", "optionally, a sentence with the hole {qualifier} (unconditionally, conditionally)", "qualifier", false)}),
       unconditional_stability_shape});
  add({"root-criterion", "a stability criterion stated on the roots' modulus, against the root condition on every region of variable > 0", "scheme",
       with_where({{"scheme", argument_kind::formula, true, "a linear three-term scheme (= 0) whose first and last coefficients are equal"},
                   {"sequence", argument_kind::symbols, true, "its three states q_{j-1}, q_j, q_{j+1}", 3},
                   {"variable", argument_kind::formula, true, "the variable the scheme's roots depend on, a product of positive symbols", 0, "", true},
                   pattern_with_hole("sentence", "the sentence's pattern: the hole {modulus} (a bound, optionally with 'simple')", "modulus")}),
       root_criterion_shape});
  return all;
}

}  // namespace simpson::verify::detail

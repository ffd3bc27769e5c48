// A condition a text says "emerges" from a formula (the paper's stability condition from the pole of q_m):
// whether that argument reaches it. See shape_support.hpp.

#include <simpson/shapes/shape_support.hpp>

#include <simpson/shapes/one_variable.hpp>
#include <simpson/prove/printed_check_support.hpp>
#include <simpson/shapes/stability_regions.hpp>

#include <simpson/verify/quoted_words.hpp>

#include <fmt/format.h>

#include <optional>
#include <string>
#include <vector>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

/// A positive root of g, exact, as a value of v (v = √x when g is in x = v²); none when it is only enclosed.
std::optional<ex> value_of(const one_variable& g, const positive_root& r) {
  if (!r.exact()) return std::nullopt;
  const ex x = as_numeric(r.low);
  return g.in_square ? ex(GiNaC::sqrt(x)) : x;
}

/// Two positive values equal: compared by their squares (GiNaC leaves √8 and 2√2 apart).
bool same_value(const std::optional<ex>& a, const std::optional<ex>& b) {
  return a && b && GiNaC::normal(GiNaC::expand(*a * *a - *b * *b)).is_zero();
}

}  // namespace

/// "A stability condition is naturally emerging: 0 < v < c", after a formula: the argument the text
/// gives is the formula's first pole in v. It reaches the condition only when the scheme's stable
/// set for v > 0 (root condition, stability_regions.hpp) is exactly (0, c) and c is that pole: then
/// it holds. When c is the pole and ends the first stable band but the scheme is stable beyond it
/// too, the condition holds and its argument has a gap: a derivation-gap remark (a pole is not a
/// stability argument). When c is not the pole, or not the band's end, an erratum corrected by the
/// stable set.
decider_evidence emerging_condition_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const referenced_formula condition = read.raw("condition");
  const referenced_formula formula_printed = read.raw("formula");  // read once: its value, and the symbol it defines
  const ex formula = read.defined(formula_printed.value);
  const ex v = read.formula("variable");
  const ex scheme = read.formula("scheme");
  const std::vector<GiNaC::symbol> q = read.symbols("sequence");
  const quoted_sentence said = quote(ctx, call.with.at("sentence").values.front());
  const ex high = interval_end(condition, v, read.reading());
  // The scheme named as a reader names the equation (its left side = 0 is the scheme itself).
  std::string scheme_ref = reference_of(call, "scheme");
  if (const std::size_t side = scheme_ref.rfind(", left side"); side != std::string::npos && side + 11 == scheme_ref.size()) scheme_ref.resize(side);
  const std::string formula_ref = reference_of(call, "formula"), var = text_of(v);
  claim_result result;
  result.printed = read.printed();
  result.certificate_missing = "an argument's reach (where a pole lies against the stable set): the stable bands' signs are certified by the stability claims";
  const ex denominator = GiNaC::denom(GiNaC::normal(formula));
  const std::optional<one_variable> poles = in_variable(denominator, v);
  if (!poles) {
    result.note = fmt::format("The denominator {} of ({}) is not a function of {} alone.", text_of(denominator), formula_ref, var);
    return beyond_reach(std::move(result));
  }
  const std::optional<reversible_scheme> premise = reversible_premise(scheme, q, v, scheme_ref, result);
  if (!premise) return beyond_reach(std::move(result));
  const one_variable& g = *premise->g;
  std::vector<std::string> bands;
  std::optional<ex> first_band_end;
  bool stable_beyond = false;
  for (const discriminant_region& region : regions_of(g)) {
    if (!region.negative) continue;
    bands.push_back(region.text());
    if (bands.size() == 1 && region.from == 0 && !region.last) first_band_end = value_of(g, g.ends[region.index]);
    if (bands.size() > 1 || region.from != 0) stable_beyond = true;
  }
  const std::optional<ex> pole = poles->ends.empty() ? std::nullopt : value_of(*poles, poles->ends.front());
  const bool end_is_pole = same_value(pole, GiNaC::normal(high));
  const bool end_is_band = same_value(first_band_end, GiNaC::normal(high));
  const std::string stable_set = bands.empty() ? "no v > 0" : fmt::format("{} in {}", var, fmt::join(bands, " and "));
  result.evidence["exact"] = {
      // What the verdict decides: the bound is the formula's (first) pole and ends the scheme's first
      // stable band (not "the condition follows from the pole": a pole excludes one point only).
      {"statement", fmt::format("the bound {} = {} of the condition 0 < {} < {} is the first pole of ({}) and the end of the first stable band of ({})",
                                var, text_of(high), var, text_of(high), formula_ref, scheme_ref)},
      {"stated", [&] {
         // Quoted in the remark; the verdict rests on the formulas, not on these words.
         said.record("emerges", "quoted in the remark, not parsed: the verdict rests on the formulas");
         return said.words("emerges");
       }()},
      {"poles", [&] {
         json all = json::array();
         for (const positive_root& e : poles->ends) all.push_back(poles->text(e));
         return all;
       }()},
      {"denominator", text_of(denominator)},
      {"stable", stable_set + " (the root condition on (" + scheme_ref + "): its discriminant " + text_of(premise->delta) + " negative)"},
      {"own", "holds: the poles and the discriminant's roots by Sturm sequences, compared exactly"},
      {"ginac", "holds: the denominator in normal form and the discriminant as functions of " + var + " alone"}};
  // The poles and bands are our kernel's (Sturm sequences), compared exactly: its answer decides.
  decider_evidence e;
  e.statement = "the condition's origin";
  e.own = answer_of(end_is_pole && end_is_band);
  if (!end_is_pole) {
    result.correction = fmt::format("the first pole of ({}) is {}; the scheme ({}) is stable for {}", formula_ref,
                                    pole ? poles->text(poles->ends.front()) : std::string("none"), scheme_ref, stable_set);
    result.note = fmt::format("As printed: the bound {} is not where ({}) has its first pole.", text_of(high), formula_ref);
    result.amendments.push_back(amendment_in_words("the bound's origin", "the pole of (" + formula_ref + ")", "the stable set: " + stable_set));
    e.found = std::move(result);
    return e;
  }
  if (end_is_band && !stable_beyond) {
    result.note = fmt::format("The pole of ({}) at {} = {} ends the one stable band: the scheme is stable for {}.", formula_ref, var, text_of(high), stable_set);
    e.found = std::move(result);
    return e;
  }
  if (end_is_band) {
    // The condition is right and its end is the pole. "Emerging" is read as the field reads it, a
    // motivation: the words say more than the pole shows (a pole is no stability argument, and the
    // scheme is stable again beyond it), so the condition holds with a wording remark.
    result.remark_kind = finding::wording;
    result.remark = fmt::format("Read as a motivation, as meant: the condition is the first stable band of ({}), and its end {} = {} is the {} of "
                                "({}); its proof is the root condition on ({}) (its discriminant), not the pole, and it is sufficient, not necessary: "
                                "the scheme is stable exactly for {}, so stable again beyond it.",
                                scheme_ref, var, text_of(high), poles->ends.size() == 1 ? "pole" : "first pole", formula_ref, scheme_ref, stable_set);
    result.amendments.push_back(amendment_in_words("the condition's origin", said.words("emerges") + " (from the pole of " + formula_ref + ")",
                                                   "motivated by the pole, which ends the first stable band; proved by the root condition: stable for " + stable_set));
    e.found = std::move(result);
    return e;
  }
  // What the pole makes undefined, in the document's words: the symbol the formula defines (q_m in
  // q_m = ...), or the formula itself.
  const std::string undefined = formula_printed.sides.size() > 1 ? folded_space(formula_printed.sides.front()) : "(" + formula_ref + ")";
  result.correction = fmt::format("The condition is the first stable band's, from the root condition on ({}), stable for {}; the pole of ({}) at {} = {} "
                                  "only makes {} undefined there{}",
                                  scheme_ref, stable_set, formula_ref, var, text_of(high), undefined,
                                  stable_beyond ? ", and the scheme is stable again beyond it" : "");
  result.note = fmt::format("As printed, the condition '{}' from the pole of ({}): a pole says where the formula is undefined, not where the scheme "
                            "is stable. {}",
                            said.words("emerges"), formula_ref,
                            stable_beyond ? fmt::format("Beyond the pole the scheme is stable again ({}): the pole does not bound stability.", stable_set)
                                          : "The pole is not the end of the stable band.");
  result.amendments.push_back(amendment_in_words("the condition's derivation", said.words("emerges") + " (from the pole of " + formula_ref + ")",
                                                 "from the root condition (the discriminant): stable for " + stable_set));
  e.found = std::move(result);
  return e;
}

/// The shapes of this file, each one's name, summary, principal argument and parameters beside the
/// function that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> emerging_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  add({"emerging-condition",
       "the printed condition 0 < variable < c follows from the printed formula as the text says (c its first pole): only when the scheme's stable set "
       "for variable > 0 is (0, c)",
       "condition",
       with_where({{"condition", argument_kind::condition, true, "the printed condition 0 < variable < c"},
                   {"formula", argument_kind::formula, true, "the formula it is said to emerge from (its denominator's first positive root)"},
                   {"variable", argument_kind::formula, true, "the condition's variable, a product of positive symbols", 0, "", true},
                   {"scheme", argument_kind::formula, true, "the linear three-term scheme (= 0) whose stability the condition states"},
                   {"sequence", argument_kind::symbols, true, "its three states q_{j-1}, q_j, q_{j+1}", 3},
                   pattern_with_hole("sentence", "the sentence that says the condition emerges, with the hole {emerges}", "emerges")}),
       emerging_condition_shape});
  return all;
}

}  // namespace simpson::verify::detail

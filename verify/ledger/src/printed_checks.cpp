#include <simpson/verify/printed_checks.hpp>
#include <simpson/verify/enclosure_decision.hpp>
#include <simpson/verify/ledger.hpp>

#include <simpson/prove/coq_export.hpp>
#include "check_registry.hpp"
#include "derivation_support.hpp"
#include <simpson/shapes/proof_shapes.hpp>

#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/quoted_words.hpp>

#include <algorithm>
#include <chrono>

namespace simpson::verify {
namespace detail {

using GiNaC::ex;

oscillator_parameters<ex> parameters(const symbolic_derivation& d) { return {d.m, d.omega, d.h}; }

ex with_gear(const ex& e, const symbolic_derivation& d) {
  return e.subs(GiNaC::lst{sym("g_l") == d.g_l, sym("g_m") == d.g_m, sym("g_r") == d.g_r});
}

}  // namespace detail

namespace {

using detail::printed_outcome;

/// The registered check that decides `c`, with its facets; null for a claim a proof shape decides.
const detail::registered_check* bespoke_check(const claim& c) {
  const check_decider* check = std::get_if<check_decider>(&c.decided_by);
  return check != nullptr ? detail::registered_checks().find(check->check) : nullptr;
}

/// The GiNaC check of the printed formulas `c` reads; null when it reads none.
const detail::registered_check* printed_facet(const claim& c) {
  const detail::registered_check* check = bespoke_check(c);
  return check != nullptr && check->printed ? check : nullptr;
}

/// Two pieces of prose as sentences: a full stop after the first unless it has one.
std::string then(const std::string& first, const std::string& second) {
  if (second.empty()) return first;
  if (first.empty()) return second;
  const char last = first.back();
  return first + (last == '.' || last == ':' || last == ';' ? " " : ". ") + second;
}

/// The verdict from the two kernels. Each proves the derived statement (ours on our
/// transcription, in θ with the grid lemma; GiNaC from first principles, every symbol free); they
/// must agree, or the verdict is kernels-disagree. When they agree that it holds, the printed side
/// decides: holds, erratum (the derived formula is the correction) or fails (a printed property).
void decide(claim_result& result, const printed_outcome& g, const std::string& claim_id) {
  const bool own_derived = result.outcome != verdict::fails;
  const verdict own = result.outcome;
  // An erratum of the quoted words (a claim that reads a formula and also judges prose about it)
  // stands whatever the printed formula: the words, not the transcription, were refuted.
  const bool words_refuted = own == verdict::erratum && !result.quoted.empty();
  if (detail::kernels_disagree_if(result, own_derived != g.derived_holds,
                          "The two kernels disagree on '" + claim_id + "': ours " + (own_derived ? "proved" : "did not prove") +
                              " the derived statement, GiNaC " + (g.derived_holds ? "proved" : "did not prove") + " it (" + g.derived + ")." +
                              (result.note.empty() ? "" : " " + result.note))) {
    return;
  }
  if (!g.derived_holds) {
    result.outcome = verdict::fails;
    return;
  }
  if (g.holds && words_refuted) {
    result.note = then("The printed formula holds (" + g.proved + "); the quoted words do not.", result.note);
    return;
  }
  if (g.holds) {
    result.outcome = verdict::holds;
    if (own == verdict::erratum) {
      result.note = "This copy of the paper prints the derived formula: " + g.proved +
                    ". (Our kernel's transcription of the printed formula, typed from the GSI 2023 text, is the erratum it refutes.)";
      result.correction.clear();
    }
    return;
  }
  result.outcome = g.property || g.correction.empty() ? verdict::fails : verdict::erratum;
  if (result.outcome == verdict::erratum && own != verdict::erratum) result.correction = g.correction;
  result.note = then((own == verdict::erratum ? "As printed: " : "The formula as printed in the paper's source differs from the derived one: ") +
                         g.proved,
                     result.note);
}


}  // namespace

namespace {

/// A claim a proof shape decides: it reads every formula from the run's document, when its shape
/// judges a formula (a principal argument; the prose's shapes, spelling and citations, read none).
bool decided_by_shape(const claim& c) {
  const shape_decider* by = std::get_if<shape_decider>(&c.decided_by);
  if (by == nullptr) return false;
  const auto shape = detail::proof_shapes().find(by->shape);
  return shape == detail::proof_shapes().end() || !shape->second.principal.empty();
}

bool reads_printed(const claim& c) { return printed_facet(c) != nullptr || decided_by_shape(c); }

}  // namespace

bool reads_printed_formula(const claim& c) { return reads_printed(c); }

std::vector<std::string> claims_reading_formula(const std::vector<claim>& claims, const std::string& label) {
  std::vector<std::string> ids;
  for (const claim& c : claims) {
    const detail::registered_check* check = printed_facet(c);
    std::vector<std::string> names = check != nullptr ? check->formulas : std::vector<std::string>{};
    names.insert(names.end(), c.labels_read.begin(), c.labels_read.end());
    for (const std::string& name : names) {
      if (name == label || name.rfind(label + "#", 0) == 0) {
        ids.push_back(c.id);
        break;
      }
    }
  }
  return ids;
}

double ginac_derivation_seconds() { return detail::derivation().seconds; }

std::size_t printed_formula_claim_count(const std::vector<claim>& claims) {
  std::size_t count = 0;
  for (const claim& c : claims) count += reads_printed(c) ? 1 : 0;
  return count;
}

namespace {

/// The claim's own check, with the sentences it quotes recorded; a sentence gone or words that no
/// longer parse make the verdict text-changed, the check's other findings dropped.
claim_result checked_with_quotes(const claim& c, const run_context& ctx) {
  json quotes = json::array();
  run_context quoting = ctx;
  quoting.quotes = &quotes;
  claim_result result;
  try {
    result = c.check(quoting);
  } catch (const enclosure_undecided& e) {
    result = claim_result{};
    result.outcome = verdict::undecided;
    result.evidence["undecided"] = e.what();
    result.note = std::string("No enclosure decided this claim within the run's digits: ") + e.what() +
                  ". Raise --enclosure-budget, or find why the enclosure is wide.";
  } catch (const text_changed& e) {
    result = claim_result{};
    result.outcome = verdict::text_changed;
    result.evidence["text_changed"] = e.what();
    result.note = std::string("The words this claim quotes did not read: ") + e.what() +
                  ". Its check judges only words it reads: a new wording is judged once the claim's sentence pattern matches it "
                  "(docs/claims-file.md, sentence patterns).";
  }
  result.quoted = std::move(quotes);
  return result;
}

}  // namespace

claim_result check_claim(const claim& c, const run_context& ctx) {
  claim_result result = checked_with_quotes(c, ctx);
  if (result.outcome == verdict::text_changed || result.outcome == verdict::undecided) return result;
  const detail::registered_check* facet = printed_facet(c);
  if (facet == nullptr) {
    // The check wrote its own, or why there is none (the floating claims: Gappa's and the lifting
    // lemma; the proof shapes of claims files).
    if (!result.certificate.empty() || !result.certificate_missing.empty()) return result;
    const detail::registered_check* check = bespoke_check(c);
    if (check == nullptr || !check->coq_goals) {
      result.certificate_missing = detail::without_coq_statement(c, "its exact proof is our kernel's alone: no Coq statement yet");
      return result;
    }
    detail::record_certificate(result, detail::coq_certificate(c.id, c.statement, check->coq_goals()));
    return result;
  }
  if (!ctx.paper) {
    result.certificate_missing = "the run has no paper to read the printed formula from";
    return result;
  }
  const paper_reading& reading = *ctx.paper;
  const auto start = std::chrono::steady_clock::now();
  const printed_outcome outcome = facet->printed(reading);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  json printed = json::array();
  for (const std::string& name : facet->formulas) {
    const printed_formula& f = reading.at(name);
    json parsed = json::array();
    for (const GiNaC::ex& side : f.sides) parsed.push_back(detail::text_of(side));
    printed.push_back({{"label", f.source.locator}, {"line", f.source.line}, {"tex", folded_space(f.tex)},
                       {"parsed", parsed}});
  }
  result.printed = {{"source", reading.origin}, {"formulas", printed}};
  // What the claim's own check did, in its words when it says (evidence "exact"'s method).
  const bool says = result.evidence.contains("exact") && result.evidence["exact"].is_object() && result.evidence["exact"].contains("method");
  const std::string own_statement = says ? "the claim's check above: " + result.evidence["exact"]["method"].get<std::string>()
                                         : "the claim's check above: our transcription, rational functions of theta with the grid lemma";
  result.evidence["kernels"] = {
      {"own", {{"statement", own_statement},
               {"derived_holds", result.outcome != verdict::fails}}},
      {"ginac", {{"printed", outcome.proved}, {"printed_holds", outcome.holds}, {"derived", outcome.derived},
                 {"derived_holds", outcome.derived_holds}}}};
  result.printed_seconds = seconds;
  decide(result, outcome, c.id);
  detail::coq_export certificate = detail::coq_certificate(c.id, c.statement, outcome.goals);
  if (outcome.goals.empty()) certificate.not_exported = detail::without_coq_statement(c, certificate.not_exported);
  detail::record_certificate(result, certificate);
  return result;
}

}  // namespace simpson::verify

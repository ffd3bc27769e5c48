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

using detail::answer;
using detail::answer_of;
using detail::decider_evidence;
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

std::vector<std::string> formulas_its_check_reads(const claim& c) {
  const detail::registered_check* check = printed_facet(c);
  return check != nullptr ? check->formulas : std::vector<std::string>{};
}

double ginac_derivation_seconds() { return detail::derivation().seconds; }

std::size_t printed_formula_claim_count(const std::vector<claim>& claims) {
  std::size_t count = 0;
  for (const claim& c : claims) count += reads_printed(c) ? 1 : 0;
  return count;
}

namespace detail {

decider_evidence with_facets(decider_evidence e, const registered_check& check, const std::string& claim_id, const std::string& statement,
                             const std::string& coq_none, const run_context& ctx) {
  // Words that no longer read, or nothing decided: no facet and no certificate (a skipped or unproved
  // floating claim still says why it has none).
  if (!detail::settled(e)) return e;
  if (!check.printed) {
    // The check wrote its own, or why there is none (the floating claims: Gappa's and the lifting lemma).
    if (!e.found.certificate.empty() || !e.found.certificate_missing.empty()) return e;
    if (!check.coq_goals) {
      e.found.certificate_missing = without_coq_statement(coq_none);
      return e;
    }
    e.goals = check.coq_goals();
    return e;
  }
  if (!ctx.paper) {
    e.found.certificate_missing = "the run has no paper to read the printed formula from";
    return e;
  }
  const paper_reading& reading = *ctx.paper;
  const auto start = std::chrono::steady_clock::now();
  const printed_outcome outcome = check.printed(reading);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  json printed = json::array();
  for (const std::string& name : check.formulas) {
    const printed_formula& f = reading.at(name);
    json parsed = json::array();
    for (const GiNaC::ex& side : f.sides) parsed.push_back(text_of(side));
    printed.push_back({{"label", f.source.locator}, {"line", f.source.line}, {"tex", folded_space(f.tex)},
                       {"parsed", parsed}});
  }
  claim_result& result = e.found;
  result.printed = {{"source", reading.origin}, {"formulas", printed}};
  // What the claim's own check did, in its words when it says (evidence "exact"'s method).
  const bool says = result.evidence.contains("exact") && result.evidence["exact"].is_object() && result.evidence["exact"].contains("method");
  const std::string own_statement = says ? "the claim's check above: " + result.evidence["exact"]["method"].get<std::string>()
                                         : "the claim's check above: our transcription, rational functions of theta with the grid lemma";
  result.evidence["kernels"] = {
      {"own", {{"statement", own_statement},
               {"derived_holds", detail::derived_proved(e)}}},
      {"ginac", {{"printed", outcome.proved}, {"printed_holds", outcome.holds}, {"derived", outcome.derived},
                 {"derived_holds", outcome.derived_holds}}}};
  result.printed_seconds = seconds;
  e = with_printed(std::move(e), outcome, claim_id, ctx.quotes != nullptr && !ctx.quotes->empty());
  if (outcome.goals.empty()) {
    e.found.certificate.clear();
    e.found.certificate_missing = without_coq_statement(coq_none, coq_certificate(claim_id, statement, outcome.goals).not_exported);
    e.goals.reset();
  } else {
    e.goals = outcome.goals;
  }
  return e;
}

}  // namespace detail

}  // namespace simpson::verify

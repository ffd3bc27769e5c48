// Consequences traced: see consequences.hpp.

#include <simpson/verify/consequences.hpp>

#include <simpson/verify/formula_reference.hpp>

#include <algorithm>
#include <map>
#include <stdexcept>

namespace simpson::verify {
namespace {

/// The claim's verdict with `corrected` read instead of the printed formulas, and whether it read any.
std::pair<verdict, bool> judged_with(const claim& c, const claim_result& cause, const run_context& ctx, const claim_judge& judge) {
  formula_corrections corrections{cause.corrected_formulas};
  run_context again = ctx;
  again.corrections = &corrections;
  again.quotes = nullptr;  // the document's sentences are quoted once, by the judgment as printed
  const claim_result r = judge(c, again);
  return {r.outcome, r.printed.is_object() && r.printed.value("corrected", false)};
}

std::vector<std::string> shown(const claim_result& cause) {
  std::vector<std::string> out;
  for (const auto& c : cause.corrected_formulas) out.push_back(c->shown);
  return out;
}

}  // namespace

std::vector<std::optional<consequence>> trace_consequences(const std::vector<const claim*>& claims, const std::vector<const claim_result*>& results,
                                                           const run_context& ctx, const claim_judge& judge) {
  std::vector<std::optional<consequence>> out(claims.size());
  std::vector<std::size_t> causes;  // the errata with proved corrections of printed formulas
  for (std::size_t k = 0; k < claims.size(); ++k) {
    if (results[k]->outcome == verdict::erratum && !results[k]->corrected_formulas.empty()) causes.push_back(k);
  }
  if (causes.empty()) return out;
  for (std::size_t k = 0; k < claims.size(); ++k) {
    const claim& c = *claims[k];
    const verdict v = results[k]->outcome;
    if (v == verdict::holds || v == verdict::text_changed || v == verdict::skipped || !std::holds_alternative<shape_decider>(c.decided_by)) continue;
    // The typed cause first: what the derivation says of it decides whether the record's link stands.
    std::vector<std::size_t> order;
    for (const std::size_t e : causes) {
      if (claims[e]->id == c.follows_from) order.insert(order.begin(), e);
      else if (e != k) order.push_back(e);
    }
    for (const std::size_t e : order) {
      const auto [again, read] = judged_with(c, *results[e], ctx, judge);
      const bool typed = claims[e]->id == c.follows_from;
      if (read && again == verdict::holds) {
        out[k] = consequence{claims[e]->id, shown(*results[e])};
        break;
      }
      if (typed && read) {
        throw std::logic_error("claim '" + c.id + "' is recorded to follow from '" + c.follows_from + "', but with the corrected " + shown(*results[e]).front() +
                               " it is still " + to_string(again) + ": a link the derivation contradicts");
      }
    }
  }
  // Two records that find the same misprint each hold with the other's correction: a cycle of
  // consequences names no cause. The first in the file is the cause, each other one in the cycle
  // its consequence (the misprint counted once).
  std::map<std::string, std::size_t> index;
  for (std::size_t k = 0; k < claims.size(); ++k) index.emplace(claims[k]->id, k);
  for (std::size_t k = 0; k < claims.size(); ++k) {
    std::vector<std::size_t> chain{k};
    for (std::size_t at = k; out[at];) {
      at = index.at(out[at]->cause);
      if (std::find(chain.begin(), chain.end(), at) != chain.end()) {
        if (at == k) out[*std::min_element(chain.begin(), chain.end())].reset();
        break;
      }
      chain.push_back(at);
    }
  }
  return out;
}

}  // namespace simpson::verify

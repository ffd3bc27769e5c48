#pragma once
// Consequences traced, for any document: a claim that does not hold as printed, judged again with
// the formulas an erratum proved wrong replaced by their proved corrections wherever it reads them;
// when it then holds, it is that erratum's consequence, counted once, under its cause.

#include <simpson/verify/claim.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace simpson::verify {

struct consequence {
  std::string cause;                   // the erratum's claim
  std::vector<std::string> corrected;  // the formulas put in, as the reports name them: "(eq:PhiS)"
};

/// For each claim of `claims` (`results` its verdicts as printed) that does not hold and reads
/// printed formulas itself (a proof shape), the erratum whose corrections make it hold: its typed
/// cause (follows_from) first, then every other erratum with proved corrections, in order. None
/// where none does. Throws std::logic_error (a harness fault) when a typed cause's corrections are
/// read by its claim and do not make it hold: a link the derivation contradicts. `judge` is the
/// book's: it judges a claim again with the run's context (the corrections in it).
using claim_judge = std::function<claim_result(const claim&, const run_context&)>;
std::vector<std::optional<consequence>> trace_consequences(const std::vector<const claim*>& claims, const std::vector<const claim_result*>& results,
                                                           const run_context& ctx, const claim_judge& judge);

}  // namespace simpson::verify

#pragma once
// One checkable statement of the paper, how it is checked, and what the check found.

#include <simpson/precision.hpp>

#include <simpson/verify/json.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace simpson::verify {

/// holds: true as printed; erratum: false as printed, with a proved correction; fails: false,
/// no correction found; kernels-disagree: the two exact kernels reached different conclusions on
/// the derived statement (a bug in one of them, never expected); text-changed: the sentence a
/// prose claim quotes is no longer in the paper, or its words no longer parse (never expected:
/// the paper changed under the ledger); undecided: an enclosure could neither prove the statement
/// nor its negation within the run's precision budget (never expected: raise the budget);
/// unproved: a floating-point claim whose round-off Gappa could not bound (its reason in the
/// evidence: an intermediate that may overflow, a step outside the stable range); skipped: a
/// floating-point claim whose prover (gappa) is not installed, decided neither way and never
/// counted against the run.
enum class verdict { holds, erratum, fails, kernels_disagree, text_changed, undecided, unproved, skipped };

inline std::string to_string(verdict v) {
  switch (v) {
    case verdict::holds: return "holds";
    case verdict::erratum: return "erratum";
    case verdict::fails: return "fails";
    case verdict::kernels_disagree: return "kernels-disagree";
    case verdict::text_changed: return "text-changed";
    case verdict::undecided: return "undecided";
    case verdict::unproved: return "unproved";
    case verdict::skipped: return "skipped";
  }
  return "?";
}

/// Whether a verdict is the expected one for the run's exit code: equal, or skipped (a prover not
/// installed decides nothing, and says so).
inline bool as_expected(verdict got, verdict expected) { return got == expected || got == verdict::skipped; }

/// What a check is given: the precisions of the numeric rechecks, the seed and how many random
/// samples each recheck draws per precision.
struct paper_reading;

struct run_context {
  std::vector<precision> precisions;
  std::uint64_t seed = 0;
  unsigned samples = 0;
  /// The formulas read from the paper's source; without it, formula claims check our
  /// transcription only.
  const paper_reading* paper = nullptr;
  /// Where a prose claim's check records the sentences it quotes (quoted_words.hpp); null when the
  /// check is run on its own.
  json* quotes = nullptr;
  /// Decimal digits of the first interval evaluation of a numeric claim, and the most digits it
  /// may rise to (doubling) before the claim is undecided.
  unsigned enclosure_digits = 40;
  unsigned enclosure_budget_digits = 640;
};

/// What a check found. `evidence` has one member per method ("exact", "numeric", ...).
struct claim_result {
  verdict outcome = verdict::fails;
  json evidence = json::object();
  std::string correction;  // the corrected statement, for errata
  std::string note;        // conditions not stated in the paper, sufficiency, caveats
  /// For a claim whose formula is read from the paper: where ({label, line, tex, parsed}) and
  /// what GiNaC proved of it; null for a claim typed from prose.
  json printed;
  /// For a claim typed from the prose: the sentences it judges, as quoted from the paper
  /// ({source, line, text, pattern, words, parsed}); empty for a claim that quotes none.
  json quoted = json::array();
  /// Seconds the GiNaC proof of the printed formula took (reported under "timing", never in evidence).
  double printed_seconds = 0;
  /// The Coq certificate (certificates/<id>.v), printed from the identities GiNaC proved; empty when
  /// none is exported, `certificate_missing` then saying why.
  std::string certificate;
  std::vector<std::string> certificate_lemmas;
  std::string certificate_missing;
  /// The negation of each identity GiNaC refuted (an erratum's printed statement, a wrong formula of
  /// an altered paper), shown at a counterexample point (certificates/<id>_refuted.v); may be present
  /// without `certificate`.
  std::string refutation;
  std::vector<std::string> refutation_lemmas;
};

struct claim {
  std::string id;         // stable kebab-case
  std::string section;    // section of the paper
  std::string equation;   // the paper's equation label, or "prose"
  std::string statement;  // as printed
  std::vector<std::string> methods;
  verdict expected;
  std::function<claim_result(const run_context&)> check;
};

}  // namespace simpson::verify

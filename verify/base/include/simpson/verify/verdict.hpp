#pragma once
// A claim's verdict, and what each verdict means, in one table (LLVM lit's ResultCode: a code carries
// its name, its label and whether it fails a run; every consumer iterates the codes and none decides
// their meaning again). The spelling, whether a verdict is a finding or a judgment a record may
// expect, how a run's row treats it, what the summary calls it and report.json counts it as: all read
// from verdict_table_of_meanings(). Adding a verdict is its enumerator, its row here, and its place
// in the JSON Schema's enum (a test compares the two).

#include <array>
#include <optional>
#include <string>

namespace simpson::verify {

/// holds: true as printed (under the reading an expert gives its words; a remark may say more);
/// erratum: false as printed, with a proved correction; fails: false, no correction found;
/// unverifiable: the material it needs is absent from the source. The others are no judgment of the
/// document: kernels-disagree (the two exact kernels reached different conclusions: a bug in one),
/// text-changed (the words a prose claim quotes are no longer in the document, or no longer parse),
/// undecided (no enclosure decided it within the run's digits), unproved (Gappa could not bound a
/// floating-point program's round-off), skipped (the prover is not installed: decided neither way).
enum class verdict { holds, erratum, fails, kernels_disagree, text_changed, undecided, unproved, skipped, unverifiable };

/// What a verdict means.
struct verdict_meaning {
  verdict value;
  /// Its spelling: reports, claims files, JSON.
  const char* name;
  /// A judgment of the document, which a record, a baseline or a scene may expect.
  bool expectable;
  /// A finding about the document (a verdict other than holds that judges it).
  bool finding;
  /// How a run's row treats it when it is met: `as_judged` compares it with the expectation;
  /// `never_expected` fails the row whatever was expected (the tool's limit or a changed text, named
  /// by its JUnit type); `not_counted` neither passes nor fails (skipped).
  enum class row { as_judged, never_expected, not_counted } met;
  /// Where the row's reason is in the evidence (`evidence[reason_key]`), and the words when absent.
  const char* reason_key;
  const char* default_reason;
  /// The summary line's words for a count of them ("{} held"), and for one of them ("{} erratum");
  /// always shown, or only when nonzero.
  const char* counted_as;
  const char* counted_as_one;
  bool always_counted;
  /// report.json's summary member that counts them.
  const char* count_key;
  /// The document's statement holds as read: it may carry a remark (and a note beside it).
  bool affirms;
  /// It carries a proved correction of the document (the corrected formula or statement).
  bool corrected;
  /// Met as expected, JUnit's testcase is an expected failure (a finding with no correction found).
  bool expected_failure;
  /// No judgment because the tool reached its limit or has a bug (not a changed text): the validation
  /// line lists it apart.
  bool tool_limit;
  /// A passed JUnit testcase's first line when it is met as expected; empty for none.
  const char* passed_words;
  /// What it means, in report.md's list of the verdicts.
  const char* legend;
};

/// Every verdict's meaning, in the enum's order.
inline constexpr std::array<verdict_meaning, 9> verdict_meanings{{
    {verdict::holds, "holds", true, false, verdict_meaning::row::as_judged, "", "", "{} held", "{} held", true, "held",
     true, false, false, false, "",
     "true as printed"},
    {verdict::erratum, "erratum", true, true, verdict_meaning::row::as_judged, "", "", "{} errata", "{} erratum", true, "errata",
     false, true, false, false, "Erratum, as the ledger expects.",
     "false as printed; a corrected statement is proved"},
    {verdict::fails, "fails", true, true, verdict_meaning::row::as_judged, "", "", "{} failed", "{} failed", true, "failed",
     false, false, true, false, "",
     "false, no correction found"},
    {verdict::kernels_disagree, "kernels-disagree", false, false, verdict_meaning::row::never_expected, "kernels_disagree",
     "the two kernels disagree (a bug in one of them)", "{} with the kernels in disagreement", "{} with the kernels in disagreement", false, "kernels_disagree",
     false, false, false, true, "",
     "our kernel and GiNaC reached different conclusions on the derived statement: a bug, never expected"},
    {verdict::text_changed, "text-changed", false, false, verdict_meaning::row::never_expected, "text_changed", "the quoted words changed",
     "{} whose quoted words changed (text-changed)", "{} whose quoted words changed (text-changed)", false, "text_changed",
     false, false, false, false, "",
     "the sentence a prose claim quotes is gone from the paper, or its words no longer parse: never expected"},
    {verdict::undecided, "undecided", false, false, verdict_meaning::row::never_expected, "undecided", "no enclosure decided the claim",
     "{} undecided within the enclosure budget", "{} undecided within the enclosure budget", false, "undecided",
     false, false, false, true, "",
     "no interval enclosure proved the statement or its negation within the run's digits: never expected"},
    {verdict::unproved, "unproved", false, false, verdict_meaning::row::never_expected, "unproved", "Gappa could not bound the round-off",
     "{} unproved (Gappa could not bound the round-off)", "{} unproved (Gappa could not bound the round-off)", false, "unproved",
     false, false, false, true, "",
     "a floating-point claim whose round-off Gappa could not bound, with its reason"},
    {verdict::skipped, "skipped", false, false, verdict_meaning::row::not_counted, "skipped", "the prover is not installed",
     "{} skipped (gappa not installed)", "{} skipped (gappa not installed)", false, "skipped",
     false, false, false, false, "",
     "a floating-point claim not decided because gappa is not installed: never counted against the run"},
    {verdict::unverifiable, "unverifiable", true, true, verdict_meaning::row::as_judged, "", "",
     "{} unverifiable (material absent from the source)", "{} unverifiable (material absent from the source)", false, "unverifiable",
     false, false, false, false, "Unverifiable (material absent from the source), as the ledger expects.",
     "material the claim needs is absent from the source, a figure or a reference: no verdict on its words"},
}};

/// The meaning of `v`.
constexpr const verdict_meaning& meaning(verdict v) { return verdict_meanings[static_cast<std::size_t>(v)]; }

static_assert([] {
  for (std::size_t k = 0; k < verdict_meanings.size(); ++k) {
    if (static_cast<std::size_t>(verdict_meanings[k].value) != k) return false;
  }
  return true;
}(), "verdict_meanings lists the verdicts in the enum's order");

inline std::string to_string(verdict v) { return meaning(v).name; }

/// The verdict a report or a claims file spells `text` (to_string's spelling), or none.
inline std::optional<verdict> verdict_of_name(const std::string& text) {
  for (const verdict_meaning& m : verdict_meanings) {
    if (text == m.name) return m.value;
  }
  return std::nullopt;
}

/// Whether a record (or a baseline, or a scene's override) may expect a verdict: a judgment of the
/// document. The others are never expected: kernels-disagree is a bug, text-changed a quote the
/// document no longer has, undecided and unproved the tool's limits, skipped a prover not installed.
constexpr bool expectable(verdict v) { return meaning(v).expectable; }

/// Whether a verdict is a finding about the document (erratum, fails, unverifiable).
constexpr bool is_finding(verdict v) { return meaning(v).finding; }

/// Whether a verdict is the expected one for the run's exit code: equal to an expectable verdict, or
/// one no row counts (a prover not installed decides nothing, and says so).
constexpr bool as_expected(verdict got, verdict expected) {
  return (got == expected && expectable(expected)) || meaning(got).met == verdict_meaning::row::not_counted;
}

}  // namespace simpson::verify

#pragma once
// What the report's files share (report_counts.cpp, report_referee.cpp, report_json.cpp, report.cpp):
// the verdicts counted once, the class of a finding, and small text helpers.

#include <simpson/verify/report.hpp>
#include <simpson/verify/run.hpp>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace simpson::verify::report_parts {

std::string join(const std::vector<std::string>& parts, const std::string& separator);
std::vector<std::string> precision_names(const std::vector<precision>& precisions);

struct verdict_counts {
  std::size_t faults = 0;  // checks that threw: a bug in the harness, no verdict (exit 3)
  std::size_t paper = 0, beyond = 0, harness = 0;            // whose statements
  /// The paper's whole-text checks (its spelling, its citations): checks of the source, not claims
  /// it makes, counted apart from `paper`; `source_findings` those that are findings, the spelling apart.
  std::size_t source_checks = 0, source_findings = 0;
  /// The paper's findings, each cause once: distinct = substantive + typographical + wording (the
  /// classes wording, derivation gap and naming of a claim false under every reading) + unverifiable
  /// + constant_factor (errata off by a constant factor only, their zeros the same) + inconsistent
  /// (errata whose conclusions_kept all hold: a stated set-up that does not give its data, no
  /// conclusion changed).
  std::size_t inconsistent = 0;
  std::size_t distinct = 0, substantive = 0, constant_factor = 0, typographical = 0, wording = 0, unverifiable_findings = 0, consequences = 0;
  std::size_t errata_following = 0;  // errata (any origin) that follow from another claim's correction: counted with it, said so
  std::size_t remarks = 0;                                       // the paper's claims that hold, with a remark
  std::size_t linked_remarks = 0;  // of those, the ones that follow a finding or a remark of another claim (counted with it)
  std::size_t whole_text = 0;                                    // claims that read the text as a whole (spelling, citations)
  std::size_t prose_claims = 0, prose_slips = 0;                 // its spelling, counted apart: the claims, and the slips they found
  std::size_t prose_misspelled = 0, prose_misused = 0;           // the slips: words not in the dictionary, phrases of real words misused
  std::size_t prose_errata = 0;  // the paper's spelling checks whose verdict is erratum, named apart from the errata on the run line
  /// How many claims have each verdict, in verdict_meanings' order.
  std::array<std::size_t, verdict_meanings.size()> of{};
  std::size_t machine_read = 0, quoted = 0, typed = 0, read_and_quoted = 0, coq_exported = 0, coq_checked = 0;
  std::vector<std::string> unexpected;  // not as expected, fixes not accepted apart
  std::vector<std::string> fixed, fixes_not_accepted, changed;
  std::size_t count(verdict v) const { return of[static_cast<std::size_t>(v)]; }
};


/// A spelling check's slips, from its evidence: the words not in the dictionary, and the phrases of
/// real words the record names as misused that the prose prints.
struct prose_slips {
  std::size_t misspelled = 0, misused = 0;
};
prose_slips prose_slips_of(const claim_outcome& o);
/// "6 words not English, at least", "6 words not English and 2 phrases misused, at least".
std::string prose_slips_words(std::size_t misspelled, std::size_t misused);

/// The class of a claim's finding: the ledger's when the verdict is the expected one; an unexpected
/// finding is an erratum (or unverifiable) until the ledger classifies it; none when it holds.
finding finding_of(const claim_outcome& o);

verdict_counts count_verdicts(const run_record& r);
/// The same counts over the outcomes `keep` accepts (one group of the run line: the paper's claims,
/// the checks of its source, the harness's own records).
verdict_counts count_verdicts(const run_record& r, const std::function<bool(const claim_outcome&)>& keep);

/// The experiments' expectations of a run: how many, and the keys of those that failed.
struct expectation_counts {
  std::size_t total = 0;
  std::vector<std::string> failed;
};
expectation_counts count_expectations(const run_record& r);

/// Every plot of the run's sections, as drawn (report_json.cpp).
plot_outcome all_plots_drawn(const run_record& r);

/// report_referee.cpp: a finding's amendments in one line ("where: printed …, should be …"), the first
/// sentence of a note, the referee's summary of report.md, and the provenance of the text checked.
std::string amendments_markdown(const std::vector<amendment>& amendments);
std::string first_sentence(const std::string& text);
std::string referee_summary_markdown(const run_record& r);
std::string provenance_markdown(const run_record& r);
std::string earlier_text_markdown(const run_record& r);

}  // namespace simpson::verify::report_parts

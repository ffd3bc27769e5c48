#pragma once
// The run's verdict table: one row per claim and per experiment section's expectation, each judged
// by one rule (claim_row, expectation_row). The exit code, the summary line, the lines on stderr,
// report.json's `verdicts` and report.junit.xml all read it, so none of them can disagree.

#include <simpson/verify/run.hpp>

#include <string>
#include <vector>

namespace simpson::verify {

struct verdict_row {
  /// passed; failed or error (the run fails: exit 1, or 3 for an error); expected_failure (a `fails`
  /// its record expects) and skipped (a prover not installed) never fail the run.
  enum class status { passed, failed, error, expected_failure, skipped };
  std::string name;       // the claim's id, or "section.key" for an expectation
  std::string suite;      // "claims", or the expectation's section
  bool expectation = false;
  std::string verdict;    // the claim's verdict; an expectation's is "holds" or "fails"
  std::string expected;   // the record's expected verdict; an expectation expects "holds"
  status state = status::passed;
  /// What the row is when it is not plainly as expected, as JUnit's failure type:
  /// internal-error, a verdict never expected by its name (undecided, unproved, text-changed,
  /// kernels-disagree), changed, fixed, fixed-accepted, does-not-hold, consequence,
  /// unexpected-verdict, erratum-changed, remark-changed, certificate-rejected, expectation-failed,
  /// expected-failure, skipped; empty for a plain pass.
  std::string type;
  std::string message;  // in words: the line on stderr and JUnit's message
};

/// A status as report.json spells it.
inline const char* to_string(verdict_row::status s) {
  switch (s) {
    case verdict_row::status::passed: return "passed";
    case verdict_row::status::failed: return "failed";
    case verdict_row::status::error: return "error";
    case verdict_row::status::expected_failure: return "expected-failure";
    case verdict_row::status::skipped: return "skipped";
  }
  return "?";
}

/// What a claim's record expects, in words: its verdict, or "holds with a remark (wording)".
std::string recorded_as(const claim_outcome& o);

/// A claim's row. The one rule: an error when its check threw; a failure when its verdict is not
/// the expected one (outcome_as_expected: undecided, unproved, text-changed never are), its fix not
/// accepted, its erratum another one, or coqc rejected its certificate; in a validation (no
/// expected verdicts) a claim that does not hold fails, naming the cause it follows from.
verdict_row claim_row(const claim_outcome& o, bool validation);

/// An experiment section's expectation: a failure when the run did not show what was predicted.
verdict_row expectation_row(const section_result& section, const expectation& e);

/// Every claim's row, then every section's expectations, in the run's order.
std::vector<verdict_row> verdict_table(const run_record& r);

/// Whether a row fails the run.
inline bool fails_the_run(const verdict_row& row) {
  return row.state == verdict_row::status::failed || row.state == verdict_row::status::error;
}

/// The claims whose Coq certificate coqc rejected (evidence "coq" status "failed", with --certify).
std::vector<std::string> rejected_certificates(const run_record& r);

/// The sections' expectations that failed, as "section.key".
std::vector<std::string> failed_expectations(const run_record& r);

/// The process's exit code for a finished run: 3 when a check threw (a bug in the harness), 1 when
/// a row of the verdict table fails the run, 0 otherwise.
int run_exit_code(const run_record& r);

}  // namespace simpson::verify

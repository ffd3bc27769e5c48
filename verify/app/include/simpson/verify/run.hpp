#pragma once
// Running a scene: its claims, then the experiment sections it asks for, into one run record.

#include <simpson/verify/progress.hpp>
#include <simpson/verify/claim.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/experiment_section.hpp>
#include <simpson/verify/result_model.hpp>
#include <simpson/verify/scene.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace simpson::verify {

struct claim_outcome {
  const claim* checked = nullptr;
  verdict expected = verdict::holds;
  /// The remark the claim is expected to hold with (its record's, or the baseline's): its class, none
  /// for no remark, and its text as recorded (empty: not recorded).
  finding expected_remark = finding::none;
  std::string expected_remark_text;
  claim_result result;
  double seconds = 0;
  /// Its check threw (a harness fault): no verdict on the paper, whatever result holds.
  bool threw = false;
  /// The erratum it follows from, derived (consequences.hpp): it holds once that erratum's proved
  /// corrections are put in; empty when it does not follow so.
  std::string consequence_of;
  /// An expected erratum whose correction is not the recorded one (a new error inside an old
  /// erratum), or a claim that holds with another remark than the recorded one (or one where none was
  /// recorded): what changed, the recorded and the new text around where they differ.
  std::string content_changed;
  /// Recorded as a finding (erratum, fails, unverifiable) or with a remark, and it now holds without
  /// it: `fixed` when the text it reads changed and no claim sharing a display with it now differs
  /// from its record (a fix of the document, reported apart from failures; `fix_accepted` when the
  /// run accepts fixes, --accept-fixes); else `changed`, never accepted: `changed` says why, and
  /// `changed_cause` names the claim whose change it follows (a premise it reads), when one does.
  bool fixed = false;
  bool fix_accepted = false;
  std::string changed;
  std::string changed_cause;
  /// An erratum whose record names the conclusions it leaves standing (conclusions_kept), each run and
  /// holding in this run: those claims (an inconsistency that changes no conclusion, counted apart
  /// from substantive errors); empty otherwise. Set once every claim ran (run.cpp).
  std::vector<std::string> conclusions_standing;
};

/// Whether an outcome is the one its record expects: its verdict, for an erratum whose record
/// recorded its correction that correction, its remark; a claim changed by a premise never is. The
/// one rule every report and the exit code use.
inline bool outcome_as_expected(const claim_outcome& o) {
  if (!o.content_changed.empty() || !o.changed.empty()) return false;
  return o.fixed ? o.fix_accepted : as_expected(o.result.outcome, o.expected);
}

/// The finding a claim's outcome is counted under: its derived cause, or the one its record types;
/// for a claim changed by a premise, that premise's claim.
inline const std::string& cause_of(const claim_outcome& o) {
  if (!o.changed_cause.empty()) return o.changed_cause;
  return o.consequence_of.empty() ? o.checked->follows_from : o.consequence_of;
}

struct run_record {
  scene run_scene;
  /// The book the run judged, bound to its document: every outcome's claim is one of its claims.
  std::shared_ptr<const claim_book> book;
  /// A validation of the document (its claims file records no expected verdict, or --validate): the
  /// reports speak of what holds in the document, not of regressions against expected verdicts.
  bool validation = false;
  bool of_the_paper = true;  // the paper's claims, not a claims file's document
  std::string paper_origin;  // the paper's source the formula claims read
  std::vector<claim_outcome> outcomes;
  double ginac_derivation_seconds = 0;
  /// Claims whose check threw ("id: message"): a bug in the harness, exit code 3.
  std::vector<std::string> internal_errors;  // the GiNaC derivation the formula claims share, once per process (0 when none ran)
  json paper_configuration;
  json provenance;  // the text checked, its citations, and its earlier text (provenance.hpp)
  json environment;
  std::vector<section_result> sections;  // the experiment sections the scene asked for, in order
  std::vector<double> section_seconds;
  double seconds = 0;
  /// coqc's wall time on all the claims' certificates, checked together (--certify): a run time, so in
  /// timing.json, not in the evidence (report.json stays the same from run to run).
  double coq_seconds = 0;
  std::size_t coq_documents = 0;  // the files coqc checked
  unsigned coq_processes = 0;     // in how many coqc processes
};

/// Called before and after each claim: (index, count, claim, outcome or nullptr).
using progress_callback = std::function<void(std::size_t, std::size_t, const claim&, const claim_outcome*)>;

/// What runs a claim's check: check_claim (printed_checks.hpp) unless a test passes its own, a seam
/// (a check that throws, to test exit code 3), never a variable read in the run.
using claim_checker = std::function<claim_result(const claim&, const run_context&)>;

/// Runs every claim of the scene, each one of `book`'s (bound to `paper` by read_scene_paper); a
/// check that throws is recorded as `fails` with the message, and in `internal_errors`.
/// Throws simpson::verify::interrupted when interruption_signal() is set (checked between claims
/// and between numeric samples).
/// Then runs the experiment sections the scene asks for (table1, work_precision, stability,
/// long_time), calling `section_progress(name, seconds)` after each.
run_record run(const scene& s, std::shared_ptr<const claim_book> book, const paper_reading& paper, const progress_callback& progress = {},
               const std::function<void(const std::string&, double)>& section_progress = {}, const progress_sink& work = {},
               const claim_checker& checker = {});

/// The same for the paper's book, reading the scene's paper first (the embedded one unless the
/// scene names a file) and binding the book to it.
run_record run(const scene& s, const progress_callback& progress = {},
               const std::function<void(const std::string&, double)>& section_progress = {}, const progress_sink& work = {},
               const claim_checker& checker = {});

/// The document a scene's book checks, read, and `book` bound to it (check_claims_file_formulas):
/// the paper (embedded, or the scene's `paper` file), or the book's [document] from the scene's
/// `paper` file. Throws std::invalid_argument (one line: the file, the label, the line, the token)
/// when it is missing or does not parse, and claims_file_error when a record does not bind.
paper_reading read_scene_paper(const scene& s, claim_book& book);

/// --baseline: each of the scene's claims that `baseline` (a report.json) judged is expected to keep
/// its verdict there, an erratum its correction there, and fixes pass. Throws std::invalid_argument
/// naming `name` when a verdict there is not one.
void apply_baseline(scene& s, const json& baseline, const std::string& name);

/// What changed between an erratum's recorded correction and the one a run proved, each shown
/// around where they first differ (cut between UTF-8 characters).
std::string correction_change(const std::string& recorded, const std::string& now);

/// The same for any recorded text: "`what` is not the recorded one: recorded '…', now '…'".
std::string text_change(const std::string& what, const std::string& recorded, const std::string& now);

}  // namespace simpson::verify

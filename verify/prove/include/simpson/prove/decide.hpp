#pragma once
// What a decider found, and the one place that makes a verdict of it. A proof shape, or a bespoke
// check of a book, returns `decider_evidence`: each kernel's answer on the statement it judged, what
// a "no" means (an erratum with its correction, a plain failure, material that is absent), the
// goals Coq is to check, and everything else it found (the evidence JSON, the printed formula,
// notes, amendments). decide() applies the two-kernel rule, exports the certificate and sets the
// verdict: as LLVM lit's `setResult`, nothing else writes a claim's verdict.

#include <simpson/prove/coq_export.hpp>
#include <simpson/prove/kernel_zero.hpp>
#include <simpson/prove/printed_check_support.hpp>
#include <simpson/verify/published_fact.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace simpson::verify::detail {

/// A kernel's answer on the statement a decider judged: it holds, it does not, or this kernel did
/// not decide it (a term it does not compute, a grid too large).
enum class answer { holds, fails, none };

inline answer answer_of(bool holds) { return holds ? answer::holds : answer::fails; }

/// A kernel's answer on the statement's denial ("not linear" for "linear").
inline answer negated(answer a) { return a == answer::holds ? answer::fails : a == answer::fails ? answer::holds : answer::none; }

/// Our kernel's answer on an identity from its decision that lhs − rhs is zero.
answer answer_of(const kernel_decision& own);

/// Our kernel's answer on the statement from its decision on the fact GiNaC reduced the statement to
/// (an order, a degree, a derived entry): it confirms the fact, so its answer is GiNaC's; it refutes
/// it, so its answer is the opposite; or it did not decide.
answer confirming(answer ginac, const kernel_decision& on_fact);

struct decider_evidence {
  /// judged: the kernels answered (or not); beyond_reach: the statement is not of the shape's kind
  /// (a map whose det is not 1, a condition not in one variable), or no enclosure decided it within
  /// the run's digits: undecided, a tool's limit and never a finding; tool_missing: a program the
  /// check needs is not installed (skipped); not_proved: a prover (Gappa) could not bound what the
  /// statement bounds (unproved); words_changed: the words the claim quotes are not in the document,
  /// or no longer parse (text-changed).
  enum class reach { judged, beyond_reach, tool_missing, not_proved, words_changed };
  reach reached = reach::judged;
  /// The statement the kernels judged, in words: the note of kernels-disagree names it.
  std::string statement;
  answer ginac = answer::none;
  answer own = answer::none;
  /// The answer of a check that computes nothing (a dictionary's words, a bibliography's entries):
  /// no kernel's, and asked only where neither kernel answered.
  answer lexical = answer::none;
  /// The note when the kernels disagree, where kernels_differ_on(statement) does not say what differs.
  std::string disagreement;
  /// A statement of several parts (sides, entries, factors) the kernels answered one by one: they
  /// differ on one of them, whatever their answers on the whole.
  bool parts_differ = false;
  /// What "no" means: erratum (found.correction is the proved correction), fails (false, nothing to
  /// correct it with: a printed property, an undefined formula) or unverifiable (the material it
  /// needs is absent).
  verdict if_false = verdict::erratum;
  /// The identities and signs Coq is to check (coq_export.hpp); none: the decider exports no
  /// certificate (found.certificate_missing may say why).
  std::optional<std::vector<proof_goal>> goals;
  /// Everything else the decider found; its `outcome` is decide()'s to set.
  claim_result found;

  /// What the kernels' answers come to, before reach and `if_false`: one of them answered, and the
  /// other did not contradict it. A shape asks this to say more about a statement found false (the
  /// value of a determinant, a correction's derivation), never to set a verdict.
  bool found_holds() const { return agreed() == answer::holds; }
  bool found_false() const { return agreed() == answer::fails; }
  /// The two kernels differ: both answered, and not alike, or they differ on a part.
  bool kernels_differ() const { return parts_differ || (ginac != answer::none && own != answer::none && ginac != own); }
  answer agreed() const {
    if (kernels_differ()) return answer::none;
    return ginac != answer::none ? ginac : own != answer::none ? own : lexical;
  }
};

/// Evidence that the statement is beyond the decider's reach, `found.note` saying why.
decider_evidence beyond_reach(claim_result found);

/// Evidence that stopped at `reached` (a tool missing, a bound not proved, words changed), `found`
/// saying why.
decider_evidence stopped(decider_evidence::reach reached, claim_result found);

/// A fact an experiment published (published_fact.hpp) as evidence: measured by the harness, so our
/// side's answer; found false, an erratum with the fact's correction when it has one, else it fails.
/// It exports no Coq statement: `coq_none` says why, or by default that it is a measured fact.
decider_evidence observed(published_fact fact, const std::string& coq_none);

/// The two-kernel rule, alone: the verdict `evidence` comes to (decide() below, in words).
verdict verdict_of(const decider_evidence& evidence);

/// What decides a claim: its evidence, from the run's context.
using judge = std::function<decider_evidence(const run_context&)>;

/// What `judge` found, or why it found nothing: no enclosure decided it within the run's digits
/// (beyond reach: undecided), or the words it quotes did not read (text-changed).
decider_evidence within_reach(const judge& judged_by, const run_context& ctx);

// ---- evidence combined: what a book's check adds to a decider's evidence, judged here ----
// (decide.cpp). A book hands these its parts; none of them sets or reads a verdict in the
// book: what the parts come to is decide()'s.

/// The evidence comes to a verdict a printed facet and a certificate can be added to: its words
/// read, and a kernel decided (not text-changed, not undecided).
bool settled(const decider_evidence& e);

/// Our kernel's check proved the derived statement (its evidence does not come to a failure).
bool derived_proved(const decider_evidence& e);

/// The evidence proves its printed formula wrong as it stands (an erratum comes of it): a book that
/// compares its own code with that formula has nothing printed to compare it with, unless the
/// evidence gives the corrected formula.
bool refutes_the_print(const decider_evidence& e);

/// The book's own code (our core, bound to a printed formula) differs from the print it binds:
/// the statement, with "our code is the printed formula" in it, is false for GiNaC, and for our
/// kernel where `own_refutes` (it decided a binding) or it already refuted the rest; nothing corrects
/// it, so false means fails, `note` first in the note. Evidence that already comes to
/// kernels-disagree or text-changed stays as it is: the binding does not hide those.
decider_evidence code_differs_from_print(decider_evidence e, bool own_refutes, const std::string& note);

/// A computed result judged against the words quoted for it: when the computation holds but the
/// words deny it ("not consistent", "not symplectic"), each answer is the words' denial of it, an
/// erratum whose correction is `computed_statement`; `denied` (when given) says whether they did.
decider_evidence as_the_words_say(decider_evidence computed, bool words_affirm, std::string computed_statement, bool* denied = nullptr);

/// The two kernels on a check's derived statement, and GiNaC's on the printed one (`g`). Each proves
/// the derived statement (ours on our transcription; GiNaC from first principles, every symbol
/// free); they must agree, or they differ on that part. When they agree that it holds, the printed
/// side is GiNaC's alone: it holds, or it is false (an erratum, the derived formula its correction,
/// or a printed property that fails). `quoted`: the claim quotes words, so that an erratum of ours
/// may be of the words and not of the formula.
decider_evidence with_printed(decider_evidence e, const printed_outcome& g, const std::string& claim_id, bool quoted);

/// A claim's check: `judged_by`'s evidence within reach, made a verdict by decide().
std::function<claim_result(const run_context&)> claim_check_of(judge judged_by, const std::string& claim_id, const std::string& statement);

/// The verdict of `evidence` for the claim `claim_id` (its statement `statement`, the certificate's
/// title), in this order: skipped where a tool is missing, text-changed where the words changed,
/// unproved where a prover could not bound it; kernels-disagree where both kernels
/// answered and differ, or differ on a part (no finding then: its correction and amendments are
/// dropped); undecided where the statement is beyond reach or neither kernel answered; else holds,
/// or `if_false`. The certificate of `goals` is exported unless the kernels disagree. Amendments
/// ("printed X, should be Y") are kept only where they are said of something: an erratum, or a
/// claim that holds with a remark.
claim_result decide(const std::string& claim_id, const std::string& statement, decider_evidence evidence);

}  // namespace simpson::verify::detail

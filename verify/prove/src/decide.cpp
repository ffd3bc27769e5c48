#include <simpson/prove/decide.hpp>

#include <simpson/verify/enclosure_undecided.hpp>
#include <simpson/verify/quoted_sentence.hpp>

#include <stdexcept>
#include <utility>

namespace simpson::verify::detail {

answer answer_of(const kernel_decision& own) {
  switch (own.outcome) {
    case kernel_decision::result::zero: return answer::holds;
    case kernel_decision::result::nonzero: return answer::fails;
    case kernel_decision::result::not_applicable: return answer::none;
  }
  return answer::none;
}

answer confirming(answer ginac, const kernel_decision& on_fact) {
  if (ginac == answer::none || on_fact.outcome == kernel_decision::result::not_applicable) return answer::none;
  if (on_fact.outcome == kernel_decision::result::zero) return ginac;
  return ginac == answer::holds ? answer::fails : answer::holds;
}

verdict verdict_of(const decider_evidence& evidence) {
  switch (evidence.reached) {
    case decider_evidence::reach::tool_missing: return verdict::skipped;
    case decider_evidence::reach::words_changed: return verdict::text_changed;
    case decider_evidence::reach::not_proved: return verdict::unproved;
    case decider_evidence::reach::judged:
    case decider_evidence::reach::beyond_reach: break;
  }
  // Before reach: a fact the kernels differ on is a bug, whatever else the shape could judge.
  if (evidence.kernels_differ()) return verdict::kernels_disagree;
  if (evidence.reached == decider_evidence::reach::beyond_reach) return verdict::undecided;
  switch (evidence.agreed()) {
    case answer::holds: return verdict::holds;
    case answer::fails: return evidence.if_false;
    case answer::none: return verdict::undecided;
  }
  return verdict::undecided;
}

decider_evidence observed(published_fact fact, const std::string& coq_none) {
  decider_evidence e;
  e.own = answer_of(fact.holds);
  e.if_false = fact.correction.empty() ? verdict::fails : verdict::erratum;
  e.found.evidence = std::move(fact.evidence);
  e.found.note = std::move(fact.note);
  if (!fact.holds) e.found.correction = std::move(fact.correction);
  if (fact.holds && !fact.remark.empty()) {
    const std::optional<finding> kind = finding_of_name(fact.remark_class);
    if (!kind) throw std::logic_error("observed: a fact's remark of no class '" + fact.remark_class + "'");
    e.found.remark = std::move(fact.remark);
    e.found.remark_kind = *kind;
  }
  e.found.certificate_missing = without_coq_statement(coq_none, "a fact an experiment measured: nothing for a proof assistant to state");
  return e;
}

decider_evidence stopped(decider_evidence::reach reached, claim_result found) {
  decider_evidence e;
  e.reached = reached;
  e.found = std::move(found);
  return e;
}

decider_evidence beyond_reach(claim_result found) { return stopped(decider_evidence::reach::beyond_reach, std::move(found)); }

claim_result decide(const std::string& claim_id, const std::string& statement, decider_evidence evidence) {
  const verdict outcome = verdict_of(evidence);
  claim_result result = std::move(evidence.found);
  if (outcome == verdict::kernels_disagree) {  // no finding: what a finding would carry is dropped
    result.note = evidence.disagreement.empty() ? kernels_differ_on(evidence.statement) : evidence.disagreement;
    result.correction.clear();
    result.amendments.clear();
    result.corrected_formulas.clear();
    if (result.certificate_missing.empty()) result.certificate_missing = "the kernels disagree: nothing is certified";
  }
  if (outcome == verdict::undecided && evidence.reached == decider_evidence::reach::judged && result.note.empty()) {
    result.note = "Neither kernel decided " + evidence.statement + ".";
  }
  if (outcome != verdict::holds && !result.remark.empty()) {  // a remark is said of a claim that holds, never of a finding
    result.remark.clear();
    result.remark_kind = finding::none;
  }
  // An amendment is said of an erratum (its correction in one line) or of a remark: a decider adds it
  // whatever it found, and it is dropped here where the verdict says nothing it could belong to.
  if (!meaning(outcome).corrected && result.remark.empty()) result.amendments.clear();
  if (outcome != verdict::erratum) result.constant_factor = false;
  if (evidence.goals && outcome != verdict::kernels_disagree) record_certificate(result, coq_certificate(claim_id, statement, *evidence.goals));
  result.outcome = outcome;  // the engine's one verdict site
  return result;
}

decider_evidence within_reach(const judge& judged_by, const run_context& ctx) {
  try {
    return judged_by(ctx);
  } catch (const enclosure_undecided& e) {
    claim_result found;
    found.evidence["undecided"] = e.what();
    found.note = std::string("No enclosure decided this claim within the run's digits: ") + e.what() +
                 ". Raise --enclosure-budget, or find why the enclosure is wide.";
    return beyond_reach(std::move(found));
  } catch (const text_changed& e) {
    claim_result found;
    found.evidence["text_changed"] = e.what();
    found.note = std::string("The words this claim quotes did not read: ") + e.what() +
                 ". Its check judges only words it reads: a new wording is judged once the claim's sentence pattern matches it "
                 "(docs/claims-file.md, sentence patterns).";
    return stopped(decider_evidence::reach::words_changed, std::move(found));
  }
}

std::function<claim_result(const run_context&)> claim_check_of(judge judged_by, const std::string& claim_id, const std::string& statement) {
  return [judged_by = std::move(judged_by), claim_id, statement](const run_context& ctx) {
    return decide(claim_id, statement, within_reach(judged_by, ctx));
  };
}

// ---- evidence combined (decide.hpp): what a book's check adds to a decider's evidence, judged here ----


namespace {

/// Two pieces of prose as sentences: a full stop after the first unless it has one.
std::string then(const std::string& first, const std::string& second) {
  if (second.empty()) return first;
  if (first.empty()) return second;
  const char last = first.back();
  return first + (last == '.' || last == ':' || last == ';' ? " " : ". ") + second;
}

}  // namespace

bool settled(const decider_evidence& e) {
  const verdict v = verdict_of(e);
  return v != verdict::text_changed && v != verdict::undecided;
}

bool derived_proved(const decider_evidence& e) { return verdict_of(e) != verdict::fails; }

bool refutes_the_print(const decider_evidence& e) { return verdict_of(e) == verdict::erratum; }

decider_evidence code_differs_from_print(decider_evidence e, bool own_refutes, const std::string& note) {
  const verdict before = verdict_of(e);
  if (before == verdict::kernels_disagree || before == verdict::text_changed) return e;
  e.reached = decider_evidence::reach::judged;
  e.ginac = answer::fails;
  e.own = own_refutes || e.own == answer::fails ? answer::fails : answer::none;
  e.lexical = answer::none;
  e.if_false = verdict::fails;
  e.found.correction.clear();
  e.found.corrected_formulas.clear();
  e.found.note = note + e.found.note;
  return e;
}

decider_evidence as_the_words_say(decider_evidence computed, bool words_affirm, std::string computed_statement, bool* denied) {
  const bool denies = verdict_of(computed) == verdict::holds && !words_affirm;
  if (denied != nullptr) *denied = denies;
  if (!denies) return computed;
  computed.ginac = negated(computed.ginac);
  computed.own = negated(computed.own);
  computed.lexical = negated(computed.lexical);
  computed.if_false = verdict::erratum;  // the rest of what was computed (its formulas read, its certificate) stands
  computed.found.correction = std::move(computed_statement);
  return computed;
}

decider_evidence with_printed(decider_evidence e, const printed_outcome& g, const std::string& claim_id, bool quoted) {
  const verdict own = verdict_of(e);
  const bool own_derived = own != verdict::fails;
  claim_result& result = e.found;
  // An erratum of the quoted words (a claim that reads a formula and also judges prose about it)
  // stands whatever the printed formula: the words, not the transcription, were refuted.
  const bool words_refuted = own == verdict::erratum && quoted;
  if (own_derived != g.derived_holds) {
    e.parts_differ = true;
    e.disagreement = "The two kernels disagree on '" + claim_id + "': ours " + (own_derived ? "proved" : "did not prove") +
                     " the derived statement, GiNaC " + (g.derived_holds ? "proved" : "did not prove") + " it (" + g.derived + ")." +
                     (result.note.empty() ? "" : " " + result.note);
    return e;
  }
  if (!g.derived_holds) {  // neither proved the derived statement: it fails
    e.ginac = answer::fails;
    e.if_false = verdict::fails;
    return e;
  }
  if (g.holds && words_refuted) {  // GiNaC judged the formula, not the words: ours decide
    result.note = then("The printed formula holds (" + g.proved + "); the quoted words do not.", result.note);
    return e;
  }
  // The printed side is GiNaC's: our kernel judged our transcription, which answers for the print
  // only where it agrees (an erratum of the transcription that the print repeats).
  e.ginac = answer_of(g.holds);
  e.lexical = answer::none;
  if (g.holds) {
    if (own == verdict::erratum) {
      result.note = "This copy of the document prints the derived formula: " + g.proved +
                    ". (Our kernel's transcription of the printed formula, typed from the book's text, is the erratum it refutes.)";
      result.correction.clear();
      e.own = answer::none;
    }
    return e;
  }
  e.if_false = g.property || g.correction.empty() ? verdict::fails : verdict::erratum;
  if (e.if_false == verdict::erratum && own != verdict::erratum) result.correction = g.correction;
  e.own = own == verdict::erratum ? answer::fails : answer::none;
  result.note = then((own == verdict::erratum ? "As printed: " : "The formula as printed in the paper's source differs from the derived one: ") +
                         g.proved,
                     result.note);
  return e;
}

}  // namespace simpson::verify::detail

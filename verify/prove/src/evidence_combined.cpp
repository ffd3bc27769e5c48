// What a book's check adds to a decider's evidence, combined here (decide.hpp): the printed side
// GiNaC judges beside our kernel's derived statement, and the words a sentence says of a computed
// result. The book hands the parts; what they come to is decide()'s.

#include <simpson/prove/decide.hpp>

#include <string>
#include <utility>

namespace simpson::verify::detail {

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

#pragma once
// A claim's Coq certificate, printed from the identities its GiNaC kernel decided (proof_goal): the
// statement is never typed by hand. Each identity that holds becomes a lemma over the reals,
//   forall <symbols> : R, 0 < m -> 0 < h -> <each denominator and its factors> <> 0 -> lhs = rhs,
// proved by `field` (its side conditions closed by the hypotheses). Only Coq's standard library
// (Reals, Field, Lra, Psatz); no admit, no axiom beyond the library's real numbers. An identity that
// does not hold (a printed formula that differs from the derived one) is never exported as a proof:
// its negation is, ~ (forall ..., lhs = rhs), shown at a point where GiNaC finds the two sides differ.
// An identity whose two sides GiNaC evaluates to the same expression is not stated either: X = X
// would check nothing.

#include <simpson/prove/printed_check_support.hpp>

#include <string>
#include <vector>

namespace simpson::verify::detail {

/// The certificate's source, or why there is none (`text` empty).
struct coq_export {
  std::string text;
  std::vector<std::string> lemmas;  // their names, in order
  std::string not_exported;         // the reason, when nothing could be exported
  /// The refuted identities' negations (an erratum's printed statement), a file of their own.
  std::string refutation;
  std::vector<std::string> refutation_lemmas;
};

/// The certificate of `claim_id` from the goals GiNaC decided, and the negations of those that do
/// not hold (`refutation`); a goal with a term Coq's field tactic cannot state (a function
/// such as V, a non-integer power, a floating-point number) makes the whole export fail with the reason.
coq_export coq_certificate(const std::string& claim_id, const std::string& statement, const std::vector<proof_goal>& goals);

/// The certificate, or why there is none, and the refuted statements' negations, into `result`.
void record_certificate(claim_result& result, const coq_export& certificate);

/// A Coq identifier from a claim id or a goal name: letters, digits and '_' (every other character).
std::string coq_identifier(const std::string& name);

/// A Coq identifier from a symbol's name, keeping apart what coq_identifier would merge: '+' as p,
/// '-' as m, '/' as over (q_j+1, q_j-1, q_j+1/2: q_jp1, q_jm1, q_jp1over2); letters, digits and '_'
/// as they are, anything else '_'. The export refuses two symbols that still print alike.
std::string coq_symbol_identifier(const std::string& name);

}  // namespace simpson::verify::detail

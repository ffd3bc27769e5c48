#pragma once
// The words each hole of a sentence's pattern accepts, for the holes the proof shapes read: one
// table, by which the shapes read their sentences' words and from which `simpson-verify
// --list-holes` prints the reference (docs/claims-file.md). Words outside it are never guessed at:
// the claim is text-changed, naming the words and what the hole reads.

#include <string>
#include <utility>
#include <vector>

namespace simpson::verify {

/// How a hole's words are read.
enum class hole_reading {
  number,    // digits, or a number word (quoted_sentence.hpp, number_words)
  bound,     // a relation and a number: "smaller or equal to 1" (bound_relations)
  number_or_bound,  // a bound, or else a number
  phrases,   // exactly one of the phrases (case and white space aside)
  tex,       // a formula in TeX: "$N - 1$"
  property,  // the record's `property` word, or its denial: not P, inP, unP, non-P
  quoted,    // any words: quoted as printed in the finding, never parsed (the verdict does not turn on them)
};

struct sentence_hole {
  std::string name;  // the hole, {name}
  hole_reading reads = hole_reading::phrases;
  std::vector<std::pair<std::string, std::string>> phrases;  // phrases: the words and what they state
  std::string meaning;                                       // what the words state, for the reference
};

/// Every hole a proof shape reads, in the reference's order.
const std::vector<sentence_hole>& sentence_holes();

/// The hole `name` of the table; a name not in it is a harness fault (std::logic_error).
const sentence_hole& hole_named(const std::string& name);

/// The phrases a `property` hole accepts for the record's word: the word, and its denials.
std::vector<std::pair<std::string, std::string>> affirmed_or_denied(const std::string& word);

/// The reference: a Markdown table of every hole, the shapes whose patterns take it, and the words it
/// accepts with what they state (generated into docs/claims-file.md).
std::string holes_markdown();

}  // namespace simpson::verify

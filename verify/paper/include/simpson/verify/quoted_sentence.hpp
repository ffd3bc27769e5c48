#pragma once
// The words of a sentence the paper prints, quoted by a pattern (prose_span.hpp) and parsed in the
// pattern's holes: a number ("three", "fourth", "$ \, 1 $"), a relation and its bound ("smaller
// than 1"), or one of a set of phrases ("explicit" / "implicit"). What was quoted and what was
// parsed are recorded for the report. A sentence that is no longer in the source, or words that no
// longer parse, throw text_changed naming the sentence: a claim that reads them is then
// text-changed, never silently as expected.

#include <simpson/verify/json.hpp>
#include <simpson/verify/prose_span.hpp>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace simpson::verify {

/// The paper changed under a prose claim: its sentence is gone, or the words in a hole do not parse.
class text_changed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A relation and its bound, as in "smaller or equal to 1": relation one of <, <=, =, >=, >;
/// `rest` the words after the bound (", those of modulus 1 being simple"), empty when none.
struct stated_bound {
  std::string relation;
  int value = 0;
  std::string rest;
  /// Whether `x` satisfies it.
  bool admits(int x) const;
};

class quoted_sentence {
 public:
  quoted_sentence(prose_span span, std::string origin, json* records, std::size_t index);

  /// The words in `hole`, as printed (markup dropped by plain_words).
  std::string words(const std::string& hole) const;
  /// A whole number: digits, or an English cardinal or ordinal up to twelve ("three", "fourth").
  int number(const std::string& hole) const;
  /// The relation and bound of "smaller than 1", "smaller or equal to $1$", "at most 1", "< 1", ...
  stated_bound bound(const std::string& hole) const;
  /// The value of the phrase the words are (case and white space aside), from `phrases`.
  std::string choice(const std::string& hole, const std::vector<std::pair<std::string, std::string>>& phrases) const;
  /// The value of the first key the words contain, in the order given.
  std::string containing(const std::string& hole, const std::vector<std::pair<std::string, std::string>>& keys) const;

  const prose_span& span() const { return span_; }

  /// Records what the check made of a hole's words that no parser above reads.
  void record(const std::string& hole, const json& parsed) const;
  /// The words in `hole` are not what the check can judge: throws text_changed naming them.
  [[noreturn]] void unparsed(const std::string& hole, const std::string& expected) const;

 private:
  prose_span span_;
  std::string origin_;
  json* records_;
  std::size_t index_;
};

/// The words a number hole reads besides digits ("three", "fourth"), each with its value.
const std::vector<std::pair<std::string, int>>& number_words();
/// The phrases a bound hole reads before its number ("smaller or equal to"), each with its relation,
/// in the order they are tried (the longest first where one begins another).
const std::vector<std::pair<std::string, std::string>>& bound_relations();

/// The sentence of `paper` that matches `pattern`; recorded in `quotes` when given (the
/// claim's evidence). Throws text_changed naming the pattern when it is not there.
quoted_sentence quote_sentence(const paper_source& paper, const std::string& pattern, json* quotes);

}  // namespace simpson::verify

#pragma once
// A sentence of the paper's prose, found by a pattern: the sentence's words with holes {name}
// where the words that carry a claim stand ("accurate up to polynomials of degree {degree}.").
// White space matches any white space (the source breaks lines where it likes); everything else
// must be as printed. A hole takes the words between the text before it and the text after it;
// its name is two or more lower-case letters and it starts a word (TeX groups such as {h},
// {\rm det} or \ref{simpson} are text). Words
// match whole: "is" does not match inside "discrete".

#include <simpson/verify/paper_source.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace simpson::verify {

struct prose_span {
  int line = 0;                               // 1-based line of the span's first character
  std::string text;                           // the span as printed, white space folded
  std::map<std::string, std::string> holes;   // each hole's words, as printed (white space folded)
  /// The lines of the other spans the pattern matches, when it has holes: a pattern that matches
  /// more than one span does not say which sentence it judges, and is refused (quoted_sentence.hpp).
  std::vector<int> also_at;
};

/// The first span of the paper that matches `pattern`, with the lines of any other; none when the
/// sentence is no longer there. A hole takes words of the prose only: at least one, at most 240
/// characters, and no display (an environment, \[ \], $$) or paragraph break inside. Throws std::invalid_argument for a pattern that
/// starts or ends with a hole, has two holes side by side, or an unclosed brace.
std::optional<prose_span> find_prose(const paper_source& paper, const std::string& pattern);

/// Throws std::invalid_argument, as find_prose would, for a pattern that cannot match: what a
/// claims file's record is checked for before anything runs.
void check_pattern(const std::string& pattern);

/// The words of TeX prose or math with the markup a reader does not read dropped: $, TeX's
/// spacing (\, \! \; \quad ~), \big-style sizes, and white space folded to one space.
std::string plain_words(const std::string& tex);

}  // namespace simpson::verify

#pragma once
// The words of a document's prose, as TeX prints them: what a reader reads between the formulas.
// Math (every region the reader finds: $...$, displays, environments, macros that open them) is not
// prose; nor are the arguments a reader never sees (\label, \ref, \eqref, \cite, \begin, \end,
// \includegraphics, \bibliography..., \url, spacing, running heads); every other control sequence is dropped and
// its arguments read as prose (\emph{...}, \footnote{...}, \centerline{...}). TeX's accents are the
// letters they print (Math\'ematiques as Mathématiques, Fran\c{c}ois as François). A word is a run
// of letters, apostrophes inside it kept ("Simpson's"); hyphens and digits end one.

#include <simpson/verify/paper_source.hpp>
#include <simpson/verify/tex_document.hpp>

#include <string>
#include <vector>

namespace simpson::verify {

struct prose_word {
  std::string word;  // UTF-8, as printed
  int line = 0;      // 1-based
};

/// The words of the document's prose from `from` (the first place the source prints those words,
/// white space aside; empty: the body's start, after \begin{document} when there is one) to the end
/// of the body. Throws std::invalid_argument when `from` is not in the source.
std::vector<prose_word> prose_words(const paper_source& source, const tex_document& document, const std::string& from = {});

}  // namespace simpson::verify

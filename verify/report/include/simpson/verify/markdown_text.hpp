#pragma once
// Text put into Markdown: what GiNaC, the paper's TeX or a claim's prose says, shown as written.
// GiNaC prints products with '*' and derivatives as D[0](V)(q); unescaped, Markdown turns the
// first into emphasis and the second into a link. Every such text goes through one of these.

#include <string>
#include <string_view>

namespace simpson::verify {

/// Inline text shown literally: every character Markdown (CommonMark with GitHub's tables) could
/// read as syntax is backslash-escaped (`\ ` * _ [ ] < > | ~ & !`), and newlines become spaces, so
/// the text stays one paragraph, list item or table cell.
std::string markdown_escaped(std::string_view text);

/// A code span holding `text` verbatim: fenced by one backtick more than the longest run of
/// backticks inside it. In a table cell, pass the result through markdown_cell as well.
std::string markdown_code(std::string_view text);

}  // namespace simpson::verify

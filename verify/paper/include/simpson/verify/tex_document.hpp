#pragma once
// A LaTeX document read as TeX reads it: its tokens from the first to the last, each macro defined
// where its definition comes (\newcommand, \def, \DeclareMathOperator, ...) and expanded where it is
// used, and its math found where TeX finds it: $...$, \(...\), $$...$$, \[...\], and the math
// environments (equation, align, gather, multline, eqnarray, displaymath, their starred forms),
// whether written out or made by a macro (\moneq ... \monend). An align-like display is a list of
// rows, each with its own labels; any other is one row. A document whose math never closes, or that
// begins a document body it never ends, is refused (tex_error): it was cut short.
//
// The equations of a row: its sides split at the relations of its top level (=, <, \leq, \equiv,
// \simeq, ...), several equations at its top-level commas (g_l = ... , g_r = ...), or the rows of a
// system it holds (\left\{ \begin{array} ... \right., cases, aligned, split), a row that starts
// with a relation continuing the one before it; a last period, comma or colon is the sentence's.

#include <simpson/verify/paper_source.hpp>
#include <simpson/verify/tex_macros.hpp>
#include <simpson/verify/tex_tree.hpp>

#include <memory>
#include <string>
#include <vector>

namespace simpson::verify {

/// One row of a display (an align row, or the whole of any other display), or an inline formula.
struct tex_row {
  std::vector<tex_token> tokens;     // its math, the document's macros expanded
  std::size_t begin = 0, end = 0;    // its span in the source
  std::vector<std::string> labels;   // its \label's
  int line = 0;                      // the line of its first math token (after a leading \label)
};

struct tex_region {
  bool display = true;               // false: inline math
  std::string environment;           // "$", "$$", "\\(", "\\[", "equation", "align*", ...
  std::size_t opener = 0;            // where what opened it is (the macro call, when a macro did)
  std::size_t begin = 0, end = 0;    // the span of its math in the source
  bool aligned = false;              // rows with alignment points (align, eqnarray, alignat, flalign)
  std::vector<tex_row> rows;
};

/// One equation of a row: its sides (a chain a = b = c has three), the relations between them, its
/// TeX as the reports show it.
struct tex_equation {
  std::vector<tex_list> sides;
  std::vector<std::string> relations;  // sides.size() - 1 of them: "=", "<", "\\leq", ...
  std::vector<std::string> side_tex;
  std::string tex;
};

class tex_document {
 public:
  /// Reads `source` (its raw text: a comment is TeX's to drop, with its line's end). Throws
  /// tex_error, its offset in the source, when the document does not read.
  explicit tex_document(const paper_source& source);

  const std::vector<tex_region>& regions() const { return regions_; }
  const tex_macros& macros() const { return macros_; }
  const std::string& text() const { return text_; }
  const std::string& origin() const { return origin_; }

  /// The row (of an align-like display) or display that holds \label{label}; throws
  /// std::invalid_argument when there is none, or two.
  struct located {
    const tex_region* region = nullptr;
    int row = -1;  // -1: the whole region
  };
  located labelled(const std::string& label) const;
  /// The first display whose opener is at or after `offset`; none when there is none.
  const tex_region* display_after(std::size_t offset) const;
  /// The inline formula that holds `offset`, or else the first one after it; none when there is none.
  const tex_region* inline_at(std::size_t offset) const;

 private:
  std::string origin_;
  std::string text_;
  tex_macros macros_;
  std::vector<tex_region> regions_;
};

/// The equations of a region's row, or of all its rows (row -1), in order. Throws tex_error.
std::vector<tex_equation> equations_of(const tex_region& region, int row = -1);

/// The line of the region's (or row's) first math, as the reports give it.
int line_of(const tex_region& region, int row = -1);

/// "line N: why" for a tex_error in `text`, with the construct's hint when it has one.
std::string describe(const tex_error& e, const std::string& text);

/// The document of `source` read; a document that does not read is bad input: throws
/// std::invalid_argument "<what> '<origin>', line N: why".
tex_document read_document(const paper_source& source, const std::string& what = "document");

}  // namespace simpson::verify

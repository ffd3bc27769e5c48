#pragma once
// A document's LaTeX source as an input: a paper or a note, read from a file (the book embeds the
// paper it checks: the_paper.hpp). Displays are found by their \label, or, when unlabelled, by a
// stable anchor in the prose just before them. Comment lines (%, including an earlier display a
// source keeps in comments) are not part of the text.

#include <cstddef>
#include <optional>
#include <string>
#include <utility>

namespace simpson::verify {

struct paper_source {
  std::string origin;  // the file's path, or "embedded" for a book's compiled-in copy
  std::string text;    // with comments blanked out (line numbers kept)
  std::string sha256;  // of the source's bytes as read (report.json's environment)
  std::string raw;     // the source as read, comments included (the earlier text kept in them)
};

/// One display of the paper: where it was found and its TeX, from after its \label to its end.
struct tex_display {
  std::string locator;  // "label eq:step" or "anchor 'can be factorized'"
  int line = 0;         // 1-based line of the display's first math line
  std::string tex;      // the math, on one line, comments removed
};

/// A LaTeX source read from a file, comments blanked out (line numbers kept); `what` ("paper",
/// "document") names it in errors. Throws std::invalid_argument naming the file when it is missing,
/// a directory, unreadable or empty.
paper_source load_source(const std::string& path, const std::string& what);

/// A source given as text (a book's embedded copy), `origin` naming it.
paper_source source_from_text(const std::string& origin, const std::string& text);

/// A document other than the paper (a note checked with its own claims file), read as the paper
/// is, comments blanked out. Throws std::invalid_argument naming the file when it is missing,
/// unreadable, empty, or does not print `title`.
paper_source load_document(const std::string& path, const std::string& title);

/// Where `needle` occurs in `text` at or after `from`, white space ignored on both sides (the source
/// breaks lines where it likes): [begin, end) of the match, or none. With `whole_word`, a needle that
/// starts with a letter or a digit does not match inside a word ("is" not in "discrete"); with
/// `within`, the match starts no later than from + within.
std::optional<std::pair<std::size_t, std::size_t>> find_ignoring_space(const std::string& text, const std::string& needle,
                                                                       std::size_t from = 0, bool whole_word = false,
                                                                       std::size_t within = std::string::npos);

/// The 1-based line of `offset` in `text`.
int line_at(const std::string& text, std::size_t offset);

/// Runs of white space folded to one space, none at the ends (TeX and prose for reports).
std::string folded_space(const std::string& text);

/// The source with every comment (from an unescaped % to the end of its line) blanked out.
std::string without_comments(const std::string& tex);

/// `source` with [at, at + length) of its text replaced by `to`, in the text as read (`raw`) and in
/// the text without comments alike (an altered copy of a source: the offsets of the two agree).
void replace_text(paper_source& source, std::size_t at, std::size_t length, const std::string& to);

}  // namespace simpson::verify

#pragma once
// The paper's LaTeX source as an input: the embedded copy of the GSI 2023 text, or another version
// given by --paper (a revised preprint, a corrected copy). Displays are found by their \label, or,
// when unlabelled, by a stable anchor in the prose just before them. Comment lines (%, including
// the older Φ₃ the source keeps in comments) are not part of the text.

#include <cstddef>
#include <optional>
#include <string>
#include <utility>

namespace simpson::verify {

struct paper_source {
  std::string origin;  // "embedded" or the file's path
  std::string text;    // with comments blanked out (line numbers kept)
  std::string sha256;  // of the source's bytes as read (report.json's environment)
  std::string raw;     // the source as read, comments included (the earlier text kept in them)
};

/// One display of the paper: where it was found and its TeX, from after its \label to its end.
struct tex_display {
  std::string locator;  // "label Phi3" or "anchor 'can be factorized'"
  int line = 0;         // 1-based line of the display's first math line
  std::string tex;      // the math, on one line, comments removed
};

/// The embedded copy (verify/paper/text/simpson-symplectic-gsi2023.tex, compiled in).
paper_source embedded_paper();

/// A paper read from a file. Throws std::invalid_argument naming the file when it is missing,
/// unreadable, or not this paper (it must carry the title and the \label of Φ₃).
paper_source load_paper(const std::string& path);

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

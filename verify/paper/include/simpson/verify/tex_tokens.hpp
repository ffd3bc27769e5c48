#pragma once
// TeX's tokens, as TeX's eyes make them (The TeXbook, chapters 7 and 8): LaTeX's category codes, a
// control word swallowing the spaces after it, a comment running to the end of its line, a blank
// line a \par. Every later stage of the reader (macro expansion, the math tree, the document's
// displays) works on these, so that an argument is grabbed as TeX grabs it (\frac12) and a macro
// expands as TeX expands it.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace simpson::verify {

/// TeX's category codes as LaTeX sets them (escape, begin group, end group, math shift, alignment
/// tab, end of line, parameter, superscript, subscript, ignored, space, letter, other, active,
/// comment, invalid), folded into what the reader needs. `@` is a letter only between
/// \makeatletter and \makeatother.
enum class tex_category {
  control,       // \omega, \, (a control word or a control symbol)
  begin_group,   // {
  end_group,     // }
  math_shift,    // $
  alignment,     // &
  parameter,     // #
  superscript,   // ^
  subscript,     // _
  letter,        // a-z A-Z
  other,         // digits, punctuation, a UTF-8 character
  active,        // ~
  space,         // a run of blanks and one end of line
  paragraph,     // a blank line: TeX's \par
};

struct tex_token {
  tex_category category = tex_category::other;
  std::string text;          // "\\omega", "{", "x", "7", " "
  std::size_t offset = 0;    // in the source: where it starts, or where the macro call that made it starts
  std::size_t length = 0;    // in the source; 0 for a token a macro's body made
  std::string macro{};       // the macro whose expansion made it, outermost; empty for the source's own
  std::string trailing{};    // the blanks TeX skipped after a control word (kept for the text shown)

  bool is(tex_category c, const std::string& t) const { return category == c && text == t; }
  bool is_control(const std::string& t) const { return category == tex_category::control && text == t; }
  bool is_char(char c) const { return category != tex_category::control && text.size() == 1 && text[0] == c; }
};

/// What the reader could not read: a construct it refuses, where, and a spelling that works when
/// there is one. Bad input (exit 2), never a harness fault.
class tex_error : public std::invalid_argument {
 public:
  tex_error(const std::string& why, std::size_t offset, std::string construct = {}, std::string hint = {})
      : std::invalid_argument(why), offset_(offset), construct_(std::move(construct)), hint_(std::move(hint)) {}
  std::size_t offset() const noexcept { return offset_; }
  const std::string& construct() const noexcept { return construct_; }
  const std::string& hint() const noexcept { return hint_; }

 private:
  std::size_t offset_;
  std::string construct_;
  std::string hint_;
};

/// The tokens of `text`, whose first byte is at `base` in its source. Comments are dropped; a run of
/// blanks (with at most one end of line) is one space token; a blank line is a paragraph token.
/// Between \makeatletter and \makeatother `@` is a letter.
std::vector<tex_token> tex_tokenize(const std::string& text, std::size_t base = 0);

/// The tokens as text again: each token's text and the blanks it swallowed, a space token as one
/// blank. What the reports show of a formula.
std::string tex_text(const std::vector<tex_token>& tokens);
std::string tex_text(std::vector<tex_token>::const_iterator from, std::vector<tex_token>::const_iterator to);

}  // namespace simpson::verify

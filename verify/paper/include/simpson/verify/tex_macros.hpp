#pragma once
// The macros a LaTeX source defines, and their expansion as TeX expands them (The TeXbook, chapter
// 20): \newcommand, \renewcommand, \providecommand (an argument count, and an optional first
// argument with its default), \def, \gdef and \edef (a parameter text with delimiters included),
// \let, and amsmath's \DeclareMathOperator. An undelimited argument is the next token that is not a
// space, or a braced group without its braces; a delimited one runs to its delimiter. A macro's
// body is put in with its arguments' tokens as they are, as TeX does: \newcommand{\sq}[1]{#1^2}
// makes \sq{a+b} a + b^2.

#include <simpson/verify/tex_tokens.hpp>

#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace simpson::verify {

struct tex_macro {
  std::string name;  // with its backslash: "\\om"
  int arguments = 0;  // #1 ... #9
  /// \newcommand's optional first argument: its default, when the definition gives one.
  std::optional<std::vector<tex_token>> default_first{};
  /// \def's parameter text: the tokens between the name and the body, #n included (delimiters
  /// between them); empty for \newcommand.
  std::vector<tex_token> parameter_text{};
  std::vector<tex_token> body{};
  int line = 0;       // where it is defined
  std::size_t offset = 0;      // its definition's span in the source: [offset, end)
  std::size_t end = 0;
  std::string command{};       // "\\newcommand", "\\def", "\\DeclareMathOperator", ...
};

class tex_macros {
 public:
  const tex_macro* find(const std::string& name) const;
  void define(tex_macro macro) { macros_[macro.name] = std::move(macro); }
  bool empty() const { return macros_.empty(); }
  const std::map<std::string, tex_macro>& all() const { return macros_; }

 private:
  std::map<std::string, tex_macro> macros_;
};

/// Whether `name` ("\\newcommand", "\\def", ...) starts a definition the reader reads.
bool is_definition_command(const std::string& name);

/// Reads the definition that starts at tokens[at] (\newcommand ...), into `macros`; returns the
/// index just after it. Throws tex_error naming the line's offset when it does not read (no name,
/// no body, an argument count that is not 1 to 9).
std::size_t read_definition(const std::vector<tex_token>& tokens, std::size_t at, tex_macros& macros);
std::size_t read_definition(const std::deque<tex_token>& tokens, std::size_t at, tex_macros& macros);

/// Expands the macro call at tokens[at] in place (its arguments read from the tokens after it);
/// the body's own tokens take the call's offset and the macro's name. Throws tex_error when an
/// argument is missing or a delimited parameter text does not match ("Use of \x doesn't match its
/// definition", as TeX says).
void expand_at(std::vector<tex_token>& tokens, std::size_t at, const tex_macro& macro);
void expand_at(std::deque<tex_token>& tokens, std::size_t at, const tex_macro& macro);

/// Every macro of `macros` in `tokens` expanded, again until none is left; at most `limit`
/// expansions (a macro that uses itself never ends: tex_error).
std::vector<tex_token> expand_all(std::vector<tex_token> tokens, const tex_macros& macros, int limit = 2000);

/// The macros `text` defines, in order (a later definition replaces an earlier one), read by
/// scanning its tokens for definitions; throws tex_error.
tex_macros defined_macros(const std::string& text);

}  // namespace simpson::verify

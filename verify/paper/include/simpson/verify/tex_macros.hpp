#pragma once
// The macros a LaTeX source defines (\newcommand, \renewcommand, \providecommand, \def), and their
// expansion in the math a claim reads: a note that writes \newcommand{\om}{\omega} or
// \newcommand{\half}[1]{\frac{#1}{2}} is read as TeX would read it.

#include <map>
#include <stdexcept>
#include <string>

namespace simpson::verify {

struct tex_macro {
  int arguments = 0;  // #1 ... #9
  std::string body;
  int line = 0;       // where it is defined
  /// A \def whose parameter text has delimiters (\def\section*#1{}): read, so that the source
  /// reads, but never expanded: a formula that uses it does not read.
  bool delimited = false;
};

/// The macros `text` defines, by name with its backslash ("\\om"); a later definition replaces an
/// earlier one, as \renewcommand does. A definition that does not read (no body, an argument count
/// that is not 1 to 9) throws std::invalid_argument naming its line.
std::map<std::string, tex_macro> defined_macros(const std::string& text);

/// `tex` with every use of a macro of `macros` replaced by its body, the arguments (a braced group
/// or one token each) put in for #1 ... #9, again until none is left. Throws std::invalid_argument
/// naming the macro when an argument is missing or the expansion does not end (a macro that uses
/// itself).
std::string expand_macros(const std::string& tex, const std::map<std::string, tex_macro>& macros);

}  // namespace simpson::verify

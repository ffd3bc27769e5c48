#pragma once
// What a claims file declares of its document's names ([symbols]), read into the reader's names:
// the value the engine passes with every claim it runs, so that a formula means the same wherever
// it is read (tex_math.hpp says what declarations decide).

#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/tex_math.hpp>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace simpson::verify {

struct claim_declarations {
  claims_symbols written;           // as the file writes them (TeX)
  tex_declarations reading;         // the reader's functions and symbols
  std::set<std::string> positive;   // the reader's names of the symbols declared positive
  std::set<std::string> real;       // ... declared real
  /// The reader's names of the functions that name the exact solution ([symbols] solutions, applied
  /// like the functions): x(t_n), x(t_n + k h) and x(t_{n+k}) are its values at the nodes, the
  /// states x_{n+k} of a scheme put on it (truncation, consistency).
  std::set<std::string> solutions;
  /// A file with a [document]: every symbol a formula it reads uses must be declared (a symbol the
  /// file does not name is a misreading, or a name it forgot).
  bool complete = false;
};

/// The declarations of a claims file's contents. Throws claims_file_error naming the field when a
/// name is not one name, or is one the reader keeps (O, \pi).
claim_declarations read_declarations(const claims_file_contents& contents, const std::string& file);

/// The reader's name of a TeX name ('q_{j+1}' is "q_j+1", '\omega' "omega"); throws
/// std::invalid_argument when it is not one name.
std::string reader_name(const std::string& tex);

/// A function's declaration: its reader's name, and its variables when the file writes them
/// ('L(q, \dot q)': "L", {"q", "dq/dt"}; 'V': "V", none). Throws std::invalid_argument when it is
/// neither one name nor one name applied to distinct names.
struct function_declaration {
  std::string name;
  std::optional<std::vector<std::string>> variables;
};
function_declaration read_function_declaration(const std::string& tex);

}  // namespace simpson::verify

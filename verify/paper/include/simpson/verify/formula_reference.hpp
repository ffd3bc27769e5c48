#pragma once
// A formula a claims-file record names, read from the document's LaTeX: by the \label of its
// display, which equation of the display, which side; or by the inline formula at a phrase of the
// prose, or the first display after one; or a TeX fragment of the record itself (for a constant such as 1, or an expression of the
// declared symbols). The document's own macros are expanded first.
//
//   "phi"             the last side of the first equation of the display labelled phi
//   "phi#2"           ... of its second equation
//   "phi:lhs"         the first side (phi#2:lhs for the second equation); "phi:side2" the second
//   "inline:stable for"  the inline formula $...$ at (or first after) the phrase "stable for"
//   "after:can be factorized"  the first display after the phrase (for an unlabelled display);
//                     "after:can be factorized#2" its second equation
//   "$\omega h$"      the TeX fragment itself

#include <simpson/verify/paper_source.hpp>
#include <simpson/verify/tex_document.hpp>
#include <simpson/verify/tex_math.hpp>

#include <ginac/ginac.h>

#include <map>
#include <stdexcept>
#include <optional>
#include <string>
#include <vector>

namespace simpson::verify {

struct formula_reference {
  enum class kind { labelled, inline_formula, display_after, literal };
  kind where = kind::labelled;
  std::string key;   // the label, the phrase, or the TeX
  int equation = 1;  // 1-based, of display_equations()
  int side = 0;      // 1-based; 0: the last
};

/// Reads the text of a reference; throws std::invalid_argument saying what is wrong with it.
formula_reference parse_reference(const std::string& text);

/// The document's TeX does not read (a construct refused, a group never closed): bad input that
/// names the document and its line, never a claims file's record.
class document_error : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// One formula read: where, its TeX (the equation), its sides' TeX and trees, and the side the
/// reference names read (a GiNaC matrix for a matrix).
struct referenced_formula {
  std::string locator;  // "label phi (line 12)", "inline formula at 'stable for' (line 30)", "the record's TeX"
  std::string place;    // the same without its line: "label phi"
  std::string origin;   // the document's ("note.tex", "embedded"); empty for the record's own TeX
  const tex_document* document = nullptr;  // where it was read (its lines name a fault); null for the record's own TeX
  int line = 0;
  std::string tex;
  std::vector<std::string> sides;      // each side's TeX
  std::vector<std::string> relations;  // between them: "=", "<", "\\leq"
  std::vector<tex_list> side_trees;
  std::size_t side = 0;  // which of the sides `value` is (its tree: side_trees[side])
  GiNaC::ex value;
  /// Which printed formula this is, whatever the reference's spelling: its place, equation and side
  /// ("label eq:PhiS#1:side2"); what a proved correction of it names.
  std::string identity;
};

/// A printed formula's proved correction: the value that should stand where `identity` is printed
/// (an erratum's derived formula), and how the reports name it ("(eq:PhiS)").
struct corrected_formula {
  std::string identity;
  std::string shown;
  GiNaC::ex value;
};

/// Reads `reference` from `document` into paper_symbols(), `declared` deciding what TeX leaves
/// open. Throws std::invalid_argument with one line saying what is missing or does not read, and
/// where.
referenced_formula read_reference(const tex_document& document, const tex_declarations& declared, const std::string& reference);

/// Side `k` of `f` read (its tree); throws document_error naming the document, the formula's place
/// and line (std::invalid_argument for the record's own TeX).
GiNaC::ex read_side(const referenced_formula& f, std::size_t k, const tex_declarations& declared);

/// Every symbol in `e`, by name.
std::vector<std::string> symbol_names(const GiNaC::ex& e);

/// A definition read from a display "x = ...", "V(q) = ..." or "L(q, \dot q) = ...": its first side,
/// a symbol or a function of distinct symbols, and its value, the last side (a chain "g = dq/dt(0) = ..." defines g by its last
/// side; that the sides between are equal is another claim's).
struct definition {
  GiNaC::symbol name;  // the symbol, or the function's name as a symbol
  GiNaC::ex value;
  std::string locator;
  int line = 0;     // where it was read
  std::string tex;  // as printed
  std::string function{};               // a function's name ("V"): V(x) is value at parameter = x, and V' its derivative
  std::optional<GiNaC::symbol> parameter{};
  /// A function of several variables (L(q, \dot q) = ..., or L = ... with L's variables declared):
  /// its parameters, slot by slot; `parameter` is then empty.
  std::vector<GiNaC::symbol> parameters{};
};
definition read_definition(const tex_document& document, const tex_declarations& declared, const std::string& reference);

/// `e` with the definitions put in (a function's at each of its applications and derivatives, V'(x)
/// as the derivative of V's value, a derivative written without an argument, dq/dt with q(t)
/// defined, as the derivative of its value in its argument, and a partial derivative of a defined
/// symbol, dg/dx with g = ..., as that of its value), again until none of their symbols or
/// functions is left (a definition may use another), and its matrices evaluated (a product of two in
/// the one order whose sizes agree). A function defined in another variable than its argument, q(t)
/// = ... θ, is read in its argument when a definition gives that argument linearly in one symbol
/// of the value (t = h θ: θ = t/h put in).
/// Throws std::invalid_argument when they never end (a definition that uses itself), or a product
/// of matrices has no order or none that fits.
GiNaC::ex with_definitions(const GiNaC::ex& e, const std::vector<definition>& definitions);

}  // namespace simpson::verify

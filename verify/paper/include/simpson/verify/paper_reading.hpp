#pragma once
// A document read: its TeX, once, and the formulas a book names (printed sides), each with where it
// was found, its TeX and the parsed expression. The book's table names them (a list of
// formula_location); a label or anchor that is missing, or a formula the reader cannot parse, is an
// error naming the label, the line and the token.

#include <simpson/verify/paper_source.hpp>
#include <simpson/verify/tex_document.hpp>
#include <simpson/verify/tex_math.hpp>

#include <ginac/ginac.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace simpson::verify {

struct printed_formula {
  std::string name;    // the paper's label (with "#k" for its k-th equation), or a name for an unlabelled one
  tex_display source;  // where it was read (the whole display)
  std::string tex;     // the equation read, when the display holds several
  std::string lhs;     // the TeX of the first side ("p_r", "{\Phi}_3")
  std::vector<GiNaC::ex> sides;  // the sides parsed, in the order of formula_location::sides
  GiNaC::ex value;     // the last of them (a GiNaC matrix for Φ₃)
};

/// Where a formula is, in the paper: a \label, or an anchor (in the prose before an unlabelled
/// display, or in an inline formula); which equation of the display; which of its sides to parse.
struct formula_location {
  enum class kind { labelled, anchored_display, inline_formula };
  std::string name;
  kind where = kind::labelled;
  std::string key;               // the label or the anchor
  int equation = 0;              // of display_equations(), 0-based
  std::vector<int> sides{-1};    // indices of relation_sides(); negative counts from the end
};

struct paper_reading {
  std::string origin;  // the file read, or "embedded"
  std::string sha256;  // of the source's bytes
  paper_source source; // the text read (the prose claims quote their sentences from it)
  std::shared_ptr<const tex_document> document;  // the source read as TeX, once
  std::map<std::string, printed_formula> formulas;
  const printed_formula& at(const std::string& name) const;
};

/// A document read as TeX, no formula named (its claims read their formulas themselves). Throws
/// std::invalid_argument naming the document's line when its TeX does not read.
paper_reading read_note(const paper_source& source);

/// Reads the document and every formula of `formulas` from it, in paper_symbols(), `declared` (its
/// claims file's [symbols]) deciding what TeX leaves open. Throws std::invalid_argument with one
/// line naming the document, the label (or anchor), the line and the construct when one is missing
/// or does not read.
paper_reading read_paper(const paper_source& paper, const tex_declarations& declared, const std::vector<formula_location>& formulas);

}  // namespace simpson::verify

#pragma once
// The formulas the ledger reads from the paper (printed sides), each with where it was found, its
// TeX and the parsed expression. One table names them; a label or anchor that is missing, or a
// formula the reader cannot parse, is an error naming the label, the line and the token.

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

/// The formulas the ledger reads, in the order of the paper.
const std::vector<formula_location>& printed_formula_locations();

struct paper_reading {
  std::string origin;  // "embedded" or the file read
  std::string sha256;  // of the source's bytes
  paper_source source; // the text read (the prose claims quote their sentences from it)
  std::shared_ptr<const tex_document> document;  // the source read as TeX, once
  std::map<std::string, printed_formula> formulas;
  const printed_formula& at(const std::string& name) const;
};

/// A document other than the paper, read as TeX (its claims read their formulas themselves): no
/// formula of printed_formula_locations(). Throws std::invalid_argument naming the document's line
/// when its TeX does not read.
paper_reading read_note(const paper_source& source);

/// Reads every formula of printed_formula_locations() from the paper, in paper_symbols(), `declared`
/// (the paper's claims file's [symbols]) deciding what TeX leaves open. Throws
/// std::invalid_argument with one line naming the paper, the label (or anchor), the line and the
/// construct when one is missing or does not read.
paper_reading read_paper(const paper_source& paper, const tex_declarations& declared);

}  // namespace simpson::verify

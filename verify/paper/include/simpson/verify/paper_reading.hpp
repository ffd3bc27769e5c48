#pragma once
// The formulas the ledger reads from the paper (printed sides), each with where it was found, its
// TeX and the parsed expression. One table names them; a label or anchor that is missing, or a
// formula the reader cannot parse, is an error naming the label, the line and the token.

#include <simpson/verify/paper_source.hpp>
#include <simpson/verify/tex_math.hpp>

#include <ginac/ginac.h>

#include <map>
#include <string>
#include <vector>

namespace simpson::verify {

struct printed_formula {
  std::string name;    // the paper's label, or the name given to an unlabelled display
  tex_display source;  // where it was read
  std::string lhs;     // the TeX of the defined side ("p_r", "{\Phi}_3")
  std::string rhs;     // the TeX parsed
  GiNaC::ex value;     // the parsed right side (a GiNaC matrix for Φ₃)
};

/// Where a formula is, in the paper: a \label, or an anchor in the prose before an unlabelled display.
struct formula_location {
  std::string name;
  std::string label;   // empty when anchored
  std::string anchor;
};

/// The formulas the ledger reads, in the order of the paper.
const std::vector<formula_location>& ledger_formulas();

struct paper_reading {
  std::string origin;  // "embedded" or the file read
  tex_symbols symbols; // m, omega, h, q_l, q_r, p, q: shared with the derived formulas
  std::map<std::string, printed_formula> formulas;
  const printed_formula& at(const std::string& name) const;
};

/// Reads every formula of ledger_formulas() from the paper. Throws std::invalid_argument with one
/// line naming the paper, the label (or anchor), the line and the token when one is missing or
/// does not parse.
paper_reading read_paper(const paper_source& paper);

}  // namespace simpson::verify

#pragma once
// The paper the book checks: its LaTeX source compiled in (verify/ledger/text/), a copy of it given
// by --paper (a revised preprint, a corrected copy) checked to be this paper, and the formulas the
// book's bespoke checks read from it (check_registry.hpp's add_printed).

#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/paper_source.hpp>

#include <string>
#include <vector>

namespace simpson::verify {

/// The embedded copy (verify/ledger/text/simpson-symplectic-gsi2023.tex, compiled in).
paper_source embedded_paper();

/// A copy of the paper read from a file. Throws std::invalid_argument naming the file when it is
/// missing, unreadable, or not this paper: it must carry the title and the \label of Φ₃, and a copy
/// cut short is named as truncated.
paper_source load_paper(const std::string& path);

/// The formulas the bespoke checks read, in the order of the paper.
const std::vector<formula_location>& printed_formula_locations();

}  // namespace simpson::verify

#pragma once
// Table 1's experiment under the stated conventions, in exact arithmetic, enclosed: the schemes'
// maps and the exact solution in interval arithmetic (MPFI, π enclosed), so that each error is an
// interval holding the error of the exact scheme. The order column is decided from the enclosures:
// an integer when both log₂ ratios of successive errors are proved within ½ of it, "exact" when
// every error's enclosure holds 0 (the quantity is conserved by the exact scheme), else undecided.
// Header free of MPFI: enclosures leave as text (enclosure_text: only guaranteed digits).

#include <array>
#include <string>

namespace simpson::verify {

struct enclosed_table_row {
  std::array<std::string, 3> values;  // N = 10, 20, 40: "1.4427e-14 ± 3e-31", or "0 ± 2e-50"
  std::string order;                  // "2", "4", "exact", or "undecided (…)"
  std::string order_evidence;         // the log₂ ratios' enclosures, or why exact
};

/// The rows of published_rows() (paper_table.hpp), in order, computed in `digits` decimal digits;
/// each value printed with at most `shown_digits` digits (its radius widened by that rounding).
std::array<enclosed_table_row, 8> enclosed_table1(unsigned digits = 40, long shown_digits = 60);

}  // namespace simpson::verify

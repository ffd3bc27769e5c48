#pragma once
// Table 1 as a copy of the paper prints it, row by row in the order of the experiments'
// published_rows() (Newmark and Simpson for momentum, state, energy (HH-exact), energy
// (hamiltonien-discret)): the three values of each row ("$ 1.91 \,\, 10^{0} $"), their significant
// digits, and the order cell ("2", "4" or "exact"). Each row is quoted as a sentence
// (quoted_sentence.hpp), so a row that is gone or a cell that does not parse throws text_changed.

#include <simpson/verify/json.hpp>
#include <simpson/verify/paper_source.hpp>

#include <array>
#include <string>

namespace simpson::verify {

struct printed_table1 {
  std::array<std::array<double, 3>, 8> values{};
  std::array<std::array<int, 3>, 8> digits{};  // significant digits of each value as printed
  std::array<std::string, 8> orders;
};

/// The table of `paper`, each row recorded in `quotes` when given. Throws text_changed when a row is
/// gone or its cells do not parse.
printed_table1 read_table1(const paper_source& paper, json* quotes = nullptr);

}  // namespace simpson::verify

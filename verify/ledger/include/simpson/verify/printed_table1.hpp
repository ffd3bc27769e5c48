#pragma once
// Table 1 as printed in a copy of the paper, row by row (the rows of published_rows()): the values
// and the order column the ledger's Table 1 claims judge, for the table1 section too.

#include <simpson/verify/paper_reading.hpp>

#include <array>
#include <string>

namespace simpson::verify {

struct printed_table1 {
  std::array<std::array<double, 3>, 8> values{};
  std::array<std::array<int, 3>, 8> digits{};  // significant digits of each value as printed
  std::array<std::string, 8> orders;
};

/// Throws text_changed (quoted_words.hpp) when a row is gone or its cells do not parse.
printed_table1 read_table1(const paper_reading& paper);

}  // namespace simpson::verify

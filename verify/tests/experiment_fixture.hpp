#pragma once
// What the experiment tests share: the embedded paper's Table 1 as read, and a section's tables and
// figures found by key (experiments_test.cpp, table1_search_test.cpp, nonlinear_experiments_test.cpp).

#include <simpson/verify/table1_reader.hpp>
#include <simpson/verify/the_paper.hpp>
#include <simpson/verify/experiments.hpp>

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace simpson::verify::test {

/// Table 1 as the embedded paper prints it, read by the paper layer (the run reads it so).
inline const printed_table1& embedded_table1() {
  static const printed_table1 table = read_table1(embedded_paper());
  return table;
}

inline table1_settings with_embedded_table1() {
  table1_settings s;
  s.printed_values = embedded_table1().values;
  s.printed_orders = embedded_table1().orders;
  s.printed_digits = embedded_table1().digits;
  return s;
}

/// The figure of `key` in a table row, by the column's key.
inline const figure& cell(const table& t, std::size_t row, const std::string& key) {
  for (std::size_t k = 0; k < t.columns.size(); ++k) {
    if (t.columns[k].key == key) return t.rows.at(row).at(k);
  }
  throw std::out_of_range("no column " + key);
}

inline double number(const figure& f) {
  EXPECT_EQ(f.what(), figure::kind::number) << f.value();
  return std::stod(f.value());
}

inline const table& get(const section_result& s, const std::string& key) {
  const table* t = s.find_table(key);
  if (!t) throw std::out_of_range("no table " + key);
  return *t;
}

}  // namespace simpson::verify::test

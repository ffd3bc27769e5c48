#include <simpson/verify/result_model.hpp>

#include <fmt/format.h>

#include <stdexcept>

namespace simpson::verify {

void table::add(table_row row) {
  if (row.size() != columns.size()) {
    throw std::logic_error(fmt::format("table '{}': a row of {} cells for {} columns", key, row.size(), columns.size()));
  }
  rows.push_back(std::move(row));
}

const table* section_result::find_table(const std::string& key) const {
  for (const section_block& b : blocks) {
    if (const table* t = std::get_if<table>(&b); t && t->key == key) return t;
  }
  return nullptr;
}

}  // namespace simpson::verify

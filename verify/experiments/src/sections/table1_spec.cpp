// The table1 section as a registry entry (experiment_section.hpp).

#include <simpson/verify/table1_section.hpp>

#include <fmt/format.h>

namespace simpson::verify {

table1_section::table1_section() : typed_section("table1", "the paper's experiment (Section 8, Table 1 and Figure 1): errors against N beside the printed values") {}

std::set<std::string> table1_section::keys() const { return {"N", "figure_N", "m"}; }

table1_settings table1_section::read(const section_reader& r, const std::vector<precision>&) const {
  table1_settings t;
  if (r.has("N")) t.meshes = r.integers("N", 1, 1'000'000);
  if (r.has("figure_N")) t.figure_meshes = r.integer("figure_N", 1, 100'000);
  if (r.has("m")) t.m = r.number("m", 0, 1e300);
  return t;
}

table1_settings table1_section::initial(const std::vector<precision>&) const { return {}; }

section_cost table1_section::estimate(const table1_settings& s) const {
  double steps = 0;
  for (const long long N : s.meshes) steps += 2.0 * static_cast<double>(N);
  return {steps, fmt::format("table1: {:.3g} steps in double", steps)};
}

section_result table1_section::compute(const table1_settings& s, const section_inputs& inputs) const {
  table1_settings settings = s;
  settings.memo = inputs.memo;
  return run_table1(settings);
}

}  // namespace simpson::verify

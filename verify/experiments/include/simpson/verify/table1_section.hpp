#pragma once
// The table1 section: the paper's experiment (Section 8) for any list of N, beside Table 1's
// published values, with estimated orders and Figure 1 redrawn.

#include <simpson/verify/experiment_section.hpp>
#include <simpson/verify/table1_conventions.hpp>
#include <simpson/verify/result_model.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace simpson::verify {

struct table1_settings {
  std::vector<long long> meshes{10, 20, 40};  // N, one period each
  long long figure_meshes = 15;               // N of Figure 1
  double m = 1;
  /// Table 1 as read from the run's paper (values and order column, in published_rows() order);
  /// unset when the paper's table cannot be read: the experiment then runs beside no printed value,
  /// and no convention search is made.
  std::optional<std::array<std::array<double, 3>, 8>> printed_values;
  std::optional<std::array<std::string, 8>> printed_orders;
  std::optional<std::array<std::array<int, 3>, 8>> printed_digits;
  /// The solution the paper states for the experiment, where the convention search starts.
  table1_stated stated;
  /// The run's memo: the convention search is made once per run, here or by a claim (run_memo.hpp).
  run_memo* memo = nullptr;
};

section_result run_table1(const table1_settings& s);

/// The table1 section as a registry entry (experiment_section.hpp). It runs beside no printed value:
/// the book's entry reads Table 1 from the run's paper first (it derives from this one).
class table1_section : public typed_section<table1_settings> {
 public:
  table1_section();
  std::set<std::string> keys() const override;

 protected:
  table1_settings read(const section_reader& r, const std::vector<precision>& floating) const override;
  table1_settings initial(const std::vector<precision>& floating) const override;
  section_cost estimate(const table1_settings& s) const override;
  section_result compute(const table1_settings& s, const section_inputs& inputs) const override;
};

/// Whether a row's least-squares order in double (none: every point at the round-off floor) agrees
/// with the order its exact scheme's enclosures prove ("2", "4", "exact"): within ½ of the integer,
/// the margin that proves it, or both exact. None when `proved` decides no order (undecided).
std::optional<bool> order_agrees(const std::string& proved, std::optional<double> least_squares);

}  // namespace simpson::verify

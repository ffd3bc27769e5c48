#pragma once
// Table 1 as a parametrised experiment for the convention search: every convention Section 8
// states or leaves implicit is a parameter (the steps, the points the maximum runs over, how the
// momentum and the errors are measured, the energy error; m, the amplitude and the phase of the
// exact solution). Under the stated ones it is run_table_experiment.

#include <simpson/verify/convention_search.hpp>
#include <simpson/verify/paper_table.hpp>
#include <simpson/verify/table1_enclosed.hpp>
#include <simpson/verify/run_memo.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace simpson::verify {

/// One run of a scheme under the conventions: its errors, the H_0 they are measured against (1 for
/// relative energies) and the number of steps.
struct table1_run_errors {
  table_errors errors{0, 0, 0, 0};
  double H0 = 0;
  long long steps = 0;
};
/// The runs from the two basis states (m omega, 0) and (0, 1) of a scheme, mesh and steps, which any
/// start combines: a search makes tens of thousands of runs of a few such keys, and keeps them here,
/// a value it owns for its duration (no run shares another's).
class table1_basis_cache;

table1_run_errors table1_run(bool simpson_scheme, long long N, const convention_choice& choice, const parameter_values& values,
                             table1_basis_cache* cache = nullptr);

/// The stated conventions (the `stated` option of each of table1_discrete_conventions()).
convention_choice table1_stated_conventions();

/// Table 1's entries in the order of published_rows() and published_meshes, from the values and the
/// order column as printed ("exact" rows are round-off entries), with the significant digits each
/// was printed with (three for each when not given).
std::vector<printed_entry> table1_printed(const std::array<std::array<double, 3>, 8>& values, const std::array<std::string, 8>& orders,
                                          const std::array<std::array<int, 3>, 8>* digits = nullptr);

std::vector<discrete_convention> table1_discrete_conventions();
std::vector<continuous_parameter> table1_continuous_parameters();

/// The simple values tried before any fit: m, the amplitude and the phase of the exact solution.
simple_values table1_simple_values();

/// A simple hypothesis under the stated discrete conventions as an exact start (for its enclosure);
/// none for a fitted candidate or other conventions.
std::optional<exact_start> table1_exact_start(const convention_candidate& c);

/// The start of the experiment that reproduces the table: the search's simplest hypothesis as an
/// exact start, when it keeps the stated discrete conventions; none otherwise.
std::optional<exact_start> table1_reproducing_start(const convention_search_result& r);

/// The discrete conventions of `c` that depart from the stated ones ("energy: relative, ..."), in order.
std::vector<std::string> table1_departures(const convention_candidate& c);

/// A candidate's exact solution in words: "released from rest at q₀ = π/2, p₀ = 0, m = 1 (...)".
std::string table1_start(const convention_candidate& c);

/// The simplest hypothesis of a search in words: the exact solution, the discrete conventions that
/// depart from the stated ones, the count of entries it reproduces, and each miss with its distance
/// past its rounding boundary.
std::string table1_explanation(const convention_search_result& r, const std::vector<printed_entry>& printed);

/// How many of a candidate's entries it reproduces, the informative ones (printed digits that pin a
/// start down) apart from the round-off ones (the rows printed as exact: reproduced under any start).
struct entry_tally {
  std::size_t informative = 0, informative_reproduced = 0, round_off = 0, round_off_reproduced = 0;
};
entry_tally tally_entries(const convention_candidate& c, const std::vector<printed_entry>& printed);

/// "17 of the 18 informative entries (the 6 round-off ones of the rows printed as exact reproduced
/// too)": a candidate's count in those words.
std::string tally_text(const entry_tally& t);

/// Table 1's entries computed under `choice` and `values` (the basis runs kept in `cache` when given).
std::vector<computed_entry> table1_under(const convention_choice& choice, const parameter_values& values, table1_basis_cache* cache = nullptr);

/// The exact solution the text states for the experiment, q(t) = amplitude sin(ω t + phase) with
/// ω = 2π/period (read from the text by the book: table1_reader.hpp, read_stated_solution); m is unstated (1).
struct table1_stated {
  double amplitude = 1, phase = 0, period = 1;
};

/// The search on Table 1 as printed, from the stated solution; with a run's memo, a table searched
/// before in that run from the same stated solution is not searched again.
convention_search_result search_table1(const std::vector<printed_entry>& printed, const table1_stated& stated = {}, run_memo* memo = nullptr);

}  // namespace simpson::verify

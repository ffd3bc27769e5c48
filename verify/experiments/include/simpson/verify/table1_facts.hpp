#pragma once
// What the table1 section publishes about Table 1 as printed (published_fact.hpp), for records to
// observe (claims/paper.toml: `observes = "table1.printed-orders"`, and the rows printed "exact",
// the values): the printed order column against the orders the exact schemes' enclosed errors
// prove, the rows printed "exact" against what the exact schemes conserve, and the printed values
// against the experiment under the stated conventions and the convention search.

#include <simpson/verify/paper_table.hpp>
#include <simpson/verify/published_fact.hpp>
#include <simpson/verify/run_memo.hpp>
#include <simpson/verify/table1_conventions.hpp>

#include <array>
#include <optional>
#include <string>

namespace simpson::verify {

struct table1_facts {
  /// Each row printed with an order: the order the enclosures prove, and the paper's own rule on
  /// the printed line, give it.
  published_fact printed_orders;
  /// Each row printed "exact": every enclosure holds 0 and every printed value is at round-off; and
  /// no row printed with an order is conserved.
  published_fact printed_conservation;
};

/// Table 1's facts from its printed values, their digits and the order column (published_rows()
/// order), the solution the text states (where the convention search starts: the round-off floor
/// of the printed values is that of the orbit that reproduces the table) and the run's memo (the
/// enclosures and the search are made once per run).
table1_facts table1_printed_facts(const printed_table_values& values, const printed_table_orders& orders,
                                  const std::array<std::array<int, 3>, 8>& digits, const table1_stated& stated, run_memo* memo);

/// Table 1's printed values as a fact: each entry reproduced within its printed digits under the
/// stated conventions (the double run's judgment, confirmed by enclosures of the exact schemes; a
/// disagreement throws enclosure_undecided). Found false, its correction is the simplest start that
/// reproduces every entry, or the convention search's fit that does; with neither, it fails.
/// `stated_q`: q(t) as the text states it (GiNaC's text), none when it states none.
published_fact table1_printed_values_fact(const printed_table_values& values, const printed_table_orders& orders,
                                          const std::array<std::array<int, 3>, 8>& digits, const table1_stated& start,
                                          const std::optional<std::string>& stated_q, run_memo* memo);

}  // namespace simpson::verify

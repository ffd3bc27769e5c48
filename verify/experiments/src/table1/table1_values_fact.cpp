// Table 1's printed values as a published fact (table1_facts.hpp): reproduced under the stated
// conventions, or under which start and conventions, found by the convention search and judged
// again by enclosures.

#include <simpson/verify/table1_facts.hpp>

#include <simpson/verify/enclosure_undecided.hpp>
#include <simpson/verify/readable_math.hpp>
#include <simpson/verify/table1_enclosed.hpp>

#include <simpson/scalar_traits.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cctype>
#include <string>
#include <vector>

namespace simpson::verify {
namespace {

/// A candidate of the convention search, entry by entry beside the printed table.
json candidate_json(const convention_candidate& c, const std::vector<printed_entry>& printed) {
  json entries = json::array();
  for (std::size_t k = 0; k < printed.size(); ++k) {
    entries.push_back({{"row", printed[k].row}, {"column", printed[k].column},
                       {"printed", printed[k].round_off ? "round-off" : simpson::to_string(printed[k].value, printed[k].digits)},
                       {"computed", simpson::to_string(c.entries[k].computed, 4)},
                       {"residual", simpson::to_string(c.entries[k].residual, 3)},
                       {"reproduced", c.entries[k].reproduced}});
  }
  json joint = json::object();
  for (const auto& [name, interval] : c.joint_extent) {
    joint[name] = {simpson::to_string(interval.first, 6), simpson::to_string(interval.second, 6)};
  }
  json values = json::object();
  for (const auto& [name, value] : c.values) values[name] = simpson::to_string(value, 5);
  return {{"conventions", c.choice}, {"values", values}, {"reproduced", std::to_string(c.reproduced) + " of " + std::to_string(printed.size())},
          {"worst_residual", simpson::to_string(c.worst, 3)}, {"joint_extent", joint}, {"entries", entries}};
}

}  // namespace

published_fact table1_printed_values_fact(const printed_table_values& published, const printed_table_orders& orders,
                                          const std::array<std::array<int, 3>, 8>& digits, const table1_stated& start,
                                          const std::optional<std::string>& stated_q, run_memo* memo) {
  // The values are decided by the search below (printed digits), not by a ratio tolerance; the
  // orders' evidence (printed-orders) is shown beside them.
  json evidence;
  evidence["numeric"] = table1_printed_facts(published, orders, digits, start, memo).printed_orders.evidence["numeric"];
  evidence["numeric"]["also_tried"] = table_also_tried(published);
  // The convention search: every convention Section 8 states or leaves implicit, enumerated and fitted.
  const std::vector<printed_entry> entries = table1_printed(published, orders, &digits);
  const convention_search_result search = search_table1(entries, start, memo);
  json tried = json::array();
  for (std::size_t k = 0; k < search.tried.size() && k < 12; ++k) {
    tried.push_back({{"conventions", describe(search.tried[k])},
                     {"reproduced", std::to_string(search.tried[k].reproduced) + " of " + std::to_string(entries.size())},
                     {"worst_residual", simpson::to_string(search.tried[k].worst, 3)}});
  }
  evidence["search"] = {{"method", "numeric (double), every entry judged against the half unit of its last printed digit; "
                                   "round-off rows against 64 eps N H_0"},
                        {"family", std::to_string(search.tried.size()) + " combinations of the discrete conventions, m, the amplitude "
                                   "and the phase fitted for each"},
                        {"evaluations", search.evaluations},
                        {"stated", candidate_json(search.stated, entries)},
                        {"best", candidate_json(search.tried.front(), entries)},
                        {"tried_best_first", tried}};
  // The stated conventions judged again by enclosures of the exact schemes' errors: each entry on
  // the same side of its printed digits' interval as in the double run, or the verdict is undecided.
  std::vector<printed_value> printed_values;
  for (const printed_entry& e : entries) printed_values.push_back({e.value, e.digits, e.round_off});
  const std::vector<entry_decision> enclosed = enclosed_stated_entries(printed_values, table1_enclosure_digits, memo);
  std::size_t enclosed_reproduced = 0;
  std::string disagreements;
  for (std::size_t k = 0; k < entries.size() && k < enclosed.size(); ++k) {
    const bool in_double = search.stated.entries[k].reproduced;
    if (enclosed[k] == entry_decision::reproduced) ++enclosed_reproduced;
    if (enclosed[k] == entry_decision::undecided || (enclosed[k] == entry_decision::reproduced) != in_double) {
      disagreements += (disagreements.empty() ? "" : "; ") + entries[k].row + " " + entries[k].column;
    }
  }
  evidence["stated_enclosed"] = {
      {"method", "enclosures (MPFI, " + std::to_string(table1_enclosure_digits) +
                     " digits) of the exact schemes' errors under the stated conventions against the half-unit interval of each "
                     "printed value (the printed decimal, exactly); a round-off entry against 0"},
      {"reproduced", std::to_string(enclosed_reproduced) + " of " + std::to_string(entries.size())},
      {"agrees_with_double", disagreements.empty()}};
  if (enclosed.size() != entries.size() || !disagreements.empty()) {
    throw enclosure_undecided("table-values: under the stated conventions the enclosures and the double run do not decide the same "
                              "entries (" + disagreements + "): a value within round-off of a printed digit's boundary");
  }
  if (search.stated_reproduces()) return {true, evidence, "Table 1 is reproduced under the stated conventions."};
  // The simplest hypothesis first (simple values of m, the amplitude and the phase, before any fit),
  // judged by enclosures too when it keeps the stated discrete conventions.
  const convention_candidate* simplest = search.simplest();
  std::string explanation;
  if (simplest != nullptr) {
    evidence["simplest"] = candidate_json(*simplest, entries);
    evidence["simplest"]["in_words"] = table1_explanation(search, entries);
    if (const std::optional<exact_start> start = table1_reproducing_start(search)) {
      const std::vector<entry_decision> decided = enclosed_entries(printed_values, *start, table1_enclosure_digits, memo);
      std::size_t reproduced = 0;
      std::string differ;
      for (std::size_t k = 0; k < entries.size() && k < decided.size(); ++k) {
        reproduced += decided[k] == entry_decision::reproduced;
        if (decided[k] == entry_decision::undecided || (decided[k] == entry_decision::reproduced) != simplest->entries[k].reproduced) {
          differ += (differ.empty() ? "" : "; ") + entries[k].row + " " + entries[k].column;
        }
      }
      evidence["simplest"]["enclosed"] = {{"method", "enclosures (MPFI, " + std::to_string(table1_enclosure_digits) +
                                                         " digits) of the exact schemes' errors from this start, as for the stated one"},
                                          {"reproduced", std::to_string(reproduced) + " of " + std::to_string(entries.size())},
                                          {"agrees_with_double", differ.empty()}};
      if (!differ.empty()) {
        throw enclosure_undecided("table-values: for the simplest hypothesis the enclosures and the double run do not decide the same entries (" +
                                  differ + ")");
      }
    }
    explanation = table1_explanation(search, entries);
    explanation[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(explanation[0])));
  }
  const std::string stated_count = "Not under the stated conventions, " +
                                   (stated_q ? "q(t) = " + readable_math(*stated_q) : "the search's default q(t) = sin(ωt) (the text states none)") +
                                   " with m = 1 (" + tally_text(tally_entries(search.stated, entries)) + ").";
  // What is wrong is the description of the experiment, not its numbers, when a start under the
  // stated discrete conventions reproduces them: the numbers hold (an erratum only where every
  // reasonable reading fails), with a remark; the description is experiment-conventions' finding.
  const std::string numbers_right = "Right as numbers, not as described: the start Section 8 states does not give them (the finding is "
                                    "experiment-conventions, counted there once), another start does. ";
  const auto fact_with_remark = [&](std::string remark) {
    published_fact fact{true, evidence, stated_count + " " + table_not_reproduced(published, orders)};
    fact.remark = std::move(remark);
    return fact;
  };
  if (simplest != nullptr && simplest->reproduced == entries.size()) {
    return fact_with_remark(numbers_right + "Every entry within its printed digits: " + explanation + ".");
  }
  if (const convention_candidate* found = search.reproducing()) {
    std::vector<std::string> reach;
    for (const auto& [name, extent] : found->joint_extent) reach.push_back(fmt::format("{} from {:.6g} to {:.6g}", name, extent.first, extent.second));
    return fact_with_remark(numbers_right + (simplest != nullptr ? explanation + ". " : "") +
                            "A fit of m, the amplitude and the phase reproduces every entry: " + describe(*found) +
                            " (the values printed with the digits that reproduce them)" +
                            (reach.empty() ? std::string()
                                           : fmt::format("; moved jointly, the others free, the values that reproduce every entry reach {} "
                                                         "(each end attained by a run; the region is at least this wide)",
                                                         fmt::join(reach, ", "))) +
                            ".");
  }
  return {false, evidence,
          "No convention of the searched family reproduces Table 1: the best, " + describe(search.tried.front()) + ", reproduces " +
              std::to_string(search.tried.front().reproduced) + " of " + std::to_string(entries.size()) +
              " entries (worst residual " + simpson::to_string(search.tried.front().worst, 3) +
              " half-units of the last digit). " + table_not_reproduced(published, orders)};
}

}  // namespace simpson::verify

// The experiments' published facts a record may observe: see published_facts.hpp.

#include <simpson/verify/table1_reader.hpp>
#include "published_facts.hpp"

#include "bespoke/bespoke_checks.hpp"
#include "claim_support.hpp"

#include <simpson/verify/fpu_section.hpp>
#include <simpson/verify/inseparable_section.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/nonlinear_section.hpp>
#include <simpson/verify/quoted_words.hpp>
#include <simpson/verify/table1_facts.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <string>
#include <vector>

namespace simpson::verify::detail {
namespace {

/// Table 1's facts, from the table as the run's document prints it (each row quoted into the claim's
/// evidence) and the solution its text states (where the convention search starts).
table1_facts table1_of(const run_context& ctx) {
  const printed_table1 printed = read_table1(paper_of(ctx).source, ctx.quotes);
  return table1_printed_facts(printed.values, printed.orders, printed.digits, stated_table1_solution(ctx), ctx.memo);
}

}  // namespace

const std::map<std::string, fact_publisher>& published_facts() {
  static const std::map<std::string, fact_publisher> facts{
      {"table1.printed-orders",
       {"Each order Table 1 prints is the order the exact scheme's enclosed errors prove, and the order the paper's own rule gives "
        "on the printed line.",
        [](const run_context& ctx) { return table1_of(ctx).printed_orders; },
        {"simpson_map", "newmark_map"}}},
      {"table1.printed-conservation",
       {"Each row Table 1 prints 'exact' is conserved by the exact scheme and printed at round-off; no row printed with an order is "
        "conserved.",
        [](const run_context& ctx) { return table1_of(ctx).printed_conservation; },
        {"simpson_map", "newmark_map"}}},
      {"table1.printed-values",
       {"Table 1's printed values are reproduced, each within its printed digits, by the experiment under the stated conventions; "
        "else the start and conventions that reproduce them.",
        [](const run_context& ctx) {
          const printed_table1 printed = read_table1(paper_of(ctx).source, ctx.quotes);
          const std::optional<stated_solution> stated = stated_table1_words(ctx);
          return table1_printed_values_fact(printed.values, printed.orders, printed.digits, search_start(stated),
                                            stated ? std::optional<std::string>(stated->q_text) : std::nullopt, ctx.memo);
        },
        {"simpson_map", "newmark_map"}}},
      {"fpu.second-band-invariant",
       {"In its second stable band Simpson's scheme keeps its own oscillatory energy I_d within 5% on the stiff FPU chain over "
        "t <= 300, but not the flow's adiabatic invariant I.",
        [](const run_context&) { return fpu_second_band_fact(); },
        {"simpson_lagrangian"}}},
      {"nonlinear.pendulum-order-4",
       {"The Simpson scheme's global order on the pendulum is 4, proved by enclosures of the scheme and of the exact solution.",
        [](const run_context&) { return pendulum_order_fact(); },
        {"simpson_lagrangian"}}},
      {"nonlinear_inseparable.simpson-order",
       {"On the Lagrange top, Simpson's variational step is of order 4 and the implicit midpoint rule's of order 2 in nutation, decided by "
        "enclosed errors against the top's exact motion enclosed with Arb.",
        [](const run_context&) { return inseparable_order_fact(inseparable_fact_settings()); },
        {}}},  // Simpson's step for a general L(q, q-dot): no formula of the core binds it yet
      {"nonlinear_inseparable.top-momenta-exact",
       {"On the Lagrange top, Simpson's and the midpoint rule's steps change the cyclic momenta p_phi and p_psi only within the sum of "
        "their per-step bounds (Newton residual and rounding), at three step sizes.",
        [](const run_context&) { return inseparable_momenta_fact(inseparable_fact_settings()); },
        {}}},
  };
  return facts;
}

}  // namespace simpson::verify::detail

namespace simpson::verify {

std::string published_facts_markdown(const claim_book& book) {
  std::string out = "| fact | what it states | a document's record binds | observed by |\n|---|---|---|---|\n";
  for (const auto& [name, fact] : detail::published_facts()) {
    std::vector<std::string> by;
    for (const claim_record& r : book.records) {
      if (r.observes == name) by.push_back("`" + r.id + "`");
    }
    std::vector<std::string> schemes;
    for (const std::string& scheme : fact.schemes) schemes.push_back("`" + scheme + "`");
    out += fmt::format("| `{}` | {} | {} | {} |\n", name, fact.states,
                       schemes.empty() ? "nothing yet: no document may observe it" : fmt::format("one of {}", fmt::join(schemes, ", ")),
                       by.empty() ? "none" : fmt::format("{}", fmt::join(by, ", ")));
  }
  return out;
}

}  // namespace simpson::verify

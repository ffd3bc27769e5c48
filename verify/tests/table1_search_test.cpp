// Table 1 searched: its side numbers computed, not typed, and the convention search that explains
// a printed table (table1_conventions.hpp): tables made under known conventions are explained by
// them, hidden ones recovered, the paper's explained by its simplest start, and the fit's joint extent.

#include "experiment_fixture.hpp"

#include <simpson/verify/experiments.hpp>
#include <simpson/verify/paper_table.hpp>
#include <simpson/verify/printed_table1.hpp>
#include <simpson/verify/table1_conventions.hpp>
#include <simpson/verify/table1_enclosed.hpp>

#include <boost/math/constants/constants.hpp>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace simpson::verify {
namespace {

using test::embedded_table1;

// Table 1's side numbers are computed, not typed: the two-step start converges at the schemes'
// orders, and the comparison text follows the mass (the momentum rows scale with m, Table 1's do not).
TEST(PaperTable, TwoStepStartConvergesAtTheSchemesOrdersAndTheTextsAreComputed) {
  for (const bool simpson_scheme : {false, true}) {
    const double ratio = run_two_step_experiment(simpson_scheme, 20).p / run_two_step_experiment(simpson_scheme, 40).p;
    EXPECT_NEAR(std::log2(ratio), simpson_scheme ? 4 : 2, 0.1) << simpson_scheme;
  }
  const printed_table1& printed = embedded_table1();
  EXPECT_NE(table_not_reproduced(printed.values, printed.orders, 1), table_not_reproduced(printed.values, printed.orders, 2));
  EXPECT_NE(table_also_tried(printed.values, 1), table_also_tried(printed.values, 2));
  EXPECT_NE(table_also_tried(printed.values, 1).find("0.926, 0.242, 0.0608"), std::string::npos) << table_also_tried(printed.values, 1);
  // The printed values are the paper's as read: a table printed twice as large is compared as such
  // (a transcription typed into the code would not follow it), and a row printed "exact" is left out.
  printed_table_values doubled = printed.values;
  for (auto& row : doubled) {
    for (double& v : row) v *= 2;
  }
  EXPECT_NE(table_also_tried(doubled, 1), table_also_tried(printed.values, 1));
  EXPECT_NE(table_not_reproduced(doubled, printed.orders, 1), table_not_reproduced(printed.values, printed.orders, 1));
  printed_table_orders all_exact;
  all_exact.fill("exact");
  EXPECT_EQ(table_not_reproduced(doubled, all_exact, 1), "Every published entry is reproduced within 5%.");
}

// When the paper's Table 1 cannot be read, the section runs the experiment beside no printed value:
// no column, order or convention search stands in for the paper's.
TEST(PaperTable, WithoutTheTableReadTheSectionShowsNoPrintedValue) {
  const section_result t = run_table1(table1_settings{});
  const table& entries = get(t, "entries");
  ASSERT_EQ(entries.rows.size(), 24u);
  for (std::size_t r = 0; r < entries.rows.size(); ++r) EXPECT_EQ(cell(entries, r, "published").what(), figure::kind::empty) << r;
  EXPECT_EQ(cell(get(t, "orders"), 0, "order_published").value(), "not read");
  bool said = false;
  for (const section_block& block : t.blocks) {
    const prose* p = std::get_if<prose>(&block);
    said = said || (p != nullptr && p->markdown.find("Table 1 could not be read") != std::string::npos);
  }
  EXPECT_TRUE(said);
}

}  // namespace
}  // namespace simpson::verify


namespace simpson::verify {
namespace {

/// Table 1 as the experiment computes it under `choice` and `values`, printed with three digits.
std::vector<printed_entry> synthetic_table1(const convention_choice& choice, const parameter_values& values) {
  const std::vector<computed_entry> computed = table1_under(choice, values);
  std::array<std::array<double, 3>, 8> printed{};
  std::array<std::string, 8> orders;
  for (std::size_t r = 0; r < 8; ++r) {
    orders[r] = embedded_table1().orders[r];
    for (std::size_t k = 0; k < 3; ++k) {
      const double v = computed[3 * r + k].value;
      const double unit = 2 * half_unit_of_last_digit(v, 3);
      printed[r][k] = std::round(v / unit) * unit;
    }
  }
  return table1_printed(printed, orders);
}



TEST(ConventionSearch, ATableMadeUnderTheStatedConventionsHolds) {
  const convention_search_result r = search_table1(synthetic_table1(table1_stated_conventions(), {{"m", 1}, {"amplitude", 1}, {"phase", 0}}));
  EXPECT_TRUE(r.stated_reproduces()) << describe(r.stated);
}

TEST(ConventionSearch, TheStatedEntriesAreJudgedByEnclosuresAsInDoubleAndAMarginTooThinIsUndecided) {
  const std::vector<printed_entry> table = synthetic_table1(table1_stated_conventions(), {{"m", 1}, {"amplitude", 1}, {"phase", 0}});
  std::vector<printed_value> printed;
  for (const printed_entry& e : table) printed.push_back({e.value, e.digits, e.round_off});
  const std::vector<entry_decision> made = enclosed_stated_entries(printed);
  ASSERT_EQ(made.size(), table.size());
  for (std::size_t k = 0; k < made.size(); ++k) EXPECT_EQ(made[k], entry_decision::reproduced) << table[k].row << " " << table[k].column;
  // One entry off by 5%: that entry, and only it, not reproduced.
  std::vector<printed_value> altered = printed;
  altered[1].value *= 1.05;
  const std::vector<entry_decision> judged = enclosed_stated_entries(altered);
  EXPECT_EQ(judged[1], entry_decision::not_reproduced);
  EXPECT_EQ(std::count(judged.begin(), judged.end(), entry_decision::reproduced), static_cast<long>(judged.size()) - 1);
  // A value printed with 17 digits judged in 10-digit intervals: the enclosure is wider than the
  // half unit of the last digit and decides nothing.
  std::vector<printed_value> precise = printed;
  precise[0] = {table1_under(table1_stated_conventions(), {{"m", 1}, {"amplitude", 1}, {"phase", 0}})[0].value, 17, false};
  EXPECT_EQ(enclosed_stated_entries(precise, 10)[0], entry_decision::undecided);
}

// Before any fit, the simple values: a table computed under the stated discrete conventions from
// rest at q₀ = π/4 with m = 2 is explained by exactly those, every entry reproduced, and named so.
TEST(ConventionSearch, ATableMadeWithSimpleValuesIsExplainedByThem) {
  const double pi = boost::math::constants::pi<double>();
  const convention_search_result r = search_table1(synthetic_table1(table1_stated_conventions(), {{"m", 2}, {"amplitude", pi / 4}, {"phase", pi / 2}}));
  const convention_candidate* simplest = r.simplest();
  ASSERT_NE(simplest, nullptr);
  EXPECT_EQ(simplest->reproduced, simplest->entries.size()) << describe(*simplest);
  EXPECT_EQ(simplest->choice, table1_stated_conventions());
  EXPECT_EQ(simplest->value_names.at("m"), "2");
  EXPECT_EQ(simplest->value_names.at("amplitude"), "π/4");
  EXPECT_EQ(simplest->value_names.at("phase"), "π/2");
  EXPECT_EQ(table1_start(*simplest), "released from rest at q₀ = π/4, p₀ = 0, m = 2 (q(t) = π/4 cos ωt)");
  // The stated solution (q = sin ωt, m = 1) is the simplest of all, and does not explain this table.
  EXPECT_FALSE(r.stated_reproduces());
}

// The paper's Table 1: the oscillator released from rest at q₀ = π/2 with m = 1 under the stated
// discrete conventions reproduces 23 of the 24 entries; the 24th, Newmark's p at N = 10, misses its
// printed 1.91 by less than 10⁻⁵ past the rounding boundary 1.915. No simple hypothesis does better.
TEST(ConventionSearch, ThePapersTableIsExplainedByTheOscillatorReleasedFromRest) {
  const printed_table1& printed = embedded_table1();
  const std::vector<printed_entry> entries = table1_printed(printed.values, printed.orders, &printed.digits);
  const convention_search_result r = search_table1(entries);
  const convention_candidate* simplest = r.simplest();
  ASSERT_NE(simplest, nullptr);
  EXPECT_EQ(simplest->reproduced, 23u) << describe(*simplest);
  EXPECT_EQ(simplest->choice, table1_stated_conventions()) << describe(*simplest);
  EXPECT_EQ(table1_start(*simplest), "released from rest at q₀ = π/2, p₀ = 0, m = 1 (q(t) = π/2 cos ωt)");
  for (std::size_t k = 0; k < entries.size(); ++k) {
    if (simplest->entries[k].reproduced) continue;
    EXPECT_EQ(entries[k].row + ", " + entries[k].column, "Newmark momentum, N = 10");
    const entry_miss miss = miss_of(entries[k], simplest->entries[k].computed);
    EXPECT_GT(miss.past, 0);
    EXPECT_LT(miss.past, 1e-5) << simplest->entries[k].computed;
    EXPECT_NEAR(miss.boundary, 1.915, 1e-12);
  }
  EXPECT_EQ(table1_explanation(r, entries),
            "the oscillator released from rest at q₀ = π/2, p₀ = 0, m = 1 (q(t) = π/2 cos ωt), under the stated discrete conventions, "
            "reproduces within their printed digits 17 of the 18 informative entries (the 6 others, of the rows printed as exact, are "
            "at round-off level, as ours are); the one it misses, Newmark momentum at N = 10, computes "
            "1.915007, printed 1.91: 7.1e-06 past its rounding boundary 1.915");
  // The fit's joint region: moved together, the parameters that reproduce all 24 entries reach the
  // simple values π/2 (amplitude), 3π/2 (the phase of a release from rest, the sign flipped) and
  // m = 0.9999, which a one-parameter slice through the fit's optimum (m = 1.0006, A = 1.5695, phase
  // 4.7118) excluded.
  const convention_candidate* fit = r.reproducing();
  ASSERT_NE(fit, nullptr);
  const auto reaches = [&](const std::string& name, double value) {
    const auto& [low, high] = fit->joint_extent.at(name);
    return low <= value && value <= high;
  };
  EXPECT_TRUE(reaches("amplitude", boost::math::constants::half_pi<double>())) << describe(*fit);
  EXPECT_TRUE(reaches("phase", 3 * boost::math::constants::half_pi<double>())) << describe(*fit);
  EXPECT_TRUE(reaches("m", 0.9999)) << describe(*fit);
  parameter_values referee = fit->values;
  referee["m"] = 0.9999;
  referee["amplitude"] = boost::math::constants::half_pi<double>();
  referee["phase"] = 3 * boost::math::constants::half_pi<double>();
  std::size_t reproduced = 0;
  for (const entry_score& s : score_entries(entries, table1_under(fit->choice, referee))) reproduced += s.reproduced;
  EXPECT_EQ(reproduced, entries.size()) << "m = 0.9999, released from rest at π/2: every entry";
}

TEST(ConventionSearch, AHiddenConventionIsRecoveredWithItsParameters) {
  convention_choice hidden = table1_stated_conventions();
  hidden["momentum"] = "p/(m omega)";
  const convention_search_result r = search_table1(synthetic_table1(hidden, {{"m", 2.5}, {"amplitude", 1}, {"phase", 0}}));
  EXPECT_FALSE(r.stated_reproduces());
  const convention_candidate* found = r.reproducing();
  ASSERT_NE(found, nullptr) << describe(r.tried.front());
  // The hidden choice's own fit finds its parameters: under p/(m omega) and absolute errors, the state
  // rows fix the amplitude and the energy rows m A².
  const auto same = std::find_if(r.tried.begin(), r.tried.end(), [&](const convention_candidate& c) { return c.choice == hidden; });
  ASSERT_NE(same, r.tried.end());
  EXPECT_EQ(same->reproduced, same->entries.size()) << describe(*same);
  EXPECT_NEAR(same->values.at("amplitude"), 1, 0.02) << describe(*same);
  EXPECT_NEAR(same->values.at("m"), 2.5, 0.05) << describe(*same);
  // Other choices reproduce the table too (errors relative to the amplitude leave only m A² fixed):
  // the best's joint extent, each parameter moved with the others free, holds its own values, and
  // each end reproduces the table when the others are moved with it (attained, not a slice's bound).
  ASSERT_EQ(found->joint_extent.size(), 3u);
  for (const auto& [name, interval] : found->joint_extent) {
    EXPECT_LE(interval.first, found->values.at(name)) << name;
    EXPECT_GE(interval.second, found->values.at(name)) << name;
  }
}

// The search is global: hidden conventions drawn over the whole family (every discrete choice, m and
// the amplitude log-uniform over [0.1, 10], the phase uniform over [0, 2π)) are all recovered: the
// hidden choice's own fit reproduces its table, and so does the best candidate. The seed is fixed and
// printed. A draw whose "exact" rows are not at round-off under its own conventions (the energy at the
// internal nodes is not conserved) is not a table the paper's order column could describe: drawn again.
TEST(ConventionSearch, RandomHiddenConventionsOverTheWholeFamilyAreAllRecovered) {
#ifdef SIMPSON_SANITIZED
  const int draws = 2;  // the same code, under the sanitizers at -O0 (several seconds a search there)
#else
  const int draws = 20;
#endif
  // The seed is printed on failure; SIMPSON_CONVENTION_SEED draws other conventions.
  const unsigned seed = std::getenv("SIMPSON_CONVENTION_SEED") != nullptr ? static_cast<unsigned>(std::stoul(std::getenv("SIMPSON_CONVENTION_SEED"))) : 20261125;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  const std::vector<discrete_convention> discrete = table1_discrete_conventions();
  int recovered = 0, drawn = 0;
  while (drawn < draws) {
    convention_choice hidden;
    for (const discrete_convention& d : discrete) hidden[d.name] = d.options[random() % d.options.size()];
    const parameter_values values{{"m", std::pow(10.0, 2 * unit(random) - 1)},
                                  {"amplitude", std::pow(10.0, 2 * unit(random) - 1)},
                                  {"phase", 2 * boost::math::constants::pi<double>() * unit(random)}};
    convention_candidate hidden_candidate;
    hidden_candidate.choice = hidden;
    hidden_candidate.values = values;
    const std::vector<printed_entry> table = synthetic_table1(hidden, values);
    const std::vector<entry_score> own = score_entries(table, table1_under(hidden, values));
    if (std::count_if(own.begin(), own.end(), [](const entry_score& e) { return e.reproduced; }) != static_cast<long>(own.size())) continue;
    ++drawn;
    const convention_search_result r = search_table1(table);
    const auto same = std::find_if(r.tried.begin(), r.tried.end(), [&](const convention_candidate& c) { return c.choice == hidden; });
    ASSERT_NE(same, r.tried.end());
    const bool ok = r.reproducing() != nullptr && same->reproduced == table.size();
    recovered += ok;
    std::string missed;
    for (std::size_t k = 0; k < table.size(); ++k) {
      if (!same->entries[k].reproduced) missed += fmt::format("; {}, {}: {:.4g} printed, {:.4g} computed", table[k].row, table[k].column, table[k].value, same->entries[k].computed);
    }
    EXPECT_TRUE(ok) << missed << "\n" << "seed " << seed << ", draw " << drawn << ": hidden " << describe(hidden_candidate) << "; its fit "
                    << describe(*same) << " reproduces " << same->reproduced << " of " << table.size() << "; best "
                    << describe(r.tried.front()) << " reproduces " << r.tried.front().reproduced;
  }
  EXPECT_EQ(recovered, draws) << "seed " << seed;
}

// An "exact" row is judged by its printed values too: printed at 0.17, 0.50, 1.49 instead of at
// round-off, the stated conventions no longer reproduce it, though the computed values are at round-off.
TEST(ConventionSearch, AnExactRowPrintedAboveRoundOffIsNotReproduced) {
  const parameter_values stated{{"m", 1}, {"amplitude", 1}, {"phase", 0}};
  std::vector<printed_entry> table = synthetic_table1(table1_stated_conventions(), stated);
  const std::vector<computed_entry> computed = table1_under(table1_stated_conventions(), stated);
  std::size_t exact_rows = 0;
  for (std::size_t k = 0; k < table.size(); ++k) exact_rows += table[k].round_off;
  ASSERT_EQ(exact_rows, 6u);
  const std::vector<entry_score> before = score_entries(table, computed);
  EXPECT_EQ(std::count_if(before.begin(), before.end(), [](const entry_score& e) { return e.reproduced; }), 24);
  const double altered[] = {0.17, 0.50, 1.49};
  std::size_t row_start = 0;
  while (!table[row_start].round_off) ++row_start;
  for (std::size_t k = 0; k < 3; ++k) table[row_start + k].value = altered[k];
  const std::vector<entry_score> scores = score_entries(table, computed);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_FALSE(scores[row_start + k].reproduced) << table[row_start + k].row;
  EXPECT_EQ(std::count_if(scores.begin(), scores.end(), [](const entry_score& e) { return e.reproduced; }), 21);
}

TEST(ConventionSearch, OneEntryAlteredBeyondItsDigitsIsNamed) {
  std::vector<printed_entry> table = synthetic_table1(table1_stated_conventions(), {{"m", 1}, {"amplitude", 1}, {"phase", 0}});
  table[10].value *= 1.05;  // Symplectic Simpson state, N = 20
  const convention_search_result r = search_table1(table);
  EXPECT_EQ(r.reproducing(), nullptr);
  std::vector<std::string> missed;
  for (std::size_t k = 0; k < table.size(); ++k) {
    if (!r.stated.entries[k].reproduced) missed.push_back(table[k].row + ", " + table[k].column);
  }
  ASSERT_EQ(missed.size(), 1u);
  EXPECT_EQ(missed.front(), "Symplectic Simpson state, N = 20");
}

}  // namespace
}  // namespace simpson::verify

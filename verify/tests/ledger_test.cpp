#include <simpson/verify/ledger.hpp>
#include "embedded_reading.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <set>

namespace simpson::verify {
namespace {

TEST(LedgerShape, IdsAreUniqueKebabCase) {
  std::set<std::string> seen;
  const std::regex kebab("[a-z0-9]+(-[a-z0-9]+)*");
  for (const claim& c : paper_book().claims) {
    EXPECT_TRUE(std::regex_match(c.id, kebab)) << c.id;
    EXPECT_TRUE(seen.insert(c.id).second) << "duplicate id " << c.id;
    EXPECT_FALSE(c.statement.empty()) << c.id;
    EXPECT_FALSE(c.equation.empty()) << c.id;
    EXPECT_FALSE(c.methods.empty()) << c.id;
    EXPECT_TRUE(static_cast<bool>(c.check)) << c.id;
  }
}

TEST(LedgerShape, HasTheRequiredClaimsAndCoversSectionsTwoToNine) {
  for (const std::string& id : required_claim_ids()) EXPECT_NO_THROW(paper_book().find(id)) << id;
  EXPECT_GE(paper_book().claims.size(), 25u);
  for (const char* section : {"2", "3", "4", "5", "6", "7", "8", "9"}) {
    std::size_t n = 0;
    for (const claim& c : paper_book().claims) n += c.section == section;
    EXPECT_GT(n, 0u) << "no claim from Section " << section;
  }
}

TEST(LedgerShape, UnknownIdIsNamed) {
  try {
    paper_book().find("phi4-det");
    ADD_FAILURE() << "found a claim that does not exist";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'phi4-det'"), std::string::npos) << e.what();
  }
}

/// Each claim, in three precisions (a fixed type, a run-time mpfr and exact rationals), must reach
/// its expected verdict; errata carry a correction and every claim some evidence.
class ClaimVerdict : public ::testing::TestWithParam<std::string> {};

TEST_P(ClaimVerdict, IsAsExpected) {
  const claim& c = paper_book().find(GetParam());
  const run_context ctx{{precision::parse("double"), precision::parse("mpfr:40"), precision::parse("rational")}, 7, 3, &embedded_reading()};
  const claim_result r = c.check(ctx);
  EXPECT_EQ(to_string(r.outcome), to_string(c.expected)) << r.evidence.dump(2);
  EXPECT_FALSE(r.evidence.empty());
  if (r.outcome == verdict::erratum) {
    EXPECT_FALSE(r.correction.empty());
  }
}

std::vector<std::string> all_ids() {
  std::vector<std::string> ids;
  for (const claim& c : paper_book().claims) ids.push_back(c.id);
  return ids;
}

INSTANTIATE_TEST_SUITE_P(Ledger, ClaimVerdict, ::testing::ValuesIn(all_ids()), [](const auto& info) {
  std::string name = info.param;
  for (char& ch : name) {
    if (ch == '-') ch = '_';
  }
  return name;
});

}  // namespace
}  // namespace simpson::verify

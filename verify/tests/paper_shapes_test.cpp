// The paper's own claims through proof shapes (verify/tests/notes/simpson-paper-shapes.toml): a
// second, independent route to the ledger's verdicts, on the paper and on altered copies of it.
// The two routes must agree on whether each claim holds, except where they read different things,
// each such case named below with its reason. A claim moves onto its shape when they agree
// everywhere (docs/claims-file.md).

#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/printed_checks.hpp>

#include "altered_paper.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <iterator>
#include <set>
#include <string>
#include <vector>

namespace simpson::verify {
namespace {

std::string shape_records() {
  std::ifstream in(std::string(SIMPSON_SOURCE_DIR) + "/verify/tests/notes/simpson-paper-shapes.toml", std::ios::binary);
  EXPECT_TRUE(in.good());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The verdicts of `ids` on `paper`: the ledger's bespoke checks (first), the shape records (second).
struct both_routes {
  std::map<std::string, verdict> ledger, shapes;
};

class PaperThroughShapes : public ::testing::Test {
 protected:
  void TearDown() override { use_claims_file(embedded_claims_text(), "claims/paper.toml"); }

  both_routes verdicts(const paper_source& source) {
    const paper_reading paper = read_paper(source);
    const run_context ctx{{precision::parse("double")}, 20230830, 2, &paper};
    both_routes out;
    use_claims_file(records_, "simpson-paper-shapes.toml");
    check_claims_file_formulas(paper.source);
    std::vector<std::string> ids;
    for (const claim& c : ledger()) ids.push_back(c.id);
    for (const std::string& id : ids) out.shapes[id] = check_claim(find_claim(id), ctx).outcome;
    use_claims_file(embedded_claims_text(), "claims/paper.toml");
    for (const std::string& id : ids) out.ledger[id] = check_claim(find_claim(id), ctx).outcome;  // the same ids only
    return out;
  }

  const std::string records_ = shape_records();
};

TEST_F(PaperThroughShapes, OnThePaperEveryShapeGivesTheLedgersVerdict) {
  const both_routes v = verdicts(embedded_paper());
  ASSERT_EQ(v.shapes.size(), 2u);
  for (const auto& [id, shape] : v.shapes) {
    EXPECT_EQ(to_string(shape), to_string(v.ledger.at(id))) << id;
    EXPECT_EQ(shape, verdict::holds) << id;
  }
}

struct alteration {
  const char* where;
  const char* from;
  const char* to;
  std::set<std::string> stop_holding;  // by both routes
  /// Where the routes read different things: the shape reads the printed formula the ledger does
  /// not (its claim then stops holding by the shape alone).
  std::set<std::string> shape_alone = {};
};

TEST_F(PaperThroughShapes, OnAlteredCopiesBothRoutesStopHoldingTogether) {
  const std::vector<alteration> alterations{
      // The stability band is judged on the printed Phi_3 by the shape, on the derived scheme (where
      // q_m's denominator vanishes) by the ledger: a misprinted Phi_3 is not the band's fault.
      {"\\label{Phi3}", "{11\\over24}", "{11\\over23}", {}, {"stability-condition"}},
      {"\\label{stabilite}", "2 \\, \\sqrt{2}", "2 \\, \\sqrt{3}", {"stability-condition"}},
      {"\\label{stabilite}", "2 \\, \\sqrt{2}", "2", {"stability-condition"}},
      {"\\label{matrice-symplectique-ordre-2}", "- m \\, \\omega^2 \\, h", "- m \\, \\omega^2 \\, h^2", {"newmark-det"}},
  };
  for (const alteration& a : alterations) {
    const both_routes v = verdicts(altered(a.where, a.from, a.to));
    for (const auto& [id, shape] : v.shapes) {
      const bool ledger_holds = v.ledger.at(id) == verdict::holds, shape_holds = shape == verdict::holds;
      const std::string where = std::string(a.where) + " " + a.from + " -> " + a.to + ": " + id + " (ledger " + to_string(v.ledger.at(id)) +
                                ", shape " + to_string(shape) + ")";
      EXPECT_EQ(shape_holds, !a.stop_holding.count(id) && !a.shape_alone.count(id)) << where;
      EXPECT_EQ(ledger_holds, !a.stop_holding.count(id)) << where;
    }
  }
}

}  // namespace
}  // namespace simpson::verify

// Our core bound to the print (core_bindings.hpp): every formula of the core is bound by a record of
// the paper and equals the printed one there; a core formula that is not the print makes its
// claim fail, naming the entries; a misprint is compared with its proved correction.

#include "altered_paper.hpp"
#include "phi3_unit_record.hpp"
#include "core_bindings.hpp"

#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/printed_checks.hpp>

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace simpson::verify {
namespace {

claim_result judged(claim_book& book, const std::string& id, const paper_source& paper) {
  const paper_reading reading = read_paper(paper);
  check_claims_file_formulas(book, reading.source);
  run_context ctx;
  ctx.paper = &reading;
  ctx.book = &book;
  return check_claim(book.find(id), ctx);
}

TEST(CoreBinding, EveryCoreFormulaIsBoundByARecordOfThePaperAndIsThePrint) {
  claim_book book = paper_book();
  std::set<std::string> bound;
  std::set<std::string> ids;
  for (const claim_record& r : book.records) {
    for (const core_binding& b : r.core) {
      bound.insert(b.function);
      ids.insert(r.id);
    }
  }
  for (const detail::core_formula& f : detail::core_formulas()) EXPECT_TRUE(bound.count(f.name)) << f.name << " is bound by no record";
  const paper_reading reading = read_paper(embedded_paper());
  check_claims_file_formulas(book, reading.source);
  run_context ctx;
  ctx.paper = &reading;
  ctx.book = &book;
  for (const std::string& id : ids) {
    const claim_result r = check_claim(book.find(id), ctx);
    EXPECT_EQ(r.outcome, book.find(id).expected) << id << ": " << r.note;
    ASSERT_TRUE(r.evidence.contains("core_bound")) << id;
    for (const json& e : r.evidence["core_bound"]) {
      EXPECT_TRUE(e["agrees"].get<bool>()) << id << ": " << e.dump();
      // Our kernel evaluated the two trees (a grid), not a difference GiNaC had already cancelled.
      EXPECT_EQ(e["own_kernel"].get<std::string>().find("a constant"), std::string::npos) << id << ": " << e.dump();
    }
  }
}

// The record holds without its binding; bound to a core formula that is not the printed one, it
// fails and names the entries: a weaker check (the record alone) would pass.
TEST(CoreBinding, ACoreFormulaThatIsNotThePrintMakesItsClaimFail) {
  const std::string& record = phi3_unit_record;
  claim_book alone = read_claim_book(record, "test.toml");
  EXPECT_EQ(judged(alone, "phi3-unit", embedded_paper()).outcome, verdict::holds);

  claim_book right = read_claim_book(record + "core = { function = \"simpson_map\", formula = \"Phi3\" }\n", "test.toml");
  const claim_result agrees = judged(right, "phi3-unit", embedded_paper());
  EXPECT_EQ(agrees.outcome, verdict::holds) << agrees.note;

  claim_book wrong = read_claim_book(record + "core = { function = \"newmark_map\", formula = \"Phi3\" }\n", "test.toml");
  const claim_result r = judged(wrong, "phi3-unit", embedded_paper());
  EXPECT_EQ(r.outcome, verdict::fails);
  EXPECT_NE(r.note.find("the core's newmark_map is not label Phi3"), std::string::npos) << r.note;
  EXPECT_NE(r.note.find("entry (1, 2)"), std::string::npos) << r.note;
  ASSERT_TRUE(r.evidence.contains("core_bound"));
  EXPECT_FALSE(r.evidence["core_bound"][0]["agrees"].get<bool>());
  EXPECT_TRUE(r.correction.empty());
}

// A misprinted Phi_3 (11/24 printed 13/24 on the diagonal): the derivation proves the print wrong
// and corrects it; the core is compared with the correction, and agrees, so the verdict is the
// erratum, not a failure of our code.
TEST(CoreBinding, AMisprintIsComparedWithItsProvedCorrection) {
  claim_book book = paper_book();
  const paper_source misprint = altered("\\label{Phi3}", "1 \\!-\\! {11\\over24}", "1 \\!-\\! {13\\over24}");
  const claim_result r = judged(book, "phi3-elimination", misprint);
  EXPECT_EQ(r.outcome, verdict::erratum) << r.note;
  ASSERT_TRUE(r.evidence.contains("core_bound"));
  EXPECT_TRUE(r.evidence["core_bound"][0]["agrees"].get<bool>()) << r.evidence["core_bound"].dump();
  EXPECT_NE(r.evidence["core_bound"][0]["formula"].get<std::string>().find("as corrected by this claim"), std::string::npos);

  // A misprint the claim proves wrong without a formula to stand in its place (H_d's 1/24 printed
  // 1/25: not proportional to Q_c): the core is not compared, and the evidence says so; the verdict
  // is the claim's own.
  claim_book energy = paper_book();
  const paper_source energy_misprint = altered("\\label{hamiltonien-discret}", "{{\\omega^2 \\, h^2}\\over24}", "{{\\omega^2 \\, h^2}\\over25}");
  const claim_result e = judged(energy, "hd-proportional", energy_misprint);
  EXPECT_EQ(e.outcome, verdict::erratum) << e.note;
  ASSERT_TRUE(e.evidence.contains("core_bound"));
  EXPECT_TRUE(e.evidence["core_bound"][0].contains("not_compared")) << e.evidence["core_bound"].dump();
}

TEST(CoreBinding, ABindingThatDoesNotFitIsBadInputNamingItsField) {
  const std::string& record = phi3_unit_record;
  const auto error_of = [&](const std::string& core) -> std::string {
    try {
      claim_book book = read_claim_book(record + core + "\n", "test.toml");
      check_claims_file_formulas(book, read_paper(embedded_paper()).source);
    } catch (const claims_file_error& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(error_of("core = { function = \"simpson_mapp\", formula = \"Phi3\" }").find("field 'core.function': no core formula is named 'simpson_mapp'"),
            std::string::npos);
  EXPECT_NE(error_of("core = { function = \"simpson_map\" }").find("field 'core.formula': missing"), std::string::npos);
  EXPECT_NE(error_of("core = { function = \"discrete_energy\", formula = \"hamiltonien-discret\", variables = ['p'] }").find("field 'core.variables'"),
            std::string::npos);
  EXPECT_NE(error_of("core = { function = \"discrete_energy\", formula = \"Phi3\", variables = ['p', 'q'] }").find("field 'core.formula'"),
            std::string::npos);
  EXPECT_NE(error_of("core = { function = \"simpson_map\", formula = \"Phi3\", colour = \"red\" }").find("field 'core.colour'"), std::string::npos);
  EXPECT_NE(error_of("core = { function = \"simpson_map\", formula = \"no-such-label\" }").find("core"), std::string::npos);
}

}  // namespace
}  // namespace simpson::verify

// The Coq exporter's names (verify/prove/include/simpson/prove/coq_export.hpp): a lemma quantifies over one variable
// per symbol of the statement. q_{j+1} and q_{j-1} once both printed as q_j_1, so the certificates of
// the three-term schemes proved the case q_{j-1} = q_{j+1} only, and coqc accepted it.

#include <simpson/prove/coq_export.hpp>

#include <gtest/gtest.h>

namespace simpson::verify::detail {
namespace {

TEST(CoqExport, SymbolsThatDifferInASignAreTwoVariables) {
  EXPECT_EQ(coq_symbol_identifier("q_j+1"), "q_jp1");
  EXPECT_EQ(coq_symbol_identifier("q_j-1"), "q_jm1");
  EXPECT_EQ(coq_symbol_identifier("q_j+1/2"), "q_jp1over2");
  EXPECT_EQ(coq_symbol_identifier("omega"), "omega");
  // Claim ids keep their names: certificates/phi3_det.v, lemma phi3_det_...
  EXPECT_EQ(coq_identifier("phi3-det"), "phi3_det");
  // (q_{j+1} - q_{j-1})^2 = q_{j+1}^2 - 2 q_{j+1} q_{j-1} + q_{j-1}^2: with one variable for both, a
  // statement about 0 = 0.
  const GiNaC::symbol next("q_j+1"), previous("q_j-1");
  const coq_export e = coq_certificate("names", "a square", {{"printed", GiNaC::pow(next - previous, 2), next * next - 2 * next * previous + previous * previous, true}});
  ASSERT_TRUE(e.not_exported.empty()) << e.not_exported;
  EXPECT_NE(e.text.find("q_jm1 q_jp1 : R"), std::string::npos) << e.text;
}

TEST(CoqExport, TwoSymbolsThatWouldShareANameAreNotExported) {
  // Two symbols GiNaC keeps apart, named alike: a lemma over one variable would prove less than the
  // statement, so there is no certificate, and the reason names them.
  const GiNaC::symbol x1("x"), x2("x");
  const coq_export e = coq_certificate("clash", "x1 + x2 = x2 + x1", {{"printed", x1 + 2 * x2, 2 * x2 + x1, true}});
  EXPECT_TRUE(e.text.empty()) << e.text;
  EXPECT_NE(e.not_exported.find("would both be x in Coq"), std::string::npos) << e.not_exported;
}

}  // namespace
}  // namespace simpson::verify::detail

// The paper as printed: its formulas are read from the LaTeX source and proved against the derived
// ones in GiNaC; a coefficient changed in the text changes the matching verdict.

#include <simpson/verify/ledger.hpp>
#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/printed_checks.hpp>
#include <simpson/verify/run.hpp>

#include <gtest/gtest.h>

#include <chrono>

namespace simpson::verify {
namespace {

/// The embedded text with `from` replaced by `to` in the display after `\label{label}` (or after the
/// anchor): comments keep an older Φ₃, so the replacement is made where the reader looks.
paper_source altered(const std::string& after, const std::string& from, const std::string& to) {
  paper_source p = embedded_paper();
  const std::size_t start = p.text.find(after);
  EXPECT_NE(start, std::string::npos) << after;
  const std::size_t at = p.text.find(from, start);
  EXPECT_NE(at, std::string::npos) << from;
  p.text.replace(at, from.size(), to);
  p.origin = "altered copy";
  return p;
}

verdict verdict_of(const std::string& id, const paper_reading& paper) {
  const run_context ctx{{precision::parse("double"), precision::parse("rational")}, 20230830, 2, &paper};
  return check_claim(find_claim(id), ctx).outcome;
}

TEST(PaperReading, EveryFormulaOfTheEmbeddedPaperParsesAndHolds) {
  const auto start = std::chrono::steady_clock::now();
  const paper_reading paper = read_paper(embedded_paper());
  EXPECT_EQ(paper.formulas.size(), ledger_formulas().size());
  for (const char* id : {"qm-harmonic", "reduced-lagrangian", "discriminant-factorization", "momentum-order-3",
                         "phi3-elimination", "phi3-det", "hd-invariance", "truncation-1440"}) {
    EXPECT_TRUE(reads_printed_formula(id)) << id;
    EXPECT_EQ(verdict_of(id, paper), verdict::holds) << id;
  }
  EXPECT_EQ(paper.at("Phi3").source.line, 488);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30.0);
}

struct alteration {
  const char* where;
  const char* from;
  const char* to;
  std::vector<std::string> claims;  // each must stop holding
};

TEST(PaperReading, AChangedCoefficientInTheTextChangesTheVerdict) {
  const std::vector<alteration> alterations{
      {"\\label{Phi3}", "{11\\over24}", "{11\\over23}", {"phi3-elimination", "phi3-det", "hd-invariance"}},
      {"can be factorized", "\\over576}", "\\over575}", {"discriminant-factorization"}},
      {"\\label{hamiltonien-discret}", "\\over12} \\Big)", "\\over13} \\Big)", {"hd-invariance"}},
      {"\\label{qm-oscillateur-harmonique}", "{{q_\\ell + q_r}\\over2}", "{{q_\\ell + q_r}\\over3}", {"qm-harmonic"}},
      {"\\label{Lagrangien-reduit}", "{{22-h^2", "{{21-h^2", {"reduced-lagrangian"}},
      {"one obtains without difficulty", "{1\\over1440}", "{1\\over1441}", {"truncation-1440"}},
      {"one obtains without difficulty", "h^4", "h^3", {"truncation-1440"}},
      // ω⁴ → ω⁶ in p_r: invisible once m = ω = 1, caught with every symbol free.
      {"\\label{moment-ordre-3}", "\\omega^4}\\over48}", "\\omega^6}\\over48}", {"momentum-order-3"}},
  };
  for (const alteration& a : alterations) {
    const paper_reading paper = read_paper(altered(a.where, a.from, a.to));
    for (const std::string& id : a.claims) {
      const verdict v = verdict_of(id, paper);
      EXPECT_TRUE(v == verdict::erratum || v == verdict::fails) << a.where << ": " << id << " still " << to_string(v);
    }
  }
}

TEST(PaperReading, AnErratumOfAFormulaIsCorrectedByTheDerivedOne) {
  const paper_reading paper = read_paper(altered("\\label{qm-oscillateur-harmonique}", "{{q_\\ell + q_r}\\over2}", "{{q_\\ell + q_r}\\over3}"));
  const run_context ctx{{precision::parse("double")}, 20230830, 2, &paper};
  const claim_result r = check_claim(find_claim("qm-harmonic"), ctx);
  EXPECT_EQ(r.outcome, verdict::erratum);
  EXPECT_NE(r.correction.find("as derived"), std::string::npos) << r.correction;
  EXPECT_EQ(r.printed["formulas"][0]["label"], "label qm-oscillateur-harmonique");
}

TEST(PaperReading, BadSourcesAreNamedWithLabelLineAndToken) {
  paper_source p = embedded_paper();
  p.text.replace(p.text.find("\\label{moment-ordre-3}"), 22, "\\label{moment-order-3}");
  try {
    read_paper(p);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("label 'moment-ordre-3'"), std::string::npos) << e.what();
  }
  const paper_source q = altered("\\label{Phi3}", "{11\\over24}", "{11\\over24} \\unknowncommand");
  try {
    read_paper(q);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("label Phi3 (line 488)"), std::string::npos) << what;
    EXPECT_NE(what.find("'\\unknowncommand'"), std::string::npos) << what;
  }
  EXPECT_THROW(load_paper("/no/such/paper.tex"), std::invalid_argument);
}

TEST(TexMath, ReadsTheSubsetThePaperUses) {
  tex_symbols s;
  const GiNaC::ex h = s["h"], w = s["omega"];
  EXPECT_TRUE((parse_tex_math("{{\\omega^2 \\, h^2}\\over576}", s) - w * w * h * h / 576).is_zero());
  EXPECT_TRUE((parse_tex_math("h^24", s) - h * h * 4).is_zero());  // TeX's one-token script
  EXPECT_TRUE((parse_tex_math("\\frac{1}{2} \\big( h + 1 \\big)", s) - (h + 1) / 2).is_zero());
  EXPECT_TRUE((parse_tex_math("q_\\ell - q_r", s) - (s["q_l"] - s["q_r"])).is_zero());
  const std::vector<std::string> sides = relation_sides("H_d \\, (p,\\, q) \\equiv {1\\over2} p^2 \\, .");
  ASSERT_EQ(sides.size(), 2u);
  EXPECT_TRUE((parse_tex_math(sides[1], s) - s["p"] * s["p"] / 2).is_zero());
  EXPECT_THROW(parse_tex_math("h + \\foo", s), tex_parse_error);
}

}  // namespace
}  // namespace simpson::verify

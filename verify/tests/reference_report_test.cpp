// The committed report of the `paper` scene (reports/reference/paper) must be what this build
// produces: any change in a verdict, an evidence digit or a statement shows up here and in review.
// Run times are not in report.json or report.md (timing.json and timing.md hold them), so both are
// compared whole, apart from report.json's environment (compiler, commit, timestamp); the test
// times each configuration once, since run times are not compared.
// To accept a deliberate change: build/bin/simpson-verify --out reports/reference/paper

#include <simpson/verify/certify.hpp>
#include <simpson/verify/report.hpp>
#include <simpson/verify/report_compare.hpp>

#include "report_comparison.hpp"
#include "report_tree.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace simpson::verify {
namespace {

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(ReferenceReport, PaperSceneReproducesTheCommittedReport) {
  const std::filesystem::path dir = std::filesystem::path(SIMPSON_SOURCE_DIR) / "reports" / "reference" / "paper";
  ASSERT_TRUE(std::filesystem::exists(dir / "report.json")) << dir;
  scene s = load_scene("paper");
  s.experiments.work_precision->timing = timing_policy{1, 0.01};
  run_record r = run(s);
  // The committed report was made with --certify: its Coq counts are checked counts.
  ASSERT_FALSE(coqc_version().empty()) << "coqc is needed (scripts/install-deps installs Debian's coq)";
  EXPECT_TRUE(record_certificates(r, true).empty()) << "coqc rejected a certificate";
  // `simpson-verify compare` finds no difference (its tolerances: README, report_compare.hpp) ...
  const std::vector<std::string> differences = compare_reports(load_report(dir), report_json(r));
  for (const std::string& line : differences) ADD_FAILURE() << line;
  // ... and, on this machine, the two agree byte for byte apart from the environment.
  const json expected = test::without_volatile(json::parse(read(dir / "report.json")));
  const json actual = test::without_volatile(report_json(r));
  ASSERT_EQ(expected["claims"].size(), actual["claims"].size());
  for (std::size_t k = 0; k < actual["claims"].size(); ++k) {
    EXPECT_EQ(expected["claims"][k].dump(2), actual["claims"][k].dump(2)) << "claim " << actual["claims"][k]["id"];
  }
  EXPECT_EQ(expected.dump(2), actual.dump(2));
  EXPECT_EQ(read(dir / "report.md"), report_markdown(r));
  // The committed report has its plots and its HTML page.
  for (const json& plot : expected["plots"]) {
    EXPECT_EQ(plot["files"].size(), 2u) << plot["name"];
    for (const json& file : plot["files"]) EXPECT_TRUE(std::filesystem::exists(dir / file.get<std::string>())) << file;
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "report.html"));
  // The page shows the plots beside it (not embedded: it stays small), and its JUnit is green.
  EXPECT_NE(read(dir / "report.html").find("<img src=\"figure1.svg\""), std::string::npos);
  // Embedded, the plots made the page over 800 KB; the text of 64 claims' evidence (quoted sentences,
  // the convention search's candidates entry by entry) is about 420 KB.
  EXPECT_LT(std::filesystem::file_size(dir / "report.html"), 480'000u);
  EXPECT_NE(read(dir / "report.junit.xml").find("failures=\"0\" errors=\"0\""), std::string::npos);
  // Every table of the committed page is a table (a '|' left unescaped once made one a paragraph).
  test::expect_html_tables_rendered(dir);
  test::expect_no_bare_non_finite(dir);
}

TEST(ReferenceReport, CompareFindsAChangedFigureAndNamesIt) {
  const std::filesystem::path dir = std::filesystem::path(SIMPSON_SOURCE_DIR) / "reports" / "reference" / "paper";
  const json reference = load_report(dir);
  EXPECT_TRUE(compare_reports(reference, reference).empty());
  json altered = reference;
  for (json& c : altered["claims"]) {
    if (c["id"] == "phi3-det") c["verdict"] = "fails";
  }
  altered["experiments"]["table1"]["entries"][0]["ours"] = "9.99e-01";
  altered["environment"]["timestamp_utc"] = "2000-01-01T00:00:00Z";             // ignored
  altered["claims"][0]["evidence"]["exact"][0]["points_evaluated"] = 1;          // an integer: compared
  const std::vector<std::string> lines = compare_reports(reference, altered);
  ASSERT_EQ(lines.size(), 3u) << ::testing::PrintToString(lines);
  EXPECT_NE(lines[0].find("claim lemma-dimensional-scaling: evidence.exact[0].points_evaluated: 225 → 1"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("claim phi3-det: verdict: \"holds\" → \"fails\""), std::string::npos) << lines[1];
  EXPECT_NE(lines[2].find("section table1, entries row 0, column ours"), std::string::npos) << lines[2];
  // A residual's digits may change; leaving its bound may not.
  json residual = reference;
  for (json& c : residual["claims"]) {
    if (c["id"] == "phi3-det") {
      c["evidence"]["numeric"]["ladder"][0]["max_residual"] = "3.00e-16";
      EXPECT_TRUE(compare_reports(reference, residual).empty());
      c["evidence"]["numeric"]["ladder"][0]["within_bound"] = false;
    }
  }
  EXPECT_EQ(compare_reports(reference, residual).size(), 1u);
}

}  // namespace
}  // namespace simpson::verify

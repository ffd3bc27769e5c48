// The committed report of the `paper` scene (reports/reference/paper) must be what this build
// produces: any change in a verdict, an evidence digit or a statement shows up here and in review.
// Timing and environment (compiler, commit) are left out of the comparison, and so is the timing
// policy: the test times each configuration once, since run times are not compared.
// To accept a deliberate change: build/bin/simpson-verify --out reports/reference/paper

#include <simpson/verify/report.hpp>

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
  const run_record r = run(s);
  const json expected = test::without_volatile(json::parse(read(dir / "report.json")));
  const json actual = test::without_volatile(report_json(r));
  ASSERT_EQ(expected["claims"].size(), actual["claims"].size());
  for (std::size_t k = 0; k < actual["claims"].size(); ++k) {
    EXPECT_EQ(expected["claims"][k].dump(2), actual["claims"][k].dump(2)) << "claim " << actual["claims"][k]["id"];
  }
  EXPECT_EQ(expected.dump(2), actual.dump(2));
  EXPECT_EQ(test::without_times(read(dir / "report.md")), test::without_times(report_markdown(r)));
  // The committed report has its plots and its HTML page.
  for (const json& plot : expected["plots"]) {
    EXPECT_EQ(plot["files"].size(), 2u) << plot["name"];
    for (const json& file : plot["files"]) EXPECT_TRUE(std::filesystem::exists(dir / file.get<std::string>())) << file;
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "report.html"));
  EXPECT_NE(read(dir / "report.html").find("data:image/svg+xml;base64,"), std::string::npos);
  // Every table of the committed page is a table (a '|' left unescaped once made one a paragraph).
  test::expect_html_tables_rendered(dir);
  test::expect_no_bare_non_finite(dir);
}

}  // namespace
}  // namespace simpson::verify

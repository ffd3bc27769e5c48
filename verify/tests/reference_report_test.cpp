// The committed report of the `paper` scene (reports/reference/paper) must be what this build
// produces: any change in a verdict, an evidence digit or a statement shows up here and in review.
// Timing and environment (compiler, commit) are left out of the comparison.
// To accept a deliberate change: build/bin/simpson-verify --out reports/reference/paper

#include <simpson/verify/report.hpp>

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
  const run_record r = run(load_scene("paper"));
  json expected = json::parse(read(dir / "report.json"));
  json actual = report_json(r);
  for (json* j : {&expected, &actual}) {
    j->erase("timing");
    j->erase("environment");
  }
  ASSERT_EQ(expected["claims"].size(), actual["claims"].size());
  for (std::size_t k = 0; k < actual["claims"].size(); ++k) {
    EXPECT_EQ(expected["claims"][k].dump(2), actual["claims"][k].dump(2)) << "claim " << actual["claims"][k]["id"];
  }
  EXPECT_EQ(expected.dump(2), actual.dump(2));
  EXPECT_EQ(read(dir / "report.md"), report_markdown(r));
}

}  // namespace
}  // namespace simpson::verify

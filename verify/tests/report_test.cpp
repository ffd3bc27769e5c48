#include <simpson/verify/report.hpp>

#include "report_comparison.hpp"
#include "report_tree.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace simpson::verify {
namespace {

using test::without_volatile;

TEST(Report, SameSceneAndSeedGiveIdenticalReportsApartFromTheirRunTimes) {
  const scene s = load_scene("quick", paper_book());
  const run_record first = run(s), second = run(s);
  EXPECT_EQ(without_volatile(report_json(first)).dump(), without_volatile(report_json(second)).dump());
  EXPECT_EQ(report_markdown(first), report_markdown(second));
  // The run times are all in timing.json.
  EXPECT_FALSE(report_json(first).contains("timing"));
  EXPECT_TRUE(timing_json(first)["experiments"]["work_precision"].contains("timing_rows"));
}

TEST(Report, ADifferentSeedChangesTheSamplesAndIsRecorded) {
  // The seed draws the claims' samples; the sections, which draw none, are left out (two runs of
  // them cost 20 s under the sanitizers and add nothing here).
  scene s = load_scene("quick", paper_book());
  s.experiments = experiment_settings{};
  const json a = report_json(run(s));
  s.seed += 1;
  const json b = report_json(run(s));
  EXPECT_EQ(b["seed"].get<std::uint64_t>(), a["seed"].get<std::uint64_t>() + 1);
  EXPECT_NE(without_volatile(a).dump(), without_volatile(b).dump());
}

TEST(Report, HasTheRequiredFieldsAndAnErrataSection) {
  const run_record r = run(load_scene("quick", paper_book()));
  const json j = report_json(r);
  for (const json& c : j["claims"]) {
    for (const char* key : {"id", "equation", "statement", "methods", "verdict", "expected", "evidence"}) {
      EXPECT_TRUE(c.contains(key)) << key;
    }
    if (c["verdict"] == "erratum") {
      EXPECT_TRUE(c.contains("correction"));
    }
  }
  const std::string md = report_markdown(r);
  std::size_t expectations = 0;
  for (const section_result& section : r.sections) expectations += section.expectations.size();
  ASSERT_GT(expectations, 0u);
  EXPECT_NE(md.find(fmt::format("**7 claims: 5 held, 2 errata, 0 failed; {0} expectations of the experiments: {0} hold; all verdicts as expected**",
                                expectations)),
            std::string::npos)
      << md.substr(0, 400);
  EXPECT_NE(md.find("### gamma-system"), std::string::npos);
}

TEST(Report, WritesEveryFileAtomically) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "simpson-report-test";
  std::filesystem::remove_all(dir);
  prepare_output_directory(dir);
  EXPECT_FALSE(std::filesystem::exists(dir)) << "checking the directory creates nothing";
  write_report_files(dir, run(load_scene("quick", paper_book())));
  std::vector<std::string> names;  // report-relative paths of the files, a directory's as <directory>/<file>
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file()) names.push_back(entry.path().lexically_relative(dir).generic_string());
  }
  std::sort(names.begin(), names.end());
  // The quick scene has every section: its data files, gnuplot scripts and plots, and no staging left.
  for (const char* expected : {"report.json", "report.md", "report.html", "table1.csv", "work_precision.csv", "figure1.gp",
                               "figure1.svg", "figure1.png", "work_precision_time.svg", "truncation_digits.png",
                               "long_time_energy.svg", "long_time_phase.png"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  }
  for (const std::string& name : names) EXPECT_NE(name.front(), '.') << "left behind: " << name;
  std::ifstream in(dir / "report.json");
  const json parsed = json::parse(in);
  EXPECT_EQ(parsed["scene"], "quick");
  // report.json lists every file of the directory (those with run times apart), and nothing else is there.
  std::vector<std::string> listed = parsed["files"].get<std::vector<std::string>>();
  for (const json& f : parsed["timing_files"]) listed.push_back(f.get<std::string>());
  std::sort(listed.begin(), listed.end());
  for (const char* timing : {"timing.json", "timing.md", "timing.html", "work_precision_time.csv", "work_precision_time.png"}) {
    EXPECT_NE(std::find(parsed["timing_files"].begin(), parsed["timing_files"].end(), timing), parsed["timing_files"].end()) << timing;
  }
  EXPECT_EQ(listed, names);
  test::expect_no_bare_non_finite(dir);
  test::expect_html_tables_rendered(dir);
  // A second, smaller run replaces the report whole: nothing of the first survives, nothing staged is left.
  write_report_files(dir, run(parse_scene(R"({"name": "t", "table1": {"N": [10]}})", "t", paper_book())));
  EXPECT_FALSE(std::filesystem::exists(dir / "work_precision.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "table1.csv"));
  for (const auto& entry : std::filesystem::directory_iterator(dir.parent_path())) {
    EXPECT_EQ(entry.path().filename().string().find(".simpson-report-test."), std::string::npos) << entry.path();
  }
  std::filesystem::remove_all(dir);
}

TEST(Report, ADirectoryHoldingOtherFilesIsRefusedAndKept) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "simpson-report-foreign";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "notes.txt") << "keep";
  EXPECT_THROW(prepare_output_directory(dir), std::invalid_argument);
  EXPECT_THROW(write_report_files(dir, run(parse_scene(R"({"name": "t", "table1": {"N": [10]}})", "t", paper_book()))), std::invalid_argument);
  EXPECT_TRUE(std::filesystem::exists(dir / "notes.txt"));
  EXPECT_FALSE(holds_only_a_report(dir));
  std::filesystem::remove_all(dir);
}

TEST(Report, AnOutputDirectoryThatCannotBeCreatedIsNamed) {
  try {
    prepare_output_directory("/proc/simpson-cannot-write-here");
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'/proc/simpson-cannot-write-here'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace simpson::verify

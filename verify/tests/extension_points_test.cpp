// The extension points as data (docs/architecture.md): an experiment section is its own files and one
// line of the book's registry; the report's JSON Schema names exactly the registry's sections.

#include <simpson/verify/experiment_section.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/report.hpp>
#include <simpson/verify/run.hpp>
#include <simpson/verify/scene.hpp>
#include <simpson/verify/selection.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace simpson::verify {
namespace {

json report_schema() {
  std::ifstream in(std::filesystem::path(SIMPSON_SOURCE_DIR) / "verify" / "app" / "schema" / "report.schema.json");
  std::ostringstream text;
  text << in.rdbuf();
  return json::parse(text.str());
}

// The schema's section names are the registry's, in its order (scripts/generated-docs --write writes
// them): a section added to the registry and not to the schema fails here, before a report fails it.
TEST(SectionRegistry, TheSchemaNamesEverySectionOfTheRegistry) {
  const json schema = report_schema();
  EXPECT_EQ(schema["$defs"]["section_name"]["enum"].get<std::vector<std::string>>(), section_names(paper_book().sections));
  EXPECT_EQ(schema["properties"]["overrides"]["properties"]["sections"]["items"]["$ref"], "#/$defs/section_name");
  EXPECT_EQ(schema["properties"]["experiments"]["propertyNames"]["$ref"], "#/$defs/section_name");
}

// A section written as a test would write one: its settings, its parser, its run.
struct counting_settings {
  long long n = 3;
};

class counting_section final : public typed_section<counting_settings> {
 public:
  counting_section() : typed_section("counting", "counts to n") {}
  std::set<std::string> keys() const override { return {"n"}; }

 protected:
  counting_settings read(const section_reader& r, const std::vector<precision>&) const override {
    counting_settings s;
    if (r.has("n")) s.n = r.integer("n", 1, 100);
    return s;
  }
  counting_settings initial(const std::vector<precision>&) const override { return {}; }
  section_cost estimate(const counting_settings& s) const override { return {static_cast<double>(s.n), "counting: n steps"}; }
  section_result compute(const counting_settings& s, const section_inputs&) const override {
    section_result r;
    r.name = name();
    r.title = "Counting";
    r.conventions = {{"n", s.n}};
    r.text("Counted to " + std::to_string(s.n) + ".");
    r.expect({"counted", "the count reaches n", "n", std::to_string(s.n), true});
    return r;
  }
};

// The paper's book with the counting section as one more line of its registry: nothing else of the
// app is told about it, and a scene, --sections, the run and the report take it.
TEST(SectionRegistry, ASectionIsItsOwnFilesAndOneRegistryLine) {
  const counting_section counting;
  auto book = std::make_shared<claim_book>(paper_book());
  book->sections.push_back(&counting);

  scene s = parse_scene(R"({"name": "counting-only", "counting": {"n": 7}})", "counting.json", *book);
  ASSERT_EQ(s.experiments.names(), std::vector<std::string>{"counting"});
  const paper_reading paper = read_scene_paper(s, *book);
  const run_record r = run(s, book, paper);
  const json j = report_json(r);
  ASSERT_TRUE(j["experiments"].contains("counting")) << j["experiments"].dump();
  EXPECT_EQ(j["experiments"]["counting"]["conventions"]["n"], 7);
  EXPECT_NE(report_markdown(r).find("Counted to 7."), std::string::npos);

  // A key the section does not take is named under the section's name (bad input).
  EXPECT_THROW(parse_scene(R"({"name": "x", "counting": {"m": 1}})", "bad.json", *book), std::invalid_argument);
  // --sections knows it from the registry, and its defaults apply.
  scene quick = load_scene("quick", *book);
  apply_selection(quick, scene_selection{std::nullopt, std::vector<std::string>{"counting"}}, *book);
  EXPECT_EQ(quick.experiments.names(), std::vector<std::string>{"counting"});
  // Without the registry line the same scene is bad input.
  EXPECT_THROW(parse_scene(R"({"name": "counting-only", "counting": {}})", "counting.json", paper_book()), std::invalid_argument);
}

}  // namespace
}  // namespace simpson::verify

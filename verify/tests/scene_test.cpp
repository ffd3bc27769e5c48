#include <simpson/verify/scene.hpp>

#include <simpson/verify/ledger.hpp>

#include <gtest/gtest.h>

namespace simpson::verify {
namespace {

/// The message of the std::invalid_argument that parsing `text` throws ("" if it does not throw).
std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "t.json");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

bool mentions(const std::string& message, const std::string& part) { return message.find(part) != std::string::npos; }

TEST(Scene, EmbeddedScenesParseAndPaperHasEveryClaim) {
  const scene paper = load_scene("paper");
  EXPECT_EQ(paper.claims.size(), ledger().size());
  EXPECT_EQ(paper.seed, default_seed);
  const scene quick = load_scene("quick");
  for (const std::string& id : required_claim_ids()) {
    EXPECT_NE(std::find(quick.claims.begin(), quick.claims.end(), id), quick.claims.end()) << id;
  }
}

TEST(Scene, ValidMinimalSceneTakesDefaults) {
  const scene s = parse_scene(R"({"name": "mini", "claims": ["phi3-det"], "precisions": ["double"]})", "t.json");
  EXPECT_EQ(s.samples, default_samples);
  EXPECT_EQ(s.seed, default_seed);
  ASSERT_EQ(s.claims.size(), 1u);
}

TEST(Scene, ClaimsAreKeptInLedgerOrderWithoutDuplicates) {
  const scene s = parse_scene(R"({"name": "o", "claims": ["phi3-det", "newmark-det", "phi3-det"], "precisions": ["double"]})", "t");
  ASSERT_EQ(s.claims.size(), 2u);
  EXPECT_EQ(s.claims[0], "newmark-det");
}

TEST(Scene, MalformedJsonNamesLineAndColumn) {
  const std::string message = error_of("{\n  \"name\": \"x\",\n  \"claims\": [,]\n}");
  EXPECT_TRUE(mentions(message, "scene 't.json': malformed JSON at line 3, column")) << message;
  EXPECT_TRUE(mentions(error_of(""), "malformed JSON")) << error_of("");
  EXPECT_TRUE(mentions(error_of("{\"name\": \"x\", \"claims\""), "malformed JSON")) << "truncated";
}

TEST(Scene, NumberOverflowIsMalformedJsonNotACrash) {
  // Found by the fuzzer: nlohmann::json throws out_of_range (406), not parse_error, on this.
  EXPECT_TRUE(mentions(error_of("9999929999992e9999929999992"), "scene 't.json': malformed JSON"));
  EXPECT_TRUE(mentions(error_of(R"({"name": "x", "claims": "all", "precisions": ["double"], "samples": 1e99999})"),
                       "malformed JSON"));
}

TEST(Scene, RejectsEveryBadField) {
  const std::string base = R"("name": "x", "claims": ["phi3-det"], "precisions": ["double"])";
  EXPECT_TRUE(mentions(error_of("[1, 2]"), "top level must be an object"));
  EXPECT_TRUE(mentions(error_of("{" + base + R"(, "colour": 1})"), "unknown key 'colour'"));
  EXPECT_TRUE(mentions(error_of(R"({"claims": "all", "precisions": ["double"]})"), "'name' must be a string"));
  EXPECT_TRUE(mentions(error_of(R"({"name": "Bad Name", "claims": "all", "precisions": ["double"]})"), "'name' must be"));
  EXPECT_TRUE(mentions(error_of(R"({"name": "x", "precisions": ["double"]})"), "'claims' is missing"));
  EXPECT_TRUE(mentions(error_of(R"({"name": "x", "claims": [], "precisions": ["double"]})"), "'claims' must be"));
  EXPECT_TRUE(mentions(error_of(R"({"name": "x", "claims": ["phi4-det"], "precisions": ["double"]})"),
                       "'claims[0]': unknown claim id 'phi4-det'"));
  EXPECT_TRUE(mentions(error_of(R"({"name": "x", "claims": [3], "precisions": ["double"]})"), "'claims[0]' must be a string"));
  EXPECT_TRUE(mentions(error_of(R"({"name": "x", "claims": "all", "precisions": "double"})"), "'precisions' must be"));
  EXPECT_TRUE(mentions(error_of(R"({"name": "x", "claims": "all", "precisions": ["double", "quad"]})"),
                       "'precisions[1]': unknown precision 'quad'"));
  EXPECT_TRUE(mentions(error_of(R"({"name": "x", "claims": "all", "precisions": ["mpfr:9"]})"), "'precisions[0]'"));
  EXPECT_TRUE(mentions(error_of("{" + base + R"(, "samples": 0})"), "'samples' must be an integer from 1 to 10000"));
  EXPECT_TRUE(mentions(error_of("{" + base + R"(, "samples": 2.5})"), "'samples'"));
  EXPECT_TRUE(mentions(error_of("{" + base + R"(, "samples": "4"})"), "'samples'"));
  EXPECT_TRUE(mentions(error_of("{" + base + R"(, "seed": -1})"), "'seed' must be a non-negative integer"));
  EXPECT_TRUE(mentions(error_of("{" + base + R"(, "expected_overrides": {"phi3-det": "maybe"}})"), "is not a verdict"));
  EXPECT_TRUE(mentions(error_of("{" + base + R"(, "expected_overrides": {"nope": "holds"}})"), "unknown claim id 'nope'"));
}

TEST(Scene, UnknownNameAndUnreadableFileAreNamed) {
  try {
    load_scene("/nonexistent/scene.json");
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_TRUE(mentions(e.what(), "'/nonexistent/scene.json'")) << e.what();
  }
}

}  // namespace
}  // namespace simpson::verify

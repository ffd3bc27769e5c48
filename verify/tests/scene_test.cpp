#include <simpson/verify/experiments.hpp>
#include <simpson/verify/scene.hpp>

#include <simpson/verify/ledger.hpp>

#include <gtest/gtest.h>

#include <algorithm>

namespace simpson::verify {
namespace {

/// The message of the std::invalid_argument that parsing `text` throws ("" if it does not throw).
std::string scene_error_of(const std::string& text) {
  try {
    parse_scene(text, "t.json", paper_book());
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

bool mentions(const std::string& message, const std::string& part) { return message.find(part) != std::string::npos; }

TEST(Scene, EmbeddedScenesParseAndPaperHasEveryClaim) {
  const scene paper = load_scene("paper", paper_book());
  const scene beyond = load_scene("beyond", paper_book());
  // "all" is every claim of the paper; "beyond" the rest of the ledger.
  EXPECT_EQ(paper.claims.size() + beyond.claims.size(), paper_book().claims.size());
  const auto of_the_paper = std::count_if(paper_book().claims.begin(), paper_book().claims.end(), [](const claim& c) { return c.section != "beyond"; });
  EXPECT_EQ(paper.claims.size(), static_cast<std::size_t>(of_the_paper));
  for (const std::string& id : beyond.claims) EXPECT_EQ(paper_book().find(id).section, "beyond") << id;
  EXPECT_EQ(paper.seed, default_seed);
  const scene quick = load_scene("quick", paper_book());
  for (const std::string& id : required_claim_ids()) {
    EXPECT_NE(std::find(quick.claims.begin(), quick.claims.end(), id), quick.claims.end()) << id;
  }
}

TEST(Scene, ValidMinimalSceneTakesDefaults) {
  const scene s = parse_scene(R"({"name": "mini", "claims": ["phi3-det"], "precisions": ["double"]})", "t.json", paper_book());
  EXPECT_EQ(s.samples, default_samples);
  EXPECT_EQ(s.seed, default_seed);
  ASSERT_EQ(s.claims.size(), 1u);
}

TEST(Scene, ClaimsAreKeptInLedgerOrderWithoutDuplicates) {
  const scene s = parse_scene(R"({"name": "o", "claims": ["phi3-det", "newmark-det", "phi3-det"], "precisions": ["double"]})", "t", paper_book());
  ASSERT_EQ(s.claims.size(), 2u);
  EXPECT_EQ(s.claims[0], "newmark-det");
}

TEST(Scene, MalformedJsonNamesLineAndColumn) {
  const std::string message = scene_error_of("{\n  \"name\": \"x\",\n  \"claims\": [,]\n}");
  EXPECT_TRUE(mentions(message, "scene 't.json': malformed JSON at line 3, column")) << message;
  EXPECT_TRUE(mentions(scene_error_of(""), "malformed JSON")) << scene_error_of("");
  EXPECT_TRUE(mentions(scene_error_of("{\"name\": \"x\", \"claims\""), "malformed JSON")) << "truncated";
}

TEST(Scene, NumberOverflowIsMalformedJsonNotACrash) {
  // Found by the fuzzer: nlohmann::json throws out_of_range (406), not parse_error, on this.
  EXPECT_TRUE(mentions(scene_error_of("9999929999992e9999929999992"), "scene 't.json': malformed JSON"));
  EXPECT_TRUE(mentions(scene_error_of(R"({"name": "x", "claims": "all", "precisions": ["double"], "samples": 1e99999})"),
                       "malformed JSON"));
}

TEST(Scene, RejectsEveryBadField) {
  const std::string base = R"("name": "x", "claims": ["phi3-det"], "precisions": ["double"])";
  EXPECT_TRUE(mentions(scene_error_of("[1, 2]"), "top level must be an object"));
  EXPECT_TRUE(mentions(scene_error_of("{" + base + R"(, "colour": 1})"), "unknown key 'colour'"));
  EXPECT_TRUE(mentions(scene_error_of(R"({"claims": "all", "precisions": ["double"]})"), "'name' must be a string"));
  EXPECT_TRUE(mentions(scene_error_of(R"({"name": "Bad Name", "claims": "all", "precisions": ["double"]})"), "'name' must be"));
  EXPECT_TRUE(mentions(scene_error_of(R"({"name": "x", "precisions": ["double"]})"), "'claims' is missing"));
  EXPECT_TRUE(mentions(scene_error_of(R"({"name": "x", "claims": [], "precisions": ["double"]})"), "'claims' must be"));
  EXPECT_TRUE(mentions(scene_error_of(R"({"name": "x", "claims": ["phi4-det"], "precisions": ["double"]})"),
                       "'claims[0]': unknown claim id 'phi4-det'"));
  EXPECT_TRUE(mentions(scene_error_of(R"({"name": "x", "claims": [3], "precisions": ["double"]})"), "'claims[0]' must be a string"));
  EXPECT_TRUE(mentions(scene_error_of(R"({"name": "x", "claims": "all", "precisions": "double"})"), "'precisions' must be"));
  EXPECT_TRUE(mentions(scene_error_of(R"({"name": "x", "claims": "all", "precisions": ["double", "quad"]})"),
                       "'precisions[1]': unknown precision 'quad'"));
  EXPECT_TRUE(mentions(scene_error_of(R"({"name": "x", "claims": "all", "precisions": ["mpfr:9"]})"), "'precisions[0]'"));
  EXPECT_TRUE(mentions(scene_error_of("{" + base + R"(, "samples": 0})"), "'samples' must be an integer from 1 to 10000"));
  EXPECT_TRUE(mentions(scene_error_of("{" + base + R"(, "samples": 2.5})"), "'samples'"));
  EXPECT_TRUE(mentions(scene_error_of("{" + base + R"(, "samples": "4"})"), "'samples'"));
  EXPECT_TRUE(mentions(scene_error_of("{" + base + R"(, "seed": -1})"), "'seed' must be a non-negative integer"));
  EXPECT_TRUE(mentions(scene_error_of("{" + base + R"(, "expected_overrides": {"phi3-det": "maybe"}})"), "is not a verdict"));
  EXPECT_TRUE(mentions(scene_error_of("{" + base + R"(, "expected_overrides": {"nope": "holds"}})"), "unknown claim id 'nope'"));
}

TEST(Scene, ExperimentSectionsParseWithDefaultsAndOnlyWhenAsked) {
  const scene none = parse_scene(R"({"name": "c", "claims": ["phi3-det"], "precisions": ["double"]})", "t", paper_book());
  EXPECT_FALSE(none.experiments.any());
  const scene s = parse_scene(R"({"name": "e", "table1": {}, "long_time": {"steps_double": 1e5}})", "t", paper_book());
  EXPECT_TRUE(s.claims.empty());
  ASSERT_TRUE(s.experiments.find<table1_settings>() && s.experiments.find<long_time_settings>());
  EXPECT_FALSE(s.experiments.find<work_precision_settings>() || s.experiments.find<stability_settings>());
  EXPECT_EQ(s.experiments.find<table1_settings>()->meshes, (std::vector<long long>{10, 20, 40}));
  EXPECT_EQ(s.experiments.find<long_time_settings>()->steps_double, 100000);
  const scene paper = load_scene("paper", paper_book());
  EXPECT_TRUE(paper.experiments.find<table1_settings>() && paper.experiments.find<work_precision_settings>() && paper.experiments.find<stability_settings>() &&
              paper.experiments.find<long_time_settings>());
  // Every scheme but Lobatto IIIA–IIIB(3), Simpson's own map by another implementation: Simpson is
  // drawn once, as the method.
  std::vector<scheme_id> peers = all_schemes();
  peers.erase(std::find(peers.begin(), peers.end(), scheme_id::lobatto_iiia_iiib_3));
  EXPECT_EQ(paper.experiments.find<work_precision_settings>()->schemes, peers);
  // The paper scene's nonlinear section is its problems' error against work alone, beside the oscillator's.
  ASSERT_TRUE(paper.experiments.find<nonlinear_settings>());
  EXPECT_EQ(paper.experiments.find<nonlinear_settings>()->parts, std::vector<std::string>{"problems"});
  const scene beyond = load_scene("beyond", paper_book());
  ASSERT_TRUE(beyond.experiments.find<nonlinear_settings>());
  EXPECT_EQ(beyond.experiments.find<nonlinear_settings>()->problems, nonlinear_problem_names());
  const scene zero_e = parse_scene(R"({"name": "e", "nonlinear": {"eccentricity": 0, "problems": ["kepler"]}})", "t", paper_book());
  EXPECT_EQ(zero_e.experiments.find<nonlinear_settings>()->eccentricity, 0);  // a circle is an ellipse
}

TEST(Scene, RejectsEveryBadExperimentParameter) {
  const std::string head = R"({"name": "x", )";
  const auto section = [&](const std::string& body) { return scene_error_of(head + body + "}"); };
  EXPECT_TRUE(mentions(section(R"("table1": 3)"), "'table1' must be an object"));
  EXPECT_TRUE(mentions(section(R"("table1": {"n": [10]})"), "unknown key 'table1.n'"));
  EXPECT_TRUE(mentions(section(R"("table1": {"N": [10, 0]})"), "'table1.N'[1] must be an integer from 1"));
  EXPECT_TRUE(mentions(section(R"("table1": {"N": [10.5]})"), "'table1.N'[0] must be an integer"));
  EXPECT_TRUE(mentions(section(R"("table1": {"N": []})"), "'table1.N' must be a list"));
  EXPECT_TRUE(mentions(section(R"("table1": {"N": [1e13]})"), "'table1.N'[0] must be an integer from 1 to 1000000"));
  EXPECT_TRUE(mentions(section(R"("table1": {"m": 0})"), "'table1.m' must be a number greater than 0"));
  EXPECT_TRUE(mentions(section(R"("table1": {"m": -1})"), "'table1.m' must be a number greater than 0"));
  EXPECT_TRUE(mentions(section(R"("table1": {"m": "NaN"})"), "'table1.m' must be a number"));
  EXPECT_TRUE(mentions(section(R"("table1": {"m": NaN})"), "malformed JSON at line 1"));
  EXPECT_TRUE(mentions(section(R"("table1": {"m": Infinity})"), "malformed JSON at line 1"));
  EXPECT_TRUE(mentions(section(R"("table1": {"m": 1e999})"), "malformed JSON"));
  EXPECT_TRUE(mentions(section(R"("work_precision": {"N": [16]})"), "'work_precision.precisions' is missing"));
  EXPECT_TRUE(mentions(section(R"("work_precision": {"precisions": ["rational"]})"),
                       "'work_precision.precisions'[0]: 'rational' has no cos or sin"));
  EXPECT_TRUE(mentions(section(R"("work_precision": {"precisions": ["mpfr:9"]})"), "mpfr digits must be an integer from 30"));
  EXPECT_TRUE(mentions(section(R"("work_precision": {"precisions": ["mpfr:100001"]})"), "to 100000"));
  EXPECT_TRUE(mentions(section(R"("work_precision": {"precisions": ["double"], "schemes": ["euler"]})"),
                       "unknown scheme 'euler'"));
  EXPECT_TRUE(mentions(section(R"("work_precision": {"precisions": ["double"], "N": [1e12], "periods": 1000})"),
                       "exceeds the limit"));
  EXPECT_TRUE(mentions(section(R"("work_precision": {"precisions": ["double"], "max_seconds": 0})"),
                       "'work_precision.max_seconds' must be a number greater than 0"));
  EXPECT_TRUE(mentions(section(R"("stability": {"precisions": ["double"], "omega_h": [0]})"),
                       "'stability.omega_h'[0] must be a number greater than 0"));
  EXPECT_TRUE(mentions(section(R"("stability": {"precisions": ["double"], "stiff_ratios": [-1e8]})"),
                       "'stability.stiff_ratios'[0]"));
  EXPECT_TRUE(mentions(section(R"("stability": {"precisions": ["double"], "stiff_doublings": 61})"),
                       "'stability.stiff_doublings' must be an integer from 10 to 60"));
  // A size too small for the endpoints' fit to decide is refused, naming the smallest that decides
  // (1000 once made six endpoint expectations fail).
  EXPECT_TRUE(mentions(section(R"("stability": {"precisions": ["double"], "endpoint_power": 1000})"),
                       "'stability.endpoint_power' must be at least 1000000, the smallest size whose fit decides"));
  EXPECT_TRUE(mentions(section(R"("stability": {"precisions": ["double"], "endpoint_power": 0})"),
                       "'stability.endpoint_power' must be an integer from 1"));
  EXPECT_TRUE(mentions(section(R"("stability": {"precisions": ["double"], "masses": [0]})"), "'stability.masses'[0]"));
  EXPECT_TRUE(mentions(section(R"("stability": {"precisions": ["double"], "steps": 0})"), "'stability.steps' must be an integer"));
  EXPECT_TRUE(mentions(section(R"("long_time": {"omega_h": 3})"), "'long_time.omega_h' must be a number greater than 0 and at most 2"));
  EXPECT_TRUE(mentions(section(R"("long_time": {"mpfr_digits": 5})"), "'long_time.mpfr_digits' must be an integer from 30"));
  EXPECT_TRUE(mentions(section(R"("long_time": {"steps_double": 1e19})"), "'long_time.steps_double' must be an integer"));
  EXPECT_TRUE(mentions(section(R"("nonlinear": {"problems": ["pendulum", "lorenz"]})"),
                       "'nonlinear.problems'[1]: unknown name 'lorenz' (known: oscillator, pendulum, kepler, henon-heiles, fpu)"));
  EXPECT_TRUE(mentions(section(R"("nonlinear": {"problems": ["kepler", "kepler"]})"), "'kepler' is listed twice"));
  EXPECT_TRUE(mentions(section(R"("nonlinear": {"problems": []})"), "'nonlinear.problems' must be a non-empty list"));
  EXPECT_TRUE(mentions(section(R"("floating": {"steppers": ["phi3-matrix", "rk4"]})"), "rk4"));
  EXPECT_TRUE(mentions(section(R"("floating": {"formats": ["half"]})"), "half"));
  EXPECT_TRUE(mentions(section(R"("floating": {"h_denominator": 0})"), "'floating.h_denominator' must be an integer from 1"));
  EXPECT_TRUE(mentions(section(R"("floating": {"gappa": true})"), "gappa"));
  EXPECT_TRUE(mentions(section(R"("nonlinear": {"pendulum_q0": 3.1416})"), "'nonlinear.pendulum_q0' must be a number greater than 0"));
  EXPECT_TRUE(mentions(section(R"("nonlinear": {"pendulum_q0": 0})"), "'nonlinear.pendulum_q0' must be a number greater than 0"));
  EXPECT_TRUE(mentions(section(R"("nonlinear": {"eccentricity": 0.99})"), "'nonlinear.eccentricity' must be a number"));
  EXPECT_TRUE(mentions(section(R"("nonlinear": {"eccentricity": -0.1})"), "'nonlinear.eccentricity' must be a number"));
  EXPECT_TRUE(mentions(section(R"("nonlinear": {"pendulum_N": [0]})"), "'nonlinear.pendulum_N'[0] must be an integer from 1"));
  EXPECT_TRUE(mentions(section(R"("nonlinear": {"reference_digits": 10})"), "'nonlinear.reference_digits' must be an integer from 20"));
  EXPECT_TRUE(mentions(section(R"("nonlinear": {"brouwer_h": 0})"), "'nonlinear.brouwer_h' must be a number greater than 0"));
  EXPECT_TRUE(mentions(section(R"("nonlinear": {"brouwer_h": 1.5})"), "'nonlinear.brouwer_h' must be a number greater than 0"));
  EXPECT_TRUE(mentions(section(R"("nonlinear": {"brouwer_steps": 0})"), "'nonlinear.brouwer_steps' must be an integer from 1"));
  EXPECT_TRUE(mentions(section(R"("nonlinear": {"V": "x^3"})"), "unknown key 'nonlinear.V'"));
}

TEST(Scene, UnknownNameAndUnreadableFileAreNamed) {
  try {
    load_scene("/nonexistent/scene.json", paper_book());
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_TRUE(mentions(e.what(), "'/nonexistent/scene.json'")) << e.what();
  }
}

}  // namespace
}  // namespace simpson::verify

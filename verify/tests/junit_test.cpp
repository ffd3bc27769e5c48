// report.junit.xml parses as XML (Boost.PropertyTree's parser) and counts every claim and table.

#include "altered_paper.hpp"

#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/experiments.hpp>
#include <simpson/verify/junit.hpp>
#include <simpson/verify/report.hpp>
#include <simpson/verify/report_compare.hpp>
#include <simpson/verify/scene.hpp>
#include <simpson/verify/verdict_table.hpp>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace simpson::verify {
namespace {

boost::property_tree::ptree parsed(const std::string& xml) {
  std::istringstream in(xml);
  boost::property_tree::ptree tree;
  boost::property_tree::read_xml(in, tree);  // throws on malformed XML
  return tree;
}

/// The quick scene's stability section alone, with `claims`: a run with expectations to fail.
scene stability_scene(std::vector<std::string> claims) {
  scene s = load_scene("quick", paper_book());
  s.claims = std::move(claims);
  const scene quick = load_scene("quick", paper_book());
  s.experiments = {};
  s.experiments.set(*find_section(experiment_sections(), "stability"), *quick.experiments.find<stability_settings>(), experiment_sections());
  return s;
}

TEST(JUnit, ParsesAndCountsEveryClaimAndTable) {
  scene s = load_scene("quick", paper_book());
  s.expected_overrides["phi3-det"] = verdict::fails;  // one testcase must fail, and say why
  const run_record r = run(s);
  const boost::property_tree::ptree tree = parsed(report_junit(r));
  const auto& root = tree.get_child("testsuites");
  std::size_t suites = 0, claim_cases = 0, failures = 0;
  for (const auto& [tag, suite] : root) {
    if (tag != "testsuite") continue;
    ++suites;
    std::size_t cases = 0;
    for (const auto& [case_tag, testcase] : suite) {
      if (case_tag != "testcase") continue;
      ++cases;
      if (testcase.count("failure") > 0) {
        ++failures;
        if (suite.get<std::string>("<xmlattr>.name") == "claims") {
          EXPECT_EQ(testcase.get<std::string>("<xmlattr>.name"), "phi3-det");
          EXPECT_EQ(testcase.get<std::string>("failure.<xmlattr>.message"), "verdict holds, expected fails");
        }
      }
    }
    EXPECT_EQ(suite.get<std::size_t>("<xmlattr>.tests"), cases);
    if (suite.get<std::string>("<xmlattr>.name") == "claims") claim_cases = cases;
  }
  EXPECT_EQ(claim_cases, r.outcomes.size());
  EXPECT_EQ(suites, 1 + r.sections.size());
  EXPECT_EQ(root.get<std::size_t>("<xmlattr>.failures"), failures);
  EXPECT_GE(failures, 1u);
}

// The JUnit view agrees with the exit code: the quick scene's masses 1e-300 and 1e300 underflow in
// double (a fault of the stability section's table, a finding), and its errata and an expected
// failure are verdicts as expected: exit 0 and no failure. Errata carry their verdict as a
// property; the expected failure is skipped with its reason.
TEST(JUnit, FailuresAreExactlyWhatMakesTheExitCodeNonZero) {
  scene s = load_scene("quick", paper_book());
  s.claims = {"phi3-det", "gamma-system", "table-values"};
  for (const char* section : {"table1", "work_precision", "long_time"}) s.experiments.remove(section);
  run_record r = run(s);
  ASSERT_EQ(run_exit_code(r), 0);
  // No claim of the paper's ledger expects `fails` today: one made so (table-values, an erratum as
  // printed) shows how the JUnit view renders an expected failure.
  for (claim_outcome& o : r.outcomes) {
    if (o.checked->id == "table-values") o.result.outcome = o.expected = verdict::fails;
  }
  ASSERT_EQ(run_exit_code(r), 0);
  const boost::property_tree::ptree tree = parsed(report_junit(r));
  const auto& root = tree.get_child("testsuites");
  EXPECT_EQ(root.get<std::size_t>("<xmlattr>.failures"), 0u);
  EXPECT_EQ(root.get<std::size_t>("<xmlattr>.errors"), 0u);
  EXPECT_EQ(root.get<std::size_t>("<xmlattr>.skipped"), 1u);
  std::map<std::string, std::string> verdicts;
  bool fault_recorded = false;
  for (const auto& [tag, suite] : root) {
    if (tag != "testsuite") continue;
    for (const auto& [case_tag, testcase] : suite) {
      if (case_tag != "testcase") continue;
      EXPECT_EQ(testcase.count("failure"), 0u);
      const std::string name = testcase.get<std::string>("<xmlattr>.name");
      for (const auto& [p_tag, property] : testcase.get_child("properties")) {
        if (property.get<std::string>("<xmlattr>.name") == "verdict") verdicts[name] = property.get<std::string>("<xmlattr>.value");
        if (property.get<std::string>("<xmlattr>.name") == "faults" && property.get<std::string>("<xmlattr>.value") != "0") {
          fault_recorded = true;
        }
      }
      if (name == "table-values") {
        EXPECT_EQ(testcase.get<std::string>("skipped.<xmlattr>.message").rfind("expected failure", 0), 0u);
      }
      if (name == "gamma-system") {
        EXPECT_NE(testcase.get<std::string>("system-out").find("Corrected:"), std::string::npos);
        EXPECT_NE(testcase.get<std::string>("system-out").find("\\gamma^2-1"), std::string::npos);  // the TeX read
      }
    }
  }
  EXPECT_EQ(verdicts["gamma-system"], "erratum");
  EXPECT_EQ(verdicts["table-values"], "fails");
  EXPECT_EQ(verdicts["phi3-det"], "holds");
  EXPECT_TRUE(fault_recorded) << "the underflow of the extreme masses is recorded";
}

// A validation (no expected verdicts) speaks of what holds: an erratum fails as a claim that does
// not hold, its consequence fails naming its cause, and no line talks of expected verdicts; a claim
// that holds with a remark linked to an erratum passes. A regression run over the same verdicts
// would pass (they are the ledger's expected ones).
TEST(JUnit, AValidationFailsWhatDoesNotHoldAndNamesACauseOnce) {
  scene s = load_scene("quick", paper_book());
  s.claims = {"gamma-system", "gamma-singular", "experiment-conventions", "table-values", "phi3-det"};
  s.experiments = experiment_settings{};
  for (const std::string& id : s.claims) s.expected_overrides[id] = verdict::holds;
  s.overrides["validate"] = true;
  const run_record r = run(s);
  ASSERT_TRUE(r.validation);
  ASSERT_EQ(run_exit_code(r), 1);
  const boost::property_tree::ptree tree = parsed(report_junit(r));
  std::map<std::string, std::string> types, messages;
  for (const auto& [tag, suite] : tree.get_child("testsuites")) {
    if (tag != "testsuite") continue;
    for (const auto& [case_tag, testcase] : suite) {
      if (case_tag != "testcase" || testcase.count("failure") == 0) continue;
      const std::string name = testcase.get<std::string>("<xmlattr>.name");
      types[name] = testcase.get<std::string>("failure.<xmlattr>.type");
      messages[name] = testcase.get<std::string>("failure.<xmlattr>.message");
    }
  }
  // Table 1's numbers hold (another start reproduces them), with a remark linked to the finding on
  // their description, experiment-conventions: no failure of their own, the cause named once.
  EXPECT_EQ(types.size(), 2u);
  EXPECT_EQ(types["gamma-system"], "does-not-hold");
  EXPECT_EQ(types["experiment-conventions"], "does-not-hold");
  EXPECT_EQ(types.count("table-values"), 0u) << "holds, its remark linked to experiment-conventions: " << messages["table-values"];
  EXPECT_EQ(types.count("gamma-singular"), 0u) << "holds (its printed conclusion the corrected Gamma's): " << messages["gamma-singular"];
  const std::string line = expectation_line(r);
  EXPECT_EQ(line.rfind("Exit code 1: 2 claims do not hold as written (gamma-system, experiment-conventions); see Failures.", 0), 0u) << line;
  EXPECT_EQ(line.find("expected"), std::string::npos) << line;
  EXPECT_NE(summary_line(r).find("2 not holding"), std::string::npos) << summary_line(r);
}

// A consequence is named once, under its cause: on a copy whose Simpson state entry at N = 10 is ten
// times the printed one, no start reproduces Table 1 (table-values fails, no correction) and the
// stated one still does not (experiment-conventions): table-values' JUnit failure is a consequence
// of experiment-conventions, and the exit line counts it apart from the claims that do not hold.
TEST(JUnit, AValidationNamesAConsequenceUnderItsCause) {
  const paper_source copy = altered("Symplectic Simpson  & state", "$ 4.11  \\,\\, 10^{-4} $", "$ 4.11  \\,\\, 10^{-3} $");
  scene s = load_scene("quick", paper_book());
  s.claims = {"experiment-conventions", "table-values"};
  s.experiments = experiment_settings{};
  for (const std::string& id : s.claims) s.expected_overrides[id] = verdict::holds;
  s.overrides["validate"] = true;
  auto book = std::make_shared<claim_book>(paper_book());
  const paper_reading reading = read_paper(copy);
  check_claims_file_formulas(*book, reading.source);
  const run_record r = run(s, book, reading);
  ASSERT_TRUE(r.validation);
  const boost::property_tree::ptree tree = parsed(report_junit(r));
  std::map<std::string, std::string> types, messages;
  for (const auto& [tag, suite] : tree.get_child("testsuites")) {
    if (tag != "testsuite") continue;
    for (const auto& [case_tag, testcase] : suite) {
      if (case_tag != "testcase" || testcase.count("failure") == 0) continue;
      const std::string name = testcase.get<std::string>("<xmlattr>.name");
      types[name] = testcase.get<std::string>("failure.<xmlattr>.type");
      messages[name] = testcase.get<std::string>("failure.<xmlattr>.message");
    }
  }
  EXPECT_EQ(types["experiment-conventions"], "does-not-hold") << messages["experiment-conventions"];
  EXPECT_EQ(types["table-values"], "consequence") << messages["table-values"];
  EXPECT_NE(messages["table-values"].find("a consequence of experiment-conventions"), std::string::npos) << messages["table-values"];
  const std::string line = expectation_line(r);
  EXPECT_NE(line.find("1 follows from another's correction (table-values (from experiment-conventions))"), std::string::npos) << line;
}

// A section's expectation is a testcase of its section: passed while the run shows what was
// predicted, a failure (and exit code 1) when it does not, as a claim not as expected.
TEST(JUnit, AFailedExpectationOfASectionFailsTheRun) {
  scene s = stability_scene({});
  run_record r = run(s);
  ASSERT_EQ(r.sections.size(), 1u);
  ASSERT_FALSE(r.sections[0].expectations.empty());
  EXPECT_EQ(run_exit_code(r), 0);
  EXPECT_TRUE(failed_expectations(r).empty());
  expectation& changed = r.sections[0].expectations.front();
  changed.holds = false;  // as if the run had shown another growth than predicted
  EXPECT_EQ(run_exit_code(r), 1);
  EXPECT_EQ(failed_expectations(r), std::vector<std::string>{"stability." + changed.key});
  const boost::property_tree::ptree tree = parsed(report_junit(r));
  const auto& root = tree.get_child("testsuites");
  EXPECT_EQ(root.get<std::size_t>("<xmlattr>.failures"), 1u);
  bool found = false;
  for (const auto& [tag, suite] : root) {
    if (tag != "testsuite") continue;
    for (const auto& [case_tag, testcase] : suite) {
      if (case_tag != "testcase" || testcase.get<std::string>("<xmlattr>.name") != changed.key) continue;
      found = true;
      EXPECT_EQ(testcase.get<std::string>("failure.<xmlattr>.type"), "expectation-failed");
      EXPECT_EQ(testcase.get<std::string>("<xmlattr>.classname"), "sections.stability.expectations");
    }
  }
  EXPECT_TRUE(found);
}

// The summary is the exit code: a run with a failing expectation and a claim not as expected says
// so on the summary line, in the expectation line (report.md's headline), in report.json's summary
// and all_as_expected, and in JUnit; the same run with both as expected says "as expected"
// everywhere, and counts its expectations.
TEST(JUnit, EveryPlaceThatSummarisesARunAgreesWithItsExitCode) {
  scene s = stability_scene({"phi3-det"});
  run_record r = run(s);
  ASSERT_EQ(r.sections.size(), 1u);
  const std::size_t expectations = r.sections[0].expectations.size();
  ASSERT_GT(expectations, 0u);
  ASSERT_EQ(run_exit_code(r), 0);
  const std::string green = summary_line(r);
  EXPECT_NE(green.find(fmt::format("; {} expectations of the experiments: {} hold; all verdicts as expected", expectations, expectations)),
            std::string::npos) << green;
  EXPECT_EQ(expectation_line(r).rfind("Exit code 0", 0), 0u) << expectation_line(r);
  json report = report_json(r);
  EXPECT_TRUE(report["all_as_expected"].get<bool>());
  EXPECT_EQ(report["summary"]["exit_code"], 0);
  EXPECT_EQ(report["summary"]["expectations"], expectations);

  expectation& changed = r.sections[0].expectations.front();
  changed.holds = false;
  r.outcomes.front().expected = verdict::erratum;  // as if the ledger expected another verdict
  ASSERT_EQ(run_exit_code(r), 1);
  const std::string red = summary_line(r);
  EXPECT_EQ(red.find("as expected;"), std::string::npos) << red;
  EXPECT_EQ(red.find("all verdicts as expected"), std::string::npos) << red;
  EXPECT_NE(red.find("1 not as expected (phi3-det)"), std::string::npos) << red;
  EXPECT_NE(red.find(fmt::format("{} expectations of the experiments: {} hold, 1 failed", expectations, expectations - 1)), std::string::npos) << red;
  EXPECT_NE(red.find("1 expectation failed (stability." + changed.key + ")"), std::string::npos) << red;
  const std::string headline = expectation_line(r);
  EXPECT_EQ(headline.rfind("Exit code 1", 0), 0u) << headline;
  EXPECT_NE(headline.find("stability." + changed.key), std::string::npos) << headline;
  report = report_json(r);
  EXPECT_FALSE(report["all_as_expected"].get<bool>());
  EXPECT_EQ(report["summary"]["exit_code"], 1);
  EXPECT_EQ(report["summary"]["line"], red);
  EXPECT_EQ(report["summary"]["failed_expectations"].size(), 1u);
  EXPECT_EQ(report["summary"]["unexpected"], json::array({"phi3-det"}));
  const std::string markdown = report_markdown(r);
  EXPECT_NE(markdown.find("**" + red + "**"), std::string::npos);
  EXPECT_NE(markdown.find(headline), std::string::npos);
  EXPECT_EQ(parsed(report_junit(r)).get<std::size_t>("testsuites.<xmlattr>.failures"), 2u);

  // Validation: the same run says what does not hold, never "every claim holds".
  r.validation = true;
  r.outcomes.front().expected = verdict::holds;
  r.outcomes.front().result.outcome = verdict::fails;
  const std::string validation = summary_line(r);
  EXPECT_EQ(validation.find("every claim"), std::string::npos) << validation;
  EXPECT_NE(validation.find("1 not holding (phi3-det)"), std::string::npos) << validation;
  EXPECT_NE(validation.find("1 expectation failed"), std::string::npos) << validation;
}

// One rule for every place: a verdict never expected (undecided, unproved, text-changed) fails the
// run even where its record expects it (a record written before the claims reader refused it, or
// made so here), and the exit code, JUnit, report.json's verdict table and stderr's words agree.
// Before the verdict table, the exit code said 0 and JUnit a failure.
TEST(JUnit, AVerdictNeverExpectedFailsTheRunEverywhere) {
  scene s = stability_scene({"phi3-det"});
  run_record r = run(s);
  ASSERT_EQ(run_exit_code(r), 0);
  for (const verdict_row& row : verdict_table(r)) EXPECT_FALSE(fails_the_run(row)) << row.name;
  const std::size_t rows = 1 + r.sections[0].expectations.size();
  EXPECT_EQ(verdict_table(r).size(), rows);
  for (const verdict v : {verdict::undecided, verdict::unproved, verdict::text_changed}) {
    r.outcomes.front().result.outcome = r.outcomes.front().expected = v;
    EXPECT_EQ(run_exit_code(r), 1) << to_string(v);
    const verdict_row row = verdict_table(r).front();
    EXPECT_EQ(row.type, to_string(v));
    EXPECT_EQ(row.message.rfind("verdict " + to_string(v) + ", expected " + to_string(v) + ": ", 0), 0u) << row.message;
    EXPECT_EQ(parsed(report_junit(r)).get<std::size_t>("testsuites.<xmlattr>.failures"), 1u) << to_string(v);
    const json report = report_json(r);
    EXPECT_FALSE(report["all_as_expected"].get<bool>());
    ASSERT_EQ(report["verdicts"].size(), rows);
    EXPECT_EQ(report["verdicts"][0]["status"], "failed");
    EXPECT_EQ(report["verdicts"][1]["kind"], "expectation");
  }
  // A skipped claim never fails the run, and an expected failure is set aside, not failed.
  r.outcomes.front().result.outcome = verdict::skipped;
  r.outcomes.front().expected = verdict::holds;
  EXPECT_EQ(run_exit_code(r), 0);
  EXPECT_EQ(report_json(r)["verdicts"][0]["status"], "skipped");
  r.outcomes.front().result.outcome = r.outcomes.front().expected = verdict::fails;
  EXPECT_EQ(run_exit_code(r), 0);
  EXPECT_EQ(report_json(r)["verdicts"][0]["status"], "expected-failure");
}

// `compare --junit`: a failing testcase per difference, named by its place, in XML a CI parses; one
// passing testcase when the reports agree. `--format json`: the same as data.
TEST(JUnit, ACompareOfTwoReportsIsATestSuiteOfItsDifferences) {
  const json reference = load_report(std::filesystem::path(SIMPSON_SOURCE_DIR) / "reports" / "reference" / "paper");
  json changed = reference;
  for (json& c : changed["claims"]) {
    if (c["id"] == "phi3-det") c["verdict"] = "fails";
    if (c["id"] == "gamma-system") c["correction"] = "entry (3, 3) is <less> & \"more\"";
  }
  const report_comparison found = compare_reports(reference, changed);
  ASSERT_EQ(found.differences.size(), 2u);
  const boost::property_tree::ptree tree = parsed(comparison_junit(found, "old", "new"));
  EXPECT_EQ(tree.get<std::size_t>("testsuites.<xmlattr>.failures"), 2u);
  std::set<std::string> names;
  for (const auto& [tag, testcase] : tree.get_child("testsuites.testsuite")) {
    if (tag != "testcase") continue;
    names.insert(testcase.get<std::string>("<xmlattr>.name"));
    EXPECT_EQ(testcase.get<std::string>("failure.<xmlattr>.type"), "difference");
  }
  EXPECT_EQ(names, (std::set<std::string>{"claim phi3-det", "claim gamma-system"}));  // one testcase per claim that differs
  const json as_data = comparison_json(found, "old", "new");
  EXPECT_FALSE(as_data["agree"].get<bool>());
  EXPECT_EQ(as_data["differences"][0]["where"], "claim phi3-det");
  EXPECT_EQ(as_data["differences"][0]["what"][0], "verdict: \"holds\" → \"fails\"");

  const boost::property_tree::ptree agree = parsed(comparison_junit(compare_reports(reference, reference), "old", "new"));
  EXPECT_EQ(agree.get<std::size_t>("testsuites.<xmlattr>.failures"), 0u);
  EXPECT_EQ(agree.get<std::string>("testsuites.testsuite.testcase.<xmlattr>.name"), "the reports agree");
}

// The smallest endpoint_power a scene may ask for (10^6, scene.cpp) decides every endpoint
// expectation: the refusal below it is not a guess. 10^3, the old minimum, did not.
TEST(JUnit, TheSmallestEndpointPowerAllowedDecidesEveryExpectation) {
  scene s = stability_scene({});
  s.experiments.find<stability_settings>()->endpoint_power = 1000000;
  const run_record r = run(s);
  EXPECT_TRUE(failed_expectations(r).empty()) << ::testing::PrintToString(failed_expectations(r));
  s.experiments.find<stability_settings>()->endpoint_power = 1000;
  EXPECT_FALSE(failed_expectations(run(s)).empty());  // why the minimum is not 1000
}

// A check that throws is an error of its testcase (exit code 3).
TEST(JUnit, AThrowingCheckIsAnError) {
  scene s = load_scene("quick", paper_book());
  s.claims = {"phi3-det"};
  s.experiments = {};
  const run_record r = run(s, {}, {}, {}, [](const claim& c, const run_context&) -> claim_result { throw std::logic_error("a fault of the test's (" + c.id + ")"); });
  ASSERT_EQ(run_exit_code(r), 3);
  const boost::property_tree::ptree tree = parsed(report_junit(r));
  EXPECT_EQ(tree.get<std::size_t>("testsuites.<xmlattr>.errors"), 1u);
  EXPECT_EQ(tree.get<std::size_t>("testsuites.<xmlattr>.failures"), 0u);
}

TEST(JUnit, EscapesWhatXmlReserves) {
  scene s = load_scene("quick", paper_book());
  s.name = "a<b&\"c\"";
  s.experiments = {};
  const run_record r = run(s);
  EXPECT_EQ(parsed(report_junit(r)).get<std::string>("testsuites.<xmlattr>.name"), "simpson-verify scene a<b&\"c\"");
}

}  // namespace
}  // namespace simpson::verify

// report.junit.xml parses as XML (Boost.PropertyTree's parser) and counts every claim and table.

#include <simpson/verify/junit.hpp>
#include <simpson/verify/scene.hpp>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <gtest/gtest.h>

#include <sstream>

namespace simpson::verify {
namespace {

boost::property_tree::ptree parsed(const std::string& xml) {
  std::istringstream in(xml);
  boost::property_tree::ptree tree;
  boost::property_tree::read_xml(in, tree);  // throws on malformed XML
  return tree;
}

TEST(JUnit, ParsesAndCountsEveryClaimAndTable) {
  scene s = load_scene("quick");
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

TEST(JUnit, EscapesWhatXmlReserves) {
  scene s = load_scene("quick");
  s.name = "a<b&\"c\"";
  s.experiments = {};
  const run_record r = run(s);
  EXPECT_EQ(parsed(report_junit(r)).get<std::string>("testsuites.<xmlattr>.name"), "simpson-verify scene a<b&\"c\"");
}

}  // namespace
}  // namespace simpson::verify

#include <simpson/verify/junit.hpp>

#include <simpson/verify/printed_statement.hpp>
#include <simpson/verify/report_html.hpp>
#include <simpson/verify/verdict_table.hpp>

#include <fmt/format.h>

#include <utility>
#include <variant>

namespace simpson::verify {
namespace {

std::string escaped(const std::string& text) { return markup_escaped(text); }

/// What a testcase records. At most one of failure, error, skipped; `out` goes to <system-out>.
struct testcase {
  std::string name, classname;
  std::vector<std::pair<std::string, std::string>> properties;
  enum class result { passed, failure, error, skipped } outcome = result::passed;
  std::string message, type, detail, out;
};

struct suite_counts {
  std::size_t tests = 0, failures = 0, errors = 0, skipped = 0;
  void add(const testcase& t) {
    ++tests;
    failures += t.outcome == testcase::result::failure;
    errors += t.outcome == testcase::result::error;
    skipped += t.outcome == testcase::result::skipped;
  }
  void add(const suite_counts& c) {
    tests += c.tests;
    failures += c.failures;
    errors += c.errors;
    skipped += c.skipped;
  }
  std::string attributes() const {
    return fmt::format("tests=\"{}\" failures=\"{}\" errors=\"{}\" skipped=\"{}\"", tests, failures, errors, skipped);
  }
};

std::string testcase_xml(const testcase& t) {
  std::string xml = fmt::format("    <testcase name=\"{}\" classname=\"{}\">\n", escaped(t.name), escaped(t.classname));
  if (!t.properties.empty()) {
    xml += "      <properties>\n";
    for (const auto& [name, value] : t.properties) {
      xml += fmt::format("        <property name=\"{}\" value=\"{}\"/>\n", escaped(name), escaped(value));
    }
    xml += "      </properties>\n";
  }
  const auto element = [&](const char* tag) {
    xml += fmt::format("      <{} message=\"{}\"{}>{}</{}>\n", tag, escaped(t.message),
                       t.type.empty() ? "" : " type=\"" + escaped(t.type) + "\"", escaped(t.detail), tag);
  };
  switch (t.outcome) {
    case testcase::result::passed: break;
    case testcase::result::failure: element("failure"); break;
    case testcase::result::error: element("error"); break;
    case testcase::result::skipped: element("skipped"); break;
  }
  if (!t.out.empty()) xml += "      <system-out>" + escaped(t.out) + "</system-out>\n";
  return xml + "    </testcase>\n";
}

// No time attributes (they are optional in JUnit): run times live in timing.json, so that this file
// is the same from run to run.
std::string suite_xml(const std::string& name, const std::vector<testcase>& cases, suite_counts& total) {
  suite_counts counts;
  for (const testcase& t : cases) counts.add(t);
  total.add(counts);
  std::string xml = fmt::format("  <testsuite name=\"{}\" {}>\n", escaped(name), counts.attributes());
  for (const testcase& t : cases) xml += testcase_xml(t);
  return xml + "  </testsuite>\n";
}

/// A claim, as its row of the verdict table judges it (claim_row: a failure exactly when the exit
/// code counts it, an error when its check threw); an erratum as expected passes with its printed
/// and corrected statements in <system-out>; a `fails` as expected is skipped with its reason (an
/// expected failure, as pytest writes xfail), so that a CI view shows both for what they are.
testcase claim_case(const claim_outcome& o, bool validation) {
  const claim& c = *o.checked;
  const verdict_row row = claim_row(o, validation);
  testcase t{c.id, "claims.section-" + c.section, {}, testcase::result::passed, "", "", "", ""};
  t.properties = {{"verdict", row.verdict}, {"expected", row.expected}, {"section", c.section}, {"equation", c.equation}};
  const printed_statement printed = printed_of(o);
  std::string summary = "Printed (" + printed.source + "): " + printed.text;
  if (!o.result.correction.empty()) summary += "\nCorrected: " + o.result.correction;
  if (!o.result.note.empty()) summary += "\nNote: " + o.result.note;
  using status = verdict_row::status;
  switch (row.state) {
    case status::error:
    case status::failed:
      t.outcome = row.state == status::error ? testcase::result::error : testcase::result::failure;
      t.type = row.type;
      t.message = row.message;
      t.detail = row.type == "certificate-rejected" ? o.result.evidence["coq"].value("coqc_output", "") : summary;
      break;
    case status::skipped:
    case status::expected_failure:
      t.outcome = testcase::result::skipped;
      t.message = row.message;
      t.out = summary;
      break;
    case status::passed:
      t.out = row.type == "fixed-accepted"               ? "Fixed: recorded as " + row.expected + ", now holds (accepted: --accept-fixes).\n" + summary
              : *meaning(o.result.outcome).passed_words != '\0' ? meaning(o.result.outcome).passed_words + ("\n" + summary)
                                                                 : std::string();
      break;
  }
  return t;
}

/// A table of a section: its faults (overflow, underflow, non-finite, unstable, failed) are
/// findings of the experiment, not failures of the run (they never change the exit code): counted
/// in a property and listed in <system-out>.
testcase table_case(const section_result& section, const table& t) {
  testcase c{t.key, "sections." + section.name, {}, testcase::result::passed, "", "", "", ""};
  std::size_t faults = 0;
  for (std::size_t row = 0; row < t.rows.size(); ++row) {
    for (std::size_t col = 0; col < t.rows[row].size(); ++col) {
      if (!t.rows[row][col].is_fault()) continue;
      ++faults;
      c.out += fmt::format("row {}, column {}: {}\n", row, t.columns[col].key, t.rows[row][col].value());
    }
  }
  c.properties = {{"rows", std::to_string(t.rows.size())}, {"faults", std::to_string(faults)}};
  if (faults > 0) c.out = fmt::format("{} {} recorded in table {} (a finding of the experiment, not a failure):\n", faults,
                                      faults == 1 ? "fault" : "faults", t.key) + c.out;
  return c;
}

/// A section's expectation, as its row of the verdict table judges it: a failure when the run did
/// not show what was predicted.
testcase expectation_case(const section_result& section, const expectation& e) {
  const verdict_row row = expectation_row(section, e);
  testcase c{e.key, "sections." + section.name + ".expectations", {}, testcase::result::passed, "", "", "", ""};
  c.properties = {{"holds", e.holds ? "yes" : "no"}};
  c.out = "Expected: " + e.statement + "\nPredicted: " + e.predicted + "\nObserved: " + e.observed;
  if (fails_the_run(row)) {
    c.outcome = testcase::result::failure;
    c.type = row.type;
    c.message = row.message;
    c.detail = c.out;
  }
  return c;
}

}  // namespace

std::string report_junit(const run_record& r) {
  suite_counts total;
  std::vector<testcase> claims;
  for (const claim_outcome& o : r.outcomes) claims.push_back(claim_case(o, r.validation));
  std::string body = suite_xml("claims", claims, total);
  for (const section_result& section : r.sections) {
    std::vector<testcase> tables;
    for (const section_block& block : section.blocks) {
      const table* t = std::get_if<table>(&block);
      if (t != nullptr && !t->timing) tables.push_back(table_case(section, *t));
    }
    for (const expectation& e : section.expectations) tables.push_back(expectation_case(section, e));
    body += suite_xml("section " + section.name, tables, total);
  }
  return fmt::format("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"simpson-verify scene {}\" {}>\n",
                     escaped(r.run_scene.name), total.attributes()) +
         body + "</testsuites>\n";
}

}  // namespace simpson::verify

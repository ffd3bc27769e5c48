#include <simpson/verify/junit.hpp>

#include <fmt/format.h>

#include <variant>

namespace simpson::verify {
namespace {

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

struct testcase {
  std::string name, classname, failure, detail;
};

// No time attributes (they are optional in JUnit): run times live in timing.json, so that this file
// is the same from run to run.
std::string suite(const std::string& name, const std::vector<testcase>& cases) {
  std::size_t failures = 0;
  for (const testcase& t : cases) failures += !t.failure.empty();
  std::string xml = fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\">\n", escaped(name),
                                cases.size(), failures);
  for (const testcase& t : cases) {
    xml += fmt::format("    <testcase name=\"{}\" classname=\"{}\"", escaped(t.name), escaped(t.classname));
    if (t.failure.empty()) {
      xml += "/>\n";
    } else {
      xml += fmt::format(">\n      <failure message=\"{}\" type=\"{}\">{}</failure>\n    </testcase>\n", escaped(t.failure),
                         "simpson-verify", escaped(t.detail));
    }
  }
  return xml + "  </testsuite>\n";
}

}  // namespace

std::string report_junit(const run_record& r) {
  std::vector<testcase> claims;
  for (const claim_outcome& o : r.outcomes) {
    testcase t{o.checked->id, "claims.section-" + o.checked->section, "", ""};
    if (o.result.outcome != o.expected) {
      t.failure = "verdict " + to_string(o.result.outcome) + ", expected " + to_string(o.expected);
      t.detail = o.checked->statement + (o.result.note.empty() ? "" : "\n" + o.result.note);
    }
    claims.push_back(t);
  }
  std::string body = suite("claims", claims);
  std::size_t tests = claims.size(), failures = 0;
  for (const testcase& t : claims) failures += !t.failure.empty();
  for (const section_result& section : r.sections) {
    std::vector<testcase> tables;
    for (const section_block& block : section.blocks) {
      const table* t = std::get_if<table>(&block);
      if (t == nullptr || t->timing) continue;
      testcase c{t->key, "sections." + section.name, "", ""};
      std::size_t faults = 0;
      for (std::size_t row = 0; row < t->rows.size(); ++row) {
        for (std::size_t col = 0; col < t->rows[row].size(); ++col) {
          if (!t->rows[row][col].is_fault()) continue;
          ++faults;
          c.detail += fmt::format("row {}, column {}: {}\n", row, t->columns[col].key, t->rows[row][col].value());
        }
      }
      if (faults > 0) c.failure = fmt::format("{} {} in table {}", faults, faults == 1 ? "fault" : "faults", t->key);
      tables.push_back(c);
    }
    for (const testcase& t : tables) failures += !t.failure.empty();
    tests += tables.size();
    body += suite("section " + section.name, tables);
  }
  return fmt::format("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"simpson-verify scene {}\" tests=\"{}\" "
                     "failures=\"{}\" errors=\"0\">\n",
                     escaped(r.run_scene.name), tests, failures) +
         body + "</testsuites>\n";
}

}  // namespace simpson::verify

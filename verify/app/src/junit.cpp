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
  double seconds = 0;
};

std::string suite(const std::string& name, const std::vector<testcase>& cases, double seconds) {
  std::size_t failures = 0;
  for (const testcase& t : cases) failures += !t.failure.empty();
  std::string xml = fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"0\" time=\"{:.6f}\">\n", escaped(name),
                                cases.size(), failures, seconds);
  for (const testcase& t : cases) {
    xml += fmt::format("    <testcase name=\"{}\" classname=\"{}\" time=\"{:.6f}\"", escaped(t.name), escaped(t.classname), t.seconds);
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
  double claim_seconds = 0;
  for (const claim_outcome& o : r.outcomes) {
    testcase t{o.checked->id, "claims.section-" + o.checked->section, "", "", o.seconds};
    if (o.result.outcome != o.expected) {
      t.failure = "verdict " + to_string(o.result.outcome) + ", expected " + to_string(o.expected);
      t.detail = o.checked->statement + (o.result.note.empty() ? "" : "\n" + o.result.note);
    }
    claim_seconds += o.seconds;
    claims.push_back(t);
  }
  std::string body = suite("claims", claims, claim_seconds);
  std::size_t tests = claims.size(), failures = 0;
  for (const testcase& t : claims) failures += !t.failure.empty();
  for (std::size_t k = 0; k < r.sections.size(); ++k) {
    const section_result& section = r.sections[k];
    std::vector<testcase> tables;
    for (const section_block& block : section.blocks) {
      const table* t = std::get_if<table>(&block);
      if (t == nullptr) continue;
      testcase c{t->key, "sections." + section.name, "", "", 0};
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
    body += suite("section " + section.name, tables, k < r.section_seconds.size() ? r.section_seconds[k] : 0);
  }
  return fmt::format("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"simpson-verify scene {}\" tests=\"{}\" "
                     "failures=\"{}\" errors=\"0\" time=\"{:.6f}\">\n",
                     escaped(r.run_scene.name), tests, failures, r.seconds) +
         body + "</testsuites>\n";
}

}  // namespace simpson::verify

// The committed report of the `paper` scene (reports/reference/paper) must be what this build
// produces: any change in a verdict, an evidence digit or a statement shows up here and in review.
// Run times are not in report.json or report.md (timing.json and timing.md hold them), so both are
// compared whole, apart from report.json's environment (compiler, commit, timestamp); the test
// times each configuration once, since run times are not compared.
// To accept a deliberate change: build/bin/simpson-verify --out reports/reference/paper

#include <simpson/verify/certify.hpp>
#include <simpson/verify/experiments.hpp>
#include <simpson/verify/report.hpp>
#include <simpson/verify/report_compare.hpp>

#include "report_comparison.hpp"
#include "report_tree.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <set>
#include <functional>
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
  scene s = load_scene("paper", paper_book());
  s.experiments.find<work_precision_settings>()->timing = timing_policy{1, 0.01};
  s.experiments.find<nonlinear_settings>()->timing = timing_policy{1, 0.01};
  run_record r = run(s);
  // The committed report was made with --certify: its Coq counts are checked counts.
  ASSERT_FALSE(coqc_version().empty()) << "coqc is needed (scripts/install-deps installs Debian's coq)";
  EXPECT_TRUE(record_certificates(r, true).empty()) << "coqc rejected a certificate";
  // `simpson-verify compare` finds no difference (its tolerances: README, report_compare.hpp) ...
  const report_comparison found = compare_reports(load_report(dir), report_json(r));
  for (const std::string& line : found.lines()) ADD_FAILURE() << line;
  EXPECT_TRUE(found.notes.empty()) << ::testing::PrintToString(found.notes);
  // ... and, on this machine, the two agree byte for byte apart from the environment.
  const json expected = test::without_volatile(json::parse(read(dir / "report.json")));
  const json actual = test::without_volatile(report_json(r));
  ASSERT_EQ(expected["claims"].size(), actual["claims"].size());
  for (std::size_t k = 0; k < actual["claims"].size(); ++k) {
    EXPECT_EQ(expected["claims"][k].dump(2), actual["claims"][k].dump(2)) << "claim " << actual["claims"][k]["id"];
  }
  EXPECT_EQ(expected.dump(2), actual.dump(2));
  EXPECT_EQ(read(dir / "report.md"), report_markdown(r));
  // The committed report has its plots and its HTML page.
  for (const json& plot : expected["plots"]) {
    EXPECT_EQ(plot["files"].size(), 2u) << plot["name"];
    for (const json& file : plot["files"]) EXPECT_TRUE(std::filesystem::exists(dir / file.get<std::string>())) << file;
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "report.html"));
  // The referee's summary says first whether the headline results hold, then orders the findings by
  // consequence: what the source cannot show before the typographical slips that break nothing (the
  // Gamma typo among them: the derivations after it went through the right entry).
  const std::string md = read(dir / "report.md");
  const std::size_t summary = md.find("## Referee's summary"), headline = md.find("headline results hold (", summary),
                    gamma = md.find("- **`gamma-system`**", summary), unverifiable = md.find(", unverifiable): ", summary),
                    taylor = md.find("- **`taylor-display`**", summary);
  ASSERT_NE(summary, std::string::npos);
  EXPECT_LT(headline, unverifiable);
  EXPECT_LT(unverifiable, gamma);
  EXPECT_LT(unverifiable, taylor);
  // Every finding about the paper that is no consequence of another, but what the source cannot
  // show (unverifiable), reads in one line "printed X, should be Y"; Section 5's misprinted order
  // is one symbol, said once for its two places.
  for (const json& c : actual["claims"]) {
    const std::string kind = c["finding"].get<std::string>();
    if (c["origin"] != "paper" || c.contains("follows_from") || kind == "none" || kind == "unverifiable") continue;
    EXPECT_TRUE(c.contains("amendments") && !c["amendments"].empty()) << c["id"] << " has no \"printed X, should be Y\"";
  }
  const std::size_t taylor_line = md.find('\n', taylor);
  EXPECT_NE(md.substr(taylor, taylor_line - taylor).find("(twice): printed `\\frac{d^{6}q}{dt^{5}}`, should be `\\frac{d^{6}q}{dt^{6}}`"),
            std::string::npos)
      << md.substr(taylor, taylor_line - taylor);
  // The claims table quotes the display a record names: reduced-lagrangian compares (LLhh) with
  // (Lagrangien-reduit) and is about the latter.
  const std::size_t row = md.find("| [reduced-lagrangian](#reduced-lagrangian) |");
  ASSERT_NE(row, std::string::npos);
  EXPECT_NE(md.substr(row, md.find('\n', row) - row).find("`L_h^r (q_\\ell"), std::string::npos) << md.substr(row, 300);
  // The page shows the plots beside it (not embedded: it stays small), and its JUnit is green.
  EXPECT_NE(read(dir / "report.html").find("<img src=\"figure1.svg\""), std::string::npos);
  // Embedded, the plots made the page over 800 KB; the text of every claim's evidence (quoted sentences,
  // the convention search's candidates entry by entry, the grid lemma's computed premises) is about
  // 480 KB (2026-11-26); the table of contents, the TeX marked for KaTeX and the simple hypotheses of
  // Table 1 added about 60 KB (2026-11-28: 542 KB); the four findings' claims 33 KB more and the
  // nonlinear problems' section (error against work, beside the oscillator's) 13 KB (2026-11-28: 588 KB).
  // 640 KB leaves room for a few more claims and still catches embedded plots, 800 KB and more
  // (KaTeX's script and fonts are files beside the page, not in it).
  EXPECT_LT(std::filesystem::file_size(dir / "report.html"), 640'000u);
  EXPECT_NE(read(dir / "report.junit.xml").find("failures=\"0\" errors=\"0\""), std::string::npos);
  // Every table of the committed page is a table (a '|' left unescaped once made one a paragraph).
  test::expect_html_tables_rendered(dir);
  test::expect_no_bare_non_finite(dir);
}

// The committed reference is one run from a clean tree (`make reference`): report.json not dirty,
// timing.json of the same run (its timestamp) and naming the same claims, report.md's headline the
// summary line of report.json.
TEST(ReferenceReport, IsOneRunFromACleanTree) {
  const std::filesystem::path dir = std::filesystem::path(SIMPSON_SOURCE_DIR) / "reports" / "reference" / "paper";
  const json report = load_report(dir);
  EXPECT_FALSE(report["environment"]["git_dirty"].get<bool>()) << "regenerate it with make reference, from a clean tree";
  std::ifstream timing_in(dir / "timing.json");
  ASSERT_TRUE(timing_in) << "no timing.json beside report.json";
  const json timing = json::parse(timing_in);
  EXPECT_EQ(timing["timestamp_utc"], report["environment"]["timestamp_utc"]) << "timing.json is of another run than report.json";
  std::set<std::string> claims, timed;
  for (const json& c : report["claims"]) claims.insert(c["id"].get<std::string>());
  for (const auto& [id, seconds] : timing["claims"].items()) timed.insert(id);
  EXPECT_EQ(claims, timed);
  std::ifstream md_in(dir / "report.md");
  const std::string md((std::istreambuf_iterator<char>(md_in)), std::istreambuf_iterator<char>());
  EXPECT_NE(md.find("**" + report["summary"]["line"].get<std::string>() + "**"), std::string::npos) << "report.md is of another run";
}

// The stiff scene's committed report (reports/reference/stiff), from which README.md's and
// docs/findings.md's sentence on the FPU chain is generated (scripts/readme-counts): made by the same
// `make reference` as the paper's, from the same clean commit, and what this build computes.
TEST(ReferenceReport, StiffSceneIsOfThePapersCommitAndReproduced) {
  const std::filesystem::path root = std::filesystem::path(SIMPSON_SOURCE_DIR) / "reports" / "reference";
  const json stiff = load_report(root / "stiff"), paper = load_report(root / "paper");
  EXPECT_FALSE(stiff["environment"]["git_dirty"].get<bool>()) << "regenerate it with make reference, from a clean tree";
  EXPECT_EQ(stiff["environment"]["git_commit"], paper["environment"]["git_commit"]) << "make reference writes both: one was not regenerated";
#ifndef SIMPSON_SANITIZED  // about 20 s in Release; the sanitizer build runs the fpu section at the quick size (Experiments.Fpu*)
  const run_record r = run(load_scene("stiff", paper_book()));
  const json expected = test::without_volatile(json::parse(read(root / "stiff" / "report.json")));
  const json actual = test::without_volatile(report_json(r));
  EXPECT_EQ(expected["experiments"].dump(2), actual["experiments"].dump(2));
#endif
}

/// Whether `text` is valid UTF-8 (a CI log that is not is shown as binary by grep).
bool valid_utf8(const std::string& text) {
  for (std::size_t k = 0; k < text.size();) {
    const auto c = static_cast<unsigned char>(text[k]);
    const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (n == 0 || k + n > text.size()) return false;
    for (std::size_t j = 1; j < n; ++j) {
      if ((static_cast<unsigned char>(text[k + j]) & 0xC0) != 0x80) return false;
    }
    k += n;
  }
  return true;
}

// The paper is compared by its SHA-256: the same bytes given with --paper (its name a path, not
// "embedded") is one paper and a note; other bytes under that name are compared as before.
TEST(ReferenceReport, CompareTakesTheSamePaperUnderAnotherNameAsOne) {
  const std::filesystem::path dir = std::filesystem::path(SIMPSON_SOURCE_DIR) / "reports" / "reference" / "paper";
  const json reference = load_report(dir);
  const std::string name = reference["paper"].get<std::string>();
  json renamed = reference;
  std::size_t renamed_places = 0;
  std::function<void(json&)> rename = [&](json& v) {
    if (v.is_string() && v.get<std::string>() == name) {
      v = "/ci/checkout/paper.tex";
      ++renamed_places;
    } else if (v.is_structured()) {
      for (json& item : v) rename(item);
    }
  };
  for (auto& [key, value] : renamed.items()) {
    if (key != "environment") rename(value);
  }
  renamed["environment"]["paper"] = "/ci/checkout/paper.tex";
  renamed["overrides"]["paper"] = "/ci/checkout/paper.tex";
  ASSERT_GT(renamed_places, 50u);
  const report_comparison same = compare_reports(reference, renamed);
  EXPECT_TRUE(same.differences.empty()) << ::testing::PrintToString(same.lines());
  ASSERT_EQ(same.notes.size(), 1u);
  EXPECT_NE(same.notes[0].find("the same paper (SHA-256"), std::string::npos) << same.notes[0];
  EXPECT_TRUE(compare_report_subset(reference, renamed).differences.empty());
  // Other bytes: another document, one note, and its name no difference on every claim that names
  // it (what its text changed is; here nothing).
  renamed["environment"]["paper_sha256"] = std::string(64, '0');
  const report_comparison other = compare_reports(reference, renamed);
  EXPECT_TRUE(other.differences.empty()) << ::testing::PrintToString(other.lines());
  ASSERT_EQ(other.notes.size(), 1u);
  EXPECT_NE(other.notes[0].find("the documents differ"), std::string::npos) << other.notes[0];
}

// A long value that changes near its end is shown around the change, cut between characters: the
// output is valid UTF-8 and holds both versions of the changed part.
TEST(ReferenceReport, CompareShowsWhereALongValueDiffersAndCutsBetweenCharacters) {
  const std::filesystem::path dir = std::filesystem::path(SIMPSON_SOURCE_DIR) / "reports" / "reference" / "paper";
  const json reference = load_report(dir);
  std::string long_text;
  for (int k = 0; k < 80; ++k) long_text += "x − y ";
  json a = reference, b = reference;
  a["claims"][0]["note"] = long_text + "end 11/24";
  b["claims"][0]["note"] = long_text + "end 11/25";
  const std::vector<std::string> lines = compare_reports(a, b).lines();
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_TRUE(valid_utf8(lines[0])) << lines[0];
  EXPECT_NE(lines[0].find("end 11/24"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("end 11/25"), std::string::npos) << lines[0];
  EXPECT_LT(lines[0].size(), 400u) << lines[0];
  for (std::size_t shift = 0; shift < 6; ++shift) {  // every cut position against the 3-byte '−'
    json c = reference, d = reference;
    c["claims"][0]["note"] = std::string(shift, 'x') + long_text + "a";
    d["claims"][0]["note"] = std::string(shift, 'x') + long_text + "b";
    for (const std::string& line : compare_reports(c, d).lines()) EXPECT_TRUE(valid_utf8(line)) << shift << ": " << line;
  }
}

TEST(ReferenceReport, CompareFindsAChangedFigureAndNamesIt) {
  const std::filesystem::path dir = std::filesystem::path(SIMPSON_SOURCE_DIR) / "reports" / "reference" / "paper";
  const json reference = load_report(dir);
  EXPECT_TRUE(compare_reports(reference, reference).differences.empty());
  json altered = reference;
  for (json& c : altered["claims"]) {
    if (c["id"] == "phi3-det") c["verdict"] = "fails";
  }
  altered["experiments"]["table1"]["entries"][0]["ours"] = "9.99e-01";
  altered["environment"]["timestamp_utc"] = "2000-01-01T00:00:00Z";             // ignored
  altered["claims"][0]["evidence"]["exact"][0]["points_evaluated"] = 1;          // an integer: compared
  const std::vector<std::string> lines = compare_reports(reference, altered).lines();
  ASSERT_EQ(lines.size(), 3u) << ::testing::PrintToString(lines);
  EXPECT_NE(lines[0].find("claim lemma-dimensional-scaling: evidence.exact[0].points_evaluated: 225 → 1"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("claim phi3-det: verdict: \"holds\" → \"fails\""), std::string::npos) << lines[1];
  EXPECT_NE(lines[2].find("section table1: entries row 0, column ours"), std::string::npos) << lines[2];
  // A residual's digits may change; leaving its bound may not.
  json residual = reference;
  for (json& c : residual["claims"]) {
    if (c["id"] == "peer-schemes") {  // a claim with a numeric recheck
      c["evidence"]["numeric"]["ladder"][0]["max_residual"] = "3.00e-16";
      EXPECT_TRUE(compare_reports(reference, residual).differences.empty());
      c["evidence"]["numeric"]["ladder"][0]["within_bound"] = false;
    }
  }
  EXPECT_EQ(compare_reports(reference, residual).differences.size(), 1u);
  // A section's expectation that no longer holds is a difference, and so is a table or a column that
  // only the new report has (before, compare walked the old report's members alone).
  json expectation_changed = reference;
  expectation_changed["experiments"]["stability"]["expectations"][0]["holds"] = false;
  EXPECT_EQ(compare_reports(reference, expectation_changed).differences.size(), 1u);
  json extended = reference;
  extended["experiments"]["stability"]["new_table"] = json::array();
  extended["experiments"]["stability"]["intervals"][0]["new_column"] = "x";
  const std::vector<std::string> added = compare_reports(reference, extended).lines();
  EXPECT_EQ(compare_reports(reference, extended).differences.size(), 1u);  // one section
  ASSERT_EQ(added.size(), 2u) << ::testing::PrintToString(added);
  EXPECT_NE(added[0].find("intervals row 0, column new_column: only in the new report"), std::string::npos) << added[0];
  EXPECT_NE(added[1].find("new_table: only in the new report"), std::string::npos) << added[1];
}

/// A run that did not check the certificates (--no-certify, or no coqc) against the reference made
/// with coqc: noted, not a difference; a rejected certificate, or a lemma changed, still is.
TEST(ReferenceReport, CompareNotesCertificatesOnlyExported) {
  const json reference = load_report(std::filesystem::path(SIMPSON_SOURCE_DIR) / "reports" / "reference" / "paper");
  json exported = reference;
  for (json& c : exported["claims"]) {
    json& coq = c["evidence"]["coq"];
    if (coq["status"] == "checked") {
      coq["status"] = "exported";
      coq.erase("coq_version");
    }
  }
  exported["summary"]["coq_checked"] = 0;
  const report_comparison plain = compare_reports(reference, exported);
  EXPECT_TRUE(plain.differences.empty()) << ::testing::PrintToString(plain.lines());
  ASSERT_EQ(plain.notes.size(), 1u);
  EXPECT_NE(plain.notes[0].find("checked by coqc in one run and only exported"), std::string::npos) << plain.notes[0];
  EXPECT_TRUE(compare_report_subset(reference, exported).differences.empty());
  // Rejected is not "not computed".
  json rejected = reference;
  for (json& c : rejected["claims"]) {
    if (c["id"] == "phi3-det") c["evidence"]["coq"]["status"] = "failed";
  }
  EXPECT_EQ(compare_reports(reference, rejected).differences.size(), 1u);
  // A lemma gone from an exported certificate is a difference too.
  for (json& c : exported["claims"]) {
    if (c["id"] == "phi3-det") c["evidence"]["coq"]["lemmas"].erase(0);
  }
  EXPECT_FALSE(compare_reports(reference, exported).differences.empty());
}

/// --no-timing leaves out the timing files, the plots of run times and says so in the timed
/// section's title: noted. An untimed plot missing is still a difference.
TEST(ReferenceReport, CompareNotesWhatNoTimingLeavesOut) {
  const json reference = load_report(std::filesystem::path(SIMPSON_SOURCE_DIR) / "reports" / "reference" / "paper");
  json untimed = reference;
  untimed["overrides"]["timing"] = false;
  untimed["timing_files"] = json::array();
  json plots = json::array();
  for (const json& p : reference["plots"]) {
    if (!p["run_times"].get<bool>()) plots.push_back(p);
  }
  ASSERT_LT(plots.size(), reference["plots"].size());
  untimed["plots"] = plots;
  untimed["experiments"]["work_precision"]["title"] = "Work against precision: error (not timed)";
  const report_comparison found = compare_reports(reference, untimed);
  EXPECT_TRUE(found.differences.empty()) << ::testing::PrintToString(found.differences);
  EXPECT_EQ(found.notes.size(), 1u);
  untimed["plots"].erase(0);
  EXPECT_EQ(compare_reports(reference, untimed).differences.size(), 1u);
  // Without --no-timing on either side, the same title change is a difference.
  json retitled = reference;
  retitled["experiments"]["work_precision"]["title"] = "Work against precision: error (not timed)";
  EXPECT_EQ(compare_reports(reference, retitled).differences.size(), 1u);
}

/// Round-off figures (det Φ₃ − 1 in double: −1.11e-16) move with another libm or compiler: within
/// 1024 ε of their row's precision they are equal; past it, or in a row naming no precision, not.
TEST(ReferenceReport, CompareTakesRoundOffFiguresAsRoundOff) {
  const json reference = load_report(std::filesystem::path(SIMPSON_SOURCE_DIR) / "reports" / "reference" / "paper");
  json moved = reference;
  json& row = moved["paper_configuration"]["rows"][0];
  ASSERT_EQ(row["precision"], "double");
  row["det_minus_one"] = "2.22e-16";
  row["hd_change_one_step"] = "-4.44e-15";
  EXPECT_TRUE(compare_reports(reference, moved).differences.empty());
  row["det_minus_one"] = "1.00e-12";  // 4500 ε: a change of the formula, not of round-off
  EXPECT_EQ(compare_reports(reference, moved).differences.size(), 1u);
  // A digit of a figure that is not at round-off level still counts.
  json figure = reference;
  figure["paper_configuration"]["rows"][0]["discriminant"] = "-6.71464e-01";
  EXPECT_EQ(compare_reports(reference, figure).differences.size(), 1u);
  // In a long double row the limit is 1024 of its ε (1.08e-19), not double's.
  json extended = reference;
  ASSERT_EQ(extended["paper_configuration"]["rows"][1]["precision"], "long double");
  extended["paper_configuration"]["rows"][1]["det_minus_one"] = "1.00e-15";  // 9000 of its ε
  EXPECT_EQ(compare_reports(reference, extended).differences.size(), 1u);
}

}  // namespace
}  // namespace simpson::verify

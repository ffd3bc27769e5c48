// Errata guarded by their content: a recorded erratum records its proved correction
// (`correction` in claims/paper.toml); a second error inside a formula already known to be wrong
// gives the same verdict word with another correction, and that is a changed verdict (exit 1, named
// in the summary, the report and JUnit). The same runs on the printed paper are as expected.

#include "altered_paper.hpp"
#include "phi3_unit_record.hpp"

#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/junit.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/report.hpp>
#include <simpson/verify/report_compare.hpp>
#include <simpson/verify/run.hpp>
#include <simpson/verify/verdict_table.hpp>
#include <simpson/verify/scene.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

namespace simpson::verify {
namespace {

run_record run_on(const std::string& id, const paper_source& paper, bool accept_fixes = false, const json* baseline = nullptr) {
  scene s = load_scene("quick", paper_book());
  s.claims = {id};
  s.experiments = {};
  s.accept_fixes = accept_fixes;
  if (baseline) apply_baseline(s, *baseline, "reference");
  auto book = std::make_shared<claim_book>(paper_book());
  const paper_reading reading = read_paper(paper);
  check_claims_file_formulas(*book, reading.source);
  return run(s, book, reading);
}

void expect_content_changed(const std::string& id, const paper_source& second_error) {
  const run_record printed = run_on(id, embedded_paper());
  ASSERT_EQ(printed.outcomes.size(), 1u);
  EXPECT_EQ(printed.outcomes[0].result.outcome, verdict::erratum);
  EXPECT_TRUE(printed.outcomes[0].content_changed.empty()) << printed.outcomes[0].content_changed;
  EXPECT_EQ(run_exit_code(printed), 0);

  const run_record r = run_on(id, second_error);
  ASSERT_EQ(r.outcomes.size(), 1u);
  const claim_outcome& o = r.outcomes[0];
  EXPECT_EQ(o.result.outcome, verdict::erratum) << id << ": " << o.result.note;  // the same word ...
  EXPECT_NE(o.content_changed.find("its correction is not the recorded one"), std::string::npos) << id;  // ... another erratum
  EXPECT_EQ(run_exit_code(r), 1) << id;
  EXPECT_NE(summary_line(r).find("1 not as expected (" + id + ")"), std::string::npos) << summary_line(r);
  EXPECT_NE(report_junit(r).find("erratum-changed"), std::string::npos) << id;
  EXPECT_NE(report_markdown(r).find("erratum, as expected, but its correction is not the recorded one"), std::string::npos) << id;
  EXPECT_EQ(report_json(r)["claims"][0]["content_changed"], o.content_changed);
}

TEST(ErratumContent, ASecondWrongEntryOfGammaIsAChangedVerdict) {
  // Gamma's entry (1, 2) printed 2 alpha gamma: entry (3, 3) is still wrong, and now (1, 2) too.
  expect_content_changed("gamma-system", altered("the following homogeneous linear system", "& \\alpha \\, \\gamma &", "& 2 \\, \\alpha \\, \\gamma &"));
}

TEST(ErratumContent, ASecondSlipInTheTaylorDisplayIsAChangedVerdict) {
  // h^4/24 printed h^4/25 in the expansion of q_{j+1}, beside the d^6q/dt^5 already misprinted:
  // the correction names each wrong term ("printed X, should be Y"), so it changes.
  expect_content_changed("taylor-display", altered("at the precise points", "{{h^4}\\over{24}}", "{{h^4}\\over{25}}"));
}

TEST(ErratumContent, OneMoreChangedEntryOfTable1IsAChangedVerdict) {
  // Newmark's momentum at N = 20 printed 5.12e-1 for 5.02e-1: no convention reproduces the table
  // any more, so the verdict word itself changes (fails), named as a change.
  const run_record r = run_on("table-values", altered("\\begin{tabular}", "5.02 \\,\\, 10^{-1}", "5.12 \\,\\, 10^{-1}"));
  ASSERT_EQ(r.outcomes.size(), 1u);
  EXPECT_FALSE(outcome_as_expected(r.outcomes[0])) << to_string(r.outcomes[0].result.outcome) << ": " << r.outcomes[0].result.correction;
  EXPECT_EQ(run_exit_code(r), 1);
  EXPECT_NE(summary_line(r).find("1 not as expected (table-values)"), std::string::npos) << summary_line(r);
  EXPECT_NE(report_junit(r).find("failures=\"1\""), std::string::npos);
}

// An author's fix is an outcome of its own: Gamma printed with (delta^2 - 1)/2 holds, and
// gamma-system, recorded as an erratum, is fixed. A guard (the default) reports it as a change,
// exit 1, under Fixed and not under Failures; --accept-fixes passes it.
TEST(ErratumContent, AFixIsReportedAsFixedAndPassesWhenAccepted) {
  const paper_source corrected = altered("the following homogeneous linear system", "{{\\gamma^2-1}\\over2}", "{{\\delta^2-1}\\over2}");
  const run_record guard = run_on("gamma-system", corrected);
  ASSERT_EQ(guard.outcomes.size(), 1u);
  EXPECT_EQ(guard.outcomes[0].result.outcome, verdict::holds);
  EXPECT_TRUE(guard.outcomes[0].fixed);
  EXPECT_EQ(run_exit_code(guard), 1);
  EXPECT_NE(summary_line(guard).find("1 fixed (gamma-system"), std::string::npos) << summary_line(guard);
  EXPECT_NE(report_junit(guard).find("type=\"fixed\""), std::string::npos);
  const std::string md = report_markdown(guard);
  const std::size_t fixed_at = md.find("## Fixed"), failures_at = md.find("## Failures");
  ASSERT_NE(fixed_at, std::string::npos);
  EXPECT_NE(md.find("**gamma-system**", fixed_at), std::string::npos);
  ASSERT_NE(failures_at, std::string::npos);
  const std::string failures = md.substr(failures_at, md.find("\n## ", failures_at + 1) - failures_at);
  EXPECT_EQ(failures.find("gamma-system"), std::string::npos) << "a fix listed among the failures: " << failures;

  const run_record author = run_on("gamma-system", corrected, true);
  EXPECT_EQ(run_exit_code(author), 0);
  EXPECT_NE(summary_line(author).find("all verdicts as expected, 1 fixed, fixes accepted (gamma-system)"), std::string::npos) << summary_line(author);
  const json report = report_json(author);
  EXPECT_TRUE(report["all_as_expected"].get<bool>());
  EXPECT_TRUE(report["claims"][0]["fixed"].get<bool>());
  EXPECT_EQ(report["summary"]["fixed"], json::array({"gamma-system"}));
  EXPECT_EQ(report_junit(author).find("type=\"fixed\""), std::string::npos);

  // Accepting fixes accepts nothing else: a second error in Gamma still fails.
  const run_record worse =
      run_on("gamma-system", altered("the following homogeneous linear system", "& \\alpha \\, \\gamma &", "& 2 \\, \\alpha \\, \\gamma &"), true);
  EXPECT_EQ(run_exit_code(worse), 1);
}

// --baseline REPORT: nothing may get worse than that report. Against the committed reference, the
// printed paper passes, a fix passes, and a second error in Gamma or a new failure of det Phi_3
// fails.
TEST(ErratumContent, NothingMayGetWorseThanABaseline) {
  const json reference = load_report(std::filesystem::path(SIMPSON_SOURCE_DIR) / "reports" / "reference" / "paper");
  EXPECT_EQ(run_exit_code(run_on("gamma-system", embedded_paper(), false, &reference)), 0);
  const run_record fixed =
      run_on("gamma-system", altered("the following homogeneous linear system", "{{\\gamma^2-1}\\over2}", "{{\\delta^2-1}\\over2}"), false, &reference);
  EXPECT_TRUE(fixed.outcomes[0].fixed);
  EXPECT_EQ(run_exit_code(fixed), 0);
  const run_record worse =
      run_on("gamma-system", altered("the following homogeneous linear system", "& \\alpha \\, \\gamma &", "& 2 \\, \\alpha \\, \\gamma &"), false, &reference);
  EXPECT_FALSE(worse.outcomes[0].content_changed.empty());
  EXPECT_EQ(run_exit_code(worse), 1);
  const run_record broken = run_on("phi3-det", altered("\\label{Phi3}", "{11\\over24}", "{13\\over24}"), false, &reference);
  EXPECT_EQ(broken.outcomes[0].result.outcome, verdict::fails);
  EXPECT_EQ(run_exit_code(broken), 1);
  // A baseline that could not decide a claim keeps no judgment of it: the record's expectation
  // stays, so an undecided claim is no regression to keep (it would expect what is never expected).
  json undecided = reference;
  for (json& c : undecided["claims"]) {
    if (c["id"] == "gamma-system") c["verdict"] = "undecided";
  }
  scene kept = load_scene("quick", paper_book());
  kept.claims = {"gamma-system"};
  apply_baseline(kept, undecided, "undecided");
  EXPECT_EQ(kept.expected_overrides.count("gamma-system"), 0u);
  json no_claims = reference;
  no_claims.erase("claims");
  scene s = load_scene("quick", paper_book());
  EXPECT_THROW(apply_baseline(s, no_claims, "x"), std::invalid_argument);
}

// Only an expected erratum records a correction: on another record it is bad input, named.
TEST(ErratumContent, ACorrectionOnARecordThatIsNoErratumIsBadInput) {
  const std::string record = phi3_unit_record + "correction = 'det = 1'\n";
  try {
    read_claim_book(record, "test.toml");
    ADD_FAILURE() << "a correction on a record expected to hold was read";
  } catch (const claims_file_error& e) {
    EXPECT_NE(std::string(e.what()).find("line 9, field 'correction': given for a claim whose expected verdict is holds"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace simpson::verify

// The engine's one verdict site (verify/prove/include/simpson/prove/decide.hpp): the two-kernel rule
// on a decider's evidence. Every proof shape's verdict comes from here, so a rule that let one
// kernel's "no" pass under the other's "yes", or a finding survive a disagreement, would move them all.

#include <simpson/prove/decide.hpp>
#include <simpson/verify/enclosure_undecided.hpp>
#include <simpson/verify/quoted_sentence.hpp>

#include <gtest/gtest.h>

namespace simpson::verify::detail {
namespace {

decider_evidence answered(answer ginac, answer own) {
  decider_evidence e;
  e.statement = "det (phi) = 1";
  e.ginac = ginac;
  e.own = own;
  return e;
}

TEST(Decide, BothKernelsMustAgreeAndEitherAloneDecides) {
  EXPECT_EQ(verdict_of(answered(answer::holds, answer::holds)), verdict::holds);
  EXPECT_EQ(verdict_of(answered(answer::fails, answer::fails)), verdict::erratum);
  EXPECT_EQ(verdict_of(answered(answer::holds, answer::fails)), verdict::kernels_disagree);
  EXPECT_EQ(verdict_of(answered(answer::fails, answer::holds)), verdict::kernels_disagree);
  EXPECT_EQ(verdict_of(answered(answer::holds, answer::none)), verdict::holds);  // our kernel not applicable: GiNaC's alone
  EXPECT_EQ(verdict_of(answered(answer::none, answer::fails)), verdict::erratum);  // the signs by Sturm sequences: ours alone
  EXPECT_EQ(verdict_of(answered(answer::none, answer::none)), verdict::undecided);
}

TEST(Decide, ANoMeansWhatTheShapeSaysItMeans) {
  decider_evidence e = answered(answer::fails, answer::fails);
  e.if_false = verdict::fails;  // a printed property: nothing to correct it with
  EXPECT_EQ(verdict_of(e), verdict::fails);
  e.if_false = verdict::unverifiable;
  EXPECT_EQ(verdict_of(e), verdict::unverifiable);
}

TEST(Decide, APartTheKernelsDifferOnIsADisagreementWhateverTheWhole) {
  decider_evidence e = answered(answer::fails, answer::fails);  // both find a side wrong, but not the same side
  e.parts_differ = true;
  EXPECT_EQ(verdict_of(e), verdict::kernels_disagree);
  e.reached = decider_evidence::reach::beyond_reach;  // a fact they differ on is a bug even where the shape stops
  EXPECT_EQ(verdict_of(e), verdict::kernels_disagree);
}

TEST(Decide, ReachAndMissingToolsAreNoFinding) {
  decider_evidence beyond = beyond_reach({});
  EXPECT_EQ(verdict_of(beyond), verdict::undecided);
  decider_evidence missing;
  missing.reached = decider_evidence::reach::tool_missing;
  missing.lexical = answer::fails;
  EXPECT_EQ(verdict_of(missing), verdict::skipped);
}

TEST(Decide, ALexicalAnswerCountsOnlyWhereNoKernelAnswered) {
  decider_evidence e;
  e.lexical = answer::fails;
  EXPECT_EQ(verdict_of(e), verdict::erratum);
  e.ginac = answer::holds;
  EXPECT_EQ(verdict_of(e), verdict::holds);
}

TEST(Decide, ADisagreementDropsTheFindingAndExportsNoCertificate) {
  decider_evidence e = answered(answer::fails, answer::holds);
  e.found.correction = "det (phi) = 1 + h^4/144";
  e.found.amendments.push_back({"the determinant", "1", "1 + h^4/144", true});
  const GiNaC::symbol h("h");
  e.goals = std::vector<proof_goal>{decided("det", GiNaC::pow(h + 1, 2), h * h + 2 * h + 1)};
  const claim_result r = decide("phi3-det", "det phi = 1", e);
  EXPECT_EQ(r.outcome, verdict::kernels_disagree);
  EXPECT_TRUE(r.correction.empty());
  EXPECT_TRUE(r.amendments.empty());
  EXPECT_TRUE(r.certificate.empty());
  EXPECT_EQ(r.note, kernels_differ_on("det (phi) = 1"));
  // Agreeing, the same evidence keeps its correction and exports its goals.
  e.own = answer::fails;
  const claim_result agreed = decide("phi3-det", "det phi = 1", e);
  EXPECT_EQ(agreed.outcome, verdict::erratum);
  EXPECT_EQ(agreed.correction, "det (phi) = 1 + h^4/144");
  EXPECT_NE(agreed.certificate.find("Lemma phi3_det"), std::string::npos) << agreed.certificate << agreed.certificate_missing;
}

TEST(Decide, WhatStopsAJudgeIsItsVerdictAndNoFinding) {
  // An enclosure that decides nothing within the run's digits: undecided, the enclosure named.
  const auto wide = claim_check_of([](const run_context&) -> decider_evidence { throw enclosure_undecided("0 ± 3e-20 at 640 digits"); }, "c", "s");
  const claim_result undecided = wide(run_context{});
  EXPECT_EQ(undecided.outcome, verdict::undecided);
  EXPECT_NE(undecided.note.find("--enclosure-budget"), std::string::npos) << undecided.note;
  // Words the claim quotes that no longer read: text-changed, whatever the judge would have found.
  const auto reworded = claim_check_of([](const run_context&) -> decider_evidence { throw text_changed("the pattern is not in the document"); }, "c", "s");
  const claim_result changed = reworded(run_context{});
  EXPECT_EQ(changed.outcome, verdict::text_changed);
  EXPECT_EQ(changed.evidence.value("text_changed", std::string()), "the pattern is not in the document");
}

TEST(Decide, AnObservedFactIsAnErratumOnlyWithTheCorrectionItFound) {
  // A fact an experiment published: found false, it fails unless the experiment found what holds
  // instead (then an erratum with that correction, and only then), and it says why no Coq statement
  // is exported.
  const published_fact found{true, json{{"numeric", "measured"}}, "as measured"};
  const claim_result held = decide("table-orders", "orders", observed(found, ""));
  EXPECT_EQ(held.outcome, verdict::holds);
  EXPECT_EQ(held.evidence, found.evidence);
  EXPECT_EQ(held.note, "as measured");
  EXPECT_EQ(held.certificate_missing, "a fact an experiment measured: nothing for a proof assistant to state");
  EXPECT_TRUE(held.certificate.empty());
  const claim_result failed = decide("table-orders", "orders", observed(published_fact{false, json::object(), ""}, "the record's reason"));
  EXPECT_EQ(failed.outcome, verdict::fails);
  EXPECT_TRUE(failed.correction.empty());
  EXPECT_EQ(failed.certificate_missing, "the record's reason");
  const claim_result corrected = decide("table-values", "values", observed(published_fact{false, json::object(), "", "another start"}, ""));
  EXPECT_EQ(corrected.outcome, verdict::erratum);
  EXPECT_EQ(corrected.correction, "another start");
  // A correction beside a fact that holds is not a finding.
  const claim_result held_anyway = decide("table-values", "values", observed(published_fact{true, json::object(), "", "another start"}, ""));
  EXPECT_EQ(held_anyway.outcome, verdict::holds);
  EXPECT_TRUE(held_anyway.correction.empty());
}

}  // namespace
}  // namespace simpson::verify::detail

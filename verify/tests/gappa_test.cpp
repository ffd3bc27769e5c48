// The steppers' one-step round-off proved by Gappa and checked by coqc (verify/floating): numbers in
// Gappa's notation both ways, the script written from the program (a changed program changes it),
// a proved bound that holds on random states and is not loose, an overflowing box unproved with
// its reason. Skipped, and shown so, without gappa (or coqc for the certificate).

#include <simpson/verify/gappa_run.hpp>
#include <simpson/verify/global_roundoff.hpp>
#include <simpson/verify/stepper_roundoff.hpp>

#include <simpson/verify/command.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/paper_source.hpp>

#include <gtest/gtest.h>

#include <numeric>

#include <cstdlib>
#include <random>

namespace simpson::verify {
namespace {

TEST(Gappa, NumbersInGappasNotationBothWays) {
  EXPECT_EQ(gappa_number(rational(825) / rational(boost::multiprecision::cpp_int(1) << 62)), "825b-62");
  EXPECT_EQ(gappa_number(rational(-3, 8)), "-3b-3");
  EXPECT_EQ(gappa_number(rational(12)), "3b2");
  EXPECT_EQ(gappa_number(rational(1, 3)), "(1/3)");
  EXPECT_EQ(gappa_number(rational(0)), "0");
  EXPECT_EQ(parse_gappa_number("-825b-62"), rational(-825) / rational(boost::multiprecision::cpp_int(1) << 62));
  EXPECT_EQ(parse_gappa_number("3b2"), rational(12));
  EXPECT_EQ(parse_gappa_number("1"), rational(1));
  EXPECT_THROW(parse_gappa_number("1.5"), std::invalid_argument);
  EXPECT_EQ(exact_binary_value(0.1), rational(3602879701896397LL, 36028797018963968LL));
  EXPECT_EQ(exact_binary_value(static_cast<double>(0.1F)), rational(13421773, 134217728));
}

TEST(Gappa, TheScriptIsWrittenFromTheProgram) {
  const roundoff_problem p = stepper_roundoff_problem("phi3-shear", "double", rational(1), rational(1), rational(1, 10), rational(1), rational(1));
  const std::string script = gappa_script(p);
  for (const rounded_instruction& i : p.program.body) {
    EXPECT_NE(script.find(i.target + " = rnd(" + i.left), std::string::npos) << i.target << "\n" << script;
  }
  EXPECT_NE(script.find("@rnd = float<ieee_64, ne>;"), std::string::npos);
  roundoff_problem changed = p;
  changed.program.body[2].right = "q";  // the kick reads the old q: another program, another script
  EXPECT_NE(gappa_script(changed), script);
  EXPECT_THROW(stepper_roundoff_problem("leapfrog-verinum", "float32", rational(2), rational(1), rational(1, 32), rational(1), rational(1)),
               std::invalid_argument);
  EXPECT_THROW(stepper_roundoff_problem("phi3-matrix", "half", rational(1), rational(1), rational(1, 32), rational(1), rational(1)),
               std::invalid_argument);
}

/// The largest |error| in p and q of the program in double over random states of the box,
/// computed exactly: the program evaluated in double, Φ y in rationals.
std::pair<rational, rational> measured_roundoff(const roundoff_problem& problem) {
  std::map<std::string, double> stored;
  for (const auto& [name, value] : problem.stored) stored[name] = static_cast<double>(value);
  std::mt19937_64 g(20231025);
  std::uniform_real_distribution<double> u(-1, 1);
  rational worst_p(0), worst_q(0);
  for (int k = 0; k < 20000; ++k) {
    const phase_point<double> y{u(g) * static_cast<double>(problem.p_bound), u(g) * static_cast<double>(problem.q_bound)};
    const phase_point<double> computed = evaluate(problem.program, stored, y);
    const phase_point<rational> exact = problem.exact * phase_point<rational>{exact_binary_value(y.p), exact_binary_value(y.q)};
    worst_p = std::max(worst_p, rational(abs(exact_binary_value(computed.p) - exact.p)));
    worst_q = std::max(worst_q, rational(abs(exact_binary_value(computed.q) - exact.q)));
  }
  return {worst_p, worst_q};
}

TEST(Gappa, AProvedBoundHoldsOnRandomStatesAndIsNotLoose) {
  if (!program_on_path("gappa")) GTEST_SKIP() << "gappa not found: nothing proved";
  for (const std::string& stepper : proved_steppers()) {
    const rational h = stepper == "leapfrog-verinum" ? rational(1, 32) : rational(1, 10);
    const roundoff_problem problem = stepper_roundoff_problem(stepper, "double", rational(1), rational(1), h, rational(1), rational(1));
    const roundoff_proof proof = prove_roundoff(problem, false);
    ASSERT_EQ(proof.status, proof_status::proved) << stepper << ": " << proof.reason;
    const auto [p, q] = measured_roundoff(problem);
    // Sound: no random state errs by more than the bound. Not loose: the bound is within 4 times
    // the worst error seen (a few ulps of slack where Gappa adds the roundings' worst cases).
    EXPECT_LE(p, proof.bounds.p) << stepper;
    EXPECT_LE(q, proof.bounds.q) << stepper;
    EXPECT_LE(proof.bounds.p, 4 * p) << stepper << ": bound " << static_cast<double>(proof.bounds.p) << ", seen " << static_cast<double>(p);
    EXPECT_LE(proof.bounds.q, 4 * q) << stepper << ": bound " << static_cast<double>(proof.bounds.q) << ", seen " << static_cast<double>(q);
  }
}

TEST(Gappa, ABoxWhereTheStepMayOverflowIsUnprovedWithItsReason) {
  if (!program_on_path("gappa")) GTEST_SKIP() << "gappa not found: nothing proved";
  // m = 2^60: β = −m ω² h (…) is about 1e17, and q up to 2^1000 takes β q past double's range.
  const rational heavy{boost::multiprecision::cpp_int(1) << 60}, far{boost::multiprecision::cpp_int(1) << 1000};
  const roundoff_proof proof = prove_roundoff(
      stepper_roundoff_problem("phi3-matrix", "double", heavy, rational(1), rational(1, 10), rational(1), far), false);
  EXPECT_EQ(proof.status, proof_status::unproved);
  EXPECT_NE(proof.reason.find("overflow possible"), std::string::npos) << proof.reason;
}

TEST(Gappa, TheBoundsCoqProofIsCheckedByCoqc) {
  if (!program_on_path("gappa") || !program_on_path("coqc")) GTEST_SKIP() << "gappa or coqc not found: nothing checked";
  const roundoff_proof proof = prove_roundoff(
      stepper_roundoff_problem("leapfrog-verinum", "float32", rational(1), rational(1), rational(1, 32), rational(1), rational(1)));
  ASSERT_EQ(proof.status, proof_status::proved) << proof.reason;
  EXPECT_EQ(proof.coq, "checked");
  EXPECT_NE(proof.certificate.find("Require Import Gappa.Gappa_library."), std::string::npos);
  // Gappa states its rewriting hints as section hypotheses; the certificate proves them instead.
  EXPECT_EQ(proof.certificate.find("Hypothesis"), std::string::npos);
  EXPECT_NE(proof.certificate.find("Lemma a1 :"), std::string::npos);
}

/// VeriNum's setting: float32 leapfrog, h = 1/32, from (p, q) = (0, 1), on the box |p|, |q| ≤ 9/8.
struct verinum_case {
  roundoff_problem problem =
      stepper_roundoff_problem("leapfrog-verinum", "float32", rational(1), rational(1), rational(1, 32), rational(9, 8), rational(9, 8));
  phase_point<rational> y0{rational(0), rational(1)};
};

TEST(GappaGlobal, TheLiftingConstantsAreExactAndTheBoundIsWithinTwiceTheErrorMade) {
  if (!program_on_path("gappa")) GTEST_SKIP() << "gappa not found: nothing proved";
  const verinum_case v;
  const roundoff_proof proof = prove_roundoff(v.problem, false);
  ASSERT_EQ(proof.status, proof_status::proved) << proof.reason;
  const std::optional<lifting_constants> lifting = lifting_for(v.problem, proof.bounds, v.y0);
  ASSERT_TRUE(lifting);
  // Velocity Verlet conserves p² + (1 − h²/4) q².
  EXPECT_EQ(lifting->w_p, 1);
  EXPECT_EQ(lifting->w_q, rational(4095, 4096));
  const rational squared = lifting->w_p * proof.bounds.p * proof.bounds.p + lifting->w_q * proof.bounds.q * proof.bounds.q;
  EXPECT_GE(lifting->epsilon * lifting->epsilon, squared);
  EXPECT_LE(lifting->epsilon * lifting->epsilon, squared * rational(1000001, 1000000));
  EXPECT_GE(lifting->valid_steps, 1000);
  // Sound at every n, and (the goal) within twice the error made at n = 1000, where
  // VerifiedLeapfrog proves 0.0308.
  const std::vector<global_row> rows = global_comparison(v.problem, *lifting, rational(1, 32), v.y0, {1, 10, 100, 1000});
  for (const global_row& r : rows) {
    EXPECT_GE(std::stod(r.roundoff_bound), std::stod(r.roundoff_seen)) << r.n;
    EXPECT_GE(r.bound_over_seen, 1) << r.n;
  }
  EXPECT_LE(rows.back().bound_over_seen, 2) << rows.back().total_bound << " against " << rows.back().total_seen;
  EXPECT_LT(std::stod(rows.back().total_bound), 0.0308 / 20);
  EXPECT_THROW(global_comparison(v.problem, *lifting, rational(1, 32), v.y0, {lifting->valid_steps + 1}), std::invalid_argument);
}

// VerifiedLeapfrog's 0.0308 holds at every n <= 1000; the row set beside it is uniform over n <= 1000:
// each figure the largest over every n, found again here from the rows at each n.
TEST(GappaGlobal, TheUniformRowIsTheLargestOverEveryStep) {
  if (!program_on_path("gappa")) GTEST_SKIP() << "gappa not found: nothing proved";
  const verinum_case v;
  const roundoff_proof proof = prove_roundoff(v.problem, false);
  ASSERT_EQ(proof.status, proof_status::proved) << proof.reason;
  const lifting_constants lifting = *lifting_for(v.problem, proof.bounds, v.y0);
  constexpr long long steps = 1000;
  std::vector<long long> every(steps);
  std::iota(every.begin(), every.end(), 1LL);
  const std::vector<global_row> rows = global_comparison(v.problem, lifting, rational(1, 32), v.y0, every);
  const global_row uniform = global_uniform(v.problem, lifting, rational(1, 32), v.y0, steps);
  EXPECT_TRUE(uniform.uniform);
  EXPECT_EQ(uniform.n, steps);
  double seen = 0, discretization = 0, bound = 0;
  long long argmax = 0;
  for (const global_row& r : rows) {
    if (std::stod(r.total_seen) > seen) argmax = r.n;
    seen = std::max(seen, std::stod(r.total_seen));
    discretization = std::max(discretization, std::stod(r.discretization));
    bound = std::max(bound, std::stod(r.total_bound));
  }
  EXPECT_EQ(std::stod(uniform.total_seen), seen) << "largest error made at n = " << argmax;
  EXPECT_EQ(std::stod(uniform.discretization), discretization);
  EXPECT_GE(std::stod(uniform.total_bound), bound);
  EXPECT_GE(std::stod(uniform.total_bound), seen);
  EXPECT_THROW(global_uniform(v.problem, lifting, rational(1, 32), v.y0, lifting.valid_steps + 1), std::invalid_argument);
}

TEST(GappaGlobal, TheLiftingLemmaIsCheckedByCoqcAndAWrongConstantIsRejected) {
  if (!program_on_path("gappa") || !program_on_path("coqc")) GTEST_SKIP() << "gappa or coqc not found: nothing checked";
  const verinum_case v;
  const roundoff_proof proof = prove_roundoff(v.problem, false);
  ASSERT_EQ(proof.status, proof_status::proved) << proof.reason;
  lifting_constants lifting = *lifting_for(v.problem, proof.bounds, v.y0);
  EXPECT_EQ(coqc_check(lifting_lemma_coq(v.problem, proof.bounds, lifting), "lifting"), "checked");
  lifting.epsilon /= 2;  // below √(w_p B_p² + w_q B_q²): the one-step lemma is false
  EXPECT_EQ(coqc_check(lifting_lemma_coq(v.problem, proof.bounds, lifting), "lifting").rfind("rejected", 0), 0u);
  lifting = *lifting_for(v.problem, proof.bounds, v.y0);
  lifting.w_q += rational(1, 1000000);  // not Φ-invariant: the isometry lemma is false
  EXPECT_EQ(coqc_check(lifting_lemma_coq(v.problem, proof.bounds, lifting), "lifting").rfind("rejected", 0), 0u);
}

/// table-roundoff on a copy of the paper where Simpson's state error at N = 40 is printed with `digits`.
claim_result table_roundoff_with_state_printed(const std::string& printed) {
  paper_source copy = embedded_paper();
  const std::string row = "Symplectic Simpson  & state    & $ 4.11  \\,\\, 10^{-4} $  & $ 2.55 \\,\\, 10^{-5} $   & $ 1.60 \\,\\, 10^{-6} $";
  const std::size_t at = copy.text.find(row);
  EXPECT_NE(at, std::string::npos);
  if (at != std::string::npos) replace_text(copy, at + row.size() - 19, 4, printed);
  copy.origin = "altered copy";
  const paper_reading paper = read_paper(copy);
  run_context ctx;
  ctx.paper = &paper;
  return paper_book().find("table-roundoff").check(ctx);
}

TEST(GappaClaims, TableOnesDigitsAreAboveTheProvedRoundoffAndTooManyDigitsFail) {
  if (!program_on_path("gappa")) GTEST_SKIP() << "gappa not found: the claim is skipped";
  const claim_result printed = table_roundoff_with_state_printed("1.60");
  EXPECT_EQ(printed.outcome, verdict::holds) << printed.evidence.dump();
  EXPECT_NE(printed.certificate.find("Module Lifting_N40."), std::string::npos);
  // Printed to 11 digits, the last digit's half unit (5e-17) is below the proved 1.04e-13: round-off could change it.
  const claim_result fine = table_roundoff_with_state_printed("1.6000000000");
  EXPECT_EQ(fine.outcome, verdict::fails) << fine.evidence.dump();
}

TEST(GappaClaims, WithoutGappaTheClaimIsSkippedNotPassed) {
  // gappa hidden from the PATH: the claim is skipped, with the reason, and the run not failed by it.
  const std::string path = std::getenv("PATH") != nullptr ? std::getenv("PATH") : "";
  ::setenv("PATH", "/nonexistent", 1);
  const claim_result r = table_roundoff_with_state_printed("1.60");
  ::setenv("PATH", path.c_str(), 1);
  EXPECT_EQ(r.outcome, verdict::skipped);
  EXPECT_NE(r.evidence.value("skipped", std::string()).find("gappa"), std::string::npos) << r.evidence.dump();
  EXPECT_TRUE(as_expected(r.outcome, verdict::holds));
  EXPECT_FALSE(as_expected(verdict::unproved, verdict::holds));
}

}  // namespace
}  // namespace simpson::verify

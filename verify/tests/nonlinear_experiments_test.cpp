// The nonlinear section (nonlinear_section.hpp): the pendulum pinned by its exact solution and a
// multiprecision reference, Brouwer's summation of the forms, a failed Newton solve recorded and the
// run going on, and the force evaluations each step makes counted.

#include "experiment_fixture.hpp"

#include <simpson/verify/experiments.hpp>
#include <simpson/verify/report.hpp>

#include <simpson/nonlinear_brouwer_step.hpp>
#include <simpson/nonlinear_partitioned_rk.hpp>
#include <simpson/pendulum_exact.hpp>
#include <simpson/potential.hpp>
#include <simpson/runge_kutta_tableaux.hpp>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace simpson::verify {
namespace {

using test::cell;
using test::get;
using test::number;

TEST(Experiments, NonlinearPendulumIsPinnedByLobattoInMpfr100AndTheExactSolution) {
  nonlinear_settings s;
  s.pendulum_N = {10, 20, 40};
  s.energy_steps = 2000;
  s.brouwer_steps = 1000;
  s.problems.clear();
  s.double_pendulum_N = {10};
  s.timing.max_runs = 0;
  const section_result out = run_nonlinear(s);
  const table& t = get(out, "pendulum");
  ASSERT_EQ(t.rows.size(), 3u);
  // The independent route: Lobatto IIIA–IIIB (the other formulation, claim nonlinear-lobatto-
  // equivalence) in mpfr:100 against the exact solution in mpfr:100.
  const scoped_mpfr_digits digits(100);
  const pendulum_potential<mpfr> V{mpfr(1), mpfr(1)};
  const pendulum_from_rest<mpfr> exact{mpfr(1), mpfr(1), mpfr(s.pendulum_q0)};
  const auto for_q = lobatto_iiia3_tableau<mpfr>(), for_p = lobatto_iiib3_tableau<mpfr>();
  const auto coupling = couple(for_q, for_p);
  const mpfr eps50 = pow(mpfr(10), -49);  // mpfr:50's unit round-off is below 10^-49
  for (std::size_t k = 0; k < s.pendulum_N.size(); ++k) {
    const long long N = s.pendulum_N[k];
    const mpfr h = mpfr(s.pendulum_T) / N;
    phase_point<mpfr> y = exact.at(mpfr(0));
    for (long long j = 0; j < N; ++j) y = prk_nonlinear_step(for_q, for_p, coupling, mpfr(1), h, V, y).state;
    const phase_point<mpfr> end = exact.at(mpfr(s.pendulum_T));
    // The table's run rounds in mpfr:50: N steps, each a Newton solve to 16 eps of terms ~1 and a few
    // roundings, carried to T by the pendulum's flow, whose sensitivity to the state grows linearly
    // in t (the period depends on the amplitude), below 100 over T = 10: 16 × 100 × N eps₅₀ < 1e4 N eps₅₀.
    const mpfr bound = 10000 * N * eps50;
    EXPECT_LE(abs(mpfr(digits_of(cell(t, k, "error_q")) - abs(mpfr(y.q - end.q)))), bound) << "N = " << N;
    EXPECT_LE(abs(mpfr(digits_of(cell(t, k, "error_p")) - abs(mpfr(y.p - end.p)))), bound) << "N = " << N;
    EXPECT_LE(digits_of(cell(t, k, "max_simpson_minus_lobatto")), bound) << "N = " << N;
    if (k > 0) {
      EXPECT_NEAR(number(cell(t, k, "order_q")), 4, 0.1) << "N = " << N;
    }
    EXPECT_EQ(cell(t, k, "status").value(), "ok");
  }
  // The double pendulum: fourth order, and H_d kept to mpfr:50's round-off while H moves by O(h⁴).
  const table& d = get(out, "double_pendulum");
  ASSERT_EQ(d.rows.size(), 1u);
  EXPECT_LE(digits_of(cell(d, 0, "Hd_change_mpfr")), 10000 * 10 * eps50);
  EXPECT_GT(number(cell(d, 0, "H_change_double")), 1e-3);
}

TEST(Experiments, NonlinearBrouwerFormsMatchAReferenceInMpfr) {
  nonlinear_settings s;
  s.pendulum_N = {10};
  s.energy_steps = 10;
  s.brouwer_steps = 20'000;
  s.problems.clear();
  s.double_pendulum_N = {10};
  s.timing.max_runs = 0;
  const section_result out = run_nonlinear(s);
  const table& t = get(out, "pendulum_brouwer");
  // Rows at 100, 1000, 10000 and the last step for each of the three forms.
  ASSERT_EQ(t.rows.size(), 3u * 4u);
  // The independent route: the same double runs (deterministic) against the same map in mpfr:40
  // instead of long double. The table's running maxima differ from these by at most the largest
  // |H(ref in long double) − H(ref in mpfr)|/H₀ over the run (triangle inequality), plus H's
  // rounding in long double (a few eps of terms ≤ 1).
  const scoped_mpfr_digits digits(40);
  const double h = s.brouwer_h;
  const brouwer_coefficients<double> k = simpson_brouwer_coefficients(h);
  const brouwer_coefficients<mpfr> k_mpfr = k.cast<mpfr>();
  const brouwer_coefficients<long double> k_long = k.cast<long double>();
  const pendulum_potential<double> V{1, 1};
  const pendulum_potential<mpfr> V_mpfr{mpfr(1), mpfr(1)};
  const pendulum_potential<long double> V_long{1, 1};
  phase_point<double> standard{0, s.pendulum_q0}, plain = standard;
  compensated_point<double> compensated{standard};
  phase_point<mpfr> reference{mpfr(0), mpfr(s.pendulum_q0)};
  phase_point<long double> reference_long{0, s.pendulum_q0};
  const auto H = [&V_mpfr](const mpfr& p, const mpfr& q) { return mpfr(p * p / 2 + V_mpfr.value(q)); };
  const mpfr H0 = H(reference.p, reference.q);
  std::array<mpfr, 3> running{mpfr(0), mpfr(0), mpfr(0)};
  mpfr reference_gap(0);
  for (long long j = 1; j <= s.brouwer_steps; ++j) {
    standard = simpson_nonlinear_step(1.0, h, V, standard).state;
    simpson_brouwer_step(k, 1.0, V, plain);
    simpson_brouwer_step_compensated(k, 1.0, V, compensated);
    simpson_brouwer_step(k_mpfr, mpfr(1), V_mpfr, reference);
    simpson_brouwer_step(k_long, 1.0L, V_long, reference_long);
    const mpfr Href = H(reference.p, reference.q);
    running[0] = max(running[0], mpfr(abs(H(standard.p, standard.q) - Href) / H0));
    running[1] = max(running[1], mpfr(abs(H(plain.p, plain.q) - Href) / H0));
    running[2] = max(running[2], mpfr(abs(H(compensated.y.p, compensated.y.q) - Href) / H0));
    reference_gap = max(reference_gap, mpfr(abs(H(mpfr(reference_long.p), mpfr(reference_long.q)) - Href) / H0));
  }
  const mpfr bound = reference_gap + 8 * std::numeric_limits<long double>::epsilon();
  const std::array<std::string, 3> forms{"standard", "brouwer", "brouwer-compensated"};
  for (std::size_t f = 0; f < 3; ++f) {
    const std::size_t last = 4 * f + 3;
    EXPECT_EQ(cell(t, last, "form").value(), forms[f]);
    EXPECT_EQ(cell(t, last, "steps").value(), "20000");
    EXPECT_LE(abs(mpfr(mpfr(cell(t, last, "energy_error_relative").value()) - running[f])), bound) << forms[f];
    EXPECT_GT(running[f], 0) << forms[f];  // every form rounds: the comparison is not of zeros
  }
  // The reference is the same map rounded 2¹¹ times more finely: far below double's round-off.
  EXPECT_LT(reference_gap, running[2] / 16);
}

/// The nonlinear section's problems part alone, nothing timed, at the meshes N.
nonlinear_settings problems_only(const std::string& problem, std::vector<long long> N) {
  nonlinear_settings s;
  s.parts = {"problems"};
  s.problems = {problem};
  s.N = std::move(N);
  s.double_pendulum_N = {10};
  s.timing.max_runs = 0;
  return s;
}

TEST(Experiments, NonlinearProblemsRecordAFailedNewtonSolveAndGoOn) {
  nonlinear_settings s = problems_only("kepler", {8, 256, 512});
  s.eccentricity = 0.6;  // one period of the moderate orbit: the failure at N = 8 and the order at 256, 512 below
  s.kepler_periods = 1;
  const section_result out = run_nonlinear(s);
  const table& t = get(out, "problems");
  ASSERT_EQ(t.rows.size(), 5u * 3u);
  std::map<std::string, std::vector<std::size_t>> by_method;
  for (std::size_t k = 0; k < t.rows.size(); ++k) by_method[cell(t, k, "method").value()].push_back(k);
  // At N = 8 (h ≈ 0.79, against a perihelion distance 0.4) Gauss–Legendre's Newton solve does not
  // converge: the row says so, and every other row is computed.
  const figure& failed = cell(t, by_method["gauss-legendre-2"][0], "status");
  EXPECT_TRUE(failed.is_fault() && failed.value().rfind("failed: ", 0) == 0) << failed.value();
  EXPECT_EQ(cell(t, by_method["gauss-legendre-2"][0], "error_q").what(), figure::kind::empty);
  EXPECT_EQ(cell(t, by_method["gauss-legendre-2"][1], "status").value(), "ok");
  // Simpson is drawn once, as the method: Lobatto IIIA–IIIB(3), its map by another implementation, is
  // not among the peers. Its error has order 4 against Kepler's equation.
  EXPECT_EQ(by_method.count("lobatto-iiia-iiib-3"), 0u);
  const std::size_t simpson = by_method["simpson"][1];
  EXPECT_NEAR(std::log2(number(cell(t, simpson, "error_q")) / number(cell(t, by_method["simpson"][2], "error_q"))), 4, 0.1);
  EXPECT_EQ(cell(t, by_method["rk4"][0], "newton_iterations_mean").what(), figure::kind::empty);  // explicit
}

TEST(Experiments, NonlinearProblemsRunThePapersOscillatorThroughTheGeneralSteps) {
  // The paper's oscillator (ω = 2π, one period) as a problem: Simpson's error at T against the exact
  // flow has order 4, Gauss–Legendre 2 keeps the quadratic H to round-off, Störmer–Verlet has order
  // 2. A wrong state at T (sin and cos swapped, or ω for √K) flattens the orders.
  const section_result out = run_nonlinear(problems_only("oscillator", {64, 128}));
  const table& t = get(out, "problems");
  ASSERT_EQ(t.rows.size(), 5u * 2u);
  std::map<std::string, std::vector<std::size_t>> by_method;
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    EXPECT_EQ(cell(t, k, "problem").value(), "oscillator");
    by_method[cell(t, k, "method").value()].push_back(k);
  }
  const auto order = [&](const std::string& method) {
    const std::vector<std::size_t>& r = by_method[method];
    return std::log2(number(cell(t, r[0], "error_q")) / number(cell(t, r[1], "error_q")));
  };
  // At N = 64, 128 (ωh = 0.098, 0.049) the next term of each error is (ωh)² ≈ 1e-2 relative to the
  // leading one, which moves log₂ of the ratio by less than 0.02; 0.05 leaves room for that, while a
  // wrong exact state (an error that stops falling) moves it by whole orders.
  EXPECT_NEAR(order("simpson"), 4, 0.05);
  EXPECT_NEAR(order("gauss-legendre-2"), 4, 0.05);
  EXPECT_NEAR(order("stormer-verlet"), 2, 0.05);
  // Gauss–Legendre keeps quadratic invariants exactly; what is left is each step's Newton stop (16 eps
  // of the terms) and rounding, about 20 eps a step: over 128 steps 2560 eps ≈ 6e-13 at worst. The
  // bound 1e-12 is that worst case; a method that does not conserve H is at 1e-6 and above here.
  EXPECT_LT(number(cell(t, by_method["gauss-legendre-2"][1], "energy_error_max_relative")), 1e-12);
}

TEST(Experiments, NonlinearSectionRunsOnlyThePartsItIsGiven) {
  // The paper scene's nonlinear section is its problems part alone: no pendulum table, no Brouwer
  // runs, no double pendulum, and a title that says what it is.
  const section_result out = run_nonlinear(problems_only("pendulum", {16, 32}));
  EXPECT_NE(out.find_table("problems"), nullptr);
  for (const char* absent : {"pendulum", "pendulum_brouwer", "double_pendulum"}) EXPECT_EQ(out.find_table(absent), nullptr) << absent;
  EXPECT_EQ(out.title.rfind("Error against work on nonlinear problems", 0), 0u) << out.title;
  // The cost of an error, against Simpson's: Simpson's own ratio is 1, and every method that reaches
  // the target does so between the work of its two runs (16 and 32 steps here), never beyond them.
  const table& costs = get(out, "problems_cost");
  ASSERT_EQ(costs.rows.size(), 5u);
  EXPECT_EQ(cell(costs, 0, "method").value(), "simpson");
  EXPECT_EQ(number(cell(costs, 0, "ratio")), 1.0);
  const table& runs = get(out, "problems");
  for (std::size_t r = 0; r < costs.rows.size(); ++r) {
    if (cell(costs, r, "status").value() != "ok") continue;
    const double work = number(cell(costs, r, "work"));
    const double coarse = 16 * number(cell(runs, 2 * r, "gradients_per_step")), fine = 32 * number(cell(runs, 2 * r + 1, "gradients_per_step"));
    EXPECT_GE(work, coarse * (1 - 1e-12)) << cell(costs, r, "method").value();
    EXPECT_LE(work, fine * (1 + 1e-12)) << cell(costs, r, "method").value();
  }
  nonlinear_settings all = problems_only("pendulum", {16});
  all.parts = nonlinear_part_names();
  all.pendulum_N = {10};
  all.energy_steps = 10;
  all.brouwer_steps = 10;
  all.double_pendulum_N = {10};
  const section_result whole = run_nonlinear(all);
  for (const char* present : {"problems", "pendulum", "pendulum_brouwer", "double_pendulum"}) EXPECT_NE(whole.find_table(present), nullptr) << present;
}

TEST(Experiments, NonlinearProblemsCountTheForceEvaluationsTheStepsMake) {
  // Work as evaluations of ∇V and ∇²V, counted as each step makes them: fixed per step for the
  // explicit methods, tied to the Newton iterations for the implicit ones. A count that missed the
  // Newton passes, or counted the timed runs, breaks these equalities.
  nonlinear_settings s = problems_only("fpu", {32, 64});
  s.fpu_T = 1;
  const section_result out = run_nonlinear(s);
  const table& t = get(out, "problems");
  ASSERT_EQ(t.rows.size(), 5u * 2u);
  // The kick–drift–kick compositions evaluate ∇V once a substep (first same as last: the force a
  // kick ends with starts the next), plus once at the start of the run: per step 1 + 1/N and 3 + 1/N.
  const std::map<std::string, double> explicit_calls{{"stormer-verlet", 1}, {"yoshida", 3}, {"rk4", 4}};
  const std::map<std::string, double> stages{{"simpson", 1}, {"gauss-legendre-2", 2}};
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const std::string method = cell(t, r, "method").value();
    ASSERT_EQ(cell(t, r, "status").value(), "ok") << method;
    const double gradients = number(cell(t, r, "gradients_per_step")), hessians = number(cell(t, r, "hessians_per_step"));
    if (explicit_calls.count(method)) {
      const double N = std::stod(cell(t, r, "N").value());
      EXPECT_NEAR(gradients, explicit_calls.at(method) + (method == "rk4" ? 0 : 1 / N), 1e-12) << method;
      EXPECT_EQ(hessians, 0) << method;
      continue;
    }
    const double iterations = number(cell(t, r, "newton_iterations_mean")), k = stages.at(method);
    EXPECT_GT(iterations, 0) << method;
    // Simpson: once per Newton pass (iterations + 1 of them) and at the new q, which the next step
    // starts from (first same as last), plus once at the start of the run.
    const double N = std::stod(cell(t, r, "N").value());
    EXPECT_NEAR(gradients, method == "simpson" ? iterations + 2 + 1 / N : k * (iterations + 1), 1e-9) << method;
    EXPECT_NEAR(hessians, k * iterations, 1e-9) << method;
  }
  // The error against work is drawn: a plot with one panel for the problem.
  EXPECT_TRUE(std::any_of(out.blocks.begin(), out.blocks.end(), [](const section_block& b) {
    const plot_description* p = std::get_if<plot_description>(&b);
    return p && p->name == "nonlinear_problems_work";
  }));
}

}  // namespace
}  // namespace simpson::verify

// The nonlinear_inseparable section: its expectations at a small size, and for each check a change
// that breaks it (a wrong order, a perturbed exact solution, a bound left out); its bad input (a
// top that is not physical, a step too large for Newton) and a run whose Newton fails.

#include <simpson/verify/inseparable_section.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/scene.hpp>

#include "inseparable/inseparable_parts.hpp"

#include <simpson/lagrange_top.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace simpson::verify {
namespace {

/// The section at a test's size (about the quick scene's).
inseparable_settings small() {
  inseparable_settings s;
  s.top_end_time = 2;
  s.top_N = {20, 40, 80};
  s.long_h = {0.1, 0.05};
  s.long_steps = 400;
  s.samples = 20;
  s.reference_digits = 12;
  s.pendulum_end_time = 1;
  s.pendulum_N = {20, 40, 80};
  s.pendulum_reference_digits = 12;
  s.lyapunov_time = 20;
  s.timed = false;
  return s;
}

const expectation* find(const section_result& r, const std::string& key) {
  for (const expectation& e : r.expectations) {
    if (e.key == key) return &e;
  }
  return nullptr;
}

TEST(Inseparable, SectionMeetsItsExpectationsAtASmallSize) {
  const section_result r = run_inseparable(small());
  for (const std::string key : {"top-exact-agrees-with-reference", "top-simpson-order", "top-implicit-midpoint-order", "top-momenta-within-bound",
                                "top-rk4-momenta-exact", "pendulum-inside-horizon", "pendulum-simpson-order"}) {
    const expectation* e = find(r, key);
    ASSERT_NE(e, nullptr) << key;
    EXPECT_TRUE(e->holds) << key << ": " << e->observed;
  }
  for (const expectation& e : r.expectations) EXPECT_TRUE(e.holds) << e.key << ": " << e.observed;
  ASSERT_NE(r.find_table("cost"), nullptr);
  ASSERT_NE(r.find_table("top_errors"), nullptr);
  EXPECT_EQ(r.find_table("top_seconds"), nullptr) << "no timing tables without timing";
  // Never NaN in a report: every figure a number, a count, a word or a blank.
  for (const section_block& b : r.blocks) {
    if (const table* t = std::get_if<table>(&b)) {
      for (const table_row& row : t->rows) {
        for (const figure& f : row) EXPECT_NE(f.value(), "non-finite") << t->key;
      }
    }
  }
}

TEST(Inseparable, APerturbedExactSolutionFailsTheAgreementAndTheOrders) {
  inseparable_settings s = small();
  s.perturb_exact = 1e-6;  // far above the reference's 1e-12 and the errors at the finer N
  const section_result r = run_inseparable(s);
  EXPECT_FALSE(find(r, "top-exact-agrees-with-reference")->holds);
  EXPECT_FALSE(find(r, "top-simpson-order")->holds);
}

TEST(Inseparable, OrderFactProvesFourAndTwoAndAWrongOrderIsRefuted) {
  const published_fact f = inseparable_order_fact(inseparable_fact_settings());
  EXPECT_TRUE(f.holds) << f.note;
  // The same enclosed errors against a wrong order: Simpson's local orders are not 2, nor 3.
  const std::vector<long long> N{50, 100, 200};
  EXPECT_EQ(f.evidence["enclosure"]["methods"][0]["theta_order"], "proved");
  EXPECT_EQ(f.evidence["enclosure"]["methods"][1]["theta_order"], "proved");
  std::vector<interval> errors;
  // Errors e_N = C N^-4 enclosed: order 4 proved, order 2 refuted, order 3 refuted (4 lies outside (2.5, 3.5)).
  for (const long long n : N) errors.push_back(interval(1) / (interval(n) * n * n * n));
  EXPECT_EQ(detail::decide_order(N, errors, 4).outcome, detail::order_decision::verdict::proved);
  EXPECT_EQ(detail::decide_order(N, errors, 2).outcome, detail::order_decision::verdict::refuted);
  EXPECT_EQ(detail::decide_order(N, errors, 3).outcome, detail::order_decision::verdict::refuted);
  // Errors below the rounding allowance decide nothing.
  std::vector<interval> tiny;
  for (const long long n : N) tiny.push_back(interval(1e-14) / (interval(n) * n * n * n));
  EXPECT_EQ(detail::decide_order(N, tiny, 4).outcome, detail::order_decision::verdict::undecided);
}

TEST(Inseparable, MomentaMoveOnlyWithinTheBoundAndNotAtAllUnderRk4) {
  inseparable_settings s = inseparable_fact_settings();
  s.long_steps = 500;
  const published_fact f = inseparable_momenta_fact(s);
  EXPECT_TRUE(f.holds) << f.note;
  // The bound is needed: Simpson's position–momentum update does move p_φ (by rounding), RK4's does not.
  const lagrange_top<double> L(1, 0.5, 1);
  dense_vector<double> q(3), v(3);
  q << s.top.theta0, 0, 0;
  v << 0, 0.5, 8;
  const ndof_state<double> y0{lagrangian_gradient_at(L, q, v).dv, q};
  double simpson_moved = 0, bound = 0;
  const detail::ins_run r = detail::run_method(detail::ins_method::simpson, L, y0, 0.05, 500, [&](long long, const detail::ins_step& st) {
    simpson_moved = std::max(simpson_moved, std::abs(st.state.p(1) - y0.p(1)));
    bound += st.noether_bound(1);
  });
  ASSERT_TRUE(r.ok());
  EXPECT_GT(simpson_moved, 0.0);
  EXPECT_LE(simpson_moved, bound);
  EXPECT_LT(bound, 1e-6);
  const detail::ins_run rk4 = detail::run_method(detail::ins_method::rk4, L, y0, 0.05, 500, [](long long, const detail::ins_step&) {});
  EXPECT_EQ(rk4.state.p(1), y0.p(1));
  EXPECT_EQ(rk4.state.p(2), y0.p(2));
}

TEST(Inseparable, CostIsInterpolatedBetweenTheBracketingRuns) {
  std::vector<detail::convergence_point> points;
  for (const long long n : {10LL, 20LL, 40LL, 80LL}) {
    detail::convergence_point p;
    p.N = n;
    p.error = std::pow(static_cast<double>(n), -4.0);
    p.seconds = 1e-3 * static_cast<double>(n);
    points.push_back(p);
  }
  const detail::reached r = detail::interpolate_reach(points, std::pow(30.0, -4.0));
  ASSERT_TRUE(r.N);
  EXPECT_NEAR(*r.N, 30.0, 1e-9);
  EXPECT_NEAR(*r.seconds, 0.03, 1e-12);
  EXPECT_FALSE(detail::interpolate_reach(points, 1e-12).N);
  EXPECT_EQ(detail::interpolate_reach(points, 1e-12).why_not, "not reached by N = 80");
  EXPECT_EQ(detail::interpolate_reach(points, 1).why_not, "already below at N = 10");
}

TEST(Inseparable, ANewtonFailureStopsTheRunWithItsReason) {
  // A heavy top (Mgl = 100) at h = 1/2: Simpson's Newton does not converge on its first step. (The
  // default top's converges at every h tried up to 200: a solution exists, a meaningless one.)
  const lagrange_top<double> L(1, 0.5, 100);
  dense_vector<double> q(3), v(3);
  q << 1, 0, 0;
  v << 0, 0.5, 8;
  const ndof_state<double> y0{lagrangian_gradient_at(L, q, v).dv, q};
  long long observed = 0;
  const detail::ins_run r = detail::run_method(detail::ins_method::simpson, L, y0, 0.5, 10, [&](long long, const detail::ins_step&) { ++observed; });
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.failure->find("failed at step"), std::string::npos) << *r.failure;
  EXPECT_NE(r.failure->find("Newton"), std::string::npos) << *r.failure;
  EXPECT_EQ(observed, r.steps);
  EXPECT_TRUE(r.state.q.allFinite());
  inseparable_top_settings heavy;
  heavy.Mgl = 100;
  heavy.theta0 = 1;
  EXPECT_FALSE(first_newton_failure(heavy, {0.5}).empty());
  EXPECT_TRUE(first_newton_failure(heavy, {0.01}).empty());
}

std::string inseparable_scene_error(const std::string& section) {
  try {
    parse_scene(R"({"name": "x", "nonlinear_inseparable": )" + section + "}", "t.json", paper_book());
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Inseparable, SceneRefusesANonPhysicalTopAndAStepTooLargeNamingTheField) {
  const auto mentions = [](const std::string& m, const std::string& part) { return m.find(part) != std::string::npos; };
  EXPECT_TRUE(mentions(inseparable_scene_error(R"({"I1": 0})"), "'nonlinear_inseparable.I1'")) << inseparable_scene_error(R"({"I1": 0})");
  EXPECT_TRUE(mentions(inseparable_scene_error(R"({"I3": -1})"), "'nonlinear_inseparable.I3'"));
  EXPECT_TRUE(mentions(inseparable_scene_error(R"({"theta0": 0})"), "'nonlinear_inseparable.theta0'"));
  EXPECT_TRUE(mentions(inseparable_scene_error(R"({"theta0": 3.2})"), "'nonlinear_inseparable.theta0' must lie in (0, pi)")) << inseparable_scene_error(R"({"theta0": 3.2})");
  const std::string heavy = R"({"Mgl": 100, "theta0": 1, "top_N": [1000], "long_h": [0.01, 0.5]})";
  EXPECT_TRUE(mentions(inseparable_scene_error(heavy), "'nonlinear_inseparable.long_h': too large a step for Newton")) << inseparable_scene_error(heavy);
  const std::string coarse = R"({"Mgl": 100, "theta0": 1, "top_end_time": 5, "top_N": [10, 1000], "long_h": [0.01]})";
  EXPECT_TRUE(mentions(inseparable_scene_error(coarse), "'nonlinear_inseparable.top_N' with 'nonlinear_inseparable.top_end_time': too large a step"))
      << inseparable_scene_error(coarse);
  EXPECT_TRUE(mentions(inseparable_scene_error(R"({"top_N": [1]})"), "'nonlinear_inseparable.top_N'"));
  EXPECT_TRUE(mentions(inseparable_scene_error(R"({"colour": 1})"), "unknown key 'nonlinear_inseparable.colour'")) << inseparable_scene_error(R"({"colour": 1})");
  EXPECT_EQ(inseparable_scene_error("{}"), "");
  EXPECT_THROW(check_inseparable_top(inseparable_top_settings{-1, 1, 1, 1, 0, 0, 1}), std::invalid_argument);
}

}  // namespace
}  // namespace simpson::verify

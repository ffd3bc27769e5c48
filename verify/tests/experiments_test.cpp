// The experiment sections: computed only when asked, with finite figures or named faults, and
// results that agree with the ledger's exact algebra.

#include <simpson/verify/experiments.hpp>
#include <simpson/verify/report.hpp>

#include "figures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace simpson::verify {
namespace {

/// Every number in a JSON tree is finite (nlohmann writes NaN and inf as null, so none may be null).
void expect_no_bare_non_finite(const json& j, const std::string& path) {
  if (j.is_null()) ADD_FAILURE() << "null (a NaN or inf) at " << path;
  if (j.is_number_float()) {
    EXPECT_TRUE(std::isfinite(j.get<double>())) << path;
  }
  if (j.is_object()) {
    for (const auto& item : j.items()) expect_no_bare_non_finite(item.value(), path + "." + item.key());
  }
  if (j.is_array()) {
    for (std::size_t k = 0; k < j.size(); ++k) expect_no_bare_non_finite(j[k], path + "[" + std::to_string(k) + "]");
  }
}

TEST(Experiments, FiguresNameTheirFaults) {
  EXPECT_EQ(detail::figure(std::numeric_limits<double>::infinity()), json("overflow"));
  EXPECT_EQ(detail::figure(std::numeric_limits<double>::quiet_NaN()), json("non-finite"));
  EXPECT_EQ(detail::figure(bin100("1e-400")), json("underflow"));
  EXPECT_EQ(detail::figure(bin100("1e400")), json("overflow"));
  EXPECT_EQ(detail::figure(0.25), json(0.25));
  EXPECT_EQ(detail::figure_text(std::numeric_limits<double>::infinity()), "overflow");
  EXPECT_EQ(detail::to_rational(0.375), rational(3, 8));
  // long double's 64-bit mantissa: 1 + 2^-63 is exact, and converts exactly.
  EXPECT_EQ(detail::to_rational(std::ldexp(1.0L, -63) + 1), rational(1) + rational(1) / rational(pow(boost::multiprecision::cpp_int(2), 63)));
}

TEST(Experiments, OnlyTheSectionsAskedForAreComputed) {
  scene s = parse_scene(R"({"name": "t", "table1": {"N": [10, 20]}})", "t");
  const run_record r = run(s);
  ASSERT_EQ(r.sections.size(), 1u);
  EXPECT_EQ(r.sections[0].name, "table1");
  EXPECT_TRUE(r.outcomes.empty());
}

TEST(Experiments, Table1ReproducesTheSimpsonStateRowAndTheOrders) {
  const section_output t = run_table1(table1_settings{});
  expect_no_bare_non_finite(t.data, "table1");
  const json& simpson_state = t.data["rows"][3];
  ASSERT_EQ(simpson_state["quantity"], "state");
  for (const json& e : simpson_state["entries"]) {
    EXPECT_GT(e["published_over_ours"].get<double>(), 0.98);
    EXPECT_LT(e["published_over_ours"].get<double>(), 1.02);
  }
  EXPECT_NEAR(simpson_state["order_least_squares"].get<double>(), 4, 0.05);
  EXPECT_NEAR(t.data["rows"][0]["order_least_squares"].get<double>(), 2, 0.05);  // Newmark momentum
  EXPECT_EQ(t.data["rows"][7]["order_least_squares"], "exact");                   // Simpson H_d
  EXPECT_EQ(t.data["figure1"]["points"].size(), 16u);
}

TEST(Experiments, StabilityFindsTheLedgersIntervalsAndNamesOverflow) {
  stability_settings s;
  s.precisions = {precision::parse("double"), precision::mpfr_digits(50)};
  s.stiff_omegas = {1, 1e8};
  s.omega_h = {1e-6, 1};
  s.masses = {1e-300, 1, 1e300};
  s.steps = 100;
  const section_output out = run_stability(s);
  expect_no_bare_non_finite(out.data, "stability");
  const json& stable = out.data["stable_intervals_omega_h"];
  ASSERT_EQ(stable.size(), 2u);
  EXPECT_EQ(stable[0], json::array({"0", "2 sqrt(2)"}));
  EXPECT_EQ(stable[1], json::array({"2 sqrt(3)", "2 sqrt(6)"}));
  std::map<std::string, std::string> status;
  for (const json& row : out.data["extreme_masses"]) {
    status[row["precision"].get<std::string>() + " " + simpson::to_string(row["m"].get<double>(), 1)] = row["status"];
  }
  EXPECT_EQ(status["double 1e+300"], "overflow");
  EXPECT_EQ(status["double 1e-300"], "underflow");
  EXPECT_EQ(status["double 1e+00"], "ok");
  EXPECT_EQ(status["mpfr:50 1e+300"], "ok");
  EXPECT_EQ(status["mpfr:50 1e-300"], "ok");
  for (const json& row : out.data["endpoints"]) {
    if (row["jordan_block"].is_boolean()) {
      EXPECT_TRUE(row["jordan_block"].get<bool>()) << row["omega_h"];
    }
  }
}

TEST(Experiments, LongRunDriftIsExplainedByTheRoundedDeterminant) {
  long_time_settings s;
  s.steps_double = 200000;
  s.steps_mpfr = 2000;
  s.windows = 20;
  const section_output out = run_long_time(s);
  expect_no_bare_non_finite(out.data, "long_time");
  for (const json& row : out.data["rows"]) {
    // The measured phase error is the one the characteristic roots predict (to the ellipse's O(θ²) wobble).
    EXPECT_NEAR(row["measured_over_predicted"].get<double>(), 1, 0.05) << row["scheme"] << " " << row["precision"];
  }
}

TEST(Experiments, WorkPrecisionRecordsEveryRunWithItsStatus) {
  work_precision_settings w;
  w.schemes = {"simpson", "rk4", "gauss-legendre-2"};
  w.precisions = {precision::parse("double")};
  w.meshes = {8, 32};
  w.timing = {2, 0.1};
  const section_output out = run_work_precision(w);
  ASSERT_EQ(out.data["rows"].size(), 6u);
  for (const json& row : out.data["rows"]) {
    EXPECT_EQ(row["status"], "ok");
    EXPECT_LE(row["timing"]["runs"].get<unsigned>(), 2u);
  }
  // 4th order: the error falls by about 4^4 from N = 8 to 32.
  const double ratio = out.data["rows"][0]["error_q_max"].get<double>() / out.data["rows"][1]["error_q_max"].get<double>();
  EXPECT_GT(ratio, 200);
  EXPECT_LT(ratio, 300);
  // At ωh beyond the stable region the run is recorded as unstable, not dropped.
  w.schemes = {"simpson"};
  w.meshes = {2};  // ωh = π, inside the unstable band (2√2, 2√3)
  w.periods = 100;
  const section_output unstable = run_work_precision(w);
  ASSERT_EQ(unstable.data["rows"].size(), 1u);
  EXPECT_EQ(unstable.data["rows"][0]["status"], "unstable");
  EXPECT_FALSE(unstable.data["rows"][0].contains("error_q_max"));
}

TEST(Experiments, CostEstimateGrowsWithStepsAndPrecision) {
  experiment_settings e;
  e.long_time = long_time_settings{};
  const double base = estimate_cost(e).units;
  e.long_time->steps_double = 1'000'000'000;
  EXPECT_GT(estimate_cost(e).units, default_cost_budget);
  EXPECT_LT(base, default_cost_budget);
  EXPECT_LT(estimate_cost(load_scene("paper").experiments).units, default_cost_budget);
}

}  // namespace
}  // namespace simpson::verify

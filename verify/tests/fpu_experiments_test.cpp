// The fpu section's experiments: the chain's second stability band, its expectations at the quick
// size, and its methods compared at equal cost (force evaluations per unit time).

#include <simpson/verify/experiments.hpp>

#include "experiment_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace simpson::verify {
namespace {

using test::cell;
using test::get;
using test::number;

TEST(Experiments, FpuSecondBandKeepsTheSchemesOwnInvariantNotTheFlows) {
  // Simpson at the middle of its second band (x = 18) keeps I_d but not I; in its first band (ωh = 2)
  // both. A check on I alone would call the second band unstable; one on I_d alone would hide that
  // the numerical solution does not carry the flow's oscillatory energy there.
  const fpu_settings s;
  const fpu_run_summary second = run_fpu_chain(s, "simpson", std::sqrt(18.0), 60);
  const fpu_run_summary first = run_fpu_chain(s, "simpson", 2.0, 60);
  EXPECT_EQ(second.status, "ok");
  EXPECT_LT(second.max_discrete_invariant_error, 0.05);
  EXPECT_GT(second.max_invariant_error, 1.0);
  EXPECT_LT(first.max_invariant_error, 0.1);
  // Störmer–Verlet beyond ωh = 2 and Simpson in its gap become unstable; the A-stable methods do not.
  EXPECT_EQ(run_fpu_chain(s, "stormer-verlet", 2.5, 20).status.rfind("unstable", 0), 0u);
  EXPECT_EQ(run_fpu_chain(s, "simpson", 3.1, 20).status.rfind("unstable", 0), 0u);
  EXPECT_EQ(run_fpu_chain(s, "implicit-midpoint", 3.1, 20).status, "ok");
  // The trigonometric integrator takes the stiff springs' flow exactly: stable in Simpson's gap and
  // beyond Störmer–Verlet's limit.
  EXPECT_EQ(run_fpu_chain(s, "trigonometric", 3.1, 20).status, "ok");
  EXPECT_EQ(run_fpu_chain(s, "trigonometric", 4.5, 20).status, "ok");
  EXPECT_THROW(run_fpu_chain(s, "euler", 1, 1), std::invalid_argument);
}

/// The fpu section at a test's size: runs to t = 4, a scan from `scan_from` to 5 in steps of
/// `scan_step` to t = 2, 50 samples a curve.
fpu_settings fpu_at_test_size(double scan_from, double scan_step) {
  fpu_settings s;
  s.end_time = s.exchange_time = 4;
  s.scan_from = scan_from;
  s.scan_to = 5;
  s.scan_step = scan_step;
  s.scan_end_time = 2;
  s.samples = 50;
  return s;
}

TEST(Experiments, FpuSectionMeetsItsExpectationsAtTheQuickSize) {
  fpu_settings s = fpu_at_test_size(1, 1);
  s.omega_h = {1.5, 3.0};
  s.reference_omega_h = 1;
  s.resonances = {3, 4};
  s.equal_cost_omega_h = {1.5};
  const section_result out = run_fpu(s);
  ASSERT_EQ(out.expectations.size(), 5u);
  // The step-size resonances in closed form: Störmer–Verlet's cos θ = 1 − (ωh)²/2 gives θ = π/2 at
  // √2 and 2π/3 at √3; the implicit midpoint rule's θ = 2 arctan(ωh/2) gives 2 and 2√3. A search
  // for θ = π/k, or one that stopped at the first crossing, would not find these rows.
  const table& scan = get(out, "scan");
  std::map<std::string, std::vector<std::pair<double, std::string>>> resonant;
  for (std::size_t r = 0; r < scan.rows.size(); ++r) {
    const std::string label = cell(scan, r, "resonance").value();
    if (!label.empty()) resonant[cell(scan, r, "method").value()].emplace_back(number(cell(scan, r, "omega_h")), label);
  }
  ASSERT_EQ(resonant["stormer-verlet"].size(), 2u);
  EXPECT_NEAR(resonant["stormer-verlet"][0].first, std::sqrt(2.0), 1e-12);
  EXPECT_EQ(resonant["stormer-verlet"][0].second, "θ = π/2");
  EXPECT_NEAR(resonant["stormer-verlet"][1].first, std::sqrt(3.0), 1e-12);
  EXPECT_EQ(resonant["stormer-verlet"][1].second, "θ = 2π/3");
  ASSERT_EQ(resonant["implicit-midpoint"].size(), 2u);
  EXPECT_NEAR(resonant["implicit-midpoint"][0].first, 2, 1e-12);
  EXPECT_NEAR(resonant["implicit-midpoint"][1].first, 2 * std::sqrt(3.0), 1e-12);
  // Φ₃ turns through π/2 and 2π/3 in each of its two bands (θ runs from 0 to π in the first, and
  // back in the second): four resonances up to ωh = 5.
  EXPECT_EQ(resonant["simpson"].size(), 4u);
  // The trigonometric method turns the stiff springs exactly, θ = ωh: π/2, 2π/3, 4π/3 and 3π/2 up to 5.
  ASSERT_EQ(resonant["trigonometric"].size(), 4u);
  EXPECT_NEAR(resonant["trigonometric"][0].first, std::acos(-1.0) / 2, 1e-9);
  EXPECT_NEAR(resonant["trigonometric"][3].first, 3 * std::acos(-1.0) / 2, 1e-9);
  for (const expectation& e : out.expectations) EXPECT_TRUE(e.holds) << e.key << ": " << e.observed;
  const table& runs = get(out, "runs");
  for (std::size_t r = 0; r < runs.rows.size(); ++r) {
    const bool gap = cell(runs, r, "omega_h").value().rfind("3", 0) == 0;
    const std::string method = cell(runs, r, "method").value();
    const bool unstable = cell(runs, r, "status").value().rfind("unstable", 0) == 0;
    EXPECT_EQ(unstable, gap && (method == "simpson" || method == "stormer-verlet")) << method << " " << cell(runs, r, "omega_h").value();
  }
}

TEST(Experiments, FpuMethodsAreComparedAtEqualCost) {
  // Each method's step at the force evaluations per unit time of Störmer–Verlet at ωh = 0.5 and 1.5:
  // the explicit ones (one evaluation a step) at that ωh exactly, the implicit ones where their own
  // evaluations per step over ωh are 1/0.5 and 1/1.5. A comparison at equal step (every ωh the same)
  // fails the second check.
  fpu_settings s = fpu_at_test_size(0.25, 0.25);
  s.omega_h = {1.5};
  s.reference_omega_h = 0.5;
  s.resonances = {};
  s.equal_cost_omega_h = {0.5, 1.5};
  const section_result out = run_fpu(s);
  const table& costs = get(out, "equal_cost");
  ASSERT_EQ(costs.rows.size(), 10u);
  for (std::size_t r = 0; r < costs.rows.size(); ++r) {
    const std::string method = cell(costs, r, "method").value(), status = cell(costs, r, "status").value();
    const double budget = number(cell(costs, r, "budget"));
    if (method == "stormer-verlet" || method == "trigonometric") {
      EXPECT_EQ(status, "ok");
      EXPECT_EQ(number(cell(costs, r, "omega_h")), budget) << method;
      EXPECT_EQ(number(cell(costs, r, "gradients_per_step")), 1.0) << method;
      continue;
    }
    if (status != "ok") {
      // Simpson at Störmer–Verlet's cost at 1.5: its cheapest stable step costs more.
      EXPECT_EQ(status.rfind("no scanned stable step this cheap", 0), 0u) << method << " at " << budget << ": " << status;
      continue;
    }
    // The step comes from the scan's runs (t ≤ 2), the row from a run to t = 4: the Newton iterations
    // per step of the two differ by a few percent, hence 10%.
    const double omega_h = number(cell(costs, r, "omega_h")), per_step = number(cell(costs, r, "gradients_per_step"));
    EXPECT_GT(per_step, 1.5) << method;
    EXPECT_NEAR(per_step / omega_h * budget, 1.0, 0.1) << method << " at " << budget << ": ωh " << omega_h << ", " << per_step << " a step";
  }
  EXPECT_EQ(cell(costs, 5, "method").value(), "simpson");
  EXPECT_EQ(cell(costs, 5, "status").value().rfind("no scanned stable step this cheap", 0), 0u) << cell(costs, 5, "status").value();
}

/// Midpoint and radius of an enclosed figure's text ("1.4427e-14 ± 3e-31"), read in mpfr.

}  // namespace
}  // namespace simpson::verify

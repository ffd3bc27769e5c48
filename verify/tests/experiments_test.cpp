// The experiment sections: computed only when asked, with figures in their own precision or named
// faults, and results that agree with the ledger's exact algebra.

#include <simpson/verify/experiment_cost.hpp>
#include <simpson/verify/enclosure_undecided.hpp>
#include <simpson/verify/experiments.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/nonlinear_section.hpp>
#include <simpson/verify/paper_table.hpp>
#include <simpson/verify/printed_table1.hpp>
#include <simpson/verify/report.hpp>
#include <simpson/verify/table1_enclosed.hpp>

#include "experiment_fixture.hpp"
#include "stability_parts.hpp"

#include <simpson/verify/floating_tools.hpp>

#include <simpson/nonlinear_brouwer_step.hpp>
#include <simpson/nonlinear_partitioned_rk.hpp>
#include <simpson/pendulum_exact.hpp>
#include <simpson/potential.hpp>
#include <simpson/runge_kutta_tableaux.hpp>

#include <boost/math/constants/constants.hpp>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <set>

#include <cmath>
#include <limits>

namespace simpson::verify {
namespace {

using test::cell;
using test::embedded_table1;
using test::get;
using test::number;
using test::with_embedded_table1;

TEST(Figures, NameTheirFaultsInTheirOwnPrecision) {
  EXPECT_EQ(figure::of(std::numeric_limits<double>::infinity()), figure::fault("overflow"));
  EXPECT_EQ(figure::of(std::numeric_limits<double>::quiet_NaN()), figure::fault("non-finite"));
  EXPECT_EQ(figure::of(std::numeric_limits<double>::denorm_min()), figure::fault("underflow"));
  // Far below double's range is an ordinary number in bin100 and in mpfr: no fault, every digit kept.
  const figure tiny = figure::of(bin100("3.25e-400"));
  EXPECT_EQ(tiny.what(), figure::kind::number);
  EXPECT_EQ(round_decimal(tiny.value(), 3), "3.25e-400");
  EXPECT_FALSE(tiny.plottable());
  {
    const scoped_mpfr_digits digits(3000);
    const mpfr v = mpfr(1) / mpfr(3) * pow(mpfr(10), -2987);
    const figure f = figure::of(v);
    EXPECT_EQ(display(f, 2), "3.3e-2988");
    EXPECT_GE(f.value().size(), 3000u);  // the digits the precision carries
  }
  EXPECT_EQ(figure::of(0.25).as_computed_double(), std::optional<double>(0.25));
  EXPECT_EQ(figure_json(figure::of(0.25)), json(0.25));
  EXPECT_EQ(figure_json(figure::of(bin100("3.25e-400"))).get<std::string>().substr(0, 6), "3.2500");
  EXPECT_EQ(to_rational(0.375), rational(3, 8));
  // long double's 64-bit mantissa: 1 + 2^-63 is exact, and converts exactly.
  EXPECT_EQ(to_rational(std::ldexp(1.0L, -63) + 1), rational(1) + rational(1) / rational(pow(boost::multiprecision::cpp_int(2), 63)));
}

TEST(Figures, RoundDecimalRoundsTheDigitsThemselves) {
  EXPECT_EQ(round_decimal("1.4449e-14", 3), "1.44e-14");
  EXPECT_EQ(round_decimal("1.4450e-14", 3), "1.45e-14");
  EXPECT_EQ(round_decimal("9.996e+02", 3), "1.00e+03");
  EXPECT_EQ(round_decimal("-0.000123456", 2), "-1.2e-04");
  EXPECT_EQ(round_decimal("123", 5), "1.2300e+02");
  EXPECT_EQ(round_decimal("-0.0000e+00", 3), "0.00e+00");
  EXPECT_EQ(round_decimal("1e+300", 1), "1e+300");
  EXPECT_THROW(round_decimal("nan", 3), std::invalid_argument);
  // Fixed decimals: a rounding that carries into a new leading digit keeps the decimals asked
  // (0.9975 to two decimals is 1.00, not 0.10; a one-digit probe of its exponent took it for 1's).
  EXPECT_EQ(fixed_decimal("0.9975", 2), "1.00");
  EXPECT_EQ(fixed_decimal("-0.9975", 2), "-1.00");
  EXPECT_EQ(fixed_decimal("9.96", 1), "10.0");
  EXPECT_EQ(fixed_decimal("142.0117", 1), "142.0");
  EXPECT_EQ(fixed_decimal("0.006", 2), "0.01");
  EXPECT_EQ(fixed_decimal("0.004", 2), "0.00");
  EXPECT_EQ(fixed_decimal("0.0001", 2), "0.00");
  EXPECT_EQ(fixed_decimal("1.5", 0), "2");
  EXPECT_EQ(fixed_decimal("0", 3), "0.000");
}

TEST(Figures, AnEnclosedNumberShowsItsRadiusWhenItHasFewerGuaranteedDigitsThanAsked) {
  const figure wide = figure::enclosed("1.4e-14", "3e-16"), narrow = figure::enclosed("1.4427e-14", "3e-31");
  EXPECT_EQ(display(wide, 3), "1.4e-14 ± 3e-16");
  EXPECT_EQ(display(narrow, 3), "1.44e-14");
  EXPECT_EQ(display(figure::enclosed("0", "2e-50"), 3), "0 ± 2e-50");
  EXPECT_EQ(narrow.full_text(), "1.4427e-14 ± 3e-31");
  EXPECT_EQ(figure_json(narrow), json("1.4427e-14 ± 3e-31"));
  EXPECT_FALSE(wide == figure::enclosed("1.4e-14", "4e-16"));  // the radius is part of the figure
  // Without the radius, for a text that states it on its own: the value display shows, no more.
  EXPECT_EQ(display_value(wide, 3), "1.4e-14");
  EXPECT_EQ(display_value(narrow, 3), "1.44e-14");
  EXPECT_EQ(display_value(figure::enclosed("0", "2e-50"), 3), "0");
}

TEST(Figures, MarkdownCellsEscapePipes) {
  EXPECT_EQ(markdown_cell("max |y|/A"), "max \\|y\\|/A");
}

TEST(Experiments, OnlyTheSectionsAskedForAreComputed) {
  scene s = parse_scene(R"({"name": "t", "table1": {"N": [10, 20]}})", "t", paper_book());
  const run_record r = run(s);
  ASSERT_EQ(r.sections.size(), 1u);
  EXPECT_EQ(r.sections[0].name, "table1");
  EXPECT_TRUE(r.outcomes.empty());
}

TEST(Experiments, Table1ReproducesTheSimpsonStateRowAndTheOrders) {
  const section_result t = run_table1(with_embedded_table1());
  const table& entries = get(t, "entries");
  ASSERT_EQ(entries.rows.size(), 24u);  // 8 rows × 3 meshes
  for (std::size_t r = 9; r < 12; ++r) {  // Simpson state at N = 10, 20, 40
    ASSERT_EQ(cell(entries, r, "quantity").value(), "state");
    ASSERT_EQ(cell(entries, r, "scheme").value(), "Symplectic Simpson");
    EXPECT_GT(number(cell(entries, r, "published_over_ours")), 0.98);
    EXPECT_LT(number(cell(entries, r, "published_over_ours")), 1.02);
  }
  const table& orders = get(t, "orders");
  EXPECT_NEAR(number(cell(orders, 3, "order_least_squares")), 4, 0.05);
  EXPECT_NEAR(number(cell(orders, 0, "order_least_squares")), 2, 0.05);  // Newmark momentum
  EXPECT_EQ(cell(orders, 7, "order_least_squares").value(), "exact");       // Simpson H_d
  // Each row's order is held against the order the exact scheme's enclosures prove: eight
  // expectations, all held.
  ASSERT_EQ(t.expectations.size(), 8u);
  for (const expectation& e : t.expectations) EXPECT_TRUE(e.holds) << e.key << ": " << e.observed;
  EXPECT_EQ(t.expectations[3].key, "order-symplectic-simpson-state");
  EXPECT_EQ(t.expectations[7].key, "order-symplectic-simpson-energy-hamiltonien-discret");
}

TEST(Experiments, AnOrderAgreesWithTheProvedOneWithinAHalfOrBothExact) {
  EXPECT_EQ(order_agrees("4", 4.02), true);
  EXPECT_EQ(order_agrees("4", 3.55), true);
  // A third-order run against a proved fourth order fails; a rule of "within 1" would pass it.
  EXPECT_EQ(order_agrees("4", 3.02), false);
  EXPECT_EQ(order_agrees("2", std::nullopt), false);  // a proved order, yet every error at round-off
  EXPECT_EQ(order_agrees("exact", std::nullopt), true);
  EXPECT_EQ(order_agrees("exact", 4.0), false);  // the exact scheme conserves it, the run does not
  EXPECT_EQ(order_agrees("undecided (a log2 ratio is not within 1/2 of an integer)", 4.0), std::nullopt);
}

TEST(Experiments, StabilityFindsTheLedgersIntervalsAndDecidesFaultsInItsPrecision) {
  stability_settings s;
  s.precisions = {precision::parse("double"), precision::mpfr_digits(50)};
  s.stiff_ratios = {1e3};
  s.stiff_doublings = 20;
  s.omega_h = {1e-6, 1, 3.0, 4.5};  // 3.0: the unstable band (2√2, 2√3); 4.5: the second stable band
  s.masses = {1e-300, 1, 1e300};
  s.steps = 100;
  const section_result out = run_stability(s);
  std::vector<std::pair<std::string, std::string>> stable;
  const table& intervals = get(out, "intervals");
  for (std::size_t r = 0; r < intervals.rows.size(); ++r) {
    if (cell(intervals, r, "stable").value() == "yes") {
      stable.emplace_back(cell(intervals, r, "omega_h_from").value(), cell(intervals, r, "omega_h_to").value());
    }
  }
  const std::vector<std::pair<std::string, std::string>> expected{{"0", "2 sqrt(2)"}, {"2 sqrt(3)", "2 sqrt(6)"}};
  EXPECT_EQ(stable, expected);
  std::map<std::string, std::string> status;
  const table& masses = get(out, "extreme_masses");
  for (std::size_t r = 0; r < masses.rows.size(); ++r) {
    status[cell(masses, r, "precision").value() + " " + display(cell(masses, r, "m"), 1)] = cell(masses, r, "status").value();
  }
  EXPECT_EQ(status["double 1e+300"], "overflow");
  EXPECT_EQ(status["double 1e-300"], "underflow");
  EXPECT_EQ(status["double 1e+00"], "ok");
  EXPECT_EQ(status["mpfr:50 1e+300"], "ok");
  EXPECT_EQ(status["mpfr:50 1e-300"], "ok");
  for (const expectation& e : out.expectations) EXPECT_TRUE(e.holds) << e.key << ": " << e.observed;
  const table& endpoints = get(out, "endpoints");
  for (std::size_t r = 0; r < endpoints.rows.size(); ++r) {
    const figure& j = cell(endpoints, r, "jordan_block");
    if (j.what() == figure::kind::flag) {
      EXPECT_EQ(j.value(), "yes") << cell(endpoints, r, "omega_h").value();
    }
  }
  const table& extreme = get(out, "extreme_omega_h");
  for (std::size_t r = 0; r < extreme.rows.size(); ++r) {
    const double th = std::stod(cell(extreme, r, "omega_h").value());
    const figure& st = cell(extreme, r, "status");
    // ωh = 3 lies in (2√2, 2√3): the run leaves its orbit and stops, reported as unstable with its step.
    if (th == 3.0) {
      EXPECT_TRUE(is_unstable(st)) << st.value();
    } else {
      EXPECT_EQ(st.value(), "ok") << th;
    }
    // The digits of c are a number everywhere, including the second band where c < 0.
    EXPECT_EQ(cell(extreme, r, "digits_of_c").what(), figure::kind::number) << th;
  }
}

/// Φ₃'s exact region, as the stability section computes it.
stability_report simpson_region() { return simpson_exact_region(); }

/// The expectations of a section by key.
std::map<std::string, expectation> expectations_of(const section_result& out) {
  std::map<std::string, expectation> by_key;
  for (const expectation& e : out.expectations) by_key[e.key] = e;
  return by_key;
}

TEST(Experiments, EndpointGrowthIsFittedAsTheExactRegionPredicts) {
  section_result out;
  detail::add_endpoint_growth(simpson_region(), 1000000000LL, out);
  const std::map<std::string, expectation> e = expectations_of(out);
  ASSERT_EQ(e.size(), 9u);
  for (const auto& [key, one] : e) EXPECT_TRUE(one.holds) << key << ": " << one.predicted << " / " << one.observed;
  // Each class where the region puts it: bounded inside, linear at the endpoint, exponential outside.
  EXPECT_EQ(e.at("endpoint-x8-below").observed.rfind("bounded", 0), 0u) << e.at("endpoint-x8-below").observed;
  EXPECT_EQ(e.at("endpoint-x8-at").observed.rfind("linear", 0), 0u);
  EXPECT_EQ(e.at("endpoint-x8-above").observed.rfind("exponential", 0), 0u);
  EXPECT_EQ(e.at("endpoint-x12-above").observed.rfind("bounded", 0), 0u);  // the second band begins
  // At the endpoint, 1000 steps show growth on both sides, as the old fixed-count table did; the
  // fit over 10⁶..10⁹ steps separates them.
  const table& t = get(out, "endpoints");
  EXPECT_GT(number(cell(t, 0, "max_amplitude_to_1000")), 100);
  EXPECT_LT(number(cell(t, 0, "max_amplitude_to_1000000000")), 2 * number(cell(t, 0, "max_amplitude_to_1000")));
  EXPECT_GT(cell(t, 2, "max_amplitude_to_1000000000").log10_magnitude().value(), 300000.0);  // above 2√2: e^{n ln|λ|}, beyond double
}

TEST(Experiments, AWrongRegionMakesTheStabilityExpectationsFail) {
  // A harness that knew only the first band (0, 2√2), with (2√3, 2√6) marked unstable: the rows its
  // runs show bounded there must fail, and only those. (A check that compared a run with itself, or
  // typed its prediction from the run, would pass them.)
  stability_report first_band_only = simpson_region();
  for (stability_band& band : first_band_only.bands) band.stable = band.stable && band.x_from == 0;
  section_result out;
  detail::add_endpoint_growth(first_band_only, 1000000000LL, out);
  detail::add_stiff_chain(first_band_only, {1e3}, 20, out);
  std::set<std::string> failed;
  for (const expectation& e : out.expectations) {
    if (!e.holds) failed.insert(e.key);
  }
  const std::set<std::string> expected{"endpoint-x12-above", "endpoint-x24-below", "stiff-chain-r1.00e+03-x18"};
  EXPECT_EQ(failed, expected);
}

TEST(Experiments, TheStiffChainIsDecidedByItsFastModes) {
  section_result out;
  detail::add_stiff_chain(simpson_region(), {1e3, 1e6}, 30, out);
  const table& t = get(out, "stiff_chain");
  ASSERT_EQ(t.rows.size(), 8u);  // two ratios, the fast modes mid-band in each of the four bands
  const std::vector<std::string> predicted{"bounded", "exponential", "bounded", "exponential"};
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    EXPECT_EQ(cell(t, r, "predicted").value(), predicted[r % 4]) << r;
    EXPECT_EQ(cell(t, r, "fitted").value(), predicted[r % 4]) << r;
    EXPECT_LT(number(cell(t, r, "slow_omega_h")), 0.01) << r;  // the step resolves the slow modes
    EXPECT_GT(number(cell(t, r, "ratio")), 0.9 * (r < 4 ? 1e3 : 1e6)) << r;
  }
  // In the second band (12, 24) the slow modes sit in (0, 8) and the fast ones in (12, 24): stable.
  EXPECT_EQ(cell(t, 2, "modes").value(), "2 in (0, 8), 2 in (12, 24)");
  for (const expectation& e : out.expectations) EXPECT_TRUE(e.holds) << e.key << ": " << e.observed;
  // The run is enclosed: every figure of the growth carries its radius, far below its size.
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const figure& exponent = cell(t, r, "growth_exponent");
    EXPECT_FALSE(exponent.radius().empty()) << exponent.full_text();
    EXPECT_LT(std::stod(exponent.radius()), 1e-30) << exponent.full_text();
  }
}

std::pair<mpfr, mpfr> enclosure_parts_of(const figure& f) {
  EXPECT_FALSE(f.radius().empty()) << f.full_text() << " is not an enclosure";
  return {mpfr(f.value()), mpfr(f.radius().empty() ? "0" : f.radius())};
}

TEST(Experiments, LongRunDriftIsExplainedByTheRoundedDeterminantAndEnclosedAboveDouble) {
  long_time_settings s;
  s.steps_double = 200000;
  s.steps_mpfr = 2000;
  s.windows = 20;
  const section_result out = run_long_time(s);
  const table& rows = get(out, "rows");
  const scoped_mpfr_digits digits(80);
  int enclosed = 0;
  for (std::size_t r = 0; r < rows.rows.size(); ++r) {
    // The measured phase error is the one the characteristic roots predict (to the ellipse's O(θ²) wobble).
    EXPECT_NEAR(static_cast<double>(mpfr(cell(rows, r, "measured_over_predicted").value())), 1, 0.05)
        << cell(rows, r, "scheme").value();
    const figure& change = cell(rows, r, "max_relative_energy_change");
    if (cell(rows, r, "precision").value() == "double") {
      EXPECT_TRUE(change.radius().empty());
      continue;
    }
    ++enclosed;
    // The enclosure's radius is far below mpfr:50's own evaluation round-off (~1e-49), and the
    // floating evaluation's drift prediction |det − 1| · steps agrees with it within that round-off.
    const auto [mid, radius] = enclosure_parts_of(change);
    EXPECT_LT(radius, mpfr("1e-55")) << change.full_text();
    const mpfr predicted(cell(rows, r, "drift_predicted_by_rounded_det").value());
    if (cell(rows, r, "scheme").value() != "rk4") {
      EXPECT_LT(abs(mpfr(mid - predicted)), mpfr("1e-48")) << change.full_text();
    }
    const auto [phase, phase_radius] = enclosure_parts_of(cell(rows, r, "phase_error_measured"));
    EXPECT_LT(phase_radius, mpfr("1e-50"));
    EXPECT_GT(abs(phase), mpfr("1e-6"));  // a phase error of the scheme, not of the rounding
  }
  EXPECT_EQ(enclosed, 3);
  // The drift law: linear for Simpson and Newmark in double (|detⁿ − 1| = 2000 n eps there, far above
  // the round-off's walk); in mpfr:50 at 2000 steps it is under 100 eps √n, and not predicted.
  ASSERT_EQ(out.expectations.size(), 2u);
  for (const expectation& e : out.expectations) {
    EXPECT_TRUE(e.holds) << e.key << ": " << e.observed;
    EXPECT_EQ(e.observed.rfind("linear: drift slope", 0), 0u) << e.observed;
  }
  EXPECT_EQ(out.expectations[0].key, "drift-law-simpson-double");
}

TEST(Experiments, AnEnergyDriftIsClassedAtTheMidpointsOfTheThreeLaws) {
  EXPECT_EQ(energy_drift_class(0.02), "bounded");
  // A random walk of round-off is not a linear drift: the stability tables' growth classes (linear from
  // 0.5) would call it one.
  EXPECT_EQ(energy_drift_class(0.5), "random walk");
  EXPECT_EQ(energy_drift_class(0.74), "random walk");
  EXPECT_EQ(energy_drift_class(0.999), "linear");
  EXPECT_EQ(energy_drift_class(2), "faster than linear");
}

TEST(Experiments, AboveDoubleTheWorkPrecisionErrorsAreEnclosuresOfTheSchemesErrors) {
  work_precision_settings w;
  w.schemes = {scheme_id::simpson, scheme_id::newmark};
  w.precisions = {precision::parse("double"), precision::mpfr_digits(50)};
  w.meshes = {16, 64};
  w.timing.max_runs = 0;
  const section_result out = run_work_precision(w);
  const table& rows = get(out, "rows");
  ASSERT_EQ(rows.rows.size(), 16u);  // two schemes, two forms, two precisions, two N
  const scoped_mpfr_digits digits(80);
  std::map<std::string, double> in_double;
  for (std::size_t r = 0; r < rows.rows.size(); ++r) {
    const std::string key = cell(rows, r, "scheme").value() + " " + cell(rows, r, "form").value() + " " + cell(rows, r, "N_per_period").value();
    const figure& error = cell(rows, r, "error_q_max");
    if (cell(rows, r, "precision").value() == "double") {
      in_double[key] = number(error);
      continue;
    }
    // The enclosed error is the double run's within double's round-off floor (100 N eps, the
    // section's own), the error being the scheme's, far above it; its radius is far below both.
    const auto [mid, radius] = enclosure_parts_of(error);
    EXPECT_LT(radius, mpfr("1e-40")) << error.full_text();
    const double N = std::stod(cell(rows, r, "N_per_period").value());
    EXPECT_NEAR(static_cast<double>(mid), in_double.at(key), 100 * N * std::numeric_limits<double>::epsilon())
        << key << ": " << error.full_text();
  }
}

TEST(Experiments, TheEnclosedPaperExperimentProvesEachSchemesOrderAndDecidesFigure1sBounds) {
  // Table 1's rows (published_rows()): Newmark's p and q (rows 0, 2) of order 2, Simpson's (rows 1, 3) of order 4.
  const std::array<enclosed_table_row, 8> rows = enclosed_table1(40, 12);
  EXPECT_EQ(rows[0].order, "2") << rows[0].order_evidence;
  EXPECT_EQ(rows[2].order, "2") << rows[2].order_evidence;
  EXPECT_EQ(rows[1].order, "4") << rows[1].order_evidence;
  EXPECT_EQ(rows[3].order, "4") << rows[3].order_evidence;
  // Figure 1 (N = 15): Simpson's momentum within 1/500 of the amplitude, Newmark's above it; both
  // within 1/10; and a bound between Simpson's p error (5.14e-5) and q error (7.98e-5) splits them.
  const std::vector<std::pair<long, long>> bounds{{1, 10}, {1, 500}, {1, 15000}};
  const bounded_errors s = enclosed_errors_within(true, 15, bounds), n = enclosed_errors_within(false, 15, bounds);
  EXPECT_EQ(s.worst_within[0], bound_decision::at_most);
  EXPECT_EQ(n.worst_within[0], bound_decision::at_most);
  EXPECT_EQ(s.p_within[1], bound_decision::at_most);
  EXPECT_EQ(n.p_within[1], bound_decision::above);
  EXPECT_EQ(s.p_within[2], bound_decision::at_most) << s.p_over_m_omega;
  EXPECT_EQ(s.worst_within[2], bound_decision::above) << s.q;
}

TEST(Experiments, TheShearFormsOfPhi3DoNotDrift) {
  long_time_settings s;
  s.steps_double = 1000000;
  s.steps_mpfr = 100;
  s.windows = 10;
  const section_result out = run_long_time(s);
  const table& forms = get(out, "forms");
  std::map<std::string, std::pair<double, double>> at_end;  // form: (H_d error at 1e6 steps, growth exponent)
  for (std::size_t r = 0; r < forms.rows.size(); ++r) {
    if (cell(forms, r, "steps").value() != "1000000") continue;
    at_end[cell(forms, r, "form").value()] = {number(cell(forms, r, "hd_error_relative")), number(cell(forms, r, "growth_exponent"))};
  }
  ASSERT_EQ(at_end.size(), 3u);
  // The rounded matrix drifts linearly (det Φ − 1 ≈ −2.2e-16 a step: 2.2e-10 at 1e6 steps).
  EXPECT_NEAR(at_end["matrix"].second, 1, 0.02);
  EXPECT_NEAR(at_end["matrix"].first, 2.2e-10, 0.1e-10);
  // The shear forms only random-walk: a growth exponent well below 1, and errors more than 100 times
  // smaller; compensated summation below the plain shear form.
  EXPECT_LT(at_end["shear"].second, 0.8);
  EXPECT_LT(at_end["shear-compensated"].second, 0.8);
  EXPECT_LT(at_end["shear"].first, at_end["matrix"].first / 100);
  EXPECT_LT(at_end["shear-compensated"].first, at_end["shear"].first);
}

TEST(Experiments, WorkPrecisionRecordsEveryRunWithItsStatus) {
  work_precision_settings w;
  w.schemes = {scheme_id::simpson, scheme_id::rk4, scheme_id::gauss_legendre_2};
  w.precisions = {precision::parse("double")};
  w.meshes = {8, 32};
  w.timing = {2, 0.1};
  const section_result out = run_work_precision(w);
  const table& rows = get(out, "rows");
  const table& times = get(out, "timing_rows");
  ASSERT_EQ(rows.rows.size(), 12u);  // three schemes, two forms (step, matrix), two N
  ASSERT_EQ(times.rows.size(), 12u);
  EXPECT_TRUE(times.timing);
  EXPECT_FALSE(rows.timing);
  for (std::size_t r = 0; r < rows.rows.size(); ++r) {
    EXPECT_EQ(cell(rows, r, "status").value(), "ok");
    EXPECT_LE(std::stoi(cell(times, r, "runs").value()), 2);
    EXPECT_GT(number(cell(times, r, "min_seconds")), 0);
    // The spread of the timed runs: minimum ≤ median ≤ maximum.
    EXPECT_LE(number(cell(times, r, "min_seconds")), number(cell(times, r, "median_seconds")));
    EXPECT_LE(number(cell(times, r, "median_seconds")), number(cell(times, r, "max_seconds")));
  }
  // Against run time the general step only: the matrix form costs the same per step for every
  // scheme, and drawn against time it would be error against N relabelled.
  bool drawn = false;
  for (const section_block& block : out.blocks) {
    const plot_description* plot = std::get_if<plot_description>(&block);
    if (plot == nullptr || plot->name != "work_precision_time") continue;
    drawn = !plot->panels.empty();
    for (const panel& p : plot->panels) EXPECT_EQ(p.title.find("matrix"), std::string::npos) << p.title;
  }
  EXPECT_TRUE(drawn) << "the time plot";
  // Untimed (--no-timing): the same errors, and no timing table or time plot.
  work_precision_settings untimed = w;
  untimed.timing.max_runs = 0;
  const section_result plain = run_work_precision(untimed);
  EXPECT_EQ(plain.find_table("timing_rows"), nullptr);
  EXPECT_FALSE(has_timing(plain));
  EXPECT_EQ(section_json(plain)["rows"].dump(), section_json(out)["rows"].dump());
  EXPECT_EQ(section_files(plain).size(), 1u + 1u);  // work_precision.csv and work_precision_n.dat
  // 4th order: the error falls by about 4^4 from N = 8 to 32.
  const double ratio = number(cell(rows, 0, "error_q_max")) / number(cell(rows, 1, "error_q_max"));
  EXPECT_GT(ratio, 200);
  EXPECT_LT(ratio, 300);
  // The two forms are the same scheme: Simpson's nonlinear step (Newton on the internal node) and Φ₃
  // agree to round-off, and so do RK4's stages and its matrix. The largest energy change over the run
  // is at least the one at its end (a whole period, back near y₀).
  for (std::size_t r = 0; r + 2 < rows.rows.size(); r += 4) {
    ASSERT_EQ(cell(rows, r, "form").value(), "step");
    ASSERT_EQ(cell(rows, r + 2, "form").value(), "matrix");
    for (std::size_t k : {r, r + 1}) {
      const double step = number(cell(rows, k, "error_q_max")), matrix = number(cell(rows, k + 2, "error_q_max"));
      EXPECT_NEAR(step, matrix, 1e-12 + 1e-6 * matrix) << cell(rows, k, "scheme").value();
      EXPECT_GE(number(cell(rows, k, "error_H_max_relative")), number(cell(rows, k, "error_H_end_relative")));
    }
  }
  // At ωh beyond the stable region the run is recorded as unstable, with its step, not dropped.
  w.schemes = {scheme_id::simpson};
  w.meshes = {2};  // ωh = π, inside the unstable band (2√2, 2√3)
  w.periods = 100;
  const section_result unstable = run_work_precision(w);
  const table& u = get(unstable, "rows");
  ASSERT_EQ(u.rows.size(), 2u);  // the step and the matrix form
  for (std::size_t r = 0; r < 2; ++r) {
    EXPECT_TRUE(is_unstable(cell(u, r, "status"))) << cell(u, r, "status").value();
    EXPECT_EQ(cell(u, r, "error_q_max").what(), figure::kind::empty);
  }
}

/// A figure's digits (every digit computed, figure.hpp) read into mpfr at the current precision.
mpfr digits_of(const figure& f) {
  EXPECT_EQ(f.what(), figure::kind::number) << f.value();
  return mpfr(f.value());
}

TEST(Experiments, CostEstimateGrowsWithStepsAndPrecision) {
  experiment_settings e;
  e.set(*find_section(experiment_sections(), "long_time"), long_time_settings{}, experiment_sections());
  const double base = estimate_cost(e).units;
  e.find<long_time_settings>()->steps_double = 1'000'000'000;
  EXPECT_GT(estimate_cost(e).units, default_cost_budget);
  EXPECT_LT(base, default_cost_budget);
  EXPECT_LT(estimate_cost(load_scene("paper", paper_book()).experiments).units, default_cost_budget);
  EXPECT_LT(estimate_cost(load_scene("beyond", paper_book()).experiments).units, default_cost_budget);
  // The numeric rechecks count too: 16 claims x 10000 samples in mpfr:100000 is far over the budget,
  // the paper scene's 16 samples across its ladder far under it.
  const recheck_load huge{16, 10000, {precision::mpfr_digits(100000)}};
  EXPECT_GT(estimate_cost(experiment_settings{}, huge).units, default_cost_budget);
  const scene paper = load_scene("paper", paper_book());
  const recheck_load usual{16, paper.samples, paper.precisions};
  EXPECT_LT(estimate_cost(experiment_settings{}, usual).units, default_cost_budget / 100);
}

TEST(PublishedFacts, ThePendulumsOrderIsUndecidedWhereItsEnclosuresDecideNothing) {
  // At 60 digits the order is proved (the beyond scene's nonlinear-order-4); at 6 the enclosures
  // are too wide to prove q_m unique or a ratio within 1/2 of 4, and the fact says so by throwing,
  // never by failing with a note.
  EXPECT_THROW(pendulum_order_fact(6), enclosure_undecided);
}

}  // namespace
}  // namespace simpson::verify

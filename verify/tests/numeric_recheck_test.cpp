#include <simpson/verify/numeric_recheck.hpp>

#include <gtest/gtest.h>

namespace simpson::verify {
namespace {

TEST(SampleGenerator, IsReproducibleAndSeparatesStreams) {
  sample_generator a(42, "phi3-det"), b(42, "phi3-det"), c(42, "hd-invariance"), d(43, "phi3-det");
  for (int k = 0; k < 5; ++k) {
    const std::uint64_t x = a.next();
    EXPECT_EQ(x, b.next());
    EXPECT_NE(x, c.next());
    EXPECT_NE(x, d.next());
  }
  sample_generator g(1, "range");
  for (int k = 0; k < 1000; ++k) {
    const sample s = draw_sample(g);
    EXPECT_GT(s.m, 0);
    EXPECT_LT(s.omega * s.h, 2.7 * (1 + 1e-12));
    EXPECT_LE(std::abs(s.q), 1);
  }
}

const run_context ladder{{precision::parse("double"), precision::parse("float128"), precision::parse("mpfr:60")}, 5, 6};

TEST(NumericRecheck, PassesARoundOffResidualThatFallsWithPrecision) {
  bool within = false;
  const json e = numeric_recheck(ladder, "test", [](auto tag, const sample& s) {
    using Real = typename decltype(tag)::type;
    const Real x(s.q);
    const Real third = x / 3;
    return residual_and_bound<Real>{Real(third * 3 - x), Real(4 * eps<Real>() * abs(x))};
  }, within);
  EXPECT_TRUE(within) << e.dump(2);
  EXPECT_TRUE(e["residuals_fall_with_precision"].get<bool>());
}

TEST(NumericRecheck, AnEnclosureDecidesAnIdentityAtFortyDigits) {
  bool within = false;
  const json e = numeric_recheck(ladder, "test", [](auto tag, const sample& s) {
    using Real = typename decltype(tag)::type;
    const Real x(s.q);
    return residual_and_bound<Real>{Real(x / 3 * 3 - x), Real(4 * eps<Real>() * abs(x))};
  }, within);
  EXPECT_TRUE(within) << e.dump(2);
  EXPECT_EQ(e["enclosure"]["decision"], "holds");
  EXPECT_EQ(e["enclosure"]["decided_at_digits"], 40);
}

TEST(NumericRecheck, AnEnclosureRefutesAnErrorFarBelowDoubleRoundOff) {
  // A relative error of 1e-35: invisible to double, float128 and the ladder's bounds; the 40-digit
  // enclosure excludes 0.
  bool within = true;
  const json e = numeric_recheck(ladder, "test", [](auto tag, const sample& s) {
    using Real = typename decltype(tag)::type;
    const Real x(s.q);
    const Real wrong = x * (1 + Real(1) / Real(boost::multiprecision::cpp_int("100000000000000000000000000000000000")));
    return residual_and_bound<Real>{Real(wrong - x), Real(4 * eps<Real>() * abs(x))};
  }, within);
  EXPECT_FALSE(within) << e.dump(2);
  EXPECT_EQ(e["enclosure"]["decision"], "fails");
  EXPECT_TRUE(e["enclosure"].contains("refuted"));
  EXPECT_TRUE(e["ladder"][0]["within_bound"].get<bool>()) << "double cannot see it: the ladder alone would pass it";
}

TEST(NumericRecheck, AnUndecidedEnclosureDoublesItsDigitsAndStopsAtTheBudget) {
  // |x/3| ≤ |x|/3 + 1e-60 |x|: the two ends overlap below 60 digits; 80 digits decide.
  const auto check = [](auto tag, const sample& s) {
    using Real = typename decltype(tag)::type;
    const Real x(s.q);
    const Real margin = abs(x) / Real(boost::multiprecision::cpp_int("1000000000000000000000000000000000000000000000000000000000000"));
    const Real round_off = is_interval_v<Real> ? Real(0) : Real(8 * eps<Real>() * abs(x));  // an interval's is inside it
    return residual_and_bound<Real>{Real(x / 3), Real(abs(x) / 3 + margin + round_off), false};
  };
  run_context wide = ladder;
  wide.precisions = {precision::parse("mpfr:100")};  // (its own round-off term keeps the ladder consistent)
  bool within = false;
  const json e = numeric_recheck(wide, "test", check, within);
  EXPECT_TRUE(within) << e.dump(2);
  EXPECT_EQ(e["enclosure"]["decided_at_digits"], 80);
  wide.enclosure_budget_digits = 60;  // 40 is undecided and 80 is over the budget
  EXPECT_THROW(numeric_recheck(wide, "test", check, within), enclosure_undecided);
}

TEST(NumericRecheck, FlagsADoubleLeakedIntoGenericCode) {
  // The residual is computed through a double: in mpfr:60 it is stuck near 1e-17, far above the bound.
  bool within = true;
  const json e = numeric_recheck(ladder, "test", [](auto tag, const sample& s) {
    using Real = typename decltype(tag)::type;
    const Real x(s.q);
    const Real third(static_cast<double>(x) / 3);  // the leak
    return residual_and_bound<Real>{Real(third * 3 - x), Real(4 * eps<Real>() * abs(x))};
  }, within);
  EXPECT_FALSE(within);
  EXPECT_EQ(e["enclosure"]["decision"], "fails") << "the enclosure sees the leak too";
  ASSERT_TRUE(e.contains("diagnosis")) << e.dump(2);
  EXPECT_NE(e["diagnosis"].get<std::string>().find("leaked"), std::string::npos);
}

}  // namespace
}  // namespace simpson::verify

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
  ASSERT_TRUE(e.contains("diagnosis")) << e.dump(2);
  EXPECT_NE(e["diagnosis"].get<std::string>().find("leaked"), std::string::npos);
}

}  // namespace
}  // namespace simpson::verify

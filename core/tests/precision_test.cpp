#include <simpson/precision.hpp>

#include "test_support.hpp"

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <gtest/gtest.h>

#include <string>

namespace simpson {
namespace {

/// log10 of a precision's epsilon as a double (mpfr:1000's epsilon underflows every fixed type).
double log10_epsilon(const precision& p) {
  return p.visit([](auto tag) {
    using Real = typename decltype(tag)::type;
    if constexpr (is_exact_v<Real>) {
      return -std::numeric_limits<double>::infinity();
    } else {
      using std::log10;
      return static_cast<double>(boost::multiprecision::cpp_bin_float_50(log10(Real(eps<Real>()))));
    }
  });
}

TEST(Precision, EveryDefaultNameParsesBackToItself) {
  for (const precision& p : default_precisions()) {
    EXPECT_EQ(precision::parse(p.name()), p) << p.name();
  }
}

TEST(Precision, DefaultLadderHasEveryKindAndFallingEpsilon) {
  // The ladder must carry every kind of the list, each step no coarser than the one before.
  const std::vector<precision> ladder = default_precisions();
  std::vector<bool> seen(7, false);
  double previous_log10 = 1;
  for (const precision& p : ladder) {
    seen[static_cast<std::size_t>(p.kind())] = true;
    if (p.exact()) {
      EXPECT_EQ(p.epsilon(), "0");
      continue;
    }
    const double log10_eps = log10_epsilon(p);
    EXPECT_LE(log10_eps, previous_log10) << p.name();
    previous_log10 = log10_eps;
  }
  for (std::size_t k = 0; k < seen.size(); ++k) EXPECT_TRUE(seen[k]) << "kind " << k << " missing";
}

TEST(Precision, MpfrDigitsAreSetDuringVisitAndRestoredAfter) {
  const unsigned before = mpfr::default_precision();
  const precision p = precision::parse("mpfr:300");
  const double log10_eps = log10_epsilon(p);
  // 300 decimal digits carry about 997 bits: epsilon = 2^(1-997) ~ 1e-300.
  EXPECT_NEAR(log10_eps, -300, 2);
  EXPECT_EQ(mpfr::default_precision(), before);
  EXPECT_EQ(p.digits10(), 300u);
}

TEST(Precision, LongDoubleAcceptsHyphenatedAlias) {
  EXPECT_EQ(precision::parse("long-double").name(), "long double");
}

TEST(Precision, RejectsUnknownNamesAndMpfrDigitsOutOfRange) {
  for (const char* bad : {"float", "", "mpfr", "mpfr:", "mpfr:29", "mpfr:100001", "mpfr:-40", "mpfr:40x", "Double"}) {
    try {
      precision::parse(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("'") + bad + "'"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(precision::parse("mpfr:30"));
  EXPECT_NO_THROW(precision::parse("mpfr:100000"));
}

TEST(Precision, ToStringIsExactForRationals) {
  EXPECT_EQ(to_string(rational(22, 7)), "22/7");
  EXPECT_EQ(to_string(0.5, 3), "5.00e-01");
}

}  // namespace
}  // namespace simpson

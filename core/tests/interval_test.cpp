// The core's formulas in interval arithmetic: an enclosure contains the exact value, shrinks as the
// precision grows, and excludes a value a wrong formula claims.

#include <simpson/interval.hpp>

#include <simpson/energy.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/three_term_scheme.hpp>

#include <boost/math/constants/constants.hpp>

#include <gtest/gtest.h>

namespace simpson {
namespace {

oscillator_parameters<interval> paper_parameters(const interval& omega_h) {
  const interval omega = 2 * boost::math::constants::pi<interval>();
  return {interval(1), omega, interval(omega_h / omega)};
}

TEST(Interval, DeterminantMinusOneEnclosesZeroAndShrinksWithThePrecision) {
  boost::multiprecision::mpfr_float narrow_width, wide_width;  // widths are numbers, not intervals
  {
    const scoped_interval_digits digits(30);
    const interval d = determinant(simpson_map(paper_parameters(interval(1) / 3))) - 1;
    EXPECT_EQ(certain_sign(d), 0);
    wide_width = width(d);
  }
  {
    const scoped_interval_digits digits(100);
    const interval d = determinant(simpson_map(paper_parameters(interval(1) / 3))) - 1;
    EXPECT_EQ(certain_sign(d), 0);
    narrow_width = width(d);
  }
  EXPECT_GT(wide_width, 0);
  EXPECT_LT(narrow_width, wide_width * 1e-60) << "the width follows the precision";
}

TEST(Interval, AWrongFormulaIsExcludedNotToleranced) {
  const scoped_interval_digits digits(60);
  one_step_matrix<interval> phi = simpson_map(paper_parameters(interval(1)));
  EXPECT_EQ(certain_sign(interval(determinant(phi) - 1)), 0);
  phi.alpha *= 1 + interval(1) / interval("1e40");  // a relative change of 1e-40, far below double's eps
  EXPECT_EQ(certain_sign(interval(determinant(phi) - 1)), 1) << enclosure_text(determinant(phi) - 1);
}

TEST(Interval, TheDiscriminantIsProvedNegativeInBothStableBands) {
  const scoped_interval_digits digits(40);
  for (const char* x : {"1e-6", "1", "7.999", "12.001", "16", "23.999"}) {
    EXPECT_EQ(certain_sign(discriminant(interval(x))), -1) << x;
  }
  for (const char* x : {"8.001", "11.999", "24.001"}) EXPECT_EQ(certain_sign(discriminant(interval(x))), 1) << x;
}

TEST(Interval, DiscreteEnergyIsConservedWithinItsEnclosure) {
  const scoped_interval_digits digits(50);
  const auto par = paper_parameters(interval(1) / 7);
  const phase_point<interval> y{interval(3) / 5, interval(-2)};
  const interval change = discrete_energy(par, simpson_map(par) * y) - discrete_energy(par, y);
  EXPECT_EQ(certain_sign(change), 0);
  EXPECT_LT(width(change), 1e-45);
}

TEST(Interval, EnclosureTextShowsOnlyGuaranteedDigits) {
  const scoped_interval_digits digits(30);
  const interval x(interval("1.44269504088896340735992468100189") * interval("1e-14"));
  using real = boost::multiprecision::mpfr_float;
  const interval blurred = x + interval(real("-3e-31"), real("3e-31"));
  const std::string text = enclosure_text(blurred);
  EXPECT_EQ(text.substr(0, 9), "1.4426950") << text;
  // The text is an enclosure: midpoint ± radius contains the interval.
  const std::size_t pm = text.find(" ± ");
  ASSERT_NE(pm, std::string::npos);
  const real printed_mid(text.substr(0, pm)), printed_radius(text.substr(pm + std::string(" ± ").size()));
  EXPECT_LE(printed_mid - printed_radius, lower(blurred)) << text;
  EXPECT_GE(printed_mid + printed_radius, upper(blurred)) << text;
  EXPECT_LT(printed_radius, real("1e-30")) << text;
  EXPECT_EQ(enclosure_text(interval(real("-2e-50"), real("1e-50"))).rfind("0 ± 2e-50", 0), 0u) << enclosure_text(interval(real("-2e-50"), real("1e-50")));
  // An unbounded enclosure (a ratio over an error that may be 0) says that nothing is known.
  EXPECT_EQ(enclosure_text(entire_line()), "0 ± inf");
  EXPECT_EQ(enclosure_text(interval(interval(1) / interval(real(0), real(1)))), "0 ± inf");
}

TEST(Interval, EnclosureTextKeepsTheDigitsOfAPrecisionAboveTheDefault) {
  // mpfr_float's default is 20 digits here: a midpoint computed there would swamp a 60-digit radius.
  using real = boost::multiprecision::mpfr_float;
  const unsigned saved = real::default_precision();
  real::default_precision(20);
  {
    const scoped_interval_digits digits(60);
    const std::string text = enclosure_text(interval(1) / 3);
    const std::size_t pm = text.find(" ± ");
    ASSERT_NE(pm, std::string::npos);
    EXPECT_LT(real(text.substr(pm + std::string(" ± ").size())), real("1e-58")) << text;
    EXPECT_EQ(text.rfind("3.333333333333333333333333333333333333333333333333333333333", 0), 0u) << text;
  }
  real::default_precision(saved);
}

TEST(Interval, SquareEnclosedIsNeverNegativeWhereAProductOfTwoCopiesIs) {
  const scoped_interval_digits digits(30);
  const interval x = hull(interval(-1), interval(2)), copy = x;
  const interval product = x * copy, square = square_enclosed(x);
  EXPECT_EQ(lower(product), -2);  // two equal factors, taken as independent
  EXPECT_EQ(lower(square), 0);
  EXPECT_EQ(upper(square), 4);
  const interval third = square_enclosed(interval(interval(-1) / 3));
  EXPECT_TRUE(zero_in(interval(third - interval(1) / 9))) << enclosure_text(third);
  EXPECT_LT(width(third), 1e-29);
}

}  // namespace
}  // namespace simpson

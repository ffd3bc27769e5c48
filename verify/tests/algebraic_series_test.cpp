// The exact arithmetic of the peer comparison: Q(r) with r^n = d, and truncated power series.

#include <simpson/verify/algebraic_series.hpp>

#include <gtest/gtest.h>

namespace simpson::verify {
namespace {

using sqrt3 = number_field_element<2, 3>;
using cbrt2 = number_field_element<3, 2>;

TEST(AlgebraicSeries, TheRootSatisfiesItsEquationAndInversesAreExact) {
  const sqrt3 s = sqrt3::root();
  EXPECT_TRUE(s * s == sqrt3(3));
  const cbrt2 c = cbrt2::root();
  EXPECT_TRUE(c * c * c == cbrt2(2));
  const cbrt2 x = cbrt2(2) - c;  // 1/(2 − ∛2) = (4 + 2∛2 + ∛4)/6
  const cbrt2 inverse = x.inverse();
  EXPECT_TRUE(x * inverse == cbrt2(1));
  EXPECT_EQ(inverse[0], rational(2, 3));
  EXPECT_EQ(inverse[1], rational(1, 3));
  EXPECT_EQ(inverse[2], rational(1, 6));
  EXPECT_THROW(cbrt2(0).inverse(), std::domain_error);
}

TEST(AlgebraicSeries, SeriesDivisionInvertsMultiplication) {
  using series = truncated_series<number_field_element<1, 1>, 8>;
  const series t = series::variable();
  const series one_minus_t = series(1) - t;
  const series geometric = series(1) / one_minus_t;  // 1 + t + t² + ... + t⁸
  for (int k = 0; k <= 8; ++k) EXPECT_EQ(geometric[k][0], rational(1)) << k;
  EXPECT_TRUE(geometric * one_minus_t == series(1));
  EXPECT_THROW(series(1) / t, std::domain_error);
  EXPECT_EQ(simpson::to_string(series(rational(1, 3))[0][0]), "1/3");
}

}  // namespace
}  // namespace simpson::verify

#include <simpson/verify/exact_proof.hpp>

#include <gtest/gtest.h>

namespace simpson::verify {
namespace {

TEST(RationalFunction, ArithmeticAndZeroTest) {
  const symbolic t = symbolic::variable();
  const symbolic f = (1 + t / 24) / (1 - t * t / 8);
  EXPECT_EQ(f(rational(2)), (1 + rational(2, 24)) / (1 - rational(4, 8)));
  EXPECT_TRUE((f * (1 - t * t / 8) - (1 + t / 24)).is_zero());
  EXPECT_FALSE((f - 1).is_zero());
  EXPECT_THROW(t / symbolic(0), std::domain_error);
  EXPECT_THROW(f(rational(0)) + (1 / (t - 2))(rational(2)), std::domain_error);
}

TEST(RationalFunction, LaurentCoefficientsOfAMonomialDenominator) {
  const symbolic t = symbolic::variable();
  const auto c = laurent_coefficients((t * t * t + 2) / (3 * t * t), 3);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].first, -2);
  EXPECT_EQ(c[0].second, rational(2, 3));
  EXPECT_EQ(c[1].first, 1);
  EXPECT_EQ(c[1].second, rational(1, 3));
  EXPECT_THROW(laurent_coefficients(1 / (1 + t), 3), std::invalid_argument);
}

TEST(TaylorPolynomials, CoefficientsAreExact) {
  const polynomial c = cos_taylor(6), s = sin_taylor(5);
  EXPECT_EQ(c[0], rational(1));
  EXPECT_EQ(c[2], rational(-1, 2));
  EXPECT_EQ(c[4], rational(1, 24));
  EXPECT_EQ(c[6], rational(-1, 720));
  EXPECT_EQ(s[1], rational(1));
  EXPECT_EQ(s[3], rational(-1, 6));
  EXPECT_EQ(s[5], rational(1, 120));
}

TEST(Sturm, CountsDistinctRealRootsInAnInterval) {
  // (x − 1)(x − 2)(x − 3)² : roots 1, 2, 3.
  const polynomial p = make_polynomial({rational(-1), rational(1)}) * make_polynomial({rational(-2), rational(1)}) *
                       make_polynomial({rational(-3), rational(1)}) * make_polynomial({rational(-3), rational(1)});
  EXPECT_EQ(count_real_roots(p, rational(0), rational(5, 2)), 2u);
  EXPECT_EQ(count_real_roots(p, rational(0), rational(10)), 3u);
  EXPECT_EQ(count_real_roots(p, rational(3, 2), rational(7, 4)), 0u);
  EXPECT_GE(cauchy_root_bound(p), rational(3));
}

TEST(GridLemma, FindsANonzeroPointAndAcceptsZero) {
  const auto zero = first_nonzero_on_grid(std::vector<int>{2, 2}, [](const std::vector<int>& v) {
    const rational x(v[0]), y(v[1]);
    return rational((x + y) * (x + y) - x * x - 2 * x * y - y * y);
  });
  EXPECT_FALSE(zero.has_value());
  // x y (x − 1) vanishes on {0, 1} × {0, 1} but not on the 3 × 3 grid its degree requires.
  const auto f = [](const std::vector<int>& v) { return rational(rational(v[0]) * v[1] * (v[0] - 1)); };
  EXPECT_FALSE(first_nonzero_on_grid(std::vector<int>{1, 1}, f).has_value());
  EXPECT_TRUE(first_nonzero_on_grid(std::vector<int>{2, 1}, f).has_value());
}

}  // namespace
}  // namespace simpson::verify

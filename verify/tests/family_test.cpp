// The scheme's family (verify/family): quadrature moments exact, and the members the paper and
// the theory name derived and identified: Φ₃ (s = 2, Simpson), Newmark (s = 1, midpoint),
// Störmer–Verlet (s = 1, trapezoid), Lobatto with s + 1 points of order 2s, and a member that
// loses order.

#include <simpson/verify/galerkin_member.hpp>

#include <gtest/gtest.h>

#include <algorithm>

namespace simpson::verify {
namespace {

bool equals(const member_analysis& a, const std::string& prefix) {
  return std::any_of(a.equals.begin(), a.equals.end(), [&](const std::string& e) { return e.rfind(prefix, 0) == 0; });
}

TEST(Family, QuadratureMomentsAreExact) {
  const std::vector<rational> simpson = quadrature_moments({quadrature_family::newton_cotes, 3}, 4);
  EXPECT_EQ(simpson[3], rational(1, 4));
  EXPECT_EQ(simpson[4], rational(5, 24));  // (4 (1/2)^4 + 1)/6
  EXPECT_EQ(quadrature_moments({quadrature_family::gauss, 2}, 4)[4], rational(7, 36));  // nodes 1/2 ± √3/6
  EXPECT_EQ(quadrature_moments({quadrature_family::lobatto, 3}, 4), simpson);         // Lobatto 3 is Simpson
  EXPECT_EQ(quadrature_moments({quadrature_family::newton_cotes, 4}, 4)[4], rational(11, 54));  // 3/8: (1 + 3(1/81 + 16/81) + 1)/8
}

TEST(Family, ThePapersSchemeAndNewmarkComeOutIdentical) {
  const member_analysis phi3 = analyse_member({2, {quadrature_family::newton_cotes, 3}});
  ASSERT_TRUE(phi3.derived) << phi3.failure;
  EXPECT_TRUE(phi3.det_one);
  EXPECT_TRUE(phi3.form_conserved);
  EXPECT_TRUE(equals(phi3, "Φ₃"));
  EXPECT_TRUE(equals(phi3, "Lobatto IIIA–IIIB, 3"));
  EXPECT_EQ(phi3.order, 4);
  EXPECT_EQ(phi3.error_constant, "1/1440");  // the paper's ω⁶h⁴/1440
  ASSERT_EQ(phi3.stable_set.size(), 2u);  // (0, 2√2), and a second band the paper does not state
  EXPECT_EQ(piece_text(phi3.stable_set[0]), "(0, 2 sqrt(2))");
  EXPECT_EQ(piece_text(phi3.stable_set[1]), "(2 sqrt(3), 2 sqrt(6))");

  const member_analysis newmark = analyse_member({1, {quadrature_family::gauss, 1}});
  EXPECT_TRUE(equals(newmark, "Newmark"));
  EXPECT_EQ(newmark.order, 2);
  const member_analysis verlet = analyse_member({1, {quadrature_family::newton_cotes, 2}});
  EXPECT_TRUE(equals(verlet, "Störmer–Verlet"));
  EXPECT_FALSE(equals(verlet, "Newmark"));
}

TEST(Family, LobattoWithSPlusOnePointsReachesOrder2s) {
  for (int s = 1; s <= 2; ++s) {
    const member_analysis a = analyse_member({s, {quadrature_family::lobatto, s + 1}});
    ASSERT_TRUE(a.derived) << a.failure;
    EXPECT_EQ(a.order, 2 * s) << member_name(a.member);
  }
  // Gauss with s points: Gauss–Legendre's diagonal Padé, also order 2s.
  const member_analysis gauss = analyse_member({2, {quadrature_family::gauss, 2}});
  EXPECT_TRUE(equals(gauss, "Gauss–Legendre, 2"));
  EXPECT_EQ(gauss.order, 4);
}

TEST(Family, TooFewPointsLoseOrderOrTheMap) {
  const member_analysis midpoint = analyse_member({2, {quadrature_family::gauss, 1}});
  ASSERT_TRUE(midpoint.derived);
  EXPECT_EQ(midpoint.order, 0);  // inconsistent
  EXPECT_FALSE(analyse_member({3, {quadrature_family::newton_cotes, 2}}).derived);
  // A derivation past the budget stops with the degree reached.
  const member_analysis stopped = analyse_member({2, {quadrature_family::newton_cotes, 3}}, 1);
  EXPECT_FALSE(stopped.derived);
  EXPECT_NE(stopped.failure.find("budget"), std::string::npos) << stopped.failure;
}

}  // namespace
}  // namespace simpson::verify

// Jacobi's functions and Legendre's integrals enclosed (elliptic_enclosed.hpp): each contains
// Boost.Math's value computed in 90 digits (an independent implementation: Carlson's series for
// R_F and R_J, the descending Landen transformation for sn, cn, dn), is narrow, keeps its identities
// (sn² + cn² = 1, dn² + m sn² = 1, F inverting sn), reduces arguments beyond a half period by the
// complete integral, and refuses a parameter or characteristic out of range.

#include <simpson/elliptic_enclosed.hpp>

#include <simpson/precision.hpp>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>

#include <gtest/gtest.h>

#include <string>

namespace simpson {
namespace {

using elliptic_real = boost::multiprecision::mpfr_float;

constexpr unsigned reference_digits = 90;

/// Whether the interval x holds the point v (compared exactly, in v's own digits: made an interval
/// of x's digits, v would be an interval of a few ulps, possibly wider than x).
bool holds(const interval& x, const elliptic_real& v) { return lower(x) <= v && v <= upper(x); }

// Each test sets MPFR's digits for its Boost.Math references once (an MPFR number keeps the digits
// it was made with), and the intervals' digits apart.

TEST(EllipticEnclosed, CarlsonIntegralsContainBoostMathsValues) {
  const scoped_mpfr_digits reference(reference_digits);
  struct rf_case { const char *x, *y, *z; };
  for (const rf_case c : {rf_case{"0.3", "1.7", "1"}, {"0", "0.25", "1"}, {"1e-12", "3", "1"}, {"2.5", "2.5", "2.5"}}) {
    const elliptic_real expected = boost::math::ellint_rf(elliptic_real(c.x), elliptic_real(c.y), elliptic_real(c.z));
    const scoped_interval_digits digits(50);
    const interval rf = carlson_rf_enclosed(interval(c.x), interval(c.y), interval(c.z));
    EXPECT_TRUE(holds(rf, expected)) << c.x << ", " << c.y << ": " << enclosure_text(rf);
    EXPECT_LT(width(rf), 1e-45) << enclosure_text(rf);
  }
  struct rj_case { const char *x, *y, *z, *p; };
  for (const rj_case c : {rj_case{"0.3", "1.7", "1", "0.45"}, {"0", "0.6", "1", "1.4"}, {"0.04", "0.9", "1", "0.001"}}) {
    const elliptic_real expected = boost::math::ellint_rj(elliptic_real(c.x), elliptic_real(c.y), elliptic_real(c.z), elliptic_real(c.p));
    const scoped_interval_digits digits(50);
    const interval rj = carlson_rj_enclosed(interval(c.x), interval(c.y), interval(c.z), interval(c.p));
    EXPECT_TRUE(holds(rj, expected)) << c.x << ", " << c.p << ": " << enclosure_text(rj);
    EXPECT_LT(width(rj), 1e-42) << enclosure_text(rj);
  }
}

TEST(EllipticEnclosed, JacobiFunctionsContainBoostMathsValuesAndKeepTheirIdentities) {
  const scoped_mpfr_digits reference(reference_digits);
  for (const char* m_text : {"1e-6", "0.3", "0.95"}) {
    for (const char* u_text : {"-7.3", "0", "0.4", "1.9", "5.1", "40"}) {
      elliptic_real cn, dn;
      const elliptic_real k = sqrt(elliptic_real(m_text));
      const elliptic_real sn = boost::math::jacobi_elliptic(k, elliptic_real(u_text), &cn, &dn), K = boost::math::ellint_1(k);
      const scoped_interval_digits digits(50);
      const interval m(m_text);
      const elliptic_parameter_enclosed e(m, interval(1 - m));
      const jacobi_values J = e.jacobi(interval(u_text));
      const std::string where = std::string("m = ") + m_text + ", u = " + u_text;
      EXPECT_TRUE(holds(e.K(), K)) << where << ": " << enclosure_text(e.K());
      EXPECT_TRUE(holds(complete_first_kind(m), K)) << where;
      EXPECT_TRUE(holds(J.sn, sn)) << where << ": " << enclosure_text(J.sn);
      EXPECT_TRUE(holds(J.cn, cn)) << where << ": " << enclosure_text(J.cn);
      EXPECT_TRUE(holds(J.dn, dn)) << where << ": " << enclosure_text(J.dn);
      for (const interval& x : {J.sn, J.cn, J.dn}) EXPECT_LT(width(x), 1e-44) << where << ": " << enclosure_text(x);
      EXPECT_TRUE(zero_in(interval(square_enclosed(J.sn) + square_enclosed(J.cn) - 1))) << where;
      EXPECT_TRUE(zero_in(interval(square_enclosed(J.dn) + m * square_enclosed(J.sn) - 1))) << where;
    }
  }
}

TEST(EllipticEnclosed, FirstKindInvertsSnWithinAQuarterPeriod) {
  const scoped_interval_digits digits(50);
  const interval m("0.7");
  const elliptic_parameter_enclosed e(m, interval(1 - m));
  for (const char* u_text : {"-1.9", "-0.3", "0.001", "1.2", "2.05"}) {  // K(0.7) = 2.0753...
    const interval u(u_text);
    const jacobi_values J = e.jacobi(u);
    const interval back = e.first_kind(J.sn, square_enclosed(J.cn), square_enclosed(J.dn));
    EXPECT_TRUE(zero_in(interval(back - u))) << u_text << ": " << enclosure_text(back);
    EXPECT_LT(width(back), 1e-44) << enclosure_text(back);
  }
}

TEST(EllipticEnclosed, ThirdKindExcessContainsBoostMathsValueOnEveryHalfPeriod) {
  const scoped_mpfr_digits reference(reference_digits);
  const char* m_text = "0.4";
  for (const char* n_text : {"0.6", "-0.35", "0.999"}) {
    for (const char* u_text : {"0.3", "-1.1", "1.7", "4.9", "-12.25", "30"}) {
      const elliptic_real k = sqrt(elliptic_real(m_text)), u(u_text), n(n_text);
      const elliptic_real K = boost::math::ellint_1(k);
      // am(u) = jπ + am(r), u = 2jK + r, |r| ≤ K, am(r) = atan2(sn r, cn r) (cn r ≥ 0 there).
      const elliptic_real j = round(u / (2 * K)), rest = u - 2 * j * K;
      elliptic_real cn, dn;
      const elliptic_real sn = boost::math::jacobi_elliptic(k, rest, &cn, &dn);
      const elliptic_real amplitude = j * boost::math::constants::pi<elliptic_real>() + atan2(sn, cn);
      const elliptic_real expected = boost::math::ellint_3(k, n, amplitude) - u;
      const scoped_interval_digits digits(50);
      const interval m(m_text);
      const elliptic_parameter_enclosed e(m, interval(1 - m));
      const reduced_argument r = e.reduce(interval(u_text));
      EXPECT_TRUE(r.inside) << u_text;
      const interval excess = e.third_kind_excess(e.characteristic(interval(n_text)), r, e.jacobi(r.r));
      EXPECT_TRUE(holds(excess, expected)) << "n = " << n_text << ", u = " << u_text << ": " << enclosure_text(excess);
      EXPECT_LT(width(excess), 1e-40) << enclosure_text(excess);
    }
  }
}

TEST(EllipticEnclosed, AnArgumentStraddlingAQuarterPeriodIsBoundedByTheMeanValue) {
  const scoped_interval_digits digits(50);
  const interval m("0.4");
  const elliptic_parameter_enclosed e(m, interval(1 - m));
  // u = 3K holds K's own width: r = −K within it, the reduction cannot place it inside [−K, K].
  const interval u = 3 * e.K();
  const reduced_argument r = e.reduce(u);
  EXPECT_FALSE(r.inside);
  EXPECT_EQ(r.j, 2);
  EXPECT_EQ(r.end, -1);
  const third_kind_characteristic c = e.characteristic(interval("0.6"));
  const interval excess = e.third_kind_excess(c, r, e.jacobi(r.r));
  EXPECT_TRUE(zero_in(interval(excess - 3 * c.complete_excess))) << enclosure_text(excess);  // Π(n; 3π/2) − 3K
  EXPECT_LT(width(excess), 1e-44) << enclosure_text(excess);
}

TEST(EllipticEnclosed, RefusesAParameterOrCharacteristicOutOfRange) {
  const scoped_interval_digits digits(30);
  EXPECT_THROW(elliptic_parameter_enclosed(interval(0), interval(1)), std::domain_error);
  EXPECT_THROW(elliptic_parameter_enclosed(interval(1), interval(0)), std::domain_error);
  EXPECT_THROW(elliptic_parameter_enclosed(interval(-1, 1) / 2, interval(1, 3) / 2), std::domain_error);  // m may be 0
  const elliptic_parameter_enclosed e(interval("0.5"), interval("0.5"));
  EXPECT_THROW(e.characteristic(interval(1)), std::domain_error);
  EXPECT_THROW(carlson_rf_enclosed(interval(-1), interval(1), interval(1)), std::domain_error);
  EXPECT_THROW(carlson_rj_enclosed(interval(1), interval(1), interval(1), interval(0)), std::domain_error);
  EXPECT_THROW(complete_first_kind(interval(1)), std::domain_error);
}

}  // namespace
}  // namespace simpson

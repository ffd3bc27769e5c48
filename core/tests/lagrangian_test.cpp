// The AutoDiff derivatives of lagrangian.hpp, in double, long double, mpfr and intervals, against
// two independent routes: a quadratic Lagrangian whose derivatives are known in closed form, and
// central differences in mpfr at 60 digits on the double pendulum.

#include <simpson/double_pendulum.hpp>
#include <simpson/interval.hpp>
#include <simpson/lagrangian.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

namespace simpson::lagrangian_test {
namespace {

/// L = ½ vᵀ M v + vᵀ B q − ½ qᵀ K q: ∂L/∂q = Bᵀ v − K q, ∂L/∂v = M v + B q, L_qq = −K, L_qv = Bᵀ,
/// L_vv = M. Written with integer literals (x / 2), the case Eigen alone cannot convert for mpfr.
template <class Real>
struct quadratic_lagrangian {
  dense_matrix<Real> M, B, K;
  int dof() const { return static_cast<int>(M.rows()); }
  template <class T>
  T operator()(const Eigen::Matrix<T, Eigen::Dynamic, 1>& q, const Eigen::Matrix<T, Eigen::Dynamic, 1>& v) const {
    T out(Real(0));
    for (int i = 0; i < dof(); ++i) {
      for (int j = 0; j < dof(); ++j) out += v(i) * T(M(i, j)) * v(j) / 2 + v(i) * T(B(i, j)) * q(j) - q(i) * T(K(i, j)) * q(j) / 2;
    }
    return out;
  }
};

template <class Real>
quadratic_lagrangian<Real> example() {
  dense_matrix<Real> M(2, 2), B(2, 2), K(2, 2);
  M << Real(2), Real(1), Real(1), Real(3);
  B << Real(1) / 2, Real(-1), Real(1) / 3, Real(1) / 4;
  K << Real(5), Real(-1), Real(-1), Real(2);
  return {M, B, K};
}

template <class Real>
dense_vector<Real> vec2(const Real& a, const Real& b) {
  dense_vector<Real> out(2);
  out << a, b;
  return out;
}

template <class Real>
class Lagrangian : public test::precision_fixture<Real> {};
using lagrangian_scalars = ::testing::Types<double, long double, mpfr>;
TYPED_TEST_SUITE(Lagrangian, lagrangian_scalars, test::scalar_names);

TYPED_TEST(Lagrangian, AutoDiffGivesTheClosedFormDerivativesOfAQuadraticLagrangian) {
  using Real = TypeParam;
  const auto L = example<Real>();
  const dense_vector<Real> q = vec2(test::ratio<Real>(1, 3), test::ratio<Real>(-7, 5)), v = vec2(test::ratio<Real>(2, 3), Real(1));
  const lagrangian_hessian<Real> d = lagrangian_hessian_at(L, q, v);
  const lagrangian_gradient<Real> g = lagrangian_gradient_at(L, q, v);
  const dense_vector<Real> dq = L.B.transpose() * v - L.K * q, dv = L.M * v + L.B * q;
  // Entries of size ~ 10, each the sum of a few rounded products.
  const Real bound = 64 * eps<Real>();
  for (int i = 0; i < 2; ++i) {
    EXPECT_TRUE(test::within(d.dq(i), dq(i), bound));
    EXPECT_TRUE(test::within(d.dv(i), dv(i), bound));
    EXPECT_TRUE(test::within(g.dq(i), dq(i), bound));
    EXPECT_TRUE(test::within(g.dv(i), dv(i), bound));
    for (int j = 0; j < 2; ++j) {
      EXPECT_TRUE(test::within(d.qq(i, j), Real(-L.K(i, j)), bound));
      EXPECT_TRUE(test::within(d.qv(i, j), Real(L.B(j, i)), bound));  // ∂²/∂q_i∂v_j of vᵀ B q is B_ji
      EXPECT_TRUE(test::within(d.vv(i, j), L.M(i, j), bound));
    }
  }
  EXPECT_TRUE(test::within(d.value, lagrangian_value(L, q, v), bound));
}

TYPED_TEST(Lagrangian, ADegreeOfFreedomCountOutOfRangeOrAMismatchedVectorIsAnError) {
  using Real = TypeParam;
  quadratic_lagrangian<Real> big{dense_matrix<Real>::Identity(5, 5), dense_matrix<Real>::Zero(5, 5), dense_matrix<Real>::Zero(5, 5)};
  const dense_vector<Real> five = dense_vector<Real>::Zero(5), two = dense_vector<Real>::Zero(2);
  EXPECT_THROW(lagrangian_hessian_at(big, five, five), std::invalid_argument);
  EXPECT_THROW(lagrangian_gradient_at(example<Real>(), two, five), std::invalid_argument);
}

TEST(LagrangianAutoDiff, TheDoublePendulumsDerivativesAreCentralDifferencesAt60Digits) {
  const scoped_mpfr_digits digits(60);
  const double_pendulum<mpfr> L{mpfr(1), mpfr(2), mpfr(1), mpfr(3) / 2, mpfr(98) / 10};
  const dense_vector<mpfr> q = vec2(mpfr(1) / 2, mpfr(-1) / 3), v = vec2(mpfr(1) / 5, mpfr(7) / 10);
  const lagrangian_hessian<mpfr> d = lagrangian_hessian_at(L, q, v);
  // Central differences with step δ = 1e-20: truncation ~ δ² |L'''| ~ 1e-38, rounding ~ 1e-60 / δ.
  const mpfr delta("1e-20"), bound("1e-35");
  dense_vector<mpfr> x(4);
  x << q, v;
  const auto at = [&](const dense_vector<mpfr>& z) { return lagrangian_gradient_at(L, dense_vector<mpfr>(z.head(2)), dense_vector<mpfr>(z.tail(2))); };
  const auto value = [&](const dense_vector<mpfr>& z) { return lagrangian_value(L, dense_vector<mpfr>(z.head(2)), dense_vector<mpfr>(z.tail(2))); };
  for (int k = 0; k < 4; ++k) {
    dense_vector<mpfr> up = x, down = x;
    up(k) += delta;
    down(k) -= delta;
    const mpfr slope = (value(up) - value(down)) / (2 * delta);
    EXPECT_LT(abs(mpfr(slope - (k < 2 ? d.dq(k) : d.dv(k - 2)))), bound) << "gradient " << k;
    const lagrangian_gradient<mpfr> g_up = at(up), g_down = at(down);
    for (int i = 0; i < 4; ++i) {
      const mpfr fd = ((i < 2 ? g_up.dq(i) : g_up.dv(i - 2)) - (i < 2 ? g_down.dq(i) : g_down.dv(i - 2))) / (2 * delta);
      // Row i, column k of the Hessian in (q, v): qq, qv (q row, v column), qvᵀ, vv.
      const mpfr ad = i < 2 ? (k < 2 ? d.qq(i, k) : d.qv(i, k - 2)) : (k < 2 ? d.qv(k, i - 2) : d.vv(i - 2, k - 2));
      EXPECT_LT(abs(mpfr(fd - ad)), bound) << "Hessian " << i << ", " << k;
    }
  }
}

TEST(LagrangianAutoDiff, IntervalDerivativesEncloseTheMpfrDerivatives) {
  lagrangian_hessian<mpfr> reference;
  {
    const scoped_mpfr_digits digits(80);
    const double_pendulum<mpfr> L{mpfr(1), mpfr(2), mpfr(1), mpfr(3) / 2, mpfr(98) / 10};
    reference = lagrangian_hessian_at(L, vec2(mpfr(1) / 2, mpfr(-1) / 3), vec2(mpfr(1) / 5, mpfr(7) / 10));
  }
  const scoped_interval_digits digits(40);
  const double_pendulum<interval> L{interval(1), interval(2), interval(1), interval(3) / 2, interval(98) / 10};
  const lagrangian_hessian<interval> d =
      lagrangian_hessian_at(L, vec2(interval(interval(1) / 2), interval(interval(-1) / 3)), vec2(interval(interval(1) / 5), interval(interval(7) / 10)));
  EXPECT_TRUE(in(reference.value, d.value)) << enclosure_text(d.value);
  for (int i = 0; i < 2; ++i) {
    EXPECT_TRUE(in(reference.dq(i), d.dq(i)) && in(reference.dv(i), d.dv(i)));
    for (int j = 0; j < 2; ++j) {
      EXPECT_TRUE(in(reference.qq(i, j), d.qq(i, j)) && in(reference.qv(i, j), d.qv(i, j)) && in(reference.vv(i, j), d.vv(i, j)))
          << i << ", " << j << ": " << enclosure_text(d.qq(i, j));
      EXPECT_LT(width(d.qq(i, j)), 1e-35);
    }
  }
  // The closed form, with intervals and the integer literals of quadratic_lagrangian.
  const auto Q = example<interval>();
  const dense_vector<interval> q = vec2(interval(1), interval(-2)), v = vec2(interval(3), interval(1));
  const lagrangian_hessian<interval> e = lagrangian_hessian_at(Q, q, v);
  const dense_vector<interval> dv = Q.M * v + Q.B * q;
  EXPECT_TRUE(overlap(e.dv(0), dv(0)) && overlap(e.dv(1), dv(1)));
}

}  // namespace
}  // namespace simpson::lagrangian_test

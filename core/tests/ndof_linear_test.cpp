// Φ₃ for n degrees of freedom (ndof_linear.hpp): Φ₃ itself for n = 1, symplectic and conserving the
// block H_d to round-off for a linearized double pendulum and a 3-DOF chain. In double and mpfr:
// the exact proofs belong to GiNaC (Boost 1.74's cpp_rational does not compile inside Eigen 3.4's
// products: Eigen's scalar-product overload probes is_convertible<Matrix, number>, which is a hard
// error in cpp_int's byte-container constructor).

#include <simpson/ndof_linear.hpp>

#include <simpson/simpson_map.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

namespace simpson {
namespace {

template <class Real>
class NdofLinear : public test::precision_fixture<Real> {};
using ndof_scalars = ::testing::Types<double, mpfr>;
TYPED_TEST_SUITE(NdofLinear, ndof_scalars, test::scalar_names);

template <class Real>
dense_matrix<Real> square(std::initializer_list<std::initializer_list<Real>> rows) {
  dense_matrix<Real> out(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(rows.size()));
  Eigen::Index i = 0;
  for (const auto& row : rows) {
    Eigen::Index j = 0;
    for (const Real& v : row) out(i, j++) = v;
    ++i;
  }
  return out;
}

/// max |a_ij − b_ij| ≤ bound.
template <class Real>
::testing::AssertionResult close(const dense_matrix<Real>& a, const dense_matrix<Real>& b, const Real& bound) {
  const Real gap = dense_matrix<Real>(a - b).cwiseAbs().maxCoeff();
  if (gap <= bound) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "largest entry gap " << to_string(gap, 3) << ", bound " << to_string(bound, 3);
}

TYPED_TEST(NdofLinear, OneDegreeOfFreedomIsPhi3) {
  using Real = TypeParam;
  for (const auto& par : test::parameter_cases<Real>()) {
    if (par.omega2_h2() >= 8) continue;
    const one_step_matrix<Real> expected = simpson_map(par);
    const dense_matrix<Real> phi =
        ndof_simpson_map(square<Real>({{par.m()}}), square<Real>({{Real(par.m() * par.omega() * par.omega())}}), par.h());
    // Entries as (p, q), scaled by m ω where units differ; ~32 roundings each, sizes up to |Φ₃| ≤ 2.
    const dense_matrix<Real> scale = square<Real>({{Real(1), Real(par.m() * par.omega())}, {Real(1 / (par.m() * par.omega())), Real(1)}});
    const dense_matrix<Real> want = square<Real>({{expected.alpha, expected.beta}, {expected.gamma, expected.delta}});
    EXPECT_TRUE(close<Real>(dense_matrix<Real>(phi.cwiseQuotient(scale)), dense_matrix<Real>(want.cwiseQuotient(scale)),
                            Real(64 * eps<Real>())));
  }
}

TYPED_TEST(NdofLinear, SymplecticAndConservingTheBlockDiscreteEnergy) {
  using Real = TypeParam;
  // A linearized double pendulum (m1 = m2 = l1 = l2 = g = 1: M = [[2, 1], [1, 1]], K = diag(2, 1)) and
  // a 3-DOF chain with unequal masses.
  const std::vector<std::pair<dense_matrix<Real>, dense_matrix<Real>>> systems{
      {square<Real>({{Real(2), Real(1)}, {Real(1), Real(1)}}), square<Real>({{Real(2), Real(0)}, {Real(0), Real(1)}})},
      {square<Real>({{Real(3), Real(0), Real(0)}, {Real(0), Real(1) / 2, Real(0)}, {Real(0), Real(0), Real(2)}}),
       square<Real>({{Real(2), Real(-1), Real(0)}, {Real(-1), Real(2), Real(-1)}, {Real(0), Real(-1), Real(2)}})}};
  for (const auto& [M, K] : systems) {
    const Eigen::Index n = M.rows();
    for (const Real& h : {Real(1) / 10, Real(1) / 2, Real(7) / 5}) {
      const dense_matrix<Real> phi = ndof_simpson_map(M, K, h), phi_t = phi.transpose();
      const dense_matrix<Real> J = symplectic_form<Real>(n), Q = ndof_discrete_energy_form(M, K, h);
      // Each entry of Φ and Q carries ~16 n roundings of terms of their largest size; the products
      // sum 2n terms of size max|Φ|² max|Q|: 256 n eps max|Φ|² (max|Q| + 1).
      const Real size = phi.cwiseAbs().maxCoeff(), form_size = Q.cwiseAbs().maxCoeff();
      const Real bound = 256 * Real(n) * eps<Real>() * size * size * (form_size + 1);
      EXPECT_TRUE(close<Real>(dense_matrix<Real>(dense_matrix<Real>(phi_t * J) * phi), J, bound)) << "symplectic, h " << to_string(h, 3);
      EXPECT_TRUE(close<Real>(dense_matrix<Real>(Q.transpose()), Q, Real(64 * eps<Real>() * form_size)));
      EXPECT_TRUE(close<Real>(dense_matrix<Real>(dense_matrix<Real>(phi_t * Q) * phi), Q, bound)) << "H_d, h " << to_string(h, 3);
    }
  }
}

}  // namespace
}  // namespace simpson

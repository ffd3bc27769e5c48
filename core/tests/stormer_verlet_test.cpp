#include <simpson/stormer_verlet.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

namespace simpson {
namespace {

template <class Real>
class StormerVerlet : public test::precision_fixture<Real> {};
TYPED_TEST_SUITE(StormerVerlet, test::all_scalars, test::scalar_names);

TYPED_TEST(StormerVerlet, MatrixIsKickDriftKick) {
  // α = δ = 1 − x/2, β = −mω²h (1 − x/4), γ = h/m (x = ω²h²), derived by hand from the three half-steps.
  using Real = TypeParam;
  for (const auto& par : test::parameter_cases<Real>()) {
    const Real x = par.omega2_h2();
    const one_step_matrix<Real> phi = stormer_verlet_map(par);
    const Real k = Real(16 * eps<Real>());
    EXPECT_TRUE(test::within(phi.alpha, Real(1 - x / 2), Real(k * (1 + x))));
    EXPECT_TRUE(test::within(phi.delta, Real(1 - x / 2), Real(k * (1 + x))));
    EXPECT_TRUE(test::within(phi.gamma, Real(par.h() / par.m()), Real(k * par.h() / par.m())));
    const Real beta = -par.m() * par.omega() * par.omega() * par.h() * (1 - x / 4);
    EXPECT_TRUE(test::within(phi.beta, beta, Real(k * par.m() * par.omega() * par.omega() * par.h() * (1 + x))));
  }
}

TEST(StormerVerlet, YoshidaWeightsCancelTheThirdOrderError) {
  // 2 w1 + w0 = 1 and 2 w1³ + w0³ = 0, to round-off in each precision.
  const auto w = yoshida_weights<bin100>();
  const bin100 tolerance = 64 * eps<bin100>();
  EXPECT_LT(abs(bin100(w[0] + w[1] + w[2] - 1)), tolerance);
  EXPECT_LT(abs(bin100(w[0] * w[0] * w[0] + w[1] * w[1] * w[1] + w[2] * w[2] * w[2])), 16 * tolerance);
  const auto d = yoshida_weights<double>();
  EXPECT_NEAR(d[0], 1.3512071919596578, 4e-16);
  EXPECT_NEAR(d[1], -1.7024143839193153, 4e-16);
}

TEST(StormerVerlet, YoshidaIsSymplecticAndFourthOrder) {
  // det = 1, and the local error against the exact rotation falls by 2^5 when h halves.
  const oscillator_parameters<bin100> coarse{bin100(1), bin100(1), bin100(1) / 10}, fine{bin100(1), bin100(1), bin100(1) / 20};
  const auto w = yoshida_weights<bin100>();
  EXPECT_LT(abs(bin100(determinant(yoshida_map(coarse, w)) - 1)), 64 * eps<bin100>());
  const auto local_error = [&](const oscillator_parameters<bin100>& par) {
    return abs(bin100(yoshida_map(par, w).gamma - sin(par.h())));
  };
  const bin100 ratio = local_error(coarse) / local_error(fine);
  EXPECT_GT(ratio, 30);
  EXPECT_LT(ratio, 34);
}

}  // namespace
}  // namespace simpson

// Φ₃ in shear form (shear_form.hpp): the product L(c)U(b)L(c) is Φ₃ (exactly in rationals), a step
// in shear form is a step of Φ₃ to round-off, and over a long run in double the energy H_d does not
// drift as it does with the rounded matrix.

#include <simpson/shear_form.hpp>

#include <simpson/energy.hpp>
#include <simpson/simpson_map.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

namespace simpson {
namespace {

template <class Real>
class ShearForm : public test::precision_fixture<Real> {};
TYPED_TEST_SUITE(ShearForm, test::all_scalars, test::scalar_names);

TYPED_TEST(ShearForm, TheProductIsPhi3) {
  using Real = TypeParam;
  for (const auto& par : test::parameter_cases<Real>()) {
    const shear_coefficients<Real> s = simpson_shear_coefficients(par);
    const one_step_matrix<Real> product = shear_product(s), phi = simpson_map(par);
    // Each side is a handful of roundings of terms of size |b c| ≤ ~10 (relative), c (2 + |b c|) for γ.
    const Real bc = test::magnitude(Real(s.kick * s.drift));
    EXPECT_TRUE(test::within(product.alpha, phi.alpha, Real(64 * eps<Real>() * (1 + bc))));
    EXPECT_TRUE(test::within(product.delta, phi.delta, Real(64 * eps<Real>() * (1 + bc))));
    EXPECT_TRUE(test::within(product.beta, phi.beta, Real(8 * eps<Real>() * test::magnitude(phi.beta))));
    EXPECT_TRUE(test::within(product.gamma, phi.gamma, Real(64 * eps<Real>() * test::magnitude(s.drift) * (2 + bc))));
  }
}

TYPED_TEST(ShearForm, AStepInShearFormIsAStepOfPhi3) {
  using Real = TypeParam;
  for (const auto& par : test::parameter_cases<Real>()) {
    const shear_coefficients<Real> s = simpson_shear_coefficients(par);
    const phase_point<Real> y{test::ratio<Real>(2, 7), test::ratio<Real>(-5, 9)};
    const phase_point<Real> expected = simpson_map(par) * y;
    compensated_point<Real> z{y};
    shear_step_compensated(s, z);
    const phase_point<Real> plain = shear_step(s, y);
    // Scale: the state and its intermediate values in units of p (q times m ω), times (1 + |b c|)².
    const Real mw = par.m() * par.omega(), bc = test::magnitude(Real(s.kick * s.drift));
    const Real scale = (test::magnitude(y.p) + mw * test::magnitude(y.q)) * (1 + bc) * (1 + bc);
    for (const phase_point<Real>& got : {plain, z.y}) {
      EXPECT_TRUE(test::within(got.p, expected.p, Real(64 * eps<Real>() * scale)));
      EXPECT_TRUE(test::within(Real(mw * got.q), Real(mw * expected.q), Real(64 * eps<Real>() * scale)));
    }
  }
}

TEST(ShearFormSingularSet, UndefinedOnlyAtTheDriftsPole) {
  // ω²h² = 12 and 24 have no rational solution (12 and 24 are not squares). In double, ω = 3 with
  // the steps below gives ω²h² = 12 and 24 exactly. At 12 the drift c has its pole and Φ₃ = −I + γE₂₁
  // is no product L(c)U(b)L(c) (b = β = 0 makes its diagonal 1): refused; the next double step is not.
  const double h12 = 0x1.279a74590331cp+0, h24 = 0x1.a20bd700c2c3ep+0;
  const oscillator_parameters<double> at12{1, 3, h12}, at24{1, 3, h24};
  ASSERT_EQ(at12.omega2_h2(), 12.0);
  ASSERT_EQ(at24.omega2_h2(), 24.0);
  EXPECT_THROW(simpson_shear_coefficients(at12), std::domain_error);
  EXPECT_NO_THROW(simpson_shear_coefficients(oscillator_parameters<double>{1, 3, std::nextafter(h12, 10.0)}));
  // At 24, β = 0 as well, but c = −h/(2m) is finite and Φ₃ = L(2c) = ((1, 0), (−h/m, 1)): the product.
  const shear_coefficients<double> s = simpson_shear_coefficients(at24);
  EXPECT_EQ(s.kick, 0.0);
  EXPECT_NEAR(s.drift, -h24 / 2, 4 * eps<double>());
  const one_step_matrix<double> phi = simpson_map(at24), product = shear_product(s);
  for (const auto& [got, expected] : {std::pair{product.alpha, phi.alpha}, std::pair{product.beta, phi.beta},
                                      std::pair{product.gamma, phi.gamma}, std::pair{product.delta, phi.delta}}) {
    EXPECT_NEAR(got, expected, 64 * eps<double>());
  }
  EXPECT_NEAR(phi.gamma, -h24, 64 * eps<double>());
}

TEST(ShearFormLongRun, TheEnergyDoesNotDriftInDouble) {
  // m = ω = 1, h = 0.1, 1e6 steps from (1, 0). The rounded matrix has det Φ − 1 ≈ −2.2e-16, a drift
  // of about 2.2e-10 over 1e6 steps; in shear form each step's error is a rounding of either sign,
  // which adds up like a random walk: about √(1e6) eps ≈ 2e-13, far below.
  const oscillator_parameters<double> par{1, 1, 0.1};
  const one_step_matrix<double> phi = simpson_map(par);
  const shear_coefficients<double> s = simpson_shear_coefficients(par);
  phase_point<double> matrix{1, 0}, shear = matrix;
  compensated_point<double> compensated{matrix};
  const double H0 = discrete_energy(par, matrix);
  double drift_matrix = 0, drift_shear = 0, drift_compensated = 0;
  for (int j = 0; j < 1000000; ++j) {
    matrix = phi * matrix;
    shear = shear_step(s, shear);
    shear_step_compensated(s, compensated);
    drift_matrix = std::max(drift_matrix, std::abs(discrete_energy(par, matrix) - H0) / H0);
    drift_shear = std::max(drift_shear, std::abs(discrete_energy(par, shear) - H0) / H0);
    drift_compensated = std::max(drift_compensated, std::abs(discrete_energy(par, compensated.y) - H0) / H0);
  }
  EXPECT_GT(drift_matrix, 1e-10);
  EXPECT_LT(drift_shear, 1e-12);
  EXPECT_LT(drift_compensated, drift_shear);
}

}  // namespace
}  // namespace simpson

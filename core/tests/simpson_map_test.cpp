#include <simpson/simpson_map.hpp>


#include <simpson/energy.hpp>
#include <simpson/reduced_lagrangian.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

namespace simpson {
namespace {

template <class Real>
class SimpsonMap : public test::precision_fixture<Real> {};
TYPED_TEST_SUITE(SimpsonMap, test::all_scalars, test::scalar_names);

TYPED_TEST(SimpsonMap, DeterminantIsOne) {
  using Real = TypeParam;
  for (const auto& par : test::parameter_cases<Real>()) {
    const one_step_matrix<Real> phi = simpson_map(par);
    // Each entry carries at most ~14 roundings; αδ − βγ errs by at most 2·14·eps·(|αδ| + |βγ|).
    const Real condition = test::magnitude(Real(phi.alpha * phi.delta)) + test::magnitude(Real(phi.beta * phi.gamma));
    EXPECT_TRUE(test::within(determinant(phi), Real(1), Real(32 * eps<Real>() * condition)));
  }
}

TYPED_TEST(SimpsonMap, ConservesTheDiscreteEnergy) {
  using Real = TypeParam;
  for (const auto& par : test::parameter_cases<Real>()) {
    const phase_point<Real> y{test::ratio<Real>(-3, 2), test::ratio<Real>(5, 7)};
    const phase_point<Real> y_next = simpson_map(par) * y;
    // H_d is indefinite in the unstable band, so the condition is the sum of its terms' magnitudes
    // at both states; the coefficient of q² carries ~10 roundings, the entries of Φ_3 ~14.
    const auto terms = [&](const phase_point<Real>& z) {
      return Real(test::magnitude(Real(z.p * z.p / (2 * par.m()))) +
                  test::magnitude(Real(discrete_energy(par, phase_point<Real>{Real(0), z.q}))));
    };
    EXPECT_TRUE(test::within(discrete_energy(par, y_next), discrete_energy(par, y),
                             Real(64 * eps<Real>() * (terms(y) + terms(y_next)))));
  }
}

TEST(SimpsonMapExact, KnownValues) {
  using R = rational;
  // m = 1, ω = 1, h = 2 (x = 4): 1/(7/6) × ((−1/2, −2·(2/3)(5/6)), (2·(1/2), −1/2)).
  const one_step_matrix<R> phi = simpson_map(oscillator_parameters<R>(R(1), R(1), R(2)));
  EXPECT_EQ(phi.alpha, R(-3, 7));
  EXPECT_EQ(phi.beta, R(-20, 21));
  EXPECT_EQ(phi.gamma, R(6, 7));
  EXPECT_EQ(phi.delta, R(-3, 7));
  // m = 2: β scales with m, γ with 1/m.
  const one_step_matrix<R> heavy = simpson_map(oscillator_parameters<R>(R(2), R(1), R(2)));
  EXPECT_EQ(heavy.beta, R(-40, 21));
  EXPECT_EQ(heavy.gamma, R(3, 7));
  // m = 1, ω = 1, h = 4 (x = 16, second stable band): a = 5/3, diagonal −1 → −3/5,
  // β = −4(−1/3)(1/3)(3/5) = 4/15, γ = 4(−1)(3/5) = −12/5.
  const one_step_matrix<R> wide = simpson_map(oscillator_parameters<R>(R(1), R(1), R(4)));
  EXPECT_EQ(wide.alpha, R(-3, 5));
  EXPECT_EQ(wide.beta, R(4, 15));
  EXPECT_EQ(wide.gamma, R(-12, 5));
  EXPECT_EQ(wide.delta, R(-3, 5));
}

TEST(SimpsonMapExact, BackwardMapIsTheInverse) {
  // Time reversibility, exactly: Φ_3(h) Φ_3(−h) = I, and Φ_3(−h) flips the sign of β and γ only.
  using R = rational;
  for (const auto& par : test::parameter_cases<R>()) {
    const one_step_matrix<R> forward = simpson_map(par), backward = simpson_map_backward(par);
    const one_step_matrix<R> product = forward * backward;
    EXPECT_EQ(product.alpha, R(1));
    EXPECT_EQ(product.beta, R(0));
    EXPECT_EQ(product.gamma, R(0));
    EXPECT_EQ(product.delta, R(1));
    EXPECT_EQ(backward.alpha, forward.alpha);
    EXPECT_EQ(backward.beta, -forward.beta);
  }
}

TEST(SimpsonMapExact, MomentumOfEachStepIsThatOfTheReducedLagrangian) {
  // p_{j+1} = ∂L_h^r/∂q_r(q_j, q_{j+1}) and p_j = −∂L_h^r/∂q_l(q_j, q_{j+1}), by exact differences.
  using R = rational;
  for (const auto& par : test::parameter_cases<R>()) {
    const phase_point<R> y{R(-3, 2), R(5, 7)};
    const phase_point<R> y_next = simpson_map(par) * y;
    const auto L_right = [&](const R& v) -> R { return reduced_lagrangian(par, y.q, v); };
    const auto L_left = [&](const R& v) -> R { return reduced_lagrangian(par, v, y_next.q); };
    EXPECT_EQ(y_next.p, test::exact_derivative_quartic<R>(L_right, y_next.q));
    EXPECT_EQ(y.p, -test::exact_derivative_quartic<R>(L_left, y.q));
  }
}

}  // namespace
}  // namespace simpson

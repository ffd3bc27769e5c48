#include <simpson/newmark_map.hpp>

#include <simpson/classical_lagrangian.hpp>
#include <simpson/energy.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

namespace simpson {
namespace {

template <class Real>
class NewmarkMap : public test::precision_fixture<Real> {};
TYPED_TEST_SUITE(NewmarkMap, test::all_scalars, test::scalar_names);

TYPED_TEST(NewmarkMap, DeterminantIsOne) {
  using Real = TypeParam;
  for (const auto& par : test::parameter_cases<Real>()) {
    const one_step_matrix<Real> phi = newmark_map(par);
    // Each entry carries at most ~8 roundings; αδ − βγ then errs by at most
    // 2·8·eps·(|αδ| + |βγ|), the condition factor of the difference.
    const Real condition = test::magnitude(Real(phi.alpha * phi.delta)) + test::magnitude(Real(phi.beta * phi.gamma));
    EXPECT_TRUE(test::within(determinant(phi), Real(1), Real(16 * eps<Real>() * condition)));
  }
}

TYPED_TEST(NewmarkMap, SolvesTheDiscreteSystemAndConservesH) {
  using Real = TypeParam;
  for (const auto& par : test::parameter_cases<Real>()) {
    const phase_point<Real> y{test::ratio<Real>(-3, 2), test::ratio<Real>(5, 7)};
    const phase_point<Real> y_next = newmark_map(par) * y;
    const phase_point<Real> r = newmark_system_residual(par, y, y_next);
    // Residual scales: the first relation has terms of size |p| + m ω² h |q|, the second |q|/h + |p|/m.
    const Real omega2 = par.omega() * par.omega();
    const Real scale_p = test::magnitude(y.p) + test::magnitude(y_next.p) +
                         par.m() * omega2 * par.h() * (test::magnitude(y.q) + test::magnitude(y_next.q));
    const Real scale_q = (test::magnitude(y.q) + test::magnitude(y_next.q)) / par.h() +
                         (test::magnitude(y.p) + test::magnitude(y_next.p)) / par.m();
    EXPECT_TRUE(test::within(r.p, Real(0), Real(32 * eps<Real>() * scale_p)));
    EXPECT_TRUE(test::within(r.q, Real(0), Real(32 * eps<Real>() * scale_q)));
    // (HH-exact) conserved: H is a sum of positive terms, so 32 eps H bounds its round-off.
    const Real H = energy(par, y);
    EXPECT_TRUE(test::within(energy(par, y_next), H, Real(32 * eps<Real>() * H)));
  }
}

TEST(NewmarkMapExact, MomentaAreThoseOfTheDiscreteLagrangian) {
  // Independent route: p_{j+1} = ∂L_d/∂q_r(q_j, q_{j+1}) and p_j = −∂L_d/∂q_l(q_j, q_{j+1}).
  using R = rational;
  for (const auto& par : test::parameter_cases<R>()) {
    const phase_point<R> y{R(-3, 2), R(5, 7)};
    const phase_point<R> y_next = newmark_map(par) * y;
    const auto V = [&](const R& v) -> R { return par.potential(v); };
    const auto L_right = [&](const R& v) -> R { return classical_lagrangian(par.m(), par.h(), V, y.q, v); };
    const auto L_left = [&](const R& v) -> R { return classical_lagrangian(par.m(), par.h(), V, v, y_next.q); };
    EXPECT_EQ(y_next.p, test::exact_derivative_quartic<R>(L_right, y_next.q));
    EXPECT_EQ(y.p, -test::exact_derivative_quartic<R>(L_left, y.q));
  }
}

TEST(NewmarkMapExact, KnownValueIsAQuarterTurn) {
  // m = 1, ω = 1, h = 2: x = 4, Φ = (1/2)((0, −2), (2, 0)) = ((0, −1), (1, 0)).
  using R = rational;
  const one_step_matrix<R> phi = newmark_map(oscillator_parameters<R>(R(1), R(1), R(2)));
  EXPECT_EQ(phi.alpha, R(0));
  EXPECT_EQ(phi.beta, R(-1));
  EXPECT_EQ(phi.gamma, R(1));
  EXPECT_EQ(phi.delta, R(0));
}

}  // namespace
}  // namespace simpson

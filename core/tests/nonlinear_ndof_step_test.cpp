// The nonlinear steps for n degrees of freedom (nonlinear_ndof_step.hpp) on the systems of
// separable_system.hpp, and the Kepler orbit (kepler_exact.hpp): each checked against an
// independent route (the scalar step, the linear map Φ₃, Lobatto IIIA–IIIB, the exact solution).

#include <simpson/kepler_exact.hpp>
#include <simpson/nonlinear_ndof_step.hpp>
#include <simpson/potential.hpp>
#include <simpson/runge_kutta_tableaux.hpp>
#include <simpson/stormer_verlet.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace simpson {
namespace {

template <class Real>
class NonlinearNdof : public test::precision_fixture<Real> {};
using ndof_scalars = ::testing::Types<double, mpfr>;
TYPED_TEST_SUITE(NonlinearNdof, ndof_scalars, test::scalar_names);

template <class Real>
dense_vector<Real> vec(std::initializer_list<Real> v) {
  dense_vector<Real> out(static_cast<Eigen::Index>(v.size()));
  Eigen::Index i = 0;
  for (const Real& x : v) out(i++) = x;
  return out;
}

template <class Real>
Real gap(const ndof_state<Real>& a, const ndof_state<Real>& b) {
  return std::max(Real(dense_vector<Real>(a.p - b.p).cwiseAbs().maxCoeff()), Real(dense_vector<Real>(a.q - b.q).cwiseAbs().maxCoeff()));
}

template <class Real>
separable_system<Real, kepler_potential<Real>> kepler() {
  return {dense_matrix<Real>::Identity(2, 2), kepler_potential<Real>{Real(1)}};
}

TYPED_TEST(NonlinearNdof, OneDegreeOfFreedomIsTheScalarStep) {
  using Real = TypeParam;
  using V1 = one_dof_potential<Real, pendulum_potential<Real>>;
  const Real m = test::ratio<Real>(3, 2), h = test::ratio<Real>(3, 10);
  const separable_system<Real, V1> s(dense_matrix<Real>::Constant(1, 1, m), V1{pendulum_potential<Real>{m, Real(1)}});
  const phase_point<Real> y{test::ratio<Real>(-1, 3), test::ratio<Real>(6, 5)};
  const auto scalar = simpson_nonlinear_step(m, h, pendulum_potential<Real>{m, Real(1)}, y);
  const auto ndof = simpson_ndof_step(s, h, ndof_state<Real>{vec<Real>({y.p}), vec<Real>({y.q})});
  // Both solve F(x) = 0 to 16 eps of its terms (~ m |q|) and differ by F's slope, m + h² V''/24 ≥ m/2:
  // the states by a few roundings of terms of size ~ 2.
  const Real bound = 256 * eps<Real>();
  EXPECT_TRUE(test::within(ndof.state.p(0), scalar.state.p, bound));
  EXPECT_TRUE(test::within(ndof.state.q(0), scalar.state.q, bound));
}

TYPED_TEST(NonlinearNdof, OnAQuadraticPotentialItIsTheLinearMap) {
  using Real = TypeParam;
  // The linearized double pendulum (claims ndof-*): the Newton step and the closed-form 2n × 2n map
  // of ndof_linear.hpp are two routes to the same linear step.
  dense_matrix<Real> M(2, 2), K(2, 2);
  M << Real(2), Real(1), Real(1), Real(1);
  K << Real(2), Real(0), Real(0), Real(1);
  const separable_system<Real, quadratic_potential<Real>> s(M, quadratic_potential<Real>{K});
  const Real h = test::ratio<Real>(2, 5);
  const dense_matrix<Real> phi = ndof_simpson_map(M, K, h);
  ndof_state<Real> y{vec<Real>({test::ratio<Real>(1, 3), Real(-1)}), vec<Real>({test::ratio<Real>(1, 2), test::ratio<Real>(1, 4)})};
  dense_vector<Real> z(4);
  z << y.p, y.q;
  for (int j = 0; j < 20; ++j) {
    const auto step = simpson_ndof_step(s, h, y);
    z = phi * z;
    EXPECT_LE(step.newton_iterations, 2);  // a linear equation: one correction, then the check
    y = step.state;
  }
  // Entries of size ~1, 20 steps of entries ~1, each rounding a few times.
  EXPECT_LE(std::max(Real(dense_vector<Real>(y.p - z.head(2)).cwiseAbs().maxCoeff()),
                     Real(dense_vector<Real>(y.q - z.tail(2)).cwiseAbs().maxCoeff())),
            Real(20 * 64 * eps<Real>()));
}

TYPED_TEST(NonlinearNdof, SimpsonIsLobattoIIIAIIIBOnKepler) {
  using Real = TypeParam;
  const auto s = kepler<Real>();
  const kepler_orbit<Real> orbit{test::ratio<Real>(3, 5)};
  const auto for_q = lobatto_iiia3_tableau<Real>(), for_p = lobatto_iiib3_tableau<Real>();
  const auto coupling = couple(for_q, for_p);
  const Real h = test::ratio<Real>(1, 20);
  for (int k = 0; k < 8; ++k) {
    const ndof_state<Real> y = orbit.at(Real(k * test::ratio<Real>(3, 4)));
    const auto simpson = simpson_ndof_step(s, h, y), lobatto = prk_ndof_step(for_q, for_p, coupling, s, h, y);
    // Two Newton solves of equivalent systems (claim nonlinear-lobatto-equivalence), each to 16 eps
    // of its terms; the states are ~2 at perihelion and the force's Lipschitz constant h²|∇²V| < 1.
    EXPECT_LE(gap(simpson.state, lobatto.state), Real(1024 * eps<Real>())) << "k = " << k;
    EXPECT_LE(simpson.newton_iterations, 8);
  }
}

TYPED_TEST(NonlinearNdof, KeplerOrbitIsExact) {
  using Real = TypeParam;
  const kepler_orbit<Real> orbit{test::ratio<Real>(3, 5)};
  const Real b = sqrt(Real(1 - orbit.e * orbit.e));
  for (int k = 0; k <= 12; ++k) {
    const ndof_state<Real> y = orbit.at(Real(k * test::ratio<Real>(7, 12)));
    const Real energy = y.p.squaredNorm() / 2 - 1 / sqrt(Real(y.q.squaredNorm()));
    const Real angular = y.q(0) * y.p(1) - y.q(1) * y.p(0);
    // Terms up to ~ 4 at perihelion, Kepler's equation solved to a few eps.
    EXPECT_TRUE(test::within(energy, Real(-Real(1) / 2), Real(64 * eps<Real>()))) << "k = " << k;
    EXPECT_TRUE(test::within(angular, b, Real(64 * eps<Real>()))) << "k = " << k;
  }
  // The period 2π: back at perihelion.
  const Real two_pi = 2 * boost::math::constants::pi<Real>();
  EXPECT_LE(gap(orbit.at(two_pi), orbit.initial()), Real(64 * eps<Real>()));
}

TYPED_TEST(NonlinearNdof, EachMethodHasItsOrderOnKepler) {
  using Real = TypeParam;
  if constexpr (std::is_same_v<Real, mpfr>) {
    const auto s = kepler<Real>();
    const kepler_orbit<Real> orbit{test::ratio<Real>(1, 2)};
    const Real T(1);
    const auto gl2 = gauss_legendre2_tableau<Real>();
    const auto gl2_coupling = couple(gl2, gl2);
    const auto weights = yoshida_weights<Real>();
    const auto error = [&](int method, int N) {
      const Real h = T / N;
      ndof_state<Real> y = orbit.initial();
      for (int j = 0; j < N; ++j) {
        switch (method) {
          case 0: y = simpson_ndof_step(s, h, y).state; break;
          case 1: y = prk_ndof_step(gl2, gl2, gl2_coupling, s, h, y).state; break;
          case 2: y = stormer_verlet_ndof_step(s, h, y); break;
          case 3: y = yoshida_ndof_step(s, weights, h, y); break;
          default: y = rk4_ndof_step(s, h, y); break;
        }
      }
      return gap(y, orbit.at(T));
    };
    const int orders[] = {4, 4, 2, 4, 4};
    for (int method = 0; method < 5; ++method) {
      // Error ratio between N = 40 and 80: 2^order within 20% (the next term is h² smaller).
      const double ratio = static_cast<double>(error(method, 40) / error(method, 80));
      EXPECT_NEAR(std::log2(ratio), orders[method], 0.3) << "method " << method;
    }
  }
}

// First same as last: the kept force is the one the plain step would evaluate again, so a run with
// it lands on the same state bit for bit; a force kept for another q is not used (a check that
// reused it unconditionally would drift).
TYPED_TEST(NonlinearNdof, KeepingTheLastForceChangesNoStateOfAKickDriftKickRun) {
  using Real = TypeParam;
  const auto s = kepler<Real>();
  const kepler_orbit<Real> orbit{test::ratio<Real>(1, 2)};
  const auto weights = yoshida_weights<Real>();
  const Real h = Real(1) / 40;
  for (const bool composed : {false, true}) {
    ndof_state<Real> plain = orbit.initial(), kept_run = orbit.initial();
    last_force<Real> kept;
    for (int j = 0; j < 40; ++j) {
      plain = composed ? yoshida_ndof_step(s, weights, h, plain) : stormer_verlet_ndof_step(s, h, plain);
      kept_run = composed ? yoshida_ndof_step(s, weights, h, kept_run, kept) : stormer_verlet_ndof_step(s, h, kept_run, kept);
    }
    EXPECT_EQ(gap(plain, kept_run), Real(0)) << (composed ? "yoshida" : "stormer-verlet");
  }
  // Simpson's step ends its impulse with the force at q_{j+1}, the next step's start: kept, the same
  // states bit for bit.
  ndof_state<Real> plain = orbit.initial(), kept_run = orbit.initial();
  last_force<Real> kept;
  for (int j = 0; j < 40; ++j) {
    plain = simpson_ndof_step(s, h, plain).state;
    kept_run = simpson_ndof_step(s, h, kept_run, kept).state;
  }
  EXPECT_EQ(gap(plain, kept_run), Real(0)) << "simpson";
  // A force kept for another q: recomputed, not reused.
  last_force<Real> stale{vec<Real>({Real(9), Real(9)}), vec<Real>({Real(100), Real(100)}), true};
  const ndof_state<Real> start = orbit.initial();
  EXPECT_EQ(gap(stormer_verlet_ndof_step(s, h, start, stale), stormer_verlet_ndof_step(s, h, start)), Real(0));
  last_force<Real> stale_for_simpson = stale;
  EXPECT_EQ(gap(simpson_ndof_step(s, h, start, stale_for_simpson).state, simpson_ndof_step(s, h, start).state), Real(0));
}

TYPED_TEST(NonlinearNdof, ABadMassOrAFailedSolveIsAnError) {
  using Real = TypeParam;
  dense_matrix<Real> M(2, 2);
  M << Real(1), Real(2), Real(2), Real(1);  // indefinite
  EXPECT_THROW((separable_system<Real, henon_heiles_potential<Real>>(M, {})), std::invalid_argument);
  // At the origin the Kepler force is not finite: Newton's residual is not finite and the step says so.
  const auto s = kepler<Real>();
  EXPECT_THROW(simpson_ndof_step(s, Real(1), ndof_state<Real>{vec<Real>({Real(0), Real(0)}), vec<Real>({Real(0), Real(0)})}),
               std::domain_error);
}

}  // namespace
}  // namespace simpson

// The variational steps of discrete_lagrangian_step.hpp: Simpson's for a separable L is the n-DOF
// Simpson step; orders by step halving on the double pendulum against the mpfr reference; a
// perturbed weight or interpolant breaks the order; the momentum of a cyclic coordinate is
// conserved to the stated bound; the energy's error stays bounded for Simpson and drifts for RK4;
// a step Newton cannot take throws and says why.

#include <simpson/discrete_lagrangian_step.hpp>
#include <simpson/double_pendulum.hpp>
#include <simpson/hamiltonian_prk_step.hpp>
#include <simpson/reference_flow.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace simpson::discrete_lagrangian_step_test {
namespace {

template <class Real>
dense_vector<Real> vec2(const Real& a, const Real& b) {
  dense_vector<Real> out(2);
  out << a, b;
  return out;
}

template <class Real>
Real gap(const ndof_state<Real>& a, const ndof_state<Real>& b) {
  return std::max(Real(dense_vector<Real>(a.p - b.p).cwiseAbs().maxCoeff()), Real(dense_vector<Real>(a.q - b.q).cwiseAbs().maxCoeff()));
}

/// L = ½ q̇ᵀ M q̇ − V(q) for a potential of separable_system.hpp: the same system as separable_system.
template <class Real, class Potential>
struct mechanical_lagrangian {
  dense_matrix<Real> M;
  Potential V;
  int dof() const { return static_cast<int>(M.rows()); }
  template <class T>
  T operator()(const Eigen::Matrix<T, Eigen::Dynamic, 1>& q, const Eigen::Matrix<T, Eigen::Dynamic, 1>& v) const {
    T kinetic(Real(0));
    for (int i = 0; i < dof(); ++i) {
      for (int j = 0; j < dof(); ++j) kinetic += v(i) * T(M(i, j)) * v(j) / 2;
    }
    const T x = q(0), y = q(1);  // Hénon–Heiles, as henon_heiles_potential
    return T(kinetic - ((x * x + y * y) / 2 + x * x * y - y * y * y / 3));
  }
};

/// A particle in the plane in polar coordinates (r, φ), V = −1/r: φ is cyclic, p_φ = r² φ̇ is conserved.
template <class Real>
struct polar_kepler {
  int dof() const { return 2; }
  template <class T>
  T operator()(const Eigen::Matrix<T, Eigen::Dynamic, 1>& q, const Eigen::Matrix<T, Eigen::Dynamic, 1>& v) const {
    return T((v(0) * v(0) + q(0) * q(0) * v(1) * v(1)) / 2 + 1 / q(0));
  }
};

template <class Real>
class DiscreteLagrangian : public test::precision_fixture<Real> {};
using step_scalars = ::testing::Types<double, mpfr>;
TYPED_TEST_SUITE(DiscreteLagrangian, step_scalars, test::scalar_names);

TYPED_TEST(DiscreteLagrangian, TheLagrangeBasisGivesSimpsonsGearDerivativesAndTheMidpointsAverage) {
  using Real = TypeParam;
  const discretisation<Real> simpson = simpson_discretisation<Real>(), midpoint = midpoint_discretisation<Real>();
  const auto [E, D] = lagrange_basis(simpson.times, simpson.times);
  const auto [Em, Dm] = lagrange_basis(midpoint.times, std::vector<Real>{Real(1) / 2});
  for (std::size_t k = 0; k < 3; ++k) {
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_TRUE(test::within(E[k][c], simpson.evaluation[k][c], Real(4 * eps<Real>())));
      EXPECT_TRUE(test::within(D[k][c], simpson.derivative[k][c], Real(16 * eps<Real>())));
    }
  }
  for (std::size_t c = 0; c < 2; ++c) {
    EXPECT_TRUE(test::within(Em[0][c], midpoint.evaluation[0][c], Real(4 * eps<Real>())));
    EXPECT_TRUE(test::within(Dm[0][c], midpoint.derivative[0][c], Real(4 * eps<Real>())));
  }
}

TYPED_TEST(DiscreteLagrangian, ForASeparableLagrangianSimpsonsStepIsTheNdofSimpsonStep) {
  using Real = TypeParam;
  dense_matrix<Real> M(2, 2);
  M << Real(2), Real(1), Real(1), Real(1);
  const mechanical_lagrangian<Real, henon_heiles_potential<Real>> L{M, {}};
  const separable_system<Real, henon_heiles_potential<Real>> s(M, {});
  ndof_state<Real> a{vec2(test::ratio<Real>(1, 5), test::ratio<Real>(-1, 10)), vec2(test::ratio<Real>(1, 10), test::ratio<Real>(1, 5))};
  ndof_state<Real> b = a;
  const Real h = test::ratio<Real>(1, 4);
  for (int j = 0; j < 40; ++j) {
    const auto lagrangian = simpson_lagrangian_step(L, h, a);
    a = lagrangian.state;
    b = simpson_ndof_step(s, h, b).state;
    EXPECT_LE(lagrangian.newton_iterations, 4);
  }
  // Two Newton solves of the same equations, each to its stated tolerance: the Lagrangian form's
  // residual carries |L_vv| |g's terms| ~ 8 |M| |q| / h roundings; 40 steps of states ~ 0.3.
  EXPECT_LE(gap(a, b), Real(40 * 256 * eps<Real>()));
  // And a perturbed Simpson weight is not that step.
  discretisation<Real> wrong = simpson_discretisation<Real>();
  wrong.weights[0] += Real(1) / 1000;
  wrong.weights[1] -= Real(1) / 1000;
  const ndof_state<Real> start{vec2(test::ratio<Real>(1, 5), test::ratio<Real>(-1, 10)), vec2(test::ratio<Real>(1, 10), test::ratio<Real>(1, 5))};
  EXPECT_GT(gap(discrete_lagrangian_step(wrong, L, h, start).state, simpson_ndof_step(s, h, start).state), Real(1e-7));
}

/// The double pendulum's start and its mpfr:40 reference at T = 1 (computed once).
struct pendulum_case {
  double_pendulum<double> L{1, 1, 1, 1, 1};
  ndof_state<double> start;
  ndof_state<double> at_T;
  double digits = 0;
  pendulum_case() {
    const scoped_mpfr_digits digits40(40);
    const double_pendulum<mpfr> Lm{mpfr(1), mpfr(1), mpfr(1), mpfr(1), mpfr(1)};
    const dense_vector<mpfr> q0 = vec2(mpfr(1), mpfr(-1) / 2), v0 = vec2(mpfr(3) / 10, mpfr(1) / 5);
    const ndof_state<mpfr> y0{lagrangian_gradient_at(Lm, q0, v0).dv, q0};
    const reference_state r = lagrangian_reference(Lm, y0, mpfr(1), 20, 32, 3);
    digits = r.agreed_digits;
    const auto to_double = [](const dense_vector<mpfr>& x) { return vec2(static_cast<double>(x(0)), static_cast<double>(x(1))); };
    start = {to_double(y0.p), to_double(y0.q)};
    at_T = {to_double(r.state.p), to_double(r.state.q)};
  }
};

const pendulum_case& pendulum() {
  static const pendulum_case c;
  return c;
}

/// The error at T = 1 after N steps of `step`.
double error_at_one(const std::function<ndof_state<double>(double, const ndof_state<double>&)>& step, int N) {
  ndof_state<double> y = pendulum().start;
  for (int j = 0; j < N; ++j) y = step(1.0 / N, y);
  return gap(y, pendulum().at_T);
}

/// The order measured as odeint's tests do: the error ratio of N and 2N steps against 2^order.
double measured_order(const std::function<ndof_state<double>(double, const ndof_state<double>&)>& step, int N) {
  return std::log2(error_at_one(step, N) / error_at_one(step, 2 * N));
}

TEST(DiscreteLagrangianOrders, SimpsonIsOfOrderFourAndTheMidpointOfOrderTwoOnTheDoublePendulum) {
  ASSERT_GE(pendulum().digits, 18) << "the reference";
  const auto& L = pendulum().L;
  const auto simpson = [&](double h, const ndof_state<double>& y) { return simpson_lagrangian_step(L, h, y).state; };
  const auto midpoint = [&](double h, const ndof_state<double>& y) { return midpoint_lagrangian_step(L, h, y).state; };
  // Errors from ~1e-6 to 1e-9 (far above round-off); the next term of the error is h² smaller.
  EXPECT_NEAR(measured_order(simpson, 16), 4, 0.1);
  EXPECT_NEAR(measured_order(midpoint, 16), 2, 0.1);
}

TEST(DiscreteLagrangianOrders, APerturbedWeightOrAWrongInterpolantLosesTheOrder) {
  const auto& L = pendulum().L;
  discretisation<double> weight = simpson_discretisation<double>();
  weight.weights[0] += 1e-2;  // still Σ w = 1 below: a consistent rule, of order 2 only
  weight.weights[2] -= 1e-2;
  discretisation<double> interpolant = simpson_discretisation<double>();
  interpolant.derivative[1] = {-1.0, 0.1, 0.9};  // g_m no longer (q_r − q_l)/h, still exact on constants
  for (const discretisation<double>* d : {&weight, &interpolant}) {
    const auto step = [&](double h, const ndof_state<double>& y) { return discrete_lagrangian_step(*d, L, h, y).state; };
    EXPECT_LT(measured_order(step, 16), 3);
  }
}

TEST(DiscreteLagrangianNoether, TheMomentumOfACyclicCoordinateMovesOnlyWithinTheSumOfTheStepBounds) {
  const polar_kepler<double> L;
  // An orbit of eccentricity ~0.5: r from 1/2 to 3/2, p_φ = r² φ̇.
  ndof_state<double> y{vec2(0.0, std::sqrt(0.75)), vec2(0.5, 0.0)};
  const double p_phi = y.p(1);
  double bound = 0;
  for (int j = 0; j < 2000; ++j) {
    const auto step = simpson_lagrangian_step(L, 0.02, y);
    y = step.state;
    bound += step.noether_bound(1);
  }
  EXPECT_LE(std::abs(y.p(1) - p_phi), bound) << "bound " << bound;
  // The bound adds each step's worst case; its largest term is the rounding of the velocity
  // (−3φ_l + 4φ_m − φ_r)/h with φ grown to ~40 after 6 orbits: 16 eps r² 8|φ|/h ~ 1e-10 a step.
  // What p_φ actually did is a random walk of roundings, far below the truncation error (the
  // radial momentum's, ~1e-6 here).
  EXPECT_LT(bound, 1e-6);
  EXPECT_LT(std::abs(y.p(1) - p_phi), 1e-10) << std::abs(y.p(1) - p_phi);
  EXPECT_GT(y.q(1), 35.0);  // the orbits went round
}

TEST(DiscreteLagrangianEnergy, SimpsonsEnergyErrorIsBoundedAndRk4sDrifts) {
  const polar_kepler<double> L;
  const ndof_state<double> start{vec2(0.0, std::sqrt(0.75)), vec2(0.5, 0.0)};
  const double energy = legendre_hamiltonian(L, start.q, start.p, false).value;
  // The largest |H − H₀| in the first and in the last fifth of 4000 steps of h = 0.05 (t = 200, about
  // 32 orbits of period 2π at E = −1/2): a drift shows as growth from one to the other.
  const auto spread = [&](const std::function<ndof_state<double>(const ndof_state<double>&)>& step) {
    ndof_state<double> y = start;
    double first = 0, last = 0;
    for (int j = 1; j <= 4000; ++j) {
      y = step(y);
      const double e = std::abs(legendre_hamiltonian(L, y.q, y.p, false).value - energy);
      if (j <= 800) first = std::max(first, e);
      if (j > 3200) last = std::max(last, e);
    }
    return std::make_pair(first, last);
  };
  const auto simpson = spread([&](const ndof_state<double>& y) { return simpson_lagrangian_step(L, 0.05, y).state; });
  const auto rk4 = spread([&](const ndof_state<double>& y) { return rk4_hamiltonian_step(L, 0.05, y).state; });
  EXPECT_LT(simpson.second, 1.5 * simpson.first) << simpson.first << " " << simpson.second;
  EXPECT_GT(rk4.second, 3 * rk4.first) << rk4.first << " " << rk4.second;
}

TEST(DiscreteLagrangianFailure, AStepFarTooLargeThrowsAndNamesWhy) {
  // The Kepler problem in polar coordinates from r = 1/2 with h = 100 (the orbit's period is 2π):
  // Newton wanders and stops after max_newton_iterations.
  const polar_kepler<double> L;
  const ndof_state<double> y{vec2(0.0, std::sqrt(0.75)), vec2(0.5, 0.0)};
  try {
    simpson_lagrangian_step(L, 100.0, y);
    ADD_FAILURE() << "no exception";
  } catch (const std::domain_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("simpson::discrete_lagrangian_step"), std::string::npos) << what;
    EXPECT_NE(what.find("Newton"), std::string::npos) << what;
  }
  EXPECT_THROW(simpson_lagrangian_step(L, -0.1, y), std::invalid_argument);
}

}  // namespace
}  // namespace simpson::discrete_lagrangian_step_test

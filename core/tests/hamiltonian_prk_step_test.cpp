// The Lobatto IIIA–IIIB pair and RK4 on the Hamiltonian of a Lagrangian quadratic in v
// (hamiltonian_prk_step.hpp, legendre_hamiltonian.hpp): which variational step the pair is, to
// round-off, and which it is not; their orders on the double pendulum.

#include <simpson/discrete_lagrangian_step.hpp>
#include <simpson/double_pendulum.hpp>
#include <simpson/hamiltonian_prk_step.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace simpson::hamiltonian_prk_step_test {
namespace {

dense_vector<double> vec2(double a, double b) {
  dense_vector<double> out(2);
  out << a, b;
  return out;
}

double gap(const ndof_state<double>& a, const ndof_state<double>& b) {
  return std::max((a.p - b.p).cwiseAbs().maxCoeff(), (a.q - b.q).cwiseAbs().maxCoeff());
}

/// Two pendulums coupled through a constant, non-diagonal mass matrix: L = ½ vᵀ M v + cos q₁ + cos q₂.
struct constant_mass_pendulums {
  int dof() const { return 2; }
  template <class T>
  T operator()(const Eigen::Matrix<T, Eigen::Dynamic, 1>& q, const Eigen::Matrix<T, Eigen::Dynamic, 1>& v) const {
    using std::cos;
    return T(v(0) * v(0) + v(0) * v(1) + v(1) * v(1) / 2 + cos(q(0)) + cos(q(1)));  // M = [[2, 1], [1, 1]]
  }
};


const double_pendulum<double> L{1, 1, 1, 1, 1};
ndof_state<double> start() { return {lagrangian_gradient_at(L, vec2(1.0, -0.5), vec2(0.3, 0.2)).dv, vec2(1.0, -0.5)}; }


TEST(HamiltonianPrk, LobattoIsTheCubicGalerkinVariationalStepToRoundOff) {
  for (const double h : {0.2, 0.1, 0.05}) {
    const auto lobatto = lobatto_hamiltonian_step(L, h, start());
    const auto cubic = discrete_lagrangian_step(lobatto_cubic_discretisation<double>(), L, h, start());
    // Two Newton solves to their tolerances, the Lagrangian form's ~ 16 eps |M| |q| / h in momentum.
    EXPECT_LE(gap(lobatto.state, cubic.state), 64 * eps<double>() / h) << "h = " << h;
    EXPECT_LE(lobatto.newton_iterations, 4);
  }
}

TEST(HamiltonianPrk, LobattoIsSimpsonsStepWhenTheMassIsConstantButNotOnTheDoublePendulum) {
  const constant_mass_pendulums C;
  const ndof_state<double> y{vec2(0.4, -0.3), vec2(1.2, -0.7)};
  for (const double h : {0.2, 0.05}) {
    EXPECT_LE(gap(lobatto_hamiltonian_step(C, h, y).state, simpson_lagrangian_step(C, h, y).state), 64 * eps<double>() / h);
  }
  // On the double pendulum the mass depends on q: the two are different maps, their gap of order
  // h⁵ per step (the cubic's bubble; discrete_lagrangian_step.hpp). Halving h divides it by ~2⁵.
  const double big = gap(lobatto_hamiltonian_step(L, 0.1, start()).state, simpson_lagrangian_step(L, 0.1, start()).state);
  const double small = gap(lobatto_hamiltonian_step(L, 0.05, start()).state, simpson_lagrangian_step(L, 0.05, start()).state);
  EXPECT_GT(big, 1e-9);
  EXPECT_NEAR(std::log2(big / small), 5, 0.6);
}

TEST(HamiltonianPrk, APerturbedMomentumWeightIsNotTheVariationalStep) {
  auto for_p = lobatto_iiib3_tableau<double>();
  for_p.b[1] += 1e-6;
  const auto wrong = hamiltonian_prk_step(lobatto_iiia3_tableau<double>(), for_p, L, 0.1, start());
  const auto cubic = discrete_lagrangian_step(lobatto_cubic_discretisation<double>(), L, 0.1, start());
  EXPECT_GT(gap(wrong.state, cubic.state), 1e-8);
}

TEST(HamiltonianPrk, LobattoAndRk4AreOfOrderFourOnTheDoublePendulum) {
  // Against a Lobatto run of 1024 steps (error ~1e-13, three orders below the errors compared).
  ndof_state<double> reference = start();
  for (int j = 0; j < 1024; ++j) reference = lobatto_hamiltonian_step(L, 1.0 / 1024, reference).state;
  const auto error = [&](bool rk4, int N) {
    ndof_state<double> y = start();
    for (int j = 0; j < N; ++j) y = rk4 ? rk4_hamiltonian_step(L, 1.0 / N, y).state : lobatto_hamiltonian_step(L, 1.0 / N, y).state;
    return gap(y, reference);
  };
  EXPECT_NEAR(std::log2(error(false, 16) / error(false, 32)), 4, 0.1);
  EXPECT_NEAR(std::log2(error(true, 16) / error(true, 32)), 4, 0.15);
}

}  // namespace
}  // namespace simpson::hamiltonian_prk_step_test

// GeometricIntegrators.jl's VPRK (vprk_step.hpp): with Lobatto's null vector it is Simpson's
// variational step, without it the Hamiltonian Lobatto IIIA–IIIB pair, both to round-off; of order
// 4 on the double pendulum; and of order 2 on the degenerate pendulum of their verification suite
// (GeometricProblems.Pendulum.iodeproblem), as Simpson's step is there: the order their 2026 audit
// measured (docs/src/audit.md, finding 5) is the discrete Lagrangian's on a degenerate Lagrangian.

#include <simpson/discrete_lagrangian_step.hpp>
#include <simpson/double_pendulum.hpp>
#include <simpson/hamiltonian_prk_step.hpp>
#include <simpson/vprk_step.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace simpson::vprk_step_test {
namespace {

dense_vector<double> vec2(double a, double b) {
  dense_vector<double> out(2);
  out << a, b;
  return out;
}

double gap(const ndof_state<double>& a, const ndof_state<double>& b) {
  return std::max((a.p - b.p).cwiseAbs().maxCoeff(), (a.q - b.q).cwiseAbs().maxCoeff());
}

/// GeometricProblems.jl's Pendulum.iodeproblem (l = m = g = 1): q = (θ, θ̇), ϑ(q) = (q₂, 0),
/// f = (sin q₁, v₁ − q₂), so L = q₂ v₁ − q₂²/2 − cos q₁, linear in v (degenerate): θ̇ = q₂, q̇₂ = sin θ.
struct degenerate_pendulum {
  int dof() const { return 2; }
  template <class T>
  T operator()(const Eigen::Matrix<T, Eigen::Dynamic, 1>& q, const Eigen::Matrix<T, Eigen::Dynamic, 1>& v) const {
    using std::cos;
    return T(q(1) * v(0) - q(1) * q(1) / 2 - cos(q(0)));
  }
};

const double_pendulum<double> L{1, 1, 1, 1, 1};
ndof_state<double> start() { return {lagrangian_gradient_at(L, vec2(1.0, -0.5), vec2(0.3, 0.2)).dv, vec2(1.0, -0.5)}; }

TEST(Vprk, WithTheNullVectorItIsSimpsonsStepWithoutItTheLobattoPair) {
  const std::vector<double> none;
  for (const double h : {0.2, 0.05}) {
    const auto vprk = vprk_lobatto3_step(L, h, start());
    const auto plain = vprk_lagrangian_step(lobatto_iiia3_tableau<double>(), lobatto_iiib3_tableau<double>(), none, L, h, start());
    // Newton solves of equivalent systems, each to its tolerance (~ 16 eps |M| |q| / h in momentum).
    EXPECT_LE(gap(vprk.state, simpson_lagrangian_step(L, h, start()).state), 64 * eps<double>() / h) << h;
    EXPECT_LE(gap(plain.state, lobatto_hamiltonian_step(L, h, start()).state), 64 * eps<double>() / h) << h;
    EXPECT_LE(vprk.newton_iterations, 4);
  }
  // A wrong null vector (not Σ d_i V_i = 0 for a linear velocity) is neither.
  const auto wrong = vprk_lagrangian_step(lobatto_iiia3_tableau<double>(), lobatto_iiib3_tableau<double>(), std::vector<double>{1, -2, 1.1}, L,
                                          0.1, start());
  EXPECT_GT(gap(wrong.state, simpson_lagrangian_step(L, 0.1, start()).state), 1e-8);
}

TEST(Vprk, Lobatto3IsOfOrderFourOnTheDoublePendulum) {
  ndof_state<double> reference = start();
  for (int j = 0; j < 1024; ++j) reference = lobatto_hamiltonian_step(L, 1.0 / 1024, reference).state;
  const auto error = [&](int N) {
    ndof_state<double> y = start();
    for (int j = 0; j < N; ++j) y = vprk_lobatto3_step(L, 1.0 / N, y).state;
    return gap(y, reference);
  };
  EXPECT_NEAR(std::log2(error(16) / error(32)), 4, 0.1);
}

/// GeometricIntegrators' measurement (test/verification/variational_convergence_tests.jl): T = 1,
/// h = 1/(3·2^k), k = 0..4, the maximal error in q over the run relative to the largest |q|,
/// q₀ = (acos 0.4, 0), p₀ = ϑ(q₀) = 0; the order the log-log slope. The reference: RK4 on
/// θ̇ = ω, ω̇ = sin θ with 2^12 steps per unit time (error ~1e-15, below the errors measured).
double degenerate_order(const std::function<ndof_state<double>(double, const ndof_state<double>&)>& step, double* constraint_ratio) {
  const auto reference = [](int N) {
    std::vector<dense_vector<double>> out;
    dense_vector<double> x = vec2(std::acos(0.4), 0.0);
    const int sub = 4096 / N;
    const double h = 1.0 / (N * sub);
    const auto f = [](const dense_vector<double>& u) { return vec2(u(1), std::sin(u(0))); };
    for (int j = 0; j < N; ++j) {
      for (int k = 0; k < sub; ++k) {
        const dense_vector<double> k1 = f(x), k2 = f(x + h / 2 * k1), k3 = f(x + h / 2 * k2), k4 = f(x + h * k3);
        x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      }
      out.push_back(x);
    }
    return out;
  };
  std::vector<double> logh, logerr, off;
  for (int k = 0; k <= 4; ++k) {
    const int N = 3 << k;
    const auto ref = reference(N);
    ndof_state<double> y{vec2(0.0, 0.0), vec2(std::acos(0.4), 0.0)};
    double err = 0, size = 0;
    for (int j = 0; j < N; ++j) {
      y = step(1.0 / N, y);
      err = std::max(err, (y.q - ref[static_cast<std::size_t>(j)]).cwiseAbs().maxCoeff());
      size = std::max(size, ref[static_cast<std::size_t>(j)].cwiseAbs().maxCoeff());
    }
    logh.push_back(std::log(1.0 / N));
    logerr.push_back(std::log(err / size));
    off.push_back(std::abs(y.p(0) - y.q(1)));  // p₁ − ϑ₁(q) at T: the primary constraint p = ϑ(q)
  }
  if (constraint_ratio != nullptr) *constraint_ratio = off[3] / off[4];
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < logh.size(); ++i) mx += logh[i] / 5, my += logerr[i] / 5;
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < logh.size(); ++i) sxy += (logh[i] - mx) * (logerr[i] - my), sxx += (logh[i] - mx) * (logh[i] - mx);
  return sxy / sxx;  // the least-squares slope, as their loglog_slope
}

TEST(Vprk, OnTheirDegeneratePendulumLobatto3AndSimpsonAreOfOrderTwoAndGaussOfOrderFour) {
  const degenerate_pendulum D;
  double drift = 0;
  EXPECT_NEAR(degenerate_order([&](double h, const ndof_state<double>& y) { return vprk_lobatto3_step(D, h, y).state; }, &drift), 2, 0.1);
  EXPECT_NEAR(drift, 4, 0.3) << "the momenta leave p = ϑ(q) by O(h²)";
  EXPECT_NEAR(degenerate_order([&](double h, const ndof_state<double>& y) { return simpson_lagrangian_step(D, h, y).state; }, nullptr), 2, 0.1);
  const auto gauss = gauss_legendre2_tableau<double>();
  EXPECT_NEAR(degenerate_order([&](double h, const ndof_state<double>& y) { return vprk_lagrangian_step(gauss, gauss, {}, D, h, y).state; }, nullptr),
              4, 0.1);
}

}  // namespace
}  // namespace simpson::vprk_step_test

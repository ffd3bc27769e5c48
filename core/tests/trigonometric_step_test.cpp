// The trigonometric integrator (trigonometric_step.hpp), method (C) of Hairer, Lubich and Wanner, on
// two masses whose stiff spring is ω²P, P = ½(e₂ − e₁)(e₂ − e₁)ᵀ, and a slow force of our choosing:
// each property below is one the method is built to have, checked against an independent route.
#include <simpson/trigonometric_step.hpp>

#include <simpson/fpu_chain.hpp>
#include <simpson/scalar_traits.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace simpson {
namespace {

// Tolerances: k eps times the scale of the terms compared. The states are of order 1 and the stiff
// spring's momentum terms of order ω (ω sin ωh q): each entry below is a sum of a few such terms, each
// rounded a few times, so 16 eps (order-1 terms) or 16 eps ω (terms with a factor ω) bounds its error
// with room; a wrong filter moves an entry by order h² or more, far above either. eps<double>() is
// scalar_traits.hpp's.

/// Two unit masses, stiff spring ω²P, slow potential U = ½ qᵀKq (the step is then linear), counting ∇U.
struct two_masses {
  double omega;
  dense_matrix<double> K;
  mutable int slow_gradients = 0;
  const double& stiff_frequency() const { return omega; }
  dense_vector<double> stiff_projection(const dense_vector<double>& v) const {
    dense_vector<double> out(2);
    out << (v(0) - v(1)) / 2, (v(1) - v(0)) / 2;
    return out;
  }
  dense_vector<double> slow_gradient(const dense_vector<double>& q) const {
    ++slow_gradients;
    return K * q;
  }
};

two_masses with_slow(double omega, double k11, double k12, double k22) {
  dense_matrix<double> K(2, 2);
  K << k11, k12, k12, k22;
  return {omega, K};
}

ndof_state<double> state(double p1, double p2, double q1, double q2) {
  ndof_state<double> y{dense_vector<double>(2), dense_vector<double>(2)};
  y.p << p1, p2;
  y.q << q1, q2;
  return y;
}

ndof_state<double> fresh_step(const two_masses& s, double h, const ndof_state<double>& y) {
  last_force<double> none;
  return trigonometric_step(s, h, y, none);
}

/// The 4 × 4 matrix of the (linear) step, column k the step of the k-th unit state (p₁, p₂, q₁, q₂).
dense_matrix<double> step_matrix(const two_masses& s, double h) {
  dense_matrix<double> M(4, 4);
  for (int k = 0; k < 4; ++k) {
    ndof_state<double> e = state(k == 0, k == 1, k == 2, k == 3);
    const ndof_state<double> out = fresh_step(s, h, e);
    M.col(k) << out.p(0), out.p(1), out.q(0), out.q(1);
  }
  return M;
}

TEST(TrigonometricStep, WithoutASlowForceItIsTheStiffSpringsExactFlow) {
  // The elongation d = q₂ − q₁ oscillates at ω, the centre of mass moves freely: closed form.
  const two_masses s = with_slow(50, 0, 0, 0);
  const double h = 0.07;  // ωh = 3.5, far beyond any explicit scheme's stability
  const ndof_state<double> y = state(0.3, -0.2, 0.5, 0.1);
  const ndof_state<double> out = fresh_step(s, h, y);
  const double d = y.q(1) - y.q(0), v = y.p(1) - y.p(0), c = (y.q(1) + y.q(0)) / 2, u = (y.p(1) + y.p(0)) / 2;
  const double d1 = d * std::cos(s.omega * h) + v / s.omega * std::sin(s.omega * h);
  const double v1 = -d * s.omega * std::sin(s.omega * h) + v * std::cos(s.omega * h);
  EXPECT_NEAR(out.q(1) - out.q(0), d1, 16 * eps<double>());
  EXPECT_NEAR(out.p(1) - out.p(0), v1, 16 * eps<double>() * s.omega);
  EXPECT_NEAR((out.q(1) + out.q(0)) / 2, c + h * u, 16 * eps<double>());
  EXPECT_NEAR((out.p(1) + out.p(0)) / 2, u, 16 * eps<double>());
}

TEST(TrigonometricStep, WithoutAStiffSpringItIsStormerVerlet) {
  const two_masses s = with_slow(0, 2, -0.5, 1);
  const double h = 0.1;
  const ndof_state<double> y = state(0.3, -0.2, 0.5, 0.1);
  const ndof_state<double> out = fresh_step(s, h, y);
  // Kick, drift, kick.
  const dense_vector<double> p_half = y.p - h / 2 * (s.K * y.q);
  const dense_vector<double> q1 = y.q + h * p_half;
  const dense_vector<double> p1 = p_half - h / 2 * (s.K * q1);
  EXPECT_LT((out.q - q1).cwiseAbs().maxCoeff(), 16 * eps<double>());
  EXPECT_LT((out.p - p1).cwiseAbs().maxCoeff(), 16 * eps<double>());
}

TEST(TrigonometricStep, IsSymplecticAtEveryOmegaH) {
  // ΦᵀJΦ = J for the linear step, J = [[0, −I], [I, 0]] in (p, q), at ωh across and beyond the bands
  // of the explicit and of Simpson's scheme; a filter that breaks ψ = sinc·φ (ψ₁ = 1, say) fails this.
  dense_matrix<double> J = dense_matrix<double>::Zero(4, 4);
  J.block(0, 2, 2, 2) = -dense_matrix<double>::Identity(2, 2);
  J.block(2, 0, 2, 2) = dense_matrix<double>::Identity(2, 2);
  for (const double omega_h : {0.3, 1.5, 2.9, 3.0, 4.0, 7.5}) {
    const two_masses s = with_slow(50, 2, -0.5, 1);
    const dense_matrix<double> M = step_matrix(s, omega_h / s.omega);
    // MᵀJM sums products of an entry of order ω by one of order 1/ω or 1: 16 eps ω² bounds its rounding.
    EXPECT_LT((M.transpose() * J * M - J).cwiseAbs().maxCoeff(), 16 * eps<double>() * s.omega * s.omega) << "ωh = " << omega_h;
  }
}

TEST(TrigonometricStep, IsSymmetric) {
  // A step of h then of −h returns the start.
  const two_masses s = with_slow(50, 2, -0.5, 1);
  const ndof_state<double> y = state(0.3, -0.2, 0.5, 0.1);
  const ndof_state<double> back = fresh_step(s, -0.03, fresh_step(s, 0.03, y));
  EXPECT_LT((back.q - y.q).cwiseAbs().maxCoeff(), 16 * eps<double>());
  EXPECT_LT((back.p - y.p).cwiseAbs().maxCoeff(), 16 * eps<double>() * s.omega);
}

TEST(TrigonometricStep, KeepsTheLastForceAndEvaluatesOneASteps) {
  // First same as last: a run of n steps evaluates ∇U n + 1 times, and gives the same states bit for
  // bit as steps that evaluate both ends.
  const two_masses counted = with_slow(50, 2, -0.5, 1);
  ndof_state<double> kept_run = state(0.3, -0.2, 0.5, 0.1), fresh_run = kept_run;
  last_force<double> kept;
  for (int j = 0; j < 10; ++j) kept_run = trigonometric_step(counted, 0.02, kept_run, kept);
  EXPECT_EQ(counted.slow_gradients, 11);
  const two_masses fresh = with_slow(50, 2, -0.5, 1);
  for (int j = 0; j < 10; ++j) fresh_run = fresh_step(fresh, 0.02, fresh_run);
  EXPECT_EQ(fresh.slow_gradients, 20);
  EXPECT_TRUE((kept_run.q.array() == fresh_run.q.array()).all());
  EXPECT_TRUE((kept_run.p.array() == fresh_run.p.array()).all());
}

TEST(TrigonometricStep, OnTheFpuChainItIsSecondOrder) {
  // The chain's own split (stiff_projection, slow_gradient): the step with the soft springs' ∇U and
  // the stiff ones' exact flow converges at order 2 to a fine run's state at t = 1.
  const auto chain = fpu_system(3, 50.0);
  const auto run = [&](long long n) {
    ndof_state<double> y = fpu_start(3, 50.0);
    last_force<double> kept;
    for (long long j = 0; j < n; ++j) y = trigonometric_step(chain.potential(), 1.0 / static_cast<double>(n), y, kept);
    return y;
  };
  const ndof_state<double> reference = run(1 << 16);
  const auto error = [&](long long n) { return (run(n).q - reference.q).cwiseAbs().maxCoeff(); };
  const double e1 = error(200), e2 = error(400);
  EXPECT_NEAR(std::log2(e1 / e2), 2.0, 0.15) << e1 << " " << e2;
}

TEST(FpuChain, TheSplitIsThePotentialsGradient) {
  // ∇V = ω²Pq + ∇U: the split the trigonometric step takes is the chain's potential.
  const auto chain = fpu_system(3, 50.0);
  const ndof_state<double> y = fpu_start(3, 50.0);
  dense_vector<double> q = y.q;
  q(3) += 0.3;
  const auto& V = chain.potential();
  const dense_vector<double> split = 50.0 * 50.0 * V.stiff_projection(q) + V.slow_gradient(q);
  // The stiff part's terms are of order ω² = 2500: 16 eps ω² bounds the two sums' difference.
  EXPECT_LT((split - V.gradient(q)).cwiseAbs().maxCoeff(), 16 * eps<double>() * 50.0 * 50.0);
  const dense_vector<double> Pq = V.stiff_projection(q);
  EXPECT_LT((V.stiff_projection(Pq) - Pq).cwiseAbs().maxCoeff(), 4 * eps<double>());  // P² = P
}

}  // namespace
}  // namespace simpson

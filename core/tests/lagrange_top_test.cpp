// The Lagrange top's Lagrangian (lagrange_top.hpp) against an independent route: the rigid body's
// kinetic energy ½ ωᵀ I ω, with ω the body-frame angular velocity of the z-x-z Euler angles
// (Landau & Lifshitz, Mechanics, (35.1)), less the height of the centre of mass; its momenta and
// energy against automatic differentiation of L (∂L/∂v and the Legendre transform v·∂L/∂v − L), in
// double, in 50 digits and in intervals; the default top's exact constants; and the input it
// refuses, by field.

#include <simpson/lagrange_top.hpp>

#include <simpson/interval.hpp>
#include <simpson/precision.hpp>

#include <boost/math/differentiation/autodiff.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace simpson {
namespace {

template <class Real>
using top_vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;

template <class Real>
top_vector<Real> vector3(const Real& a, const Real& b, const Real& c) {
  top_vector<Real> x(3);
  x << a, b, c;
  return x;
}

/// ½(I₁(ω₁² + ω₂²) + I₃ω₃²) − Mgl cos θ with ω₁ = φ̇ sin θ sin ψ + θ̇ cos ψ, ω₂ = φ̇ sin θ cos ψ − θ̇ sin ψ,
/// ω₃ = φ̇ cos θ + ψ̇ (Landau & Lifshitz (35.1)): the Lagrangian by the rigid body's route.
template <class Real>
Real rigid_body_lagrangian(const Real& I1, const Real& I3, const Real& Mgl, const top_state<Real>& x) {
  using std::cos;
  using std::sin;
  const Real w1 = x.phi_dot * sin(x.theta) * sin(x.psi) + x.theta_dot * cos(x.psi);
  const Real w2 = x.phi_dot * sin(x.theta) * cos(x.psi) - x.theta_dot * sin(x.psi);
  const Real w3 = x.phi_dot * cos(x.theta) + x.psi_dot;
  return (I1 * (w1 * w1 + w2 * w2) + I3 * w3 * w3) / 2 - Mgl * cos(x.theta);
}

template <class Real>
top_state<Real> sample_state() {
  return {Real(7) / 10, Real(13) / 10, Real(-2) / 5, Real(3) / 10, Real(-11) / 20, Real(9) / 2};
}

template <class Real>
void expect_lagrangian_matches_rigid_body(const Real& tolerance) {
  const lagrange_top<Real> top(Real(3) / 2, Real(4) / 5, Real(5) / 4);
  const top_state<Real> x = sample_state<Real>();
  const Real L = top(vector3(x.theta, x.phi, x.psi), vector3(x.theta_dot, x.phi_dot, x.psi_dot));
  const Real expected = rigid_body_lagrangian(top.I1(), top.I3(), top.Mgl(), x);
  using std::abs;
  EXPECT_LE(abs(Real(L - expected)), tolerance) << to_string(L, 25) << " against " << to_string(expected, 25);
  EXPECT_EQ(top.dof(), 3);
}

TEST(LagrangeTop, LagrangianIsTheRigidBodysKineticEnergyLessItsPotential) {
  expect_lagrangian_matches_rigid_body<double>(8 * std::numeric_limits<double>::epsilon() * 16);
  {
    const scoped_mpfr_digits digits(50);
    expect_lagrangian_matches_rigid_body<mpfr>(mpfr("1e-47"));
  }
  const scoped_interval_digits digits(50);
  const lagrange_top<interval> top(interval(3) / 2, interval(4) / 5, interval(5) / 4);
  const top_state<interval> x = sample_state<interval>();
  const interval L = top(vector3(x.theta, x.phi, x.psi), vector3(x.theta_dot, x.phi_dot, x.psi_dot));
  const interval difference = L - rigid_body_lagrangian(top.I1(), top.I3(), top.Mgl(), x);
  EXPECT_TRUE(zero_in(difference)) << enclosure_text(difference);
  EXPECT_LT(width(difference), 1e-46);
}

/// ∂L/∂qᵢ and ∂L/∂vᵢ by forward-mode automatic differentiation (Boost's autodiff), one variable at a time.
template <class Real>
struct lagrangian_gradient {
  Real dq[3], dv[3], L;
};

template <class Real>
lagrangian_gradient<Real> autodiff_gradient(const lagrange_top<Real>& top, const top_state<Real>& x) {
  using boost::math::differentiation::make_fvar;
  using ad = boost::math::differentiation::autodiff_fvar<Real, 1>;
  const Real q[3] = {x.theta, x.phi, x.psi}, v[3] = {x.theta_dot, x.phi_dot, x.psi_dot};
  lagrangian_gradient<Real> out;
  for (int i = 0; i < 6; ++i) {
    top_vector<ad> Q(3), V(3);
    for (int k = 0; k < 3; ++k) {
      Q(k) = (i == k) ? make_fvar<Real, 1>(q[k]) : ad(q[k]);
      V(k) = (i == 3 + k) ? make_fvar<Real, 1>(v[k]) : ad(v[k]);
    }
    const ad L = top(Q, V);
    (i < 3 ? out.dq[i] : out.dv[i - 3]) = L.derivative(1);
    out.L = L.derivative(0);
  }
  return out;
}

template <class Real>
void expect_momenta_and_energy_from_autodiff(const Real& tolerance) {
  using std::abs;
  using std::cos;
  using std::sin;
  const lagrange_top<Real> top(Real(3) / 2, Real(4) / 5, Real(5) / 4);
  const top_state<Real> x = sample_state<Real>();
  const lagrangian_gradient<Real> g = autodiff_gradient(top, x);
  const top_momenta<Real> p = top.momenta(x);
  EXPECT_LE(abs(Real(g.dv[0] - p.p_theta)), tolerance);
  EXPECT_LE(abs(Real(g.dv[1] - p.p_phi)), tolerance);
  EXPECT_LE(abs(Real(g.dv[2] - p.p_psi)), tolerance);
  // φ and ψ are cyclic; ∂L/∂θ = I₁ φ̇² sin θ cos θ − I₃ ω₃ φ̇ sin θ + Mgl sin θ.
  EXPECT_EQ(g.dq[1], Real(0));
  EXPECT_EQ(g.dq[2], Real(0));
  const Real spin = x.psi_dot + x.phi_dot * cos(x.theta);
  const Real dtheta = top.I1() * x.phi_dot * x.phi_dot * sin(x.theta) * cos(x.theta) - top.I3() * spin * x.phi_dot * sin(x.theta) +
                      top.Mgl() * sin(x.theta);
  EXPECT_LE(abs(Real(g.dq[0] - dtheta)), tolerance);
  // E = v · ∂L/∂v − L.
  const Real legendre = x.theta_dot * g.dv[0] + x.phi_dot * g.dv[1] + x.psi_dot * g.dv[2] - g.L;
  EXPECT_LE(abs(Real(legendre - top.energy(x))), tolerance) << to_string(legendre, 25) << " against " << to_string(top.energy(x), 25);
}

TEST(LagrangeTop, MomentaAndEnergyAreThoseOfTheLagrangianByAutomaticDifferentiation) {
  expect_momenta_and_energy_from_autodiff<double>(64 * std::numeric_limits<double>::epsilon());
  // Boost 1.74's autodiff does not compose with mpfr_float's expression templates: cpp_bin_float_50 here.
  expect_momenta_and_energy_from_autodiff<boost::multiprecision::cpp_bin_float_50>(boost::multiprecision::cpp_bin_float_50("1e-47"));
}

TEST(LagrangeTop, TheDefaultTopHasItsStatedConstants) {
  const scoped_interval_digits digits(50);
  const lagrange_top_problem<interval> problem = nutating_lagrange_top<interval>();
  problem.top.check_state(problem.start);
  const top_momenta<interval> p = problem.top.momenta(problem.start);
  EXPECT_TRUE(zero_in(interval(p.p_psi - interval(33) / 8))) << enclosure_text(p.p_psi);
  EXPECT_TRUE(zero_in(interval(p.p_phi - interval(39) / 16))) << enclosure_text(p.p_phi);
  EXPECT_TRUE(zero_in(p.p_theta));
  const interval E = problem.top.energy(problem.start);
  EXPECT_TRUE(zero_in(interval(E - interval(1127) / 64))) << enclosure_text(E);
  EXPECT_LT(width(E), 1e-46);
  const lagrange_top_problem<double> in_double = nutating_lagrange_top<double>();
  EXPECT_NEAR(in_double.top.energy(in_double.start), 1127.0 / 64, 1e-13);
}

TEST(LagrangeTop, RefusesBadParametersAndStatesNamingTheField) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const auto message_of = [](auto&& make) -> std::string {
    try {
      make();
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(nothing thrown)";
  };
  EXPECT_NE(message_of([&] { lagrange_top<double>(0, 1, 1); }).find("'I1'"), std::string::npos);
  EXPECT_NE(message_of([&] { lagrange_top<double>(-1, 1, 1); }).find("'I1'"), std::string::npos);
  EXPECT_NE(message_of([&] { lagrange_top<double>(nan, 1, 1); }).find("'I1'"), std::string::npos);
  EXPECT_NE(message_of([&] { lagrange_top<double>(1, 0, 1); }).find("'I3'"), std::string::npos);
  EXPECT_NE(message_of([&] { lagrange_top<double>(1, inf, 1); }).find("'I3'"), std::string::npos);
  EXPECT_NE(message_of([&] { lagrange_top<double>(1, 1, inf); }).find("'Mgl'"), std::string::npos);
  EXPECT_NO_THROW(lagrange_top<double>(1, 1, -2));  // hanging below its pivot: a top too
  {
    const scoped_interval_digits digits(30);
    EXPECT_NE(message_of([&] { lagrange_top<interval>(interval(-1, 1), interval(1), interval(1)); }).find("'I1'"), std::string::npos);
  }
  const lagrange_top<double> top(1, 0.5, 1);
  const double pi = boost::math::constants::pi<double>();
  const auto check = [&](top_state<double> x) { return message_of([&] { top.check_state(x); }); };
  EXPECT_EQ(check({1, 0, 0, 0, 0.5, 8}), "(nothing thrown)");
  EXPECT_NE(check({0, 0, 0, 0, 0.5, 8}).find("'theta'"), std::string::npos);
  EXPECT_NE(check({pi, 0, 0, 0, 0.5, 8}).find("'theta'"), std::string::npos);
  EXPECT_NE(check({-0.5, 0, 0, 0, 0.5, 8}).find("'theta'"), std::string::npos);
  EXPECT_NE(check({nan, 0, 0, 0, 0.5, 8}).find("'theta'"), std::string::npos);
  EXPECT_NE(check({1, inf, 0, 0, 0.5, 8}).find("'phi'"), std::string::npos);
  EXPECT_NE(check({1, 0, nan, 0, 0.5, 8}).find("'psi'"), std::string::npos);
  EXPECT_NE(check({1, 0, 0, inf, 0.5, 8}).find("'theta_dot'"), std::string::npos);
  EXPECT_NE(check({1, 0, 0, 0, nan, 8}).find("'phi_dot'"), std::string::npos);
  EXPECT_NE(check({1, 0, 0, 0, 0.5, -inf}).find("'psi_dot'"), std::string::npos);
  {
    const scoped_interval_digits digits(30);
    const lagrange_top<interval> itop(interval(1), interval(1) / 2, interval(1));
    // An interval θ that reaches 0 is refused, though its midpoint lies inside.
    EXPECT_THROW(itop.check_state({interval(0, 1) / 1000, interval(0), interval(0), interval(0), interval(1), interval(1)}),
                 std::invalid_argument);
  }
  EXPECT_NE(message_of([&] { top(vector3(1.0, 0.0, 0.0), top_vector<double>(2)); }).find("3 entries"), std::string::npos);
}

}  // namespace
}  // namespace simpson

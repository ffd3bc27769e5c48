// The Lagrange top's exact motion enclosed (lagrange_top_exact.hpp), against an independent route:
// the rigid body integrated in 40 digits by Boost.odeint's Bulirsch–Stoer method (dense output,
// tolerance 1e-32), in the body frame: Euler's equations I ω̇ + ω × Iω = Mgl Γ × e₃ with the vertical
// Γ of the body frame read from the attitude quaternion, q̇ = ½ q ⊗ (0, ω) (Goldstein §5.5–5.7),
// and the Euler angles read from the attitude (φ and ψ also integrated, φ̇ = (ω₁Γ₁ + ω₂Γ₂)/(1 − Γ₃²),
// ψ̇ = ω₃ − φ̇Γ₃, and checked against the attitude's modulo 2π). No elliptic function and no Euler-angle
// equation of motion enter the reference. Two tops, over four or five nutation periods: the
// enclosure at 30 digits contains the reference (whose error, at most 3.8e-33 measured against the
// 60-digit enclosure, is far inside the enclosure's width, about 1e-28), and at 60 digits it is
// narrower than 1e-52 and within 1e-31 of it. The reference takes 0.7 s (both tops), once per process.
// Then the identities (u̇² = f(u), the energy and momenta), the nutation period, the flow's group
// property, and the degenerate cases: steady precession and a top converging to it, the switch
// between the two descriptions, the sleeping top's neighbourhood, and what is refused.

#include <simpson/lagrange_top_exact.hpp>

#include <simpson/precision.hpp>

#include <boost/math/special_functions/ellint_1.hpp>

#include <boost/multiprecision/mpfr.hpp>
#include <boost/numeric/odeint.hpp>

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace simpson {
/// The reference's scalar: MPFR at 40 digits, its limbs on the stack (no allocation per operation).
using top_reference_real = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<40, boost::multiprecision::allocate_stack>>;
}  // namespace simpson

// odeint reads a state's scalar through value_type, which Boost.Multiprecision's number defines as
// itself: stop the descent at the scalar.
namespace boost::numeric::odeint::detail {
template <>
struct extract_value_type<simpson::top_reference_real, void> {
  using type = simpson::top_reference_real;
};
}  // namespace boost::numeric::odeint::detail

namespace simpson {
namespace {

using ref_real = top_reference_real;
using rigid_state = std::array<ref_real, 9>;  // quaternion (w, x, y, z), body ω (3), φ, ψ

/// A top and its start as decimal text ("pi/3" for π/3), with the times it is compared at.
struct top_case {
  const char* name;
  const char *I1, *I3, *Mgl, *theta, *theta_dot, *phi_dot, *psi_dot, *phi, *psi;
  std::vector<const char*> times;
};

template <class T>
T value_of(const char* text) {
  if (std::string(text) == "pi/3") return T(boost::math::constants::pi<T>() / 3);
  return T(text);
}

const std::vector<top_case>& top_cases() {
#ifdef SIMPSON_SANITIZED
  // Under the sanitizers (-O0), the first two times of each top: a quarter of the integration.
  static const std::vector<top_case> cases{
      {"default", "1", "0.5", "1", "pi/3", "0", "0.5", "8", "0", "0", {"0.37", "1.9"}},
      {"second", "1.5", "1", "2", "1", "0.7", "-0.3", "5", "0.25", "-0.5", {"0.53", "2.2"}},
  };
#else
  static const std::vector<top_case> cases{
      // nutating_lagrange_top(): period 1.6265; the times span 4.6 periods.
      {"default", "1", "0.5", "1", "pi/3", "0", "0.5", "8", "0", "0", {"0.37", "1.9", "4.2", "7.5"}},
      // Another top, started mid-band with θ̇₀ ≠ 0 and φ₀, ψ₀ ≠ 0: period 2.0183, 4.1 periods.
      {"second", "1.5", "1", "2", "1", "0.7", "-0.3", "5", "0.25", "-0.5", {"0.53", "2.2", "5.1", "8.3"}},
  };
#endif
  return cases;
}

lagrange_top<interval> top_of(const top_case& c) {
  return lagrange_top<interval>(value_of<interval>(c.I1), value_of<interval>(c.I3), value_of<interval>(c.Mgl));
}

top_state<interval> start_of(const top_case& c) {
  return {value_of<interval>(c.theta),     value_of<interval>(c.phi),     value_of<interval>(c.psi),
          value_of<interval>(c.theta_dot), value_of<interval>(c.phi_dot), value_of<interval>(c.psi_dot)};
}

/// The rigid body in its body frame: Euler's equations with the gravity torque Mgl Γ × e₃, Γ the
/// upward vertical in the body frame (the third row of the attitude matrix), and the attitude
/// quaternion's kinematics; φ and ψ by quadrature.
struct rigid_top {
  ref_real I1, I3, Mgl;

  void operator()(const rigid_state& s, rigid_state& ds, const ref_real& /*t*/) const {
    const ref_real &w = s[0], &x = s[1], &y = s[2], &z = s[3], &o1 = s[4], &o2 = s[5], &o3 = s[6];
    ds[0] = -(x * o1 + y * o2 + z * o3) / 2;
    ds[1] = (w * o1 + y * o3 - z * o2) / 2;
    ds[2] = (w * o2 + z * o1 - x * o3) / 2;
    ds[3] = (w * o3 + x * o2 - y * o1) / 2;
    const ref_real g1 = 2 * (x * z - w * y), g2 = 2 * (y * z + w * x), g3 = 1 - 2 * (x * x + y * y);
    ds[4] = ((I1 - I3) * o2 * o3 + Mgl * g2) / I1;
    ds[5] = ((I3 - I1) * o3 * o1 - Mgl * g1) / I1;
    ds[6] = 0;
    ds[7] = (o1 * g1 + o2 * g2) / (1 - g3 * g3);
    ds[8] = o3 - ds[7] * g3;
  }
};

/// The reference at one time: the Euler angles and rates, and the attitude's own φ and ψ (modulo 2π).
struct reference_point {
  ref_real theta, phi, psi, theta_dot, phi_dot, psi_dot, attitude_phi, attitude_psi, norm_error;
};

std::vector<reference_point> rigid_body_reference(const top_case& c) {
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  const ref_real theta = value_of<ref_real>(c.theta), phi = value_of<ref_real>(c.phi), psi = value_of<ref_real>(c.psi);
  const ref_real theta_dot(c.theta_dot), phi_dot(c.phi_dot), psi_dot(c.psi_dot);
  // q = q_z(φ) ⊗ q_x(θ) ⊗ q_z(ψ), the attitude R = R_z(φ) R_x(θ) R_z(ψ).
  const ref_real cf = cos(phi / 2), sf = sin(phi / 2), ct = cos(theta / 2), st = sin(theta / 2), cp = cos(psi / 2), sp = sin(psi / 2);
  rigid_state s;
  s[0] = cf * ct * cp - sf * ct * sp;
  s[1] = cf * st * cp + sf * st * sp;
  s[2] = sf * st * cp - cf * st * sp;
  s[3] = sf * ct * cp + cf * ct * sp;
  s[4] = phi_dot * sin(theta) * sin(psi) + theta_dot * cos(psi);
  s[5] = phi_dot * sin(theta) * cos(psi) - theta_dot * sin(psi);
  s[6] = phi_dot * cos(theta) + psi_dot;
  s[7] = phi;
  s[8] = psi;
  const rigid_top system{ref_real(c.I1), ref_real(c.I3), ref_real(c.Mgl)};
  std::vector<ref_real> times{ref_real(0)};
  for (const char* t : c.times) times.emplace_back(t);
  const ref_real tolerance("1e-32");
  auto stepper = boost::numeric::odeint::bulirsch_stoer_dense_out<rigid_state, ref_real, rigid_state, ref_real,
                                                                  boost::numeric::odeint::range_algebra>(tolerance, tolerance);
  std::vector<reference_point> out;
  boost::numeric::odeint::integrate_times(stepper, system, s, times.begin(), times.end(), ref_real("0.01"),
                                          [&](const rigid_state& y, const ref_real& t) {
                                            if (t == 0) return;
                                            const ref_real &w = y[0], &x = y[1], &yy = y[2], &z = y[3];
                                            const ref_real g1 = 2 * (x * z - w * yy), g2 = 2 * (yy * z + w * x), g3 = 1 - 2 * (x * x + yy * yy);
                                            const ref_real r13 = 2 * (x * z + w * yy), r23 = 2 * (yy * z - w * x);
                                            const ref_real sin_theta = sqrt(g1 * g1 + g2 * g2);
                                            reference_point p;
                                            p.theta = atan2(sin_theta, g3);
                                            p.phi = y[7];
                                            p.psi = y[8];
                                            p.theta_dot = (y[4] * g2 - y[5] * g1) / sin_theta;
                                            p.phi_dot = (y[4] * g1 + y[5] * g2) / (sin_theta * sin_theta);
                                            p.psi_dot = y[6] - p.phi_dot * g3;
                                            p.attitude_phi = atan2(r13, -r23);
                                            p.attitude_psi = atan2(g1, g2);
                                            p.norm_error = w * w + x * x + yy * yy + z * z - 1;
                                            out.push_back(p);
                                          });
  return out;
}

/// The reference of each case, integrated once for all the tests that read it.
const std::vector<reference_point>& reference_of(const top_case& c) {
  static std::map<std::string, std::vector<reference_point>> memo;
  auto found = memo.find(c.name);
  if (found == memo.end()) found = memo.emplace(c.name, rigid_body_reference(c)).first;
  return found->second;
}

/// The six figures of a state, named.
std::array<std::pair<const char*, interval>, 6> figures(const top_state<interval>& x) {
  return {{{"theta", x.theta}, {"phi", x.phi}, {"psi", x.psi}, {"theta_dot", x.theta_dot}, {"phi_dot", x.phi_dot}, {"psi_dot", x.psi_dot}}};
}

std::array<ref_real, 6> figures(const reference_point& p) { return {p.theta, p.phi, p.psi, p.theta_dot, p.phi_dot, p.psi_dot}; }

/// The reference's value exactly, as a variable-precision MPFR number of its precision (Boost's own
/// conversion between the two MPFR types rounds through a narrower type).
boost::multiprecision::mpfr_float exactly(const ref_real& x) {
  boost::multiprecision::mpfr_float out;
  mpfr_set_prec(out.backend().data(), mpfr_get_prec(x.backend().data()));
  mpfr_set(out.backend().data(), x.backend().data(), MPFR_RNDN);
  return out;
}

// One process per test under ctest, and the reference integrated once per process: its own check
// and the 30-digit containment share one test.
TEST(LagrangeTopExact, ContainsTheRigidBodyReferenceAtThirtyDigits) {
  const ref_real two_pi = 2 * boost::math::constants::pi<ref_real>();
  for (const top_case& c : top_cases()) {
    const std::vector<reference_point>& reference = reference_of(c);
    ASSERT_EQ(reference.size(), c.times.size()) << c.name;
    for (const reference_point& p : reference) {
      using std::abs;
      EXPECT_LT(abs(p.norm_error), ref_real("1e-33")) << c.name;
      // The integrated φ and ψ are the attitude's, modulo 2π.
      for (const ref_real& d : {ref_real(p.phi - p.attitude_phi), ref_real(p.psi - p.attitude_psi)}) {
        EXPECT_LT(abs(ref_real(d - two_pi * round(ref_real(d / two_pi)))), ref_real("1e-32")) << c.name;
      }
    }
    const scoped_interval_digits digits(30);
    const lagrange_top_exact exact(top_of(c), start_of(c));
    ASSERT_EQ(exact.motion(), top_motion::nutation) << c.name;
    for (std::size_t i = 0; i < c.times.size(); ++i) {
      const top_point_enclosed y = exact.at(interval(c.times[i]));
      const auto enclosed = figures(y.state);
      const auto expected = figures(reference[i]);
      for (std::size_t k = 0; k < 6; ++k) {
        EXPECT_TRUE(lower(enclosed[k].second) <= exactly(expected[k]) && exactly(expected[k]) <= upper(enclosed[k].second))
            << c.name << ", t = " << c.times[i] << ", " << enclosed[k].first << ": " << enclosure_text(enclosed[k].second)
            << " against " << expected[k].str(40);
        EXPECT_LT(width(enclosed[k].second), 1e-24) << c.name << ", t = " << c.times[i] << ", " << enclosed[k].first;
      }
    }
  }
}

TEST(LagrangeTopExact, IsNarrowAtSixtyDigitsAndWithinTheReferencesError) {
  for (const top_case& c : top_cases()) {
    const std::vector<reference_point>& reference = reference_of(c);
    const scoped_interval_digits digits(60);
    const lagrange_top_exact exact(top_of(c), start_of(c));
    for (std::size_t i = 0; i < c.times.size(); ++i) {
      const auto enclosed = figures(exact.at(interval(c.times[i])).state);
      const auto expected = figures(reference[i]);
      for (std::size_t k = 0; k < 6; ++k) {
        EXPECT_LT(width(enclosed[k].second), 1e-52) << c.name << ", t = " << c.times[i] << ", " << enclosed[k].first << ": "
                                                     << enclosure_text(enclosed[k].second);
        const interval distance = abs(interval(enclosed[k].second - interval(exactly(expected[k]))));
        EXPECT_LT(upper(distance), 1e-31) << c.name << ", t = " << c.times[i] << ", " << enclosed[k].first << ": " << enclosure_text(distance);
      }
    }
  }
}

TEST(LagrangeTopExact, SatisfiesItsCubicAndConservesTheEnergyAndMomenta) {
  const scoped_interval_digits digits(50);
  for (const top_case& c : top_cases()) {
    const lagrange_top<interval> top = top_of(c);
    const top_state<interval> start = start_of(c);
    const lagrange_top_exact exact(top, start);
    const interval E0 = top.energy(start);
    const top_momenta<interval> p0 = top.momenta(start);
    for (const char* t : {"0", "0.8", "3.3", "11"}) {
      const top_point_enclosed y = exact.at(interval(t));
      const interval u = cos(y.state.theta), u_dot = -sin(y.state.theta) * y.state.theta_dot;
      const interval residual = exact.cubic()(u) - square_enclosed(u_dot);
      EXPECT_TRUE(zero_in(residual)) << c.name << ", t = " << t << ": " << enclosure_text(residual);
      EXPECT_LT(width(residual), 1e-44) << c.name << ", t = " << t;
      const interval dE = top.energy(y.state) - E0;
      EXPECT_TRUE(zero_in(dE)) << c.name << ", t = " << t << ": " << enclosure_text(dE);
      EXPECT_LT(width(dE), 1e-44);
      const top_momenta<interval> p = top.momenta(y.state);
      for (const interval& d : {interval(p.p_phi - p0.p_phi), interval(p.p_psi - p0.p_psi), interval(y.momenta.p_phi - p0.p_phi),
                                interval(y.momenta.p_psi - p0.p_psi), interval(y.momenta.p_theta - p.p_theta)}) {
        EXPECT_TRUE(zero_in(d)) << c.name << ", t = " << t << ": " << enclosure_text(d);
        EXPECT_LT(width(d), 1e-44);
      }
    }
  }
}

TEST(LagrangeTopExact, ReturnsAfterANutationPeriodAndTurnsAtTheRoots) {
  const scoped_interval_digits digits(50);
  const lagrange_top_problem<interval> problem = nutating_lagrange_top<interval>();
  const lagrange_top_exact exact(problem.top, problem.start);
  const interval T = exact.nutation_period();
  // The period from the roots in closed form: u₁ = 1/2 (θ̇₀ = 0), and u₂, u₃ the roots of
  // f/(2(u − 1/2)) = 2u² − (1101/64)u + 1217/128; T = 2K(m)/λ with Boost.Math's K, in 90 digits.
  using real = boost::multiprecision::mpfr_float;
  const scoped_mpfr_digits more(90);
  const real b = real(1101) / 64, c = real(1217) / 128, root = sqrt(b * b - 8 * c);
  const real u1 = real(1) / 2, u2 = (b - root) / 4, u3 = (b + root) / 4;
  const real expected = 2 * boost::math::ellint_1(sqrt((u2 - u1) / (u3 - u1))) / (sqrt(2 * (u3 - u1)) / 2);
  EXPECT_TRUE(lower(T) <= expected && expected <= upper(T)) << enclosure_text(T);
  EXPECT_LT(width(T), 1e-47);
  // Released at rest at its lowest point (θ̇₀ = 0, u₀ = u₁ = 1/2): after T/2 at u₂, after T back.
  EXPECT_TRUE(zero_in(interval(exact.u1() - interval(1) / 2))) << enclosure_text(exact.u1());
  const top_point_enclosed half = exact.at(T / 2), whole = exact.at(T), twice = exact.at(2 * T);
  EXPECT_TRUE(zero_in(interval(cos(half.state.theta) - exact.u2()))) << enclosure_text(half.state.theta);
  EXPECT_TRUE(zero_in(half.state.theta_dot)) << enclosure_text(half.state.theta_dot);
  for (const top_point_enclosed* y : {&whole, &twice}) {
    EXPECT_TRUE(zero_in(interval(y->state.theta - problem.start.theta))) << enclosure_text(y->state.theta);
    EXPECT_TRUE(zero_in(y->state.theta_dot)) << enclosure_text(y->state.theta_dot);
    EXPECT_TRUE(zero_in(interval(y->state.phi_dot - problem.start.phi_dot))) << enclosure_text(y->state.phi_dot);
    EXPECT_LT(width(y->state.theta), 1e-46);
  }
  // φ advances by the same angle in each period.
  EXPECT_TRUE(zero_in(interval(twice.state.phi - 2 * whole.state.phi))) << enclosure_text(twice.state.phi);
}

TEST(LagrangeTopExact, RestartedFromItsOwnStateFollowsTheSameMotion) {
  const scoped_interval_digits digits(50);
  for (const top_case& c : top_cases()) {
    const lagrange_top<interval> top = top_of(c);
    const lagrange_top_exact exact(top, start_of(c));
    const interval T = exact.nutation_period();
    // Restarts on both sides of each turning point, moving up and down: both branches of τ₀.
    for (const char* fraction : {"0.1", "0.3", "0.45", "0.6", "0.85"}) {
      const interval t1 = T * interval(fraction);
      const lagrange_top_exact restarted(top, exact.at(t1).state);
      ASSERT_EQ(restarted.motion(), top_motion::nutation);
      for (const char* s : {"0.4", "2.9"}) {
        const auto here = figures(restarted.at(interval(s)).state), there = figures(exact.at(interval(t1 + interval(s))).state);
        for (std::size_t k = 0; k < 6; ++k) {
          EXPECT_TRUE(zero_in(interval(here[k].second - there[k].second)))
              << c.name << ", restart at " << fraction << " T, s = " << s << ", " << here[k].first << ": " << enclosure_text(here[k].second)
              << " against " << enclosure_text(there[k].second);
          EXPECT_LT(width(here[k].second), 1e-40);
        }
      }
    }
  }
}

TEST(LagrangeTopExact, SteadyPrecessionIsItsClosedForm) {
  const scoped_interval_digits digits(50);
  const lagrange_top_problem<interval> problem = nutating_lagrange_top<interval>();
  const steady_precession_rates rates = steady_precession(problem.top, problem.start.theta, problem.start.psi_dot);
  ASSERT_TRUE(rates.fast.has_value());
  const interval c = cos(problem.start.theta);
  for (const interval& rate : {rates.slow, *rates.fast}) {
    // (I₁ − I₃) cos θ φ̇² − I₃ ψ̇ φ̇ + Mgl = 0.
    const interval residual = (problem.top.I1() - problem.top.I3()) * c * square_enclosed(rate) - problem.top.I3() * 8 * rate + problem.top.Mgl();
    EXPECT_TRUE(zero_in(residual)) << enclosure_text(residual);
    top_state<interval> start = problem.start;
    start.phi_dot = rate;
    const lagrange_top_exact exact(problem.top, start);
    EXPECT_EQ(exact.motion(), top_motion::steady_precession) << enclosure_text(rate);
    for (const char* t : {"1", "10", "100"}) {
      const top_point_enclosed y = exact.at(interval(t));
      EXPECT_TRUE(zero_in(interval(y.state.theta - problem.start.theta))) << enclosure_text(y.state.theta);
      EXPECT_TRUE(zero_in(y.state.theta_dot));
      EXPECT_TRUE(zero_in(interval(y.state.phi - rate * interval(t)))) << "t = " << t << ": " << enclosure_text(y.state.phi);
      EXPECT_TRUE(zero_in(interval(y.state.psi - 8 * interval(t)))) << "t = " << t << ": " << enclosure_text(y.state.psi);
      EXPECT_TRUE(zero_in(interval(y.state.phi_dot - rate)));
      EXPECT_TRUE(zero_in(interval(y.state.psi_dot - 8)));
      // The band's width, about the square root of the unit round-off: θ to 1e-22, φ to 1e-22 · t.
      EXPECT_LT(width(y.state.theta), 1e-22) << enclosure_text(y.state.theta);
      EXPECT_LT(width(y.state.phi), 1e-20 * std::stod(t)) << enclosure_text(y.state.phi);
    }
  }
  EXPECT_THROW(steady_precession(problem.top, problem.start.theta, interval(1)), std::domain_error);  // too slow to precess steadily
}

TEST(LagrangeTopExact, ATopNearSteadyPrecessionConvergesToIt) {
  const scoped_interval_digits digits(50);
  const lagrange_top_problem<interval> problem = nutating_lagrange_top<interval>();
  const interval slow = steady_precession(problem.top, problem.start.theta, problem.start.psi_dot).slow;
  // φ̇₀ = φ̇_s + ε: a nutation band and a drift from the steady motion, both proportional to ε
  // (measured: u₂ − u₁ = 0.39898 ε, φ(3) − 3φ̇_s = −0.27877 ε at the first order).
  for (const char* epsilon : {"1e-4", "1e-8", "1e-16"}) {
    top_state<interval> start = problem.start;
    start.phi_dot = slow + interval(epsilon);
    const lagrange_top_exact exact(problem.top, start);
    ASSERT_EQ(exact.motion(), top_motion::nutation) << epsilon;
    const interval e(epsilon);
    const interval band = interval(exact.u2() - exact.u1()) / e;
    const interval drift = interval(exact.at(interval(3)).state.phi - 3 * slow) / e;
    EXPECT_LT(abs(median(band) - 0.39898), 1e-3) << epsilon << ": " << enclosure_text(band);
    EXPECT_LT(abs(median(drift) + 0.27877), 1e-3) << epsilon << ": " << enclosure_text(drift);
  }
}

TEST(LagrangeTopExact, SwitchesToTheClosedFormWhenTheNutationIsBelowTheDigits) {
  // A nutation of width δ in u is resolved when f between the roots, about 1.9 δ², is above the
  // round-off of f: δ above about √(unit round-off). At 50 digits, ε = 1e-20 (δ = 4e-21) nutates and
  // ε = 1e-32 (δ = 4e-33) precesses within a band of 1e-24; at 80 digits ε = 1e-32 nutates again (its
  // roots, a near-double root's, to about the unit round-off over δ), and the closed form at 50 digits
  // holds the motion computed at 80.
  const auto motion_at = [](unsigned digits, const char* epsilon, const char* t) {
    const scoped_interval_digits scope(digits);
    const lagrange_top_problem<interval> problem = nutating_lagrange_top<interval>();
    top_state<interval> start = problem.start;
    start.phi_dot = steady_precession(problem.top, problem.start.theta, problem.start.psi_dot).slow + interval(epsilon);
    const lagrange_top_exact exact(problem.top, start);
    return std::pair{exact.motion(), exact.at(interval(t)).state};
  };
  EXPECT_EQ(motion_at(50, "1e-20", "1").first, top_motion::nutation);
  const auto [coarse_motion, coarse] = motion_at(50, "1e-32", "7");
  const auto [fine_motion, fine] = motion_at(80, "1e-32", "7");
  EXPECT_EQ(coarse_motion, top_motion::steady_precession);
  EXPECT_EQ(fine_motion, top_motion::nutation);
  const scoped_interval_digits digits(80);
  const auto a = figures(coarse), b = figures(fine);
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_TRUE(zero_in(interval(a[k].second - b[k].second))) << a[k].first << ": " << enclosure_text(a[k].second) << " against "
                                                              << enclosure_text(b[k].second);
    EXPECT_LT(width(a[k].second), 1e-21) << a[k].first;
    EXPECT_LT(width(b[k].second), 1e-44) << b[k].first;  // the roots of a near-double root: to about eps/δ
  }
}

TEST(LagrangeTopExact, NearTheVerticalTheFastTopSleepsAndTheSlowTopFalls) {
  const scoped_interval_digits digits(50);
  const lagrange_top_problem<interval> problem = nutating_lagrange_top<interval>();
  // Released at rest from θ₀ with ψ̇₀ = 8: ω₃ = 8, a = I₃ω₃/I₁ = 4, β = 2, and I₃²ω₃² − 4I₁Mgl = 12 > 0:
  // the sleeping top is stable, and from θ₀ → 0 the axis circles between θ₀ and θ₀ a/√(a² − 2β) =
  // (2/√3) θ₀ (the two circular modes of the linearised motion, Goldstein §5.7), while φ + ψ − ω₃t
  // vanishes like θ₀².
  EXPECT_TRUE(zero_in(interval(sleeping_stability_margin(problem.top, interval(8)) - 12)));
  const interval ratio_limit = 2 / sqrt(interval(3));
  for (const char* theta0 : {"1e-2", "1e-4", "1e-6"}) {
    const interval th0(theta0);
    const lagrange_top_exact exact(problem.top, {th0, interval(0), interval(0), interval(0), interval(0), interval(8)});
    ASSERT_EQ(exact.motion(), top_motion::nutation);
    const interval theta_max = 2 * asin(sqrt(interval((1 - exact.u1()) / 2)));
    const interval ratio = theta_max / th0;
    EXPECT_LT(upper(interval(abs(interval(ratio - ratio_limit)))), 4 * upper(interval(th0 * th0))) << theta0 << ": " << enclosure_text(ratio);
    const top_point_enclosed y = exact.at(interval(3));
    EXPECT_LE(upper(y.state.theta), upper(theta_max));
    EXPECT_GE(lower(y.state.theta), lower(th0) * (1 - 1e-30));
    EXPECT_LT(width(y.state.theta), 1e-30 * lower(th0)) << theta0 << ": " << enclosure_text(y.state.theta);
    const interval spin_drift = y.state.phi + y.state.psi - 24;
    EXPECT_LT(upper(interval(abs(spin_drift))), upper(interval(th0 * th0))) << theta0 << ": " << enclosure_text(spin_drift);
  }
  // ψ̇₀ = 1: I₃²ω₃² − 4I₁Mgl < 0, and the top released at θ₀ = 10⁻⁴ swings down to θ = 151°.
  EXPECT_LT(upper(sleeping_stability_margin(problem.top, interval(1))), 0);
  const lagrange_top_exact slow(problem.top, {interval("1e-4"), interval(0), interval(0), interval(0), interval(0), interval(1)});
  EXPECT_LT(upper(slow.u1()), -0.87);
}

TEST(LagrangeTopExact, RefusesWhatIsOutsideTheEulerChartAndATopBelowItsPivot) {
  const scoped_interval_digits digits(40);
  const lagrange_top_problem<interval> problem = nutating_lagrange_top<interval>();
  const interval pi = boost::math::constants::pi<interval>();
  top_state<interval> start = problem.start;
  start.theta = interval(0);
  EXPECT_THROW(lagrange_top_exact(problem.top, start), std::invalid_argument);
  start.theta = pi;
  EXPECT_THROW(lagrange_top_exact(problem.top, start), std::invalid_argument);
  // p_φ = p_ψ: φ̇₀ (1 + cos θ₀) = I₃ (ψ̇₀ + φ̇₀ cos θ₀)/I₁, so φ̇₀ = 16/5 at θ₀ = π/3: the axis passes
  // through the upward vertical.
  start = problem.start;
  start.phi_dot = interval(16) / 5;
  try {
    lagrange_top_exact{problem.top, start};
    ADD_FAILURE() << "an orbit through the vertical was accepted";
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("vertical"), std::string::npos) << e.what();
  }
  // A top hanging below its pivot, or without weight: refused by the exact solution, not by the Lagrangian.
  for (const char* Mgl : {"0", "-1"}) {
    const lagrange_top<interval> top(interval(1), interval(1) / 2, interval(Mgl));
    EXPECT_THROW(lagrange_top_exact(top, problem.start), std::domain_error) << Mgl;
  }
}

TEST(LagrangeTopExact, AnIntervalOfTimesHoldsEachOfItsTimes) {
  const scoped_interval_digits digits(40);
  const lagrange_top_problem<interval> problem = nutating_lagrange_top<interval>();
  const lagrange_top_exact exact(problem.top, problem.start);
  const interval span = hull(interval(5), interval(interval(5) + interval("1e-12")));
  const auto wide = figures(exact.at(span).state);
  for (const interval& t : {interval(5), interval(interval(5) + interval("1e-12"))}) {
    const auto point = figures(exact.at(t).state);
    for (std::size_t k = 0; k < 6; ++k) EXPECT_TRUE(encloses(wide[k].second, point[k].second)) << wide[k].first;
  }
  EXPECT_LT(width(wide[2].second), 1e-10);  // ψ moves by about 8e-12 across it
}

}  // namespace
}  // namespace simpson

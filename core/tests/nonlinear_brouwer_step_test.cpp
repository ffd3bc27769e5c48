// The nonlinear Simpson step in Brouwer form (nonlinear_brouwer_step.hpp): its stored coefficients
// satisfy the symplecticity conditions exactly in every precision (a naive rounding does not), it is
// Lobatto IIIA–IIIB with h folded in, it is the nonlinear Simpson step to round-off, it is Φ₃ exactly
// in rationals on the harmonic potential, and compensated summation follows the same map computed in
// higher precision more closely than plain summation.

#include <simpson/nonlinear_brouwer_step.hpp>

#include <simpson/exact_value.hpp>
#include <simpson/nonlinear_simpson_step.hpp>
#include <simpson/potential.hpp>
#include <simpson/runge_kutta_tableaux.hpp>
#include <simpson/simpson_map.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace simpson {
namespace {

using matrix3 = std::array<std::array<rational, 3>, 3>;

/// B, A, Â of the stored coefficients, exactly.
struct exact_tableau {
  std::array<rational, 3> b;
  matrix3 a, ah;
};

template <class Real>
exact_tableau exact(const brouwer_coefficients<Real>& k) {
  const rational b1 = to_rational(k.b1), b2 = to_rational(k.b2), zero(0);
  return {{b1, b2, b1},
          {{{zero, zero, zero}, {to_rational(k.a21), to_rational(k.a22), to_rational(k.a23)}, {b1, b2, b1}}},
          {{{b1, to_rational(k.ah12), zero}, {b1, to_rational(k.ah22), zero}, {b1, to_rational(k.ah32), zero}}}};
}

/// The largest |B_i Â_ij + B_j A_ji − B_i B_j|, exactly: 0 for a symplectic method.
rational symplecticity_defect(const exact_tableau& t) {
  rational worst(0);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const rational d = abs(rational(t.b[i] * t.ah[i][j] + t.b[j] * t.a[j][i] - t.b[i] * t.b[j]));
      if (d > worst) worst = d;
    }
  }
  return worst;
}

/// Steps from 1e-3 to 2 at irregular ratios, so that every rounding case of h/6 and 2h/3 occurs.
template <class Real>
std::vector<Real> steps() {
  std::vector<Real> out;
  Real h = test::ratio<Real>(1, 1000);
  for (int k = 0; k < 60; ++k, h *= test::ratio<Real>(113, 100)) out.push_back(h);
  return out;
}

template <class Real>
class BrouwerStep : public test::precision_fixture<Real> {};
TYPED_TEST_SUITE(BrouwerStep, test::all_scalars, test::scalar_names);

template <class Real>
class BrouwerStepFloating : public test::precision_fixture<Real> {};
TYPED_TEST_SUITE(BrouwerStepFloating, test::floating_scalars, test::scalar_names);

TYPED_TEST(BrouwerStep, StoredCoefficientsAreExactlySymplectic) {
  using Real = TypeParam;
  for (const Real& h : steps<Real>()) {
    const brouwer_coefficients<Real> k = simpson_brouwer_coefficients(h);
    EXPECT_EQ(symplecticity_defect(exact(k)), rational(0)) << "h = " << h;
    // One rounding (eps/2 relative), then three bits fewer (4 eps): within 4.5 eps of h/6 and 2h/3.
    EXPECT_TRUE(test::within(k.b1, Real(h / 6), Real(5 * eps<Real>() * h / 6)));
    EXPECT_TRUE(test::within(k.b2, Real(2 * h / 3), Real(5 * eps<Real>() * 2 * h / 3)));
  }
}

TYPED_TEST(BrouwerStepFloating, NaiveRoundingIsNotSymplectic) {
  using Real = TypeParam;
  // Each entry of h·(Lobatto IIIA–IIIB) rounded on its own: the conditions fail for some h. This is
  // what the exact check above guards against, and why the coefficients are built as they are.
  int broken = 0;
  for (const Real& h : steps<Real>()) {
    const Real b1 = h / 6, b2 = 2 * h / 3;
    const brouwer_coefficients<Real> naive{b1, b2, Real(5 * h / 24), Real(h / 3), Real(-h / 24), Real(-h / 6), Real(h / 3), Real(5 * h / 6)};
    if (symplecticity_defect(exact(naive)) != 0) ++broken;
  }
  EXPECT_GT(broken, 0);
}

TEST(BrouwerStepExact, IsLobattoIIIAIIIBTimesH) {
  const rational h(3, 7);
  const exact_tableau t = exact(simpson_brouwer_coefficients(h));
  const butcher_tableau<rational> a = lobatto_iiia3_tableau<rational>(), ah = lobatto_iiib3_tableau<rational>();
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(t.b[i], h * a.b[i]);
    EXPECT_EQ(t.b[i], h * ah.b[i]);
    for (std::size_t j = 0; j < 3; ++j) {
      EXPECT_EQ(t.a[i][j], h * a.a[i][j]) << i << j;
      EXPECT_EQ(t.ah[i][j], h * ah.a[i][j]) << i << j;
    }
  }
}

TYPED_TEST(BrouwerStep, OnTheHarmonicPotentialItIsPhi3) {
  using Real = TypeParam;
  // V = m ω² q²/2: the stage equation is linear, Newton's first correction solves it and the next is
  // 0 or round-off (stagnation); exactly Φ₃ in rationals.
  for (const auto& par : test::parameter_cases<Real>()) {
    if (par.omega2_h2() >= 8) continue;  // the first stable band, where the comparison is well conditioned
    const polynomial_potential<Real> V({Real(0), Real(0), Real(par.m() * par.omega() * par.omega() / 2)});
    phase_point<Real> y{test::ratio<Real>(3, 7), test::ratio<Real>(-2, 5)};
    const phase_point<Real> expected = simpson_map(par) * y;
    const brouwer_step_report report = simpson_brouwer_step(simpson_brouwer_coefficients(par.h()), par.m(), V, y);
    EXPECT_LE(report.newton_iterations, 3);
    if constexpr (is_exact_v<Real>) {
      EXPECT_EQ(y.p, expected.p);
      EXPECT_EQ(y.q, expected.q);
    } else {
      // The coefficients differ from h/6, 2h/3 by ≤ 4.5 eps, and the step is a few roundings of terms of
      // the size of |p| + m ω |q|.
      const Real scale = test::magnitude(expected.p) + par.m() * par.omega() * test::magnitude(expected.q) + Real(1);
      EXPECT_TRUE(test::within(y.p, expected.p, Real(64 * eps<Real>() * scale)));
      EXPECT_TRUE(test::within(Real(par.m() * par.omega() * y.q), Real(par.m() * par.omega() * expected.q), Real(64 * eps<Real>() * scale)));
    }
  }
}

TYPED_TEST(BrouwerStepFloating, IsTheNonlinearSimpsonStepToRoundOff) {
  using Real = TypeParam;
  const pendulum_potential<Real> V{Real(1), Real(1)};
  const Real m(1), h = test::ratio<Real>(1, 10);
  const brouwer_coefficients<Real> k = simpson_brouwer_coefficients(h);
  phase_point<Real> y{Real(0), Real(2)}, simpson = y;
  compensated_point<Real> z{y};
  for (int j = 0; j < 50; ++j) {
    simpson_brouwer_step(k, m, V, y);
    simpson_brouwer_step_compensated(k, m, V, z);
    simpson = simpson_nonlinear_step(m, h, V, simpson).state;
  }
  // 50 steps, each a few roundings of terms of size ≤ ~3 (|q| ≤ 2, |p| ≤ 2 sin 1): 64 eps per step
  // bounds the difference of the two forms of one map, with the coefficients' 4.5 eps.
  const Real bound = 50 * 64 * eps<Real>() * 3;
  EXPECT_TRUE(test::within(y.q, simpson.q, bound));
  EXPECT_TRUE(test::within(y.p, simpson.p, bound));
  EXPECT_TRUE(test::within(z.y.q, simpson.q, bound));
  EXPECT_TRUE(test::within(z.y.p, simpson.p, bound));
}

TEST(BrouwerStepDouble, CompensatedSummationFollowsTheExactMapMoreClosely) {
  // The same map (the double coefficients, exact in long double) in long double is the reference:
  // its rounding is 2¹¹ times smaller. Over 1e5 steps the compensated run's largest energy
  // difference from it is several times smaller than the plain run's (measured 2.2e-15 against
  // 1.4e-14 at h = 0.05; asserted with a margin of 2).
  const double h = 0.05;
  const brouwer_coefficients<double> k = simpson_brouwer_coefficients(h);
  const brouwer_coefficients<long double> kl = k.cast<long double>();
  const pendulum_potential<double> V{1, 1};
  const pendulum_potential<long double> Vl{1, 1};
  phase_point<double> plain{0, 1};
  compensated_point<double> compensated{plain};
  phase_point<long double> reference{0, 1};
  const auto H = [&Vl](long double p, long double q) { return p * p / 2 + Vl.value(q); };
  long double worst_plain = 0, worst_compensated = 0;
  for (int j = 0; j < 100'000; ++j) {
    simpson_brouwer_step(k, 1.0, V, plain);
    simpson_brouwer_step_compensated(k, 1.0, V, compensated);
    simpson_brouwer_step(kl, 1.0L, Vl, reference);
    const long double Href = H(reference.p, reference.q);
    worst_plain = std::max(worst_plain, std::abs(H(plain.p, plain.q) - Href));
    worst_compensated = std::max(worst_compensated, std::abs(H(compensated.y.p, compensated.y.q) - Href));
  }
  EXPECT_LT(2 * worst_compensated, worst_plain) << static_cast<double>(worst_compensated) << " " << static_cast<double>(worst_plain);
  EXPECT_GT(worst_plain, 0);  // the plain run does round
}

TEST(BrouwerStepDouble, ANonFiniteForceIsAnError) {
  struct broken_potential {
    double derivative(double q) const { return q > 0.5 ? std::numeric_limits<double>::quiet_NaN() : q; }
    double second_derivative(double) const { return 1; }
  };
  phase_point<double> y{20, 0};  // the first guess Q₂ = q + h p/2 = 1 is where V' breaks
  try {
    simpson_brouwer_step(simpson_brouwer_coefficients(0.1), 1.0, broken_potential{}, y);
    FAIL() << "no error";
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("did not stagnate"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace simpson

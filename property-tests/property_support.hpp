#pragma once
// Shared by the property tests: the precisions they run in, the (ω, h, m, p, q) generators, and
// checks that log their numbers so a shrunk counterexample explains itself.

#include <simpson/oscillator_parameters.hpp>
#include <simpson/precision.hpp>
#include <simpson/residual.hpp>

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <ostream>
#include <string>
#include <type_traits>

namespace simpson::props {

/// A scalar and, for mpfr, its run-time digits: the properties run in every one of these.
template <class Real, unsigned MpfrDigits = 0>
struct precision_policy {
  using real = Real;
  static constexpr unsigned mpfr_digits = MpfrDigits;
};

#ifndef SIMPSON_SANITIZED
using property_precisions =
    ::testing::Types<precision_policy<double>, precision_policy<long double>, precision_policy<float128>,
                     precision_policy<bin50>, precision_policy<mpfr, 40>, precision_policy<mpfr, 200>>;
#else
// Under the sanitizers, as core/tests/test_support.hpp: the built-in types and mpfr (heap limbs), once.
using property_precisions = ::testing::Types<precision_policy<double>, precision_policy<long double>, precision_policy<mpfr, 40>>;
#endif

struct precision_names {
  template <class Policy>
  static std::string GetName(int) {
    using Real = typename Policy::real;
    if constexpr (std::is_same_v<Real, double>) return "double";
    if constexpr (std::is_same_v<Real, long double>) return "long_double";
    if constexpr (std::is_same_v<Real, float128>) return "float128";
    if constexpr (std::is_same_v<Real, bin50>) return "bin50";
    if constexpr (std::is_same_v<Real, mpfr>) return "mpfr" + std::to_string(Policy::mpfr_digits);
    return "unknown";
  }
};

/// Sets mpfr's digits for the whole test, the property's cases included (they run synchronously).
template <class Policy>
class property_fixture : public ::testing::Test {
 private:
  scoped_mpfr_digits digits_{Policy::mpfr_digits ? Policy::mpfr_digits : mpfr::default_precision()};
};

/// One drawn case. Every field is a double, so it is exact in every precision and the same case
/// can be replayed in all of them; h is ωh / ω rounded to double.
struct oscillator_case {
  double m, omega, h, p, q;
  double omega_h;       // the drawn ωh
  int boundary_digits;  // k when ωh = 2√2 (1 − 10^-k), else 0
};

inline void showValue(const oscillator_case& c, std::ostream& os) {
  os.precision(17);
  os << "{m = " << c.m << ", omega = " << c.omega << ", h = " << c.h << " (omega h = " << c.omega_h
     << (c.boundary_digits ? ", 2 sqrt 2 (1 - 1e-" + std::to_string(c.boundary_digits) + ")" : std::string()) << "), p = " << c.p
     << ", q = " << c.q << "}";
}

namespace gen {

/// 0, 1, −1, 2, −2, ...: an index that RapidCheck shrinks towards 0 maps to a value that shrinks
/// towards the middle of the range [lo, hi] (lo ≤ 0 ≤ hi).
inline int zigzag(int index) { return index % 2 == 0 ? index / 2 : -(index + 1) / 2; }

/// The size is pinned to RapidCheck's nominal 100: inRange otherwise narrows its range for the early
/// (small-size) cases, and the ends of each range would be drawn far less often than their share.
inline rc::Gen<int> centred(int lo, int hi) {
  const int span = 2 * std::max(-lo, hi) + 1;
  return rc::gen::resize(100, rc::gen::suchThat(rc::gen::map(rc::gen::inRange(0, span), zigzag),
                                                [lo, hi](int k) { return k >= lo && k <= hi; }));
}

/// 10^(k/100) with k drawn centred on 0: log-uniform over [10^(lo/100), 10^(hi/100)], shrinking towards 1.
inline rc::Gen<double> decades(int lo, int hi) {
  return rc::gen::map(centred(lo, hi), [](int k) { return std::pow(10.0, k / 100.0); });
}

/// ± 10^(k/100), any sign and scale, shrinking towards 1.
inline rc::Gen<double> signed_decades(int lo, int hi) {
  return rc::gen::apply([](bool negative, double v) { return negative ? -v : v; }, rc::gen::arbitrary<bool>(), decades(lo, hi));
}

/// ωh: log-uniform from 1e-6 to 2.825 (just below 2√2 ≈ 2.8284), shrinking towards 1; or, one draw
/// in seven, hugging the boundary: 2√2 (1 − 10^-k), k = 1..14, shrinking towards k = 1. (k ≤ 14
/// keeps the margin 2.8e-14 well above the rounding of 2√2 in double, 4.4e-16.)
inline rc::Gen<std::pair<double, int>> omega_h() {
  const auto interior = rc::gen::map(centred(-6000, 451), [](int k) { return std::make_pair(std::pow(10.0, k / 1000.0), 0); });
  const auto boundary = rc::gen::map(rc::gen::resize(100, rc::gen::inRange(1, 15)), [](int k) {
    return std::make_pair(std::sqrt(8.0) * (1 - std::pow(10.0, -k)), k);
  });
  return rc::gen::weightedOneOf<std::pair<double, int>>({{6, interior}, {1, boundary}});
}

/// m from 1e-6 to 1e6, ω from 1e-3 to 1e6, q and p/(mω) of any sign from 1e-8 to 1e8.
inline rc::Gen<oscillator_case> oscillator_cases() {
  return rc::gen::apply(
      [](std::pair<double, int> theta, double m, double omega, double scaled_p, double q) {
        return oscillator_case{m, omega, theta.first / omega, scaled_p * m * omega, q, theta.first, theta.second};
      },
      omega_h(), decades(-600, 600), decades(-300, 600), signed_decades(-800, 800), signed_decades(-800, 800));
}

}  // namespace gen

/// Tags each case so the distribution shows that both ends of each range and the boundary are sampled.
inline void classify(const oscillator_case& c) {
  RC_CLASSIFY(c.boundary_digits > 0, "omega h at 2 sqrt 2 (1 - 1e-k)");
  RC_CLASSIFY(c.boundary_digits == 0 && c.omega_h < 1e-3, "omega h < 1e-3");
  RC_CLASSIFY(c.boundary_digits == 0 && c.omega_h > 1, "1 < omega h < 2.83");
  RC_CLASSIFY(c.omega < 1e-1, "omega < 0.1");
  RC_CLASSIFY(c.omega > 1e4, "omega > 1e4");
  RC_CLASSIFY(c.m < 1e-3 || c.m > 1e3, "m beyond 1e-3..1e3");
}

template <class Real>
oscillator_parameters<Real> parameters(const oscillator_case& c) {
  return {Real(c.m), Real(c.omega), Real(c.h)};
}

/// |actual − expected| ≤ bound, logging both values, the error in units of epsilon and the bound,
/// so that a failing case explains itself.
template <class Real>
bool within(const char* what, const Real& actual, const Real& expected, const Real& bound) {
  using std::abs;
  const Real error = abs(Real(actual - expected));
  const bool ok = error <= bound;
  if (!ok) {
    RC_LOG() << what << ": actual " << to_string(actual, 20) << ", expected " << to_string(expected, 20) << ", error "
             << to_string(error, 3) << " = " << to_string(Real(error / eps<Real>()), 3) << " eps, bound "
             << to_string(bound, 3) << "\n";
  }
  return ok;
}

/// A core check (residual and its bound) holds; logged like within().
template <class Real>
bool holds(const char* what, const residual_and_bound<Real>& check) {
  using std::abs;
  return within(what, check.residual, Real(0), check.bound);
}

/// 1/|1 − ω²h²/8|: the amplification near the boundary of the stable band, where 1 − x/8 cancels
/// (its absolute error stays ~eps, its relative error grows like eps/(1 − x/8)).
template <class Real>
Real boundary_amplification(const oscillator_parameters<Real>& par) {
  using std::abs;
  return 1 / abs(Real(1 - par.omega2_h2() / 8));
}

}  // namespace simpson::props

/// A property over oscillator cases, typed over the precision list: the body sees `Real`, `c`
/// (an oscillator_case, already classified) and `par` (its parameters in Real).
#define SIMPSON_PROPERTY(Suite, Name)                                                          \
  template <class Policy>                                                                      \
  void Suite##_##Name##_body(const ::simpson::props::oscillator_case& c);                      \
  TYPED_TEST(Suite, Name) {                                                                    \
    ::rc::detail::checkGTest([]() {                                                            \
      const ::simpson::props::oscillator_case c = *::simpson::props::gen::oscillator_cases(); \
      ::simpson::props::classify(c);                                                           \
      Suite##_##Name##_body<TypeParam>(c);                                                     \
    });                                                                                        \
  }                                                                                            \
  template <class Policy>                                                                      \
  void Suite##_##Name##_body(const ::simpson::props::oscillator_case& c)

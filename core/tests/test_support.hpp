#pragma once
// Shared by the core's tests: the precision list as GoogleTest types, tolerance checks that
// report errors in units of epsilon, and exact derivatives of polynomials for independent routes.

#include <simpson/oscillator_parameters.hpp>
#include <simpson/precision.hpp>

#include <gtest/gtest.h>

#include <string>
#include <type_traits>
#include <vector>

namespace simpson::test {

#ifndef SIMPSON_SANITIZED
/// Every scalar of the precision list (mpfr at mpfr_test_digits, see precision_fixture).
using all_scalars = ::testing::Types<double, long double, float128, bin50, bin100, mpfr, rational>;
/// The floating scalars: those with cos and sin.
using floating_scalars = ::testing::Types<double, long double, float128, bin50, bin100, mpfr>;
#else
/// Under the sanitizers: the built-in types (UBSan's conversion checks are theirs) and the two whose
/// values live on the heap (MPFR's limbs, cpp_int's); float128, bin50 and bin100 are fixed-size
/// values whose arithmetic is libquadmath's and Boost's, and the core's code is the same template in
/// every type. The Release suite runs all seven.
using all_scalars = ::testing::Types<double, long double, mpfr, rational>;
using floating_scalars = ::testing::Types<double, long double, mpfr>;
#endif

/// Names typed tests after the precision list ("double", "mpfr", ...) instead of Boost's type names.
struct scalar_names {
  template <class Real>
  static std::string GetName(int) {
    if constexpr (std::is_same_v<Real, double>) return "double";
    if constexpr (std::is_same_v<Real, long double>) return "long_double";
    if constexpr (std::is_same_v<Real, float128>) return "float128";
    if constexpr (std::is_same_v<Real, bin50>) return "bin50";
    if constexpr (std::is_same_v<Real, bin100>) return "bin100";
    if constexpr (std::is_same_v<Real, mpfr>) return "mpfr";
    if constexpr (std::is_same_v<Real, rational>) return "rational";
    return "unknown";
  }
};

/// Digits of mpfr in the typed tests: neither a fixed-size type's nor the 50/100 of bin50/bin100.
inline constexpr unsigned mpfr_test_digits = 60;

/// Typed fixture: sets mpfr's working digits for each test.
template <class Real>
class precision_fixture : public ::testing::Test {
 private:
  scoped_mpfr_digits digits_{mpfr_test_digits};
};

template <class Real>
Real ratio(long numerator, long denominator) {
  return Real(numerator) / Real(denominator);
}

template <class Real>
Real magnitude(const Real& v) {
  using std::abs;
  return abs(v);
}

/// |actual − expected| <= bound; for exact scalars bound must be 0 and equality is required.
/// On failure, reports both values and the error in units of epsilon.
template <class Real>
::testing::AssertionResult within(const Real& actual, const Real& expected, const Real& bound) {
  const Real error = magnitude(Real(actual - expected));
  if (is_exact_v<Real> ? actual == expected : error <= bound) return ::testing::AssertionSuccess();
  auto failure = ::testing::AssertionFailure();
  failure << "actual " << to_string(actual, 25) << ", expected " << to_string(expected, 25) << ", error "
          << to_string(error, 3) << ", bound " << to_string(bound, 3);
  if constexpr (!is_exact_v<Real>) failure << " (" << to_string(Real(error / eps<Real>()), 3) << " eps)";
  return failure;
}

/// Representative parameters with exact rational values: x = ω²h² spans both stable bands
/// (0, 8) and (12, 24), the unstable band (8, 12), and m ≠ 1 to catch a misplaced mass.
template <class Real>
std::vector<oscillator_parameters<Real>> parameter_cases() {
  return {
      {ratio<Real>(3, 2), ratio<Real>(7, 3), ratio<Real>(1, 5)},    // x = 49/225
      {Real(1), Real(1), Real(2)},                                  // x = 4
      {Real(2), Real(1), Real(2)},                                  // x = 4, m = 2
      {ratio<Real>(1, 4), Real(10), ratio<Real>(1, 40)},            // x = 1/16
      {Real(5), Real(3), Real(1)},                                  // x = 9, unstable band
      {Real(1), Real(1), Real(4)},                                  // x = 16, second stable band
      {ratio<Real>(7, 8), ratio<Real>(1, 1000), Real(3)},           // x = 9e-6, ω small
  };
}

/// f'(v) for a polynomial f of degree at most 4, exactly in rational arithmetic:
/// the central difference D(e) = f'(v) + e² f'''(v)/6 has no e⁴ term when f⁽⁵⁾ = 0, so
/// (4 D(e) − D(2e))/3 cancels the e² term and leaves f'(v) with no error.
template <class Real, class F>
Real exact_derivative_quartic(F&& f, const Real& v) {
  const Real e(1);
  const Real d1 = (f(Real(v + e)) - f(Real(v - e))) / (2 * e);
  const Real d2 = (f(Real(v + 2 * e)) - f(Real(v - 2 * e))) / (4 * e);
  return (4 * d1 - d2) / 3;
}

}  // namespace simpson::test

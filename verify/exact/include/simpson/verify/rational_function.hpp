#pragma once
// An exact symbolic scalar: a rational function N(θ)/D(θ) of one variable with rational
// coefficients, built on boost::math::tools::polynomial<cpp_rational>. The core's formulas are
// generic, so instantiating them with this type (m = ω = 1, h = θ) yields the paper's
// expressions as exact rational functions of θ = ωh, on which identities are decided by
// checking that a numerator is the zero polynomial.

#include <simpson/precision.hpp>

#include <boost/math/tools/polynomial.hpp>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace simpson::verify {

using polynomial = boost::math::tools::polynomial<rational>;

/// The polynomial with these coefficients, constant term first. (Brace-initialising Boost's
/// polynomial with two rationals would call cpp_rational's numerator/denominator constructor.)
polynomial make_polynomial(const std::vector<rational>& coefficients);

/// True for the zero polynomial (Boost normalises it to no coefficients).
bool is_zero(const polynomial& p);

/// Degree of p, or −1 for the zero polynomial.
long degree(const polynomial& p);

/// p as text in the variable `var`, highest power first: "1/576 x^4 - 11/144 x^3 + ...".
std::string to_string(const polynomial& p, const std::string& var);

/// N/D with D not the zero polynomial. Arithmetic never reduces by a common factor, so a value
/// is zero exactly when its numerator is the zero polynomial; constant denominators are folded
/// into the numerator to keep degrees small. Compiled once (rational_function.cpp): the polynomial
/// arithmetic over cpp_rational is not instantiated again in every unit that computes with it.
class rational_function {
 public:
  rational_function();
  rational_function(int c);               // NOLINT: scalar literals
  rational_function(const rational& c);  // NOLINT
  rational_function(polynomial numerator, polynomial denominator);

  /// The variable θ itself.
  static rational_function variable();

  const polynomial& numerator() const noexcept { return numerator_; }
  const polynomial& denominator() const noexcept { return denominator_; }
  bool is_zero() const;

  /// The value at θ = t; throws std::domain_error where the denominator vanishes.
  rational operator()(const rational& t) const;

  rational_function operator-() const;

  friend rational_function operator+(const rational_function& a, const rational_function& b);
  friend rational_function operator-(const rational_function& a, const rational_function& b);
  friend rational_function operator*(const rational_function& a, const rational_function& b);
  friend rational_function operator/(const rational_function& a, const rational_function& b);
  rational_function& operator+=(const rational_function& b);
  rational_function& operator-=(const rational_function& b);
  rational_function& operator*=(const rational_function& b);
  rational_function& operator/=(const rational_function& b);

  /// Equal as functions: N_a D_b − N_b D_a is the zero polynomial.
  friend bool operator==(const rational_function& a, const rational_function& b);
  friend bool operator!=(const rational_function& a, const rational_function& b);

 private:
  void fold_constant_denominator();

  polynomial numerator_;
  polynomial denominator_;
};

rational_function operator+(const rational_function& a, const rational_function& b);
rational_function operator-(const rational_function& a, const rational_function& b);
rational_function operator*(const rational_function& a, const rational_function& b);
rational_function operator/(const rational_function& a, const rational_function& b);
bool operator==(const rational_function& a, const rational_function& b);
bool operator!=(const rational_function& a, const rational_function& b);

/// The coefficients c_k of f(θ) = Σ c_k θ^k for k < up_to, when f's denominator is a monomial
/// c θ^d (a Laurent polynomial; negative powers are reported with k < 0). Throws
/// std::invalid_argument otherwise.
std::vector<std::pair<long, rational>> laurent_coefficients(const rational_function& f, long up_to);

}  // namespace simpson::verify

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
inline polynomial make_polynomial(const std::vector<rational>& coefficients) {
  return polynomial(coefficients.begin(), coefficients.end());
}

/// True for the zero polynomial (Boost normalises it to no coefficients).
inline bool is_zero(const polynomial& p) {
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (p[k] != 0) return false;
  }
  return true;
}

/// Degree of p, or −1 for the zero polynomial.
inline long degree(const polynomial& p) {
  for (std::size_t k = p.size(); k-- > 0;) {
    if (p[k] != 0) return static_cast<long>(k);
  }
  return -1;
}

/// p as text in the variable `var`, highest power first: "1/576 x^4 - 11/144 x^3 + ...".
inline std::string to_string(const polynomial& p, const std::string& var) {
  std::string out;
  for (long k = degree(p); k >= 0; --k) {
    const rational& c = p[static_cast<std::size_t>(k)];
    if (c == 0) continue;
    const bool negative = c < 0;
    const rational magnitude = negative ? rational(-c) : c;
    out += out.empty() ? (negative ? "-" : "") : (negative ? " - " : " + ");
    const bool unit = magnitude == 1 && k > 0;
    if (!unit) out += simpson::to_string(magnitude);
    if (k > 0) out += (unit ? "" : " ") + var + (k > 1 ? "^" + std::to_string(k) : "");
  }
  return out.empty() ? "0" : out;
}

/// N/D with D not the zero polynomial. Arithmetic never reduces by a common factor, so a value
/// is zero exactly when its numerator is the zero polynomial; constant denominators are folded
/// into the numerator to keep degrees small.
class rational_function {
 public:
  rational_function() : numerator_(), denominator_(one()) {}
  rational_function(int c) : numerator_(constant(rational(c))), denominator_(one()) {}  // NOLINT: scalar literals
  rational_function(const rational& c) : numerator_(constant(c)), denominator_(one()) {}  // NOLINT
  rational_function(polynomial numerator, polynomial denominator)
      : numerator_(std::move(numerator)), denominator_(std::move(denominator)) {
    if (verify::is_zero(denominator_)) throw std::domain_error("simpson::verify::rational_function: zero denominator");
    fold_constant_denominator();
  }

  /// The variable θ itself.
  static rational_function variable() { return {make_polynomial({rational(0), rational(1)}), one()}; }

  const polynomial& numerator() const noexcept { return numerator_; }
  const polynomial& denominator() const noexcept { return denominator_; }
  bool is_zero() const { return verify::is_zero(numerator_); }

  /// The value at θ = t; throws std::domain_error where the denominator vanishes.
  rational operator()(const rational& t) const {
    const rational d = denominator_.evaluate(t);
    if (d == 0) throw std::domain_error("simpson::verify::rational_function: pole at " + simpson::to_string(t));
    return numerator_.evaluate(t) / d;
  }

  rational_function operator-() const { return {polynomial() - numerator_, denominator_}; }

  friend rational_function operator+(const rational_function& a, const rational_function& b) {
    if (a.denominator_ == b.denominator_) return {a.numerator_ + b.numerator_, a.denominator_};
    return {a.numerator_ * b.denominator_ + b.numerator_ * a.denominator_, a.denominator_ * b.denominator_};
  }
  friend rational_function operator-(const rational_function& a, const rational_function& b) { return a + (-b); }
  friend rational_function operator*(const rational_function& a, const rational_function& b) {
    return {a.numerator_ * b.numerator_, a.denominator_ * b.denominator_};
  }
  friend rational_function operator/(const rational_function& a, const rational_function& b) {
    if (b.is_zero()) throw std::domain_error("simpson::verify::rational_function: division by zero");
    return {a.numerator_ * b.denominator_, a.denominator_ * b.numerator_};
  }
  rational_function& operator+=(const rational_function& b) { return *this = *this + b; }
  rational_function& operator-=(const rational_function& b) { return *this = *this - b; }
  rational_function& operator*=(const rational_function& b) { return *this = *this * b; }
  rational_function& operator/=(const rational_function& b) { return *this = *this / b; }

  /// Equal as functions: N_a D_b − N_b D_a is the zero polynomial.
  friend bool operator==(const rational_function& a, const rational_function& b) { return (a - b).is_zero(); }
  friend bool operator!=(const rational_function& a, const rational_function& b) { return !(a == b); }

 private:
  static polynomial one() { return make_polynomial({rational(1)}); }
  static polynomial constant(const rational& c) {
    if (c == 0) return polynomial();
    return make_polynomial({c});
  }
  void fold_constant_denominator() {
    if (degree(denominator_) == 0 && denominator_[0] != 1) {
      numerator_ /= denominator_[0];
      denominator_ = one();
    }
  }

  polynomial numerator_;
  polynomial denominator_;
};

/// The coefficients c_k of f(θ) = Σ c_k θ^k for k < up_to, when f's denominator is a monomial
/// c θ^d (a Laurent polynomial; negative powers are reported with k < 0). Throws
/// std::invalid_argument otherwise.
inline std::vector<std::pair<long, rational>> laurent_coefficients(const rational_function& f, long up_to) {
  const polynomial& d = f.denominator();
  const long shift = degree(d);
  for (long k = 0; k < shift; ++k) {
    if (d[static_cast<std::size_t>(k)] != 0) {
      throw std::invalid_argument("laurent_coefficients: denominator is not a monomial");
    }
  }
  const rational scale = d[static_cast<std::size_t>(shift)];
  std::vector<std::pair<long, rational>> out;
  const polynomial& n = f.numerator();
  for (long k = 0; k <= degree(n); ++k) {
    const long power = k - shift;
    if (power >= up_to) break;
    const rational c = n[static_cast<std::size_t>(k)];
    if (c != 0) out.emplace_back(power, c / scale);
  }
  return out;
}

}  // namespace simpson::verify

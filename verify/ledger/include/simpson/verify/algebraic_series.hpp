#pragma once
// Exact arithmetic for the peers whose coefficients are irrational: power series in θ = ωh,
// truncated after θ^order, with coefficients in the number field Q(r), r^degree = radicand
// (Q(√3) for 2-stage Gauss–Legendre, Q(∛2) for Yoshida's composition). The core's generic
// formulas run on it unchanged, so Φ_peer − Φ₃ is known exactly term by term.

#include <simpson/partitioned_runge_kutta.hpp>
#include <simpson/precision.hpp>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace simpson::verify {

/// a_0 + a_1 r + ... + a_{n−1} r^{n−1} with r^n = radicand (x^n − radicand irreducible over Q).
template <int Degree, int Radicand>
class number_field_element {
 public:
  number_field_element(long v = 0) { c_.fill(rational(0)); c_[0] = rational(v); }  // NOLINT: literals mix in
  number_field_element(const rational& v) { c_.fill(rational(0)); c_[0] = v; }    // NOLINT
  /// r itself.
  static number_field_element root() {
    number_field_element e;
    e.c_[1] = 1;
    return e;
  }
  const rational& operator[](int k) const { return c_[static_cast<std::size_t>(k)]; }
  bool is_zero() const {
    for (const rational& v : c_) {
      if (v != 0) return false;
    }
    return true;
  }
  friend number_field_element operator+(number_field_element a, const number_field_element& b) {
    for (std::size_t k = 0; k < Degree; ++k) a.c_[k] += b.c_[k];
    return a;
  }
  friend number_field_element operator-(number_field_element a, const number_field_element& b) {
    for (std::size_t k = 0; k < Degree; ++k) a.c_[k] -= b.c_[k];
    return a;
  }
  friend number_field_element operator*(const number_field_element& a, const number_field_element& b) {
    number_field_element out;
    for (std::size_t i = 0; i < Degree; ++i) {
      for (std::size_t j = 0; j < Degree; ++j) {
        const rational term = a.c_[i] * b.c_[j];
        if (i + j < Degree) {
          out.c_[i + j] += term;
        } else {
          out.c_[i + j - Degree] += term * Radicand;
        }
      }
    }
    return out;
  }
  /// a⁻¹ from the linear system (multiplication by a) x = 1. Throws std::domain_error for 0.
  number_field_element inverse() const {
    if (is_zero()) throw std::domain_error("number_field_element: division by zero");
    std::vector<std::vector<rational>> M(Degree, std::vector<rational>(Degree, rational(0)));
    for (std::size_t j = 0; j < Degree; ++j) {
      number_field_element basis;
      basis.c_[0] = 0;
      basis.c_[j] = 1;
      const number_field_element column = *this * basis;
      for (std::size_t i = 0; i < Degree; ++i) M[i][j] = column.c_[i];
    }
    std::vector<rational> one(Degree, rational(0));
    one[0] = 1;
    const std::vector<rational> x = simpson::solve_linear(M, one);
    number_field_element out;
    for (std::size_t k = 0; k < Degree; ++k) out.c_[k] = x[k];
    return out;
  }
  friend bool operator==(const number_field_element& a, const number_field_element& b) { return (a - b).is_zero(); }
  friend bool operator!=(const number_field_element& a, const number_field_element& b) { return !(a == b); }
  /// "a + b·r + c·r²" with r written as `root_name`, zero terms left out.
  std::string to_string(const std::string& root_name) const {
    std::string out;
    for (std::size_t k = 0; k < Degree; ++k) {
      if (c_[k] == 0) continue;
      std::string term = simpson::to_string(c_[k]);
      if (k >= 1) term = "(" + term + ")" + root_name + (k == 2 ? "^2" : "");
      out += (out.empty() ? "" : " + ") + term;
    }
    return out.empty() ? "0" : out;
  }

 private:
  std::array<rational, Degree> c_;
};

/// Σ_{k ≤ order} a_k θ^k with coefficients in Field; products and quotients are truncated.
template <class Field, int Order>
class truncated_series {
 public:
  truncated_series(long v = 0) { c_.fill(Field(0)); c_[0] = Field(v); }        // NOLINT: literals mix in
  truncated_series(const rational& v) { c_.fill(Field(0)); c_[0] = Field(v); }  // NOLINT
  truncated_series(const Field& v) { c_.fill(Field(0)); c_[0] = v; }            // NOLINT
  static truncated_series variable() {
    truncated_series s;
    s.c_[1] = Field(1);
    return s;
  }
  static constexpr int order() { return Order; }
  const Field& operator[](int k) const { return c_[static_cast<std::size_t>(k)]; }
  bool is_zero() const {
    for (const Field& v : c_) {
      if (!v.is_zero()) return false;
    }
    return true;
  }
  truncated_series operator-() const { return truncated_series(0) - *this; }
  friend truncated_series operator+(truncated_series a, const truncated_series& b) {
    for (std::size_t k = 0; k <= Order; ++k) a.c_[k] = a.c_[k] + b.c_[k];
    return a;
  }
  friend truncated_series operator-(truncated_series a, const truncated_series& b) {
    for (std::size_t k = 0; k <= Order; ++k) a.c_[k] = a.c_[k] - b.c_[k];
    return a;
  }
  friend truncated_series operator*(const truncated_series& a, const truncated_series& b) {
    truncated_series out;
    for (std::size_t i = 0; i <= Order; ++i) {
      if (a.c_[i].is_zero()) continue;
      for (std::size_t j = 0; i + j <= Order; ++j) out.c_[i + j] = out.c_[i + j] + a.c_[i] * b.c_[j];
    }
    return out;
  }
  /// a / b for b with a non-zero constant term (a unit of the series ring); throws std::domain_error otherwise.
  friend truncated_series operator/(const truncated_series& a, const truncated_series& b) {
    if (b.c_[0].is_zero()) throw std::domain_error("truncated_series: division by a series without constant term");
    const Field inverse = b.c_[0].inverse();
    truncated_series out;
    for (std::size_t k = 0; k <= Order; ++k) {
      Field v = a.c_[k];
      for (std::size_t j = 1; j <= k; ++j) v = v - b.c_[j] * out.c_[k - j];
      out.c_[k] = v * inverse;
    }
    return out;
  }
  truncated_series& operator+=(const truncated_series& b) { return *this = *this + b; }
  truncated_series& operator-=(const truncated_series& b) { return *this = *this - b; }
  truncated_series& operator*=(const truncated_series& b) { return *this = *this * b; }
  truncated_series& operator/=(const truncated_series& b) { return *this = *this / b; }
  friend bool operator==(const truncated_series& a, const truncated_series& b) { return (a - b).is_zero(); }
  friend bool operator!=(const truncated_series& a, const truncated_series& b) { return !(a == b); }

 private:
  std::array<Field, Order + 1> c_;
};

}  // namespace simpson::verify

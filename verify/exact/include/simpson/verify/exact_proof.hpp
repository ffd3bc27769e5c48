#pragma once
// Tools of the exact proofs: symbolic parameters, the grid lemma for low-degree dependence on
// further variables, Sturm sequences for signs on intervals, and truncated Taylor polynomials.

#include <simpson/oscillator_parameters.hpp>
#include <simpson/verify/rational_function.hpp>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace simpson::verify {

using symbolic = rational_function;

/// m = ω = 1 and h = θ: by dimensional scaling (claim lemma-dimensional-scaling) every result
/// of the paper is a function of θ = ωh once p is scaled by mω and t by ω.
inline oscillator_parameters<symbolic> unit_oscillator_in_theta() {
  return {symbolic(1), symbolic(1), symbolic::variable()};
}

/// Grid lemma: a polynomial in k variables of degree at most d_i in variable i that vanishes on
/// the grid {0, ..., d_1} × ... × {0, ..., d_k} is the zero polynomial (induction on k: a
/// one-variable polynomial of degree ≤ d with d + 1 roots is zero; any d + 1 distinct values
/// serve). `f` maps a grid point to a symbolic value or a rational; returns the first point where
/// it is not zero, or nothing when the lemma proves f ≡ 0.
template <class F>
std::optional<std::vector<int>> first_nonzero_on_grid(const std::vector<int>& degree_bounds, F&& f) {
  const std::size_t variables = degree_bounds.size();
  std::vector<int> point(variables, 0);
  while (true) {
    const auto value = f(point);
    bool zero;
    if constexpr (std::is_same_v<std::decay_t<decltype(value)>, symbolic>) {
      zero = value.is_zero();
    } else {
      zero = value == 0;
    }
    if (!zero) return point;
    std::size_t k = 0;
    while (k < variables && point[k] == degree_bounds[k]) point[k++] = 0;
    if (k == variables) return std::nullopt;
    ++point[k];
  }
}

/// The Sturm sequence p, p', −rem(p, p'), ... of a non-constant polynomial.
inline std::vector<polynomial> sturm_sequence(const polynomial& p) {
  std::vector<polynomial> seq{p, p.prime()};
  while (degree(seq.back()) > 0) {
    const polynomial remainder = boost::math::tools::quotient_remainder(seq[seq.size() - 2], seq.back()).second;
    if (is_zero(remainder)) break;
    seq.push_back(polynomial() - remainder);
  }
  return seq;
}

inline std::size_t sign_changes(const std::vector<polynomial>& seq, const rational& at) {
  std::size_t changes = 0;
  int previous = 0;
  for (const polynomial& s : seq) {
    const rational v = s.evaluate(at);
    const int sign = v > 0 ? 1 : (v < 0 ? -1 : 0);
    if (sign == 0) continue;
    if (previous != 0 && sign != previous) ++changes;
    previous = sign;
  }
  return changes;
}

/// Sturm's theorem: the number of distinct real roots of p in (a, b], for a < b with p(a) ≠ 0.
inline std::size_t count_real_roots(const polynomial& p, const rational& a, const rational& b) {
  const std::vector<polynomial> seq = sturm_sequence(p);
  return sign_changes(seq, a) - sign_changes(seq, b);
}

/// Cauchy's bound: every root of p lies in [−B, B], B = 1 + max |a_k / a_n|.
inline rational cauchy_root_bound(const polynomial& p) {
  const long n = degree(p);
  rational largest = 0;
  for (long k = 0; k < n; ++k) {
    rational r = p[static_cast<std::size_t>(k)] / p[static_cast<std::size_t>(n)];
    if (r < 0) r = -r;
    if (r > largest) largest = r;
  }
  return 1 + largest;
}

/// Taylor polynomial of cos θ through θ^degree_bound, exact.
inline polynomial cos_taylor(int degree_bound) {
  std::vector<rational> c(static_cast<std::size_t>(degree_bound) + 1, rational(0));
  rational term = 1;  // θ^k / k!
  for (int k = 0; k <= degree_bound; ++k) {
    if (k > 0) term /= k;
    if (k % 2 == 0) c[static_cast<std::size_t>(k)] = (k / 2) % 2 == 0 ? term : rational(-term);
  }
  return polynomial(c.begin(), c.end());
}

/// Taylor polynomial of sin θ through θ^degree_bound, exact.
inline polynomial sin_taylor(int degree_bound) {
  std::vector<rational> c(static_cast<std::size_t>(degree_bound) + 1, rational(0));
  rational term = 1;
  for (int k = 0; k <= degree_bound; ++k) {
    if (k > 0) term /= k;
    if (k % 2 == 1) c[static_cast<std::size_t>(k)] = ((k - 1) / 2) % 2 == 0 ? term : rational(-term);
  }
  return polynomial(c.begin(), c.end());
}

/// "c0 + c1 θ^k1 + ..." of Laurent coefficients, for evidence.
inline std::string series_to_string(const std::vector<std::pair<long, rational>>& terms, const std::string& var) {
  std::string out;
  for (const auto& [power, c] : terms) {
    const bool negative = c < 0;
    out += out.empty() ? (negative ? "-" : "") : (negative ? " - " : " + ");
    out += simpson::to_string(negative ? rational(-c) : c);
    if (power != 0) out += " " + var + (power != 1 ? "^" + std::to_string(power) : "");
  }
  return out.empty() ? "0" : out;
}

}  // namespace simpson::verify

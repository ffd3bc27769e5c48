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
oscillator_parameters<symbolic> unit_oscillator_in_theta();

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
std::vector<polynomial> sturm_sequence(const polynomial& p);

/// Sign changes of the sequence at a point (zeros skipped).
std::size_t sign_changes(const std::vector<polynomial>& seq, const rational& at);

/// Sturm's theorem: the number of distinct real roots of p in (a, b], for a < b with p(a) ≠ 0.
std::size_t count_real_roots(const polynomial& p, const rational& a, const rational& b);

/// Cauchy's bound: every root of p lies in [−B, B], B = 1 + max |a_k / a_n|.
rational cauchy_root_bound(const polynomial& p);

/// Taylor polynomial of cos θ through θ^degree_bound, exact.
polynomial cos_taylor(int degree_bound);

/// Taylor polynomial of sin θ through θ^degree_bound, exact.
polynomial sin_taylor(int degree_bound);

/// "c0 + c1 θ^k1 + ..." of Laurent coefficients, for evidence.
std::string series_to_string(const std::vector<std::pair<long, rational>>& terms, const std::string& var);

}  // namespace simpson::verify

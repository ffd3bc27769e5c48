#pragma once
// Krawczyk's test for a system F(x) = 0 in n unknowns (the one-equation test is in
// interval_newton.hpp). For a box X, its midpoint x̃ and a point matrix C ≈ F'(x̃)⁻¹,
//   K(X) = x̃ − C F(x̃) + (I − C F'(X)) (X − x̃);
// if every component of K(X) lies strictly inside X's, F has exactly one zero in X, and it lies in
// K(X) (Krawczyk 1969; Moore, Kearfott & Cloud, Introduction to Interval Analysis, SIAM 2009,
// §8.2; C only has to be invertible for the uniqueness, which follows from the contraction).
// Then X ← X ∩ K(X) narrows the enclosure. Used for the Lobatto IIIA–IIIB stage values.
// Pulls in MPFI (link simpson::interval).

#include <simpson/interval.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace simpson {

using interval_vector = std::vector<interval>;
using interval_matrix = std::vector<interval_vector>;

/// What the test found: whether it proved a unique zero in the stated box, the box, and the
/// enclosure of that zero (the box itself when nothing was proved).
struct krawczyk_system_result {
  bool proved = false;
  interval_vector box;
  interval_vector enclosure;
  int iterations = 0;
};

namespace detail {
/// The midpoint of each entry, as a point interval.
inline interval_vector midpoints(const interval_vector& x) {
  interval_vector out;
  out.reserve(x.size());
  for (const interval& v : x) out.emplace_back(median(v));
  return out;
}

/// An approximate inverse of the midpoint matrix of J, as point intervals (Gauss–Jordan with
/// partial pivoting on the midpoints' magnitudes): none when a pivot's midpoint is 0.
inline std::optional<interval_matrix> approximate_inverse(const interval_matrix& J) {
  const std::size_t n = J.size();
  interval_matrix a(n, interval_vector(2 * n, interval(0)));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < n; ++k) a[i][k] = interval(median(J[i][k]));
    a[i][n + i] = interval(1);
  }
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    for (std::size_t i = col + 1; i < n; ++i) {
      if (abs(median(a[i][col])) > abs(median(a[pivot][col]))) pivot = i;
    }
    if (median(a[pivot][col]) == 0) return std::nullopt;
    std::swap(a[col], a[pivot]);
    const interval scale(median(a[col][col]));
    for (interval& v : a[col]) v = interval(median(interval(v / scale)));
    for (std::size_t i = 0; i < n; ++i) {
      if (i == col) continue;
      const interval factor = a[i][col];
      for (std::size_t k = 0; k < 2 * n; ++k) a[i][k] = interval(median(interval(a[i][k] - factor * a[col][k])));
    }
  }
  interval_matrix inverse(n, interval_vector(n));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < n; ++k) inverse[i][k] = a[i][n + k];
  }
  return inverse;
}
}  // namespace detail

/// Krawczyk's test for F on `box` (F: interval_vector → interval_vector, DF: interval_vector →
/// interval_matrix, both evaluated on intervals), then up to `narrowing` steps X ← X ∩ K(X).
template <class F, class DF>
krawczyk_system_result krawczyk_system(F&& f, DF&& df, const interval_vector& box, int narrowing = 8) {
  const std::size_t n = box.size();
  krawczyk_system_result out{false, box, box, 0};
  interval_vector X = box;
  for (int step = 0; step <= narrowing; ++step) {
    const interval_vector centre = detail::midpoints(X);
    const auto C = detail::approximate_inverse(df(centre));
    if (!C) return out;
    const interval_vector at_centre = f(centre);
    const interval_matrix J = df(X);
    interval_vector K(n);
    for (std::size_t i = 0; i < n; ++i) {
      interval k = centre[i];
      for (std::size_t j = 0; j < n; ++j) k -= (*C)[i][j] * at_centre[j];
      for (std::size_t j = 0; j < n; ++j) {
        interval entry(i == j ? 1 : 0);  // (I − C J)_ij
        for (std::size_t l = 0; l < n; ++l) entry -= (*C)[i][l] * J[l][j];
        k += entry * (X[j] - centre[j]);
      }
      K[i] = k;
    }
    if (step == 0) {
      for (std::size_t i = 0; i < n; ++i) {
        if (!proper_subset(K[i], X[i])) return out;  // nothing proved on this box
      }
      out.proved = true;
    }
    bool narrower = false;
    for (std::size_t i = 0; i < n; ++i) {
      const interval narrowed = intersect(X[i], K[i]);
      narrower = narrower || width(narrowed) < width(X[i]);
      X[i] = narrowed;
    }
    out.iterations = step + 1;
    if (!narrower) break;
  }
  out.enclosure = X;
  return out;
}

/// A box around an approximate zero x̃ of F (Newton's iterations on midpoints from x0, the linear
/// solve by the approximate inverse), of radius 2^(−bits/2)(1 + |x̃_i|) in each component: half
/// the working digits around the approximation.
template <class F, class DF>
interval_vector box_around_newton(F&& f, DF&& df, interval_vector x, int iterations = 60) {
  const std::size_t n = x.size();
  x = detail::midpoints(x);
  for (int step = 0; step < iterations; ++step) {
    const auto C = detail::approximate_inverse(df(x));
    if (!C) break;
    const interval_vector r = f(x);
    interval_vector next(n);
    bool moved = false;
    for (std::size_t i = 0; i < n; ++i) {
      interval v = x[i];
      for (std::size_t j = 0; j < n; ++j) v -= (*C)[i][j] * r[j];
      next[i] = interval(median(v));
      moved = moved || !(median(next[i]) == median(x[i]));
    }
    x = next;
    if (!moved) break;
  }
  interval_vector box(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int bits = static_cast<int>(mpfi_get_prec(x[i].backend().data()));
    const interval radius = ldexp(interval(1), -bits / 2) * (1 + abs(x[i]));
    box[i] = interval(lower(interval(x[i] - radius)), upper(interval(x[i] + radius)));
  }
  return box;
}

}  // namespace simpson

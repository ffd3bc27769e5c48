#pragma once
// Existence and uniqueness proved, not assumed: Krawczyk's interval Newton test for one equation
// F(x) = 0. For a box X, a point x̃ in it and any c ≠ 0,
//   K(X) = x̃ − F(x̃)/c + (1 − F'(X)/c)(X − x̃);
// if K(X) lies strictly inside X, F has exactly one zero in X, and it lies in K(X) (Krawczyk 1969;
// Moore, Kearfott & Cloud, Introduction to Interval Analysis, SIAM 2009, §8.2). Then X ∩ K(X) is
// iterated to narrow the enclosure. Used for the internal node q_m of the nonlinear Simpson step.
// Pulls in MPFI (link simpson::interval).

#include <simpson/interval.hpp>
#include <simpson/nonlinear_simpson_step.hpp>

#include <string>

namespace simpson {

/// What the test found: whether it proved a unique zero in the stated box, the box, and the
/// enclosure of that zero (the box itself when nothing was proved).
struct krawczyk_result {
  bool proved = false;
  interval box;
  interval enclosure;
  int iterations = 0;
};

/// Krawczyk's test for F on `box` (F and its derivative dF evaluated on intervals), then up to
/// `narrowing` steps X ← X ∩ K(X). x̃ is the box's midpoint, c = F'(x̃)'s midpoint.
template <class F, class DF>
krawczyk_result krawczyk(F&& f, DF&& df, const interval& box, int narrowing = 8) {
  krawczyk_result out{false, box, box, 0};
  interval X = box;
  for (int k = 0; k <= narrowing; ++k) {
    const interval centre(median(X));
    // Compared as a point (its median): an uncertain interval comparison throws from Boost's noexcept
    // operator== (an abort), and a derivative that is not finite proves nothing.
    const auto c_point = median(df(centre));
    if (!boost::multiprecision::isfinite(c_point) || c_point == 0) return out;
    const interval c(c_point);
    const interval K = centre - f(centre) / c + (1 - df(X) / c) * (X - centre);
    if (k == 0) {
      if (!proper_subset(K, X)) return out;  // nothing proved on this box
      out.proved = true;
    }
    const interval narrowed = intersect(X, K);
    out.iterations = k + 1;
    if (width(narrowed) >= width(X)) break;
    X = narrowed;
  }
  out.enclosure = X;
  return out;
}

/// The nonlinear Simpson step enclosed: its internal node x = q_m proved to exist and be unique in a
/// stated box by krawczyk(), then the update (simpson_update) in interval arithmetic. The box is
/// centred on a few Newton iterations on midpoints from x₀ = q + h p/(2m), of radius
/// 2^(−bits/2) (1 + |x̃|): half the working digits around the approximate node.
struct enclosed_simpson_step {
  krawczyk_result node;
  phase_point<interval> state;
};

template <class Potential>
enclosed_simpson_step simpson_enclosed_step(const interval& m, const interval& h, const Potential& V,
                                                       const phase_point<interval>& y) {
  const interval force_q = V.derivative(y.q);
  const auto F = [&](const interval& x) { return simpson_internal_residual(m, h, y.q, y.p, x, force_q, interval(V.derivative(x))); };
  const auto dF = [&](const interval& x) { return interval(m + h * h / 24 * V.second_derivative(x)); };
  // Newton on midpoints, compared as points (medians), not as intervals: a midpoint made an interval
  // again may round outward to two ulps, and comparing two such intervals is uncertain, which Boost's
  // noexcept operator== turns into an abort (seen at 6 digits). A midpoint that is not finite stops
  // the iteration; Krawczyk decides either way.
  interval approx(median(interval(y.q + h * y.p / (2 * m))));
  for (int k = 0; k < 60; ++k) {
    const auto slope = median(dF(approx));
    if (!boost::multiprecision::isfinite(slope) || slope == 0) break;
    const auto next = median(interval(approx - F(approx) / interval(slope)));
    if (!boost::multiprecision::isfinite(next) || next == median(approx)) break;
    approx = interval(next);
  }
  const int bits = static_cast<int>(mpfi_get_prec(approx.backend().data()));
  const interval radius = ldexp(interval(1), -bits / 2) * (1 + abs(approx));
  const interval box(lower(interval(approx - radius)), upper(interval(approx + radius)));
  enclosed_simpson_step out{krawczyk(F, dF, box), y};
  if (out.node.proved) {
    const auto force = [&](const interval& v) { return interval(V.derivative(v)); };
    out.state = simpson_update(m, h, force, y.q, y.p, force_q, interval(V.derivative(out.node.enclosure)));
  }
  return out;
}

}  // namespace simpson

#pragma once
// Beyond the paper: a variational step of discrete_lagrangian_step.hpp enclosed, for any Lagrangian
// of lagrangian.hpp written over intervals. The step's system R(y_1, …, y_{m−1}) = 0 (with the
// interval AutoDiff derivatives of L) is given to Krawczyk's test (krawczyk_system.hpp) on a box
// around Newton's approximation on midpoints; with the start (q_j, p_j) an interval box, K(X) is
// evaluated over the whole start box, so a proof covers every start in it. Proved: the enclosure X
// of the control points contains the exact step's, and p_{j+1} = ∂L_d/∂y_{m−1} evaluated over X
// encloses its momentum. Not proved: `proved` is false and `state` is the start (not to be used).
// Pulls in MPFI (link simpson::interval).

#include <simpson/discrete_lagrangian_step.hpp>
#include <simpson/krawczyk_system.hpp>

#include <cstddef>
#include <vector>

namespace simpson {

struct enclosed_lagrangian_step {
  bool proved = false;
  krawczyk_system_result points;  // the unknown control points y_1, …, y_{m−1}, stacked
  ndof_state<interval> state;
};

/// The step of discretisation d from the enclosed start y (every state in it is covered).
template <class Lag>
enclosed_lagrangian_step discrete_lagrangian_enclosed_step(const discretisation<interval>& d, const Lag& L, const interval& h,
                                                           const ndof_state<interval>& y) {
  const std::size_t m = d.times.size();
  const Eigen::Index n = y.q.size();
  const auto points_of = [&](const interval_vector& x) {
    std::vector<dense_vector<interval>> points(m, y.q);
    for (std::size_t c = 1; c < m; ++c) {
      for (Eigen::Index i = 0; i < n; ++i) points[c](i) = x[(c - 1) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i)];
    }
    return points;
  };
  const auto R = [&](const interval_vector& x) {  // (p_j + ∂L_d/∂y_0, ∂L_d/∂y_c for 0 < c < m − 1)
    const auto s = detail::assemble(L, d, h, points_of(x), false);
    interval_vector r(x.size());
    for (std::size_t a = 0; a + 1 < m; ++a) {
      for (Eigen::Index i = 0; i < n; ++i) {
        r[a * static_cast<std::size_t>(n) + static_cast<std::size_t>(i)] = a == 0 ? interval(y.p(i) + s.gradient[a](i)) : s.gradient[a](i);
      }
    }
    return r;
  };
  const auto dR = [&](const interval_vector& x) {
    const auto s = detail::assemble(L, d, h, points_of(x), true);
    interval_matrix J(x.size(), interval_vector(x.size()));
    for (std::size_t i = 0; i < x.size(); ++i) {
      for (std::size_t k = 0; k < x.size(); ++k) J[i][k] = s.jacobian(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k));
    }
    return J;
  };
  interval_vector start((m - 1) * static_cast<std::size_t>(n));  // y_c = q_j: Newton on midpoints goes from there
  for (std::size_t c = 1; c < m; ++c) {
    for (Eigen::Index i = 0; i < n; ++i) start[(c - 1) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i)] = y.q(i);
  }
  // The box around Newton's approximation, widened by the start's own spread (the control points
  // move about as much as q_j, and as h p_j/M): where the start is a box, the zeros fill a set that
  // wide. Where the box is, is a heuristic; what it holds is Krawczyk's proof.
  interval_vector box = box_around_newton(R, dR, start);
  using real = boost::multiprecision::mpfr_float;
  real spread(0);
  for (Eigen::Index i = 0; i < n; ++i) {
    const real s = real(width(y.q(i))) + real(upper(interval(abs(h)))) * real(width(y.p(i)));
    if (s > spread) spread = s;
  }
  for (interval& b : box) b = interval(real(real(lower(b)) - 4 * spread), real(real(upper(b)) + 4 * spread));
  enclosed_lagrangian_step out{false, krawczyk_system(R, dR, box), y};
  out.proved = out.points.proved;
  if (out.proved) {
    const auto points = points_of(out.points.enclosure);
    out.state.q = points[m - 1];
    out.state.p = detail::assemble(L, d, h, points, false).gradient[m - 1];  // p_{j+1} = ∂L_d/∂y_{m−1}
  }
  return out;
}

/// Simpson's step enclosed.
template <class Lag>
enclosed_lagrangian_step simpson_enclosed_lagrangian_step(const Lag& L, const interval& h, const ndof_state<interval>& y) {
  return discrete_lagrangian_enclosed_step(simpson_discretisation<interval>(), L, h, y);
}

}  // namespace simpson

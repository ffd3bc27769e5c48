#pragma once
// Partitioned Runge–Kutta methods on the oscillator, run by their stages: the peers of the
// Simpson scheme (implicit midpoint, Gauss–Legendre, Lobatto IIIA–IIIB, classic RK4) share this
// one stage algorithm and differ only in their tableaux (runge_kutta_tableaux.hpp).

#include <simpson/one_step_map.hpp>
#include <simpson/oscillator_parameters.hpp>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace simpson {

/// A Butcher tableau (A, b) with s stages; A is s × s, row-major.
template <class Real>
struct butcher_tableau {
  std::vector<std::vector<Real>> a;
  std::vector<Real> b;
  std::size_t stages() const noexcept { return b.size(); }
};

namespace detail {
/// Gaussian elimination on the leading n × n block of M (any row-indexable storage: vectors, or
/// arrays for small systems). Pivot: the largest |entry| for ordered numbers, the largest certainly
/// non-zero one for intervals, the first non-zero for symbolic scalars (exact, so any non-zero pivot is as good). Leaves the solution in x[0..n).
/// Throws std::domain_error when M is singular.
template <class Real, class Matrix, class Vector>
void eliminate(Matrix& M, Vector& r, Vector& x, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t pivot = n;
    for (std::size_t i = k; i < n; ++i) {
      if constexpr (is_interval_v<Real>) {
        // Intervals: the entry of largest mignitude, certainly non-zero (an ambiguous comparison throws).
        const auto smallest = [](const Real& v) { return lower(Real(abs(v))); };
        if (smallest(M[i][k]) > 0 && (pivot == n || smallest(M[i][k]) > smallest(M[pivot][k]))) pivot = i;
      } else if constexpr (detail::is_ordered_number_v<Real>) {
        using std::abs;
        if (M[i][k] != 0 && (pivot == n || abs(M[i][k]) > abs(M[pivot][k]))) pivot = i;
      } else {
        if (pivot == n && M[i][k] != Real(0)) pivot = i;
      }
    }
    if (pivot == n) throw std::domain_error("simpson::partitioned_runge_kutta: the stage equations are singular");
    std::swap(M[k], M[pivot]);
    std::swap(r[k], r[pivot]);
    for (std::size_t i = k + 1; i < n; ++i) {
      const Real factor = M[i][k] / M[k][k];
      for (std::size_t j = k; j < n; ++j) M[i][j] -= factor * M[k][j];
      r[i] -= factor * r[k];
    }
  }
  for (std::size_t k = n; k-- > 0;) {
    Real sum = r[k];
    for (std::size_t j = k + 1; j < n; ++j) sum -= M[k][j] * x[j];
    x[k] = sum / M[k][k];
  }
}
}  // namespace detail

/// Solves M x = r by Gaussian elimination (detail::eliminate). Throws std::domain_error when M is
/// singular.
template <class Real>
std::vector<Real> solve_linear(std::vector<std::vector<Real>> M, std::vector<Real> r) {
  std::vector<Real> x(r.size(), Real(0));
  detail::eliminate<Real>(M, r, x, r.size());
  return x;
}

namespace detail {
/// The step from its stages Q_k (P_i = p_j − h Σ_k â_ik m ω² Q_k; then the weights' sums), shared by
/// the step that solves for the stages and the one that has them factored.
template <class Real, class Stages>
phase_point<Real> step_from_stages(const oscillator_parameters<Real>& par, const butcher_tableau<Real>& for_q, const butcher_tableau<Real>& for_p,
                                   const phase_point<Real>& y, const Stages& Q) {
  const std::size_t s = for_q.stages();
  const Real& m = par.m();
  const Real& h = par.h();
  const Real stiffness = m * par.omega() * par.omega();
  phase_point<Real> next = y;
  for (std::size_t i = 0; i < s; ++i) {
    Real P_i = y.p;
    for (std::size_t k = 0; k < s; ++k) P_i -= h * for_p.a[i][k] * stiffness * Q[k];
    next.q += h * for_q.b[i] * P_i / m;
    next.p -= h * for_p.b[i] * stiffness * Q[i];
  }
  return next;
}

/// The step below with its system in the given storage (at least s × s).
template <class Real, class Matrix, class Vector>
phase_point<Real> prk_linear_step(const oscillator_parameters<Real>& par, const butcher_tableau<Real>& for_q,
                                  const butcher_tableau<Real>& for_p, const phase_point<Real>& y, Matrix& M, Vector& rhs, Vector& Q) {
  const std::size_t s = for_q.stages();
  const Real& m = par.m();
  const Real& h = par.h();
  const Real x = par.omega2_h2();
  for (std::size_t i = 0; i < s; ++i) {
    Real row_sum(0);
    for (std::size_t k = 0; k < s; ++k) {
      row_sum += for_q.a[i][k];
      Real product(0);
      for (std::size_t l = 0; l < s; ++l) product += for_q.a[i][l] * for_p.a[l][k];
      M[i][k] = (i == k ? Real(1) : Real(0)) + x * product;
    }
    rhs[i] = y.q;
    rhs[i] += h / m * y.p * row_sum;
  }
  eliminate<Real>(M, rhs, Q, s);
  return step_from_stages(par, for_q, for_p, y, Q);
}
}  // namespace detail

/// One step of the partitioned Runge–Kutta method with tableau `for_q` for q' = p/m and `for_p`
/// for p' = −m ω² q (both with s stages):
///   Q_i = q_j + h Σ_k a_ik P_k / m,   P_i = p_j − h Σ_k â_ik m ω² Q_k,
///   q_{j+1} = q_j + h Σ_i b_i P_i / m,   p_{j+1} = p_j − h Σ_i b̂_i m ω² Q_i.
/// The stage equations are linear here; eliminating P gives (I + ω²h² A Â) Q = q_j 1 + (h/m) p_j A 1,
/// solved at every step as an implementation for a general linear force would. Explicit tableaux
/// make that system triangular. Throws std::domain_error when it is singular.
template <class Real>
phase_point<Real> partitioned_runge_kutta_step(const oscillator_parameters<Real>& par, const butcher_tableau<Real>& for_q,
                                               const butcher_tableau<Real>& for_p, const phase_point<Real>& y) {
  const std::size_t s = for_q.stages();
  if (s == 0 || for_p.stages() != s) {
    throw std::invalid_argument("simpson::partitioned_runge_kutta_step: the tableaux must have the same number of stages");
  }
  // The system in fixed-size arrays up to 4 stages (every tableau of the project: no allocation per
  // step in double), in vectors beyond; the same operations in the same order either way.
  if (s <= 4) {
    std::array<std::array<Real, 4>, 4> M{};
    std::array<Real, 4> rhs{}, Q{};
    return detail::prk_linear_step(par, for_q, for_p, y, M, rhs, Q);
  }
  std::vector<std::vector<Real>> M(s, std::vector<Real>(s, Real(0)));
  std::vector<Real> rhs(s), Q(s);
  return detail::prk_linear_step(par, for_q, for_p, y, M, rhs, Q);
}

/// The stage system of a linear force, (I + ω²h² A Â) Q = q_j 1 + (h/m) p_j A 1, solved once for
/// q_j = 1, p_j = 0 (u) and for q_j = 0, p_j = 1 (v): at every step Q = q_j u + p_j v, and no system is
/// solved. What a user writes for a linear force (its stage matrix is constant: factor it once);
/// factored_prk_step is then the same map as partitioned_runge_kutta_step.
template <class Real>
struct factored_linear_stages {
  std::vector<Real> u, v;
};

template <class Real>
factored_linear_stages<Real> factor_linear_stages(const oscillator_parameters<Real>& par, const butcher_tableau<Real>& for_q,
                                                  const butcher_tableau<Real>& for_p) {
  const std::size_t s = for_q.stages();
  if (s == 0 || for_p.stages() != s) throw std::invalid_argument("simpson::factor_linear_stages: the tableaux must have the same number of stages");
  const Real x = par.omega2_h2();
  std::vector<std::vector<Real>> M(s, std::vector<Real>(s, Real(0)));
  std::vector<Real> ones(s, Real(1)), a_ones(s, Real(0));
  for (std::size_t i = 0; i < s; ++i) {
    for (std::size_t k = 0; k < s; ++k) {
      a_ones[i] += for_q.a[i][k];
      Real product(0);
      for (std::size_t l = 0; l < s; ++l) product += for_q.a[i][l] * for_p.a[l][k];
      M[i][k] = (i == k ? Real(1) : Real(0)) + x * product;
    }
    a_ones[i] *= par.h() / par.m();
  }
  return {solve_linear(M, ones), solve_linear(M, a_ones)};
}

/// One step with the stages of factor_linear_stages (at most 4): Q_k = q_j u_k + p_j v_k, then as
/// partitioned_runge_kutta_step.
template <class Real>
phase_point<Real> factored_prk_step(const oscillator_parameters<Real>& par, const butcher_tableau<Real>& for_q, const butcher_tableau<Real>& for_p,
                                    const factored_linear_stages<Real>& f, const phase_point<Real>& y) {
  const std::size_t s = for_q.stages();
  if (s > 4) throw std::invalid_argument("simpson::factored_prk_step: at most 4 stages");
  std::array<Real, 4> Q{};  // the stages, once per step (no allocation)
  for (std::size_t k = 0; k < s; ++k) Q[k] = y.q * f.u[k] + y.p * f.v[k];
  return detail::step_from_stages(par, for_q, for_p, y, Q);
}

/// The one-step matrix of the method: its step applied to (1, 0) and (0, 1) (exact for a linear map).
template <class Real>
one_step_matrix<Real> partitioned_runge_kutta_map(const oscillator_parameters<Real>& par, const butcher_tableau<Real>& for_q,
                                                  const butcher_tableau<Real>& for_p) {
  const phase_point<Real> from_p = partitioned_runge_kutta_step(par, for_q, for_p, phase_point<Real>{Real(1), Real(0)});
  const phase_point<Real> from_q = partitioned_runge_kutta_step(par, for_q, for_p, phase_point<Real>{Real(0), Real(1)});
  return {from_p.p, from_q.p, from_p.q, from_q.q};
}

}  // namespace simpson

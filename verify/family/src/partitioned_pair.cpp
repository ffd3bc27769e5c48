// The partitioned Runge–Kutta pair of an interpolatory rule, in the nodal quotient ring
// (partitioned_pair.hpp).

#include <simpson/verify/partitioned_pair.hpp>

#include "family_algebra.hpp"

#include <stdexcept>
#include <vector>

namespace simpson::verify::family_detail {
namespace {

using matrix = std::vector<std::vector<rational>>;  // [row][column]

matrix multiply(const matrix& a, const matrix& b) {
  const std::size_t n = a.size();
  matrix out(n, std::vector<rational>(n, rational(0)));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t l = 0; l < n; ++l) {
      if (a[i][l] == 0) continue;
      for (std::size_t j = 0; j < n; ++j) out[i][j] += a[i][l] * b[l][j];
    }
  }
  return out;
}

matrix transpose(const matrix& a) {
  matrix out(a.size(), std::vector<rational>(a.size()));
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < a.size(); ++j) out[j][i] = a[i][j];
  }
  return out;
}

/// The inverse of a nonsingular rational matrix (Gauss–Jordan).
matrix inverse(matrix a) {
  const std::size_t n = a.size();
  matrix out(n, std::vector<rational>(n, rational(0)));
  for (std::size_t i = 0; i < n; ++i) out[i][i] = 1;
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    while (pivot < n && a[pivot][col] == 0) ++pivot;
    if (pivot == n) throw std::logic_error("partitioned_pair_map: the rule's Gram matrix is singular");
    std::swap(a[pivot], a[col]);
    std::swap(out[pivot], out[col]);
    const rational scale = a[col][col];
    for (std::size_t j = 0; j < n; ++j) a[col][j] /= scale, out[col][j] /= scale;
    for (std::size_t i = 0; i < n; ++i) {
      if (i == col || a[i][col] == 0) continue;
      const rational f = a[i][col];
      for (std::size_t j = 0; j < n; ++j) a[i][j] -= f * a[col][j], out[i][j] -= f * out[col][j];
    }
  }
  return out;
}

/// Solves M x = r for rational functions of θ (elimination, each entry kept reduced).
std::vector<rational_function> solve(std::vector<std::vector<rational_function>> m, std::vector<rational_function> r) {
  const std::size_t n = m.size();
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    while (pivot < n && m[pivot][col].is_zero()) ++pivot;
    if (pivot == n) throw std::logic_error("partitioned_pair_map: the stage equations are singular");
    std::swap(m[pivot], m[col]);
    std::swap(r[pivot], r[col]);
    for (std::size_t i = col + 1; i < n; ++i) {
      if (m[i][col].is_zero()) continue;
      const rational_function f = reduced(m[i][col] / m[col][col]);
      for (std::size_t j = col; j < n; ++j) m[i][j] = reduced(m[i][j] - f * m[col][j]);
      r[i] = reduced(r[i] - f * r[col]);
    }
  }
  std::vector<rational_function> x(n);
  for (std::size_t i = n; i-- > 0;) {
    rational_function sum = r[i];
    for (std::size_t j = i + 1; j < n; ++j) sum = sum - m[i][j] * x[j];
    x[i] = reduced(sum / m[i][i]);
  }
  return x;
}

}  // namespace

one_step_matrix<rational_function> partitioned_pair_map(const quadrature_rule& rule) {
  std::vector<rational> nodal = nodal_polynomial(rule);
  while (nodal.back() == 0) nodal.pop_back();
  const std::size_t k = nodal.size() - 1;
  for (rational& c : nodal) c /= nodal.back();
  const std::vector<rational> mu = quadrature_moments(rule, static_cast<int>(2 * k));

  // A in the basis 1, τ, …, τ^{k−1} of R: column m is ∫₀^τ s^m ds = τ^{m+1}/(m+1), reduced.
  matrix A(k, std::vector<rational>(k, rational(0)));
  for (std::size_t m = 0; m < k; ++m) {
    const std::vector<rational> column = power_modulo(nodal, k, m + 1);
    for (std::size_t i = 0; i < k; ++i) A[i][m] = column[i] / rational(static_cast<long>(m + 1));
  }
  // The Gram matrix of (x, y) ↦ Q[x y]: μ_{m+n}; A* = G⁻¹ Aᵀ G; Ā = 1·bᵀ − A* (1 = the constant, bᵀ = μ_0 … μ_{k−1}).
  matrix G(k, std::vector<rational>(k));
  for (std::size_t m = 0; m < k; ++m) {
    for (std::size_t n = 0; n < k; ++n) G[m][n] = mu[m + n];
  }
  const matrix adjoint = multiply(multiply(inverse(G), transpose(A)), G);
  matrix Abar(k, std::vector<rational>(k));
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t j = 0; j < k; ++j) Abar[i][j] = (i == 0 ? mu[j] : rational(0)) - adjoint[i][j];
  }

  // (I + θ² A Ā) Q = q 1 + θ p A 1; P = p 1 − θ Ā Q; q' = q + θ μ·P, p' = p − θ μ·Q.
  const rational_function theta(make_polynomial({rational(0), rational(1)}), make_polynomial({rational(1)}));
  const matrix AAbar = multiply(A, Abar);
  std::vector<std::vector<rational_function>> M(k, std::vector<rational_function>(k));
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t j = 0; j < k; ++j) M[i][j] = rational_function(i == j ? rational(1) : rational(0)) + theta * theta * rational_function(AAbar[i][j]);
  }
  const auto step = [&](const rational& p, const rational& q) {
    std::vector<rational_function> rhs(k, rational_function(0));
    for (std::size_t i = 0; i < k; ++i) rhs[i] = rational_function(i == 0 ? q : rational(0)) + theta * rational_function(p * A[i][0]);
    const std::vector<rational_function> Q = solve(M, rhs);
    std::vector<rational_function> P(k);
    for (std::size_t i = 0; i < k; ++i) {
      rational_function sum(i == 0 ? p : rational(0));
      for (std::size_t j = 0; j < k; ++j) sum = sum - theta * rational_function(Abar[i][j]) * Q[j];
      P[i] = reduced(sum);
    }
    rational_function q_next(q), p_next(p);
    for (std::size_t i = 0; i < k; ++i) {
      q_next = q_next + theta * rational_function(mu[i]) * P[i];
      p_next = p_next - theta * rational_function(mu[i]) * Q[i];
    }
    return std::pair{reduced(p_next), reduced(q_next)};
  };
  const auto [p_from_p, q_from_p] = step(rational(1), rational(0));
  const auto [p_from_q, q_from_q] = step(rational(0), rational(1));
  return {p_from_p, p_from_q, q_from_p, q_from_q};
}

}  // namespace simpson::verify::family_detail

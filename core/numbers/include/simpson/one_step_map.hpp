#pragma once
// Linear one-step maps on the state y = (p, q): y_{j+1} = Φ y_j, written with the paper's
// entry names of Section 7, Φ = ((α, β), (γ, δ)).

#include <simpson/scalar_traits.hpp>
#include <simpson/residual.hpp>

#include <cmath>

#include <array>
#include <cstddef>

namespace simpson {

/// A point of phase space: momentum p and state q.
template <class Real>
struct phase_point {
  Real p;
  Real q;
};

/// The matrix of a linear one-step map on (p, q): p' = α p + β q, q' = γ p + δ q.
template <class Real>
struct one_step_matrix {
  Real alpha;
  Real beta;
  Real gamma;
  Real delta;
};

/// Φ y (an operator rather than a function named apply, which ADL would confuse with std::apply).
template <class Real>
phase_point<Real> operator*(const one_step_matrix<Real>& phi, const phase_point<Real>& y) {
  return {phi.alpha * y.p + phi.beta * y.q, phi.gamma * y.p + phi.delta * y.q};
}

/// det Φ = αδ − βγ; equal to 1 exactly when the map is symplectic (one degree of freedom).
template <class Real>
Real determinant(const one_step_matrix<Real>& phi) {
  return phi.alpha * phi.delta - phi.beta * phi.gamma;
}

/// det Φ − 1 for a map whose entries each carry at most `roundings` roundings: αδ − βγ then errs
/// by at most 2·roundings·eps·(|αδ| + |βγ|), the condition factor of the difference.
template <class Real>
residual_and_bound<Real> unit_determinant_check(const one_step_matrix<Real>& phi, int roundings) {
  using std::abs;
  const Real condition = abs(Real(phi.alpha * phi.delta)) + abs(Real(phi.beta * phi.gamma));
  return {Real(determinant(phi) - 1), Real(2 * roundings * eps<Real>() * condition)};
}

/// Φᵀ J Φ − J with J = ((0, 1), (−1, 0)), computed as the products (not through det Φ): zero
/// exactly when Φ preserves the symplectic form. Entries (1,1), (1,2), (2,1), (2,2).
template <class Real>
std::array<Real, 4> symplectic_form_defect(const one_step_matrix<Real>& phi) {
  const Real P[2][2] = {{phi.alpha, phi.beta}, {phi.gamma, phi.delta}};
  const int J[2][2] = {{0, 1}, {-1, 0}};
  std::array<Real, 4> defect{Real(0), Real(0), Real(0), Real(0)};
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      Real sum(0);
      for (int k = 0; k < 2; ++k) {
        for (int l = 0; l < 2; ++l) {
          if (J[k][l] != 0) sum += J[k][l] * P[k][i] * P[l][j];
        }
      }
      defect[static_cast<std::size_t>(2 * i + j)] = sum - J[i][j];
    }
  }
  return defect;
}

/// The matrix product A B (the map "B, then A").
template <class Real>
one_step_matrix<Real> operator*(const one_step_matrix<Real>& a, const one_step_matrix<Real>& b) {
  return {a.alpha * b.alpha + a.beta * b.gamma, a.alpha * b.beta + a.beta * b.delta,
          a.gamma * b.alpha + a.delta * b.gamma, a.gamma * b.beta + a.delta * b.delta};
}

}  // namespace simpson

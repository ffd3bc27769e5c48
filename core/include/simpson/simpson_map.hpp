#pragma once
// Section 6: the one-step map Φ_3 of the symplectic Simpson scheme on (p, q).

#include <simpson/one_step_map.hpp>
#include <simpson/oscillator_parameters.hpp>
#include <simpson/precision_types.hpp>
#include <simpson/residual.hpp>

namespace simpson {

namespace detail {

/// (Phi3) for a signed step h (the formula is a rational function of h; only the public entry
/// points validate their parameters).
template <class Real>
one_step_matrix<Real> simpson_map_with_step(const Real& m, const Real& omega, const Real& h) {
  const Real x = omega * omega * h * h;
  const Real denominator = 1 + x / 24;
  const Real diagonal = (1 - 11 * x / 24 + x * x / 48) / denominator;
  return {diagonal, -m * omega * omega * h * (1 - x / 12) * (1 - x / 24) / denominator,
          h / m * (1 - x / 8) / denominator, diagonal};
}

}  // namespace detail

/// (Phi3) Φ_3 = 1/(1 + ω²h²/24) ×
///   ( (1 − 11ω²h²/24 + ω⁴h⁴/48,  −m ω² h (1 − ω²h²/12)(1 − ω²h²/24)),
///     ((h/m)(1 − ω²h²/8),          1 − 11ω²h²/24 + ω⁴h⁴/48) ).
/// Regular for every h > 0, including ω²h² = 8 where q_m and p_r are not.
template <class Real>
one_step_matrix<Real> simpson_map(const oscillator_parameters<Real>& par) {
  return detail::simpson_map_with_step(par.m(), par.omega(), par.h());
}

/// det Φ_3 − 1: each entry carries at most 14 roundings (1 − ω²h²/8 entering γ as an absolute eps).
template <class Real>
residual_and_bound<Real> simpson_map_determinant_check(const oscillator_parameters<Real>& par) {
  return unit_determinant_check(simpson_map(par), 14);
}

/// (Phi3) at the step −h: the map that runs the scheme backwards in time. Time reversibility is
/// Φ_3(h) Φ_3(−h) = I.
template <class Real>
one_step_matrix<Real> simpson_map_backward(const oscillator_parameters<Real>& par) {
  return detail::simpson_map_with_step(par.m(), par.omega(), Real(-par.h()));
}

// Instantiated once per precision in core/src/simpson_map.cpp.
#define SIMPSON_MAP_TEMPLATES(prefix, Real)                                                                      \
  prefix template one_step_matrix<Real> detail::simpson_map_with_step(const Real&, const Real&, const Real&);    \
  prefix template one_step_matrix<Real> simpson_map(const oscillator_parameters<Real>&);                         \
  prefix template residual_and_bound<Real> simpson_map_determinant_check(const oscillator_parameters<Real>&);    \
  prefix template one_step_matrix<Real> simpson_map_backward(const oscillator_parameters<Real>&);
#define SIMPSON_MAP_EXTERN(Real) SIMPSON_MAP_TEMPLATES(extern, Real)
SIMPSON_FOR_EACH_PRECISION_TYPE(SIMPSON_MAP_EXTERN)

}  // namespace simpson

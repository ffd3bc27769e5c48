#pragma once
// Section 2: the classical (Newmark / implicit midpoint) scheme for the harmonic oscillator as a
// one-step map on (p, q).

#include <simpson/one_step_map.hpp>
#include <simpson/oscillator_parameters.hpp>
#include <simpson/precision_types.hpp>
#include <simpson/residual.hpp>

namespace simpson {

/// (matrice-symplectique-ordre-2)
/// Φ = 1/(1 + ω²h²/4) ((1 − ω²h²/4, −m ω² h), (h/m, 1 − ω²h²/4)).
template <class Real>
one_step_matrix<Real> newmark_map(const oscillator_parameters<Real>& par) {
  const Real x = par.omega2_h2();
  const Real denominator = 1 + x / 4;
  const Real diagonal = (1 - x / 4) / denominator;
  return {diagonal, -par.m() * par.omega() * par.omega() * par.h() / denominator, par.h() / par.m() / denominator,
          diagonal};
}

/// det Φ − 1: each entry carries at most 8 roundings.
template <class Real>
residual_and_bound<Real> newmark_map_determinant_check(const oscillator_parameters<Real>& par) {
  return unit_determinant_check(newmark_map(par), 8);
}

/// The two relations (systeme-dynamique-discret-ordre-2) that Φ solves, as residuals:
/// first  p_{j+1} − p_j + m ω² h (q_{j+1} + q_j)/2,
/// second (q_{j+1} − q_j)/h − (p_{j+1} + p_j)/(2m); both zero along the scheme.
template <class Real>
phase_point<Real> newmark_system_residual(const oscillator_parameters<Real>& par, const phase_point<Real>& y,
                                          const phase_point<Real>& y_next) {
  const Real& m = par.m();
  const Real& h = par.h();
  return {y_next.p - y.p + m * par.omega() * par.omega() * h * (y_next.q + y.q) / 2,
          (y_next.q - y.q) / h - (y_next.p + y.p) / (2 * m)};
}

// Instantiated once per precision in core/src/newmark_map.cpp.
#define SIMPSON_NEWMARK_MAP_TEMPLATES(prefix, Real)                                                           \
  prefix template one_step_matrix<Real> newmark_map(const oscillator_parameters<Real>&);                      \
  prefix template residual_and_bound<Real> newmark_map_determinant_check(const oscillator_parameters<Real>&); \
  prefix template phase_point<Real> newmark_system_residual(const oscillator_parameters<Real>&,               \
                                                            const phase_point<Real>&, const phase_point<Real>&);
#define SIMPSON_NEWMARK_MAP_EXTERN(Real) SIMPSON_NEWMARK_MAP_TEMPLATES(extern, Real)
SIMPSON_FOR_EACH_PRECISION_TYPE(SIMPSON_NEWMARK_MAP_EXTERN)

}  // namespace simpson

#pragma once
// Section 6: the one-step map Φ_3 of the symplectic Simpson scheme on (p, q).

#include <simpson/one_step_map.hpp>
#include <simpson/oscillator_parameters.hpp>

namespace simpson {

/// (Phi3) Φ_3 = 1/(1 + ω²h²/24) ×
///   ( (1 − 11ω²h²/24 + ω⁴h⁴/48,  −m ω² h (1 − ω²h²/12)(1 − ω²h²/24)),
///     ((h/m)(1 − ω²h²/8),          1 − 11ω²h²/24 + ω⁴h⁴/48) ).
/// Regular for every h > 0, including ω²h² = 8 where q_m and p_r are not.
template <class Real>
one_step_matrix<Real> simpson_map(const oscillator_parameters<Real>& par) {
  const Real& m = par.m();
  const Real& h = par.h();
  const Real x = par.omega2_h2();
  const Real denominator = 1 + x / 24;
  const Real diagonal = (1 - 11 * x / 24 + x * x / 48) / denominator;
  return {diagonal, -m * par.omega() * par.omega() * h * (1 - x / 12) * (1 - x / 24) / denominator,
          h / m * (1 - x / 8) / denominator, diagonal};
}

}  // namespace simpson

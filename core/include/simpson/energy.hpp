#pragma once
// The two energies of the paper: the exact one (Section 2) and the discrete one that the
// symplectic Simpson scheme conserves (Section 7).

#include <simpson/one_step_map.hpp>
#include <simpson/oscillator_parameters.hpp>

namespace simpson {

/// (HH-exact) H = p²/(2m) + m ω² q²/2; conserved exactly by the Newmark map.
template <class Real>
Real energy(const oscillator_parameters<Real>& par, const phase_point<Real>& y) {
  return y.p * y.p / (2 * par.m()) + par.m() * par.omega() * par.omega() * y.q * y.q / 2;
}

/// (hamiltonien-discret)
/// H_d = p²/(2m) + m ω² (1 − ω²h²/12)(1 − ω²h²/24) q² / (2 (1 − ω²h²/8)).
/// Throws std::domain_error at ω²h² = 8, where it is singular.
template <class Real>
Real discrete_energy(const oscillator_parameters<Real>& par, const phase_point<Real>& y) {
  const Real x = par.omega2_h2();
  const Real internal = 1 - x / 8;
  detail::require_nonzero("simpson::discrete_energy", "1 - omega^2 h^2 / 8", internal);
  return y.p * y.p / (2 * par.m()) +
         par.m() * par.omega() * par.omega() * (1 - x / 12) * (1 - x / 24) * y.q * y.q / (2 * internal);
}

}  // namespace simpson

#pragma once
// The two energies of the paper: the exact one (Section 2) and the discrete one that the
// symplectic Simpson scheme conserves (Section 7).

#include <simpson/newmark_map.hpp>
#include <simpson/one_step_map.hpp>
#include <simpson/oscillator_parameters.hpp>
#include <simpson/precision_types.hpp>
#include <simpson/residual.hpp>
#include <simpson/simpson_map.hpp>

#include <cmath>

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

/// H(Φ y) − H(y) for the Newmark map. H is a sum of squares and Φ a rotation in (p/(mω), q), so
/// 32 eps H bounds the rounding of Φ y and of both energies.
template <class Real>
residual_and_bound<Real> newmark_energy_step_check(const oscillator_parameters<Real>& par, const phase_point<Real>& y) {
  const Real H = energy(par, y);
  return {Real(energy(par, newmark_map(par) * y) - H), Real(32 * eps<Real>() * H)};
}

/// H_d(Φ_3 y) − H_d(y) on the first stable band (H_d > 0). The q² weight of H_d and the entry γ of
/// Φ_3 contain 1 − ω²h²/8, whose relative error grows like eps/|1 − ω²h²/8| near ωh = 2√2:
/// the bound is 64 eps (1 + 1/|1 − ω²h²/8|) H_d.
template <class Real>
residual_and_bound<Real> discrete_energy_step_check(const oscillator_parameters<Real>& par, const phase_point<Real>& y) {
  using std::abs;
  const Real H = discrete_energy(par, y);
  const Real condition = 1 + 1 / abs(Real(1 - par.omega2_h2() / 8));
  return {Real(discrete_energy(par, simpson_map(par) * y) - H), Real(64 * eps<Real>() * condition * H)};
}

// Instantiated once per precision in core/src/energy.cpp.
#define SIMPSON_ENERGY_TEMPLATES(prefix, Real)                                                                    \
  prefix template Real energy(const oscillator_parameters<Real>&, const phase_point<Real>&);                      \
  prefix template Real discrete_energy(const oscillator_parameters<Real>&, const phase_point<Real>&);             \
  prefix template residual_and_bound<Real> newmark_energy_step_check(const oscillator_parameters<Real>&,          \
                                                                     const phase_point<Real>&);                   \
  prefix template residual_and_bound<Real> discrete_energy_step_check(const oscillator_parameters<Real>&,         \
                                                                      const phase_point<Real>&);
#define SIMPSON_ENERGY_EXTERN(Real) SIMPSON_ENERGY_TEMPLATES(extern, Real)
SIMPSON_FOR_EACH_PRECISION_TYPE(SIMPSON_ENERGY_EXTERN)

}  // namespace simpson

#pragma once
// The Störmer–Verlet method (velocity form, kick–drift–kick) and Yoshida's fourth-order
// symmetric composition of it: the explicit symplectic peers of the Simpson scheme.

#include <simpson/one_step_map.hpp>
#include <simpson/oscillator_parameters.hpp>

#include <boost/math/special_functions/cbrt.hpp>

#include <array>

namespace simpson {

/// One Störmer–Verlet step of size τ: p_{1/2} = p − (τ/2) m ω² q, q' = q + τ p_{1/2}/m,
/// p' = p_{1/2} − (τ/2) m ω² q'. τ may be negative (Yoshida's middle step).
template <class Real>
phase_point<Real> stormer_verlet_step(const oscillator_parameters<Real>& par, const phase_point<Real>& y, const Real& tau) {
  const Real stiffness = par.m() * par.omega() * par.omega();
  const Real p_half = y.p - tau / 2 * stiffness * y.q;
  const Real q_next = y.q + tau * p_half / par.m();
  return {p_half - tau / 2 * stiffness * q_next, q_next};
}

/// The Störmer–Verlet one-step matrix for the step h.
template <class Real>
one_step_matrix<Real> stormer_verlet_map(const oscillator_parameters<Real>& par) {
  const phase_point<Real> from_p = stormer_verlet_step(par, phase_point<Real>{Real(1), Real(0)}, par.h());
  const phase_point<Real> from_q = stormer_verlet_step(par, phase_point<Real>{Real(0), Real(1)}, par.h());
  return {from_p.p, from_q.p, from_p.q, from_q.q};
}

/// Yoshida (1990) / Forest–Ruth weights (w₁, w₀, w₁): w₁ = 1/(2 − ∛2), w₀ = −∛2/(2 − ∛2), so
/// that 2w₁ + w₀ = 1 and 2w₁³ + w₀³ = 0. Given ∛2, so that exact scalars with ∛2 can run it.
template <class Real>
std::array<Real, 3> yoshida_weights(const Real& cube_root_of_two) {
  const Real w1 = 1 / (2 - cube_root_of_two);
  return {w1, Real(-cube_root_of_two * w1), w1};
}

template <class Real>
std::array<Real, 3> yoshida_weights() {
  return yoshida_weights(Real(boost::math::cbrt(Real(2))));
}

/// One step of Yoshida's composition: Störmer–Verlet steps of w₁h, w₀h, w₁h.
template <class Real>
phase_point<Real> yoshida_step(const oscillator_parameters<Real>& par, const std::array<Real, 3>& weights,
                               phase_point<Real> y) {
  for (const Real& w : weights) y = stormer_verlet_step(par, y, Real(w * par.h()));
  return y;
}

/// The one-step matrix of Yoshida's composition.
template <class Real>
one_step_matrix<Real> yoshida_map(const oscillator_parameters<Real>& par, const std::array<Real, 3>& weights) {
  const phase_point<Real> from_p = yoshida_step(par, weights, phase_point<Real>{Real(1), Real(0)});
  const phase_point<Real> from_q = yoshida_step(par, weights, phase_point<Real>{Real(0), Real(1)});
  return {from_p.p, from_q.p, from_p.q, from_q.q};
}

}  // namespace simpson

#pragma once
// The exact flow of m q'' + m ω² q = 0, against which the schemes are measured.

#include <simpson/one_step_map.hpp>
#include <simpson/oscillator_parameters.hpp>

#include <cmath>

namespace simpson {

/// q(t) = q_0 cos ωt + p_0/(mω) sin ωt, p(t) = m q'(t) = p_0 cos ωt − m ω q_0 sin ωt,
/// for the state y_0 = (p_0, q_0) at t = 0. Floating-point scalars only (cos, sin).
template <class Real>
phase_point<Real> exact_solution(const oscillator_parameters<Real>& par, const phase_point<Real>& y0, const Real& t) {
  using std::cos;
  using std::sin;
  const Real phase = par.omega() * t;
  const Real c = cos(phase);
  const Real s = sin(phase);
  const Real m_omega = par.m() * par.omega();
  return {y0.p * c - m_omega * y0.q * s, y0.q * c + y0.p / m_omega * s};
}

}  // namespace simpson

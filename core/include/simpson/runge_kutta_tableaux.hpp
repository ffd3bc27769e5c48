#pragma once
// The tableaux of the Simpson scheme's peers, with exact coefficients (no double literals):
// Hairer, Lubich, Wanner, Geometric Numerical Integration (2006), Tables II.1.1–II.2.2.

#include <simpson/partitioned_runge_kutta.hpp>

#include <cmath>

namespace simpson {

/// Implicit midpoint rule (1-stage Gauss–Legendre): A = (1/2), b = (1). On the oscillator it is
/// the Newmark average-acceleration scheme of Section 2.
template <class Real>
butcher_tableau<Real> implicit_midpoint_tableau() {
  return {{{Real(1) / 2}}, {Real(1)}};
}

/// 2-stage Gauss–Legendre (order 4), given √3 (so exact scalars with √3 can run it).
template <class Real>
butcher_tableau<Real> gauss_legendre2_tableau(const Real& sqrt3) {
  const Real quarter = Real(1) / 4;
  return {{{quarter, quarter - sqrt3 / 6}, {quarter + sqrt3 / 6, quarter}}, {Real(1) / 2, Real(1) / 2}};
}

/// 2-stage Gauss–Legendre with √3 computed in Real.
template <class Real>
butcher_tableau<Real> gauss_legendre2_tableau() {
  using std::sqrt;
  return gauss_legendre2_tableau(Real(sqrt(Real(3))));
}

/// 3-stage Lobatto IIIA (used for q): the collocation method at 0, 1/2, 1 (order 4).
template <class Real>
butcher_tableau<Real> lobatto_iiia3_tableau() {
  return {{{Real(0), Real(0), Real(0)},
           {Real(5) / 24, Real(1) / 3, Real(-1) / 24},
           {Real(1) / 6, Real(2) / 3, Real(1) / 6}},
          {Real(1) / 6, Real(2) / 3, Real(1) / 6}};
}

/// 3-stage Lobatto IIIB (used for p), the symplectic partner of IIIA.
template <class Real>
butcher_tableau<Real> lobatto_iiib3_tableau() {
  return {{{Real(1) / 6, Real(-1) / 6, Real(0)},
           {Real(1) / 6, Real(1) / 3, Real(0)},
           {Real(1) / 6, Real(5) / 6, Real(0)}},
          {Real(1) / 6, Real(2) / 3, Real(1) / 6}};
}

/// 2-stage Lobatto IIIA (for q) and IIIB (for p): together the Störmer–Verlet method.
template <class Real>
butcher_tableau<Real> lobatto_iiia2_tableau() {
  return {{{Real(0), Real(0)}, {Real(1) / 2, Real(1) / 2}}, {Real(1) / 2, Real(1) / 2}};
}
template <class Real>
butcher_tableau<Real> lobatto_iiib2_tableau() {
  return {{{Real(1) / 2, Real(0)}, {Real(1) / 2, Real(0)}}, {Real(1) / 2, Real(1) / 2}};
}

/// The classic fourth-order Runge–Kutta method (not symplectic).
template <class Real>
butcher_tableau<Real> classic_rk4_tableau() {
  const Real zero(0), half = Real(1) / 2;
  return {{{zero, zero, zero, zero}, {half, zero, zero, zero}, {zero, half, zero, zero}, {zero, zero, Real(1), zero}},
          {Real(1) / 6, Real(1) / 3, Real(1) / 3, Real(1) / 6}};
}

}  // namespace simpson

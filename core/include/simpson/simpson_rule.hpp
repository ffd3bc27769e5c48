#pragma once
// Section 4: Simpson's quadrature on [0, 1].

namespace simpson {

/// (simpson) ∫_0^1 ψ(s) ds ≈ [ψ(0) + 4 ψ(1/2) + ψ(1)] / 6; exact up to degree three.
template <class Real, class Integrand>
Real simpson_rule(Integrand&& psi) {
  return (psi(Real(0)) + 4 * psi(Real(1) / 2) + psi(Real(1))) / 6;
}

}  // namespace simpson

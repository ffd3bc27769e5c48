#pragma once
// The exact solution of the pendulum (V = m ω² (1 − cos q)) released from rest at q₀, |q₀| < π,
// in the working precision, by Jacobi's elliptic functions (Boost.Math): with k = sin(q₀/2) and
// K = K(k), sin(q/2) = k sn(K − ωt, k), so q(t) = 2 asin(k sn(K − ωt, k)) and
// p(t) = m q'(t) = −2 m ω k cn(K − ωt, k); the period is 4K/ω. Beyond the paper.

#include <simpson/one_step_map.hpp>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>

#include <cmath>
#include <stdexcept>

namespace simpson {

template <class Real>
struct pendulum_from_rest {
  Real m, omega, q0;

  Real modulus() const {
    using std::sin;
    return sin(q0 / 2);
  }
  /// The period 4 K(k)/ω.
  Real period() const { return 4 * boost::math::ellint_1(modulus()) / omega; }

  phase_point<Real> at(const Real& t) const {
    using std::asin;
    using std::abs;
    if (!(abs(q0) < boost::math::constants::pi<Real>())) {
      throw std::domain_error("simpson::pendulum_from_rest: |q0| must be below pi");
    }
    const Real k = modulus();
    const Real u = boost::math::ellint_1(k) - omega * t;
    Real cn(0), dn(0);
    const Real sn = boost::math::jacobi_elliptic(k, u, &cn, &dn);
    return {Real(-2 * m * omega * k * cn), Real(2 * asin(Real(k * sn)))};
  }
};

}  // namespace simpson

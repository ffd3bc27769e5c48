#pragma once
// The exact solution of the Kepler problem V(q) = −1/|q| (μ = 1) on the ellipse of semi-major axis 1
// and eccentricity e, 0 ≤ e < 1, from perihelion: q(0) = (1 − e, 0), p(0) = (0, √((1 + e)/(1 − e))),
// H = −1/2, period 2π. With the eccentric anomaly E solving Kepler's equation E − e sin E = t:
//   q(t) = (cos E − e, √(1 − e²) sin E),  p(t) = (−sin E, √(1 − e²) cos E)/(1 − e cos E).
// In the working precision (Newton's method on Kepler's equation). Beyond the paper.

#include <simpson/separable_system.hpp>

#include <cmath>
#include <stdexcept>

namespace simpson {

template <class Real>
struct kepler_orbit {
  Real e;

  ndof_state<Real> initial() const { return at(Real(0)); }

  /// E with E − e sin E = t: Newton's method from E = t (+ e for t away from 0), converging
  /// monotonically for 0 ≤ e < 1; stops when a correction no longer shrinks |f|.
  Real eccentric_anomaly(const Real& t) const {
    using std::abs;
    using std::cos;
    using std::sin;
    if (!(e >= 0 && e < 1)) throw std::domain_error("simpson::kepler_orbit: the eccentricity must be in [0, 1)");
    Real E = t;
    Real last = abs(Real(E - e * sin(E) - t)) + 1;
    for (int k = 0; k < 200; ++k) {
      const Real f = E - e * sin(E) - t;
      if (!(abs(f) < last)) return E;
      last = abs(f);
      E -= f / (1 - e * cos(E));
    }
    throw std::domain_error("simpson::kepler_orbit: Kepler's equation did not converge");
  }

  ndof_state<Real> at(const Real& t) const {
    using std::cos;
    using std::sin;
    using std::sqrt;
    const Real E = eccentric_anomaly(t), c = cos(E), s = sin(E), b = sqrt(Real(1 - e * e)), d = 1 - e * c;
    ndof_state<Real> y{dense_vector<Real>(2), dense_vector<Real>(2)};
    y.q << Real(c - e), Real(b * s);
    y.p << Real(-s / d), Real(b * c / d);
    return y;
  }
};

}  // namespace simpson

#pragma once
// Potentials V for the nonlinear scheme (beyond the paper, whose §9 leaves the nonlinear case open):
// each gives V, V' and V'' at a point, generically over the scalar.

#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace simpson {

/// The pendulum V(q) = m ω² (1 − cos q): V' = m ω² sin q, V'' = m ω² cos q.
template <class Real>
struct pendulum_potential {
  Real m, omega;
  Real value(const Real& q) const {
    using std::cos;
    return m * omega * omega * (1 - cos(q));
  }
  Real derivative(const Real& q) const {
    using std::sin;
    return m * omega * omega * sin(q);
  }
  Real second_derivative(const Real& q) const {
    using std::cos;
    return m * omega * omega * cos(q);
  }
};

/// The quartic oscillator V(q) = m ω² q²/2 + λ q⁴/4: V' = m ω² q + λ q³, V'' = m ω² + 3 λ q².
template <class Real>
struct quartic_potential {
  Real m, omega, lambda;
  Real value(const Real& q) const { return m * omega * omega * q * q / 2 + lambda * q * q * q * q / 4; }
  Real derivative(const Real& q) const { return m * omega * omega * q + lambda * q * q * q; }
  Real second_derivative(const Real& q) const { return m * omega * omega + 3 * lambda * q * q; }
};

/// A polynomial V(q) = Σ_k c_k q^k of any degree (Horner's rule for V, V' and V'').
template <class Real>
struct polynomial_potential {
  std::vector<Real> coefficients;  // c_0, c_1, ...

  explicit polynomial_potential(std::vector<Real> c) : coefficients(std::move(c)) {
    if (coefficients.empty()) throw std::invalid_argument("simpson::polynomial_potential: no coefficient");
  }
  Real value(const Real& q) const { return horner(0, q); }
  Real derivative(const Real& q) const { return horner(1, q); }
  Real second_derivative(const Real& q) const { return horner(2, q); }

 private:
  /// The `order`-th derivative at q: Σ_k c_k k!/(k − order)! q^(k − order).
  Real horner(std::size_t order, const Real& q) const {
    Real sum(0);
    for (std::size_t k = coefficients.size(); k-- > order;) {
      Real factor(1);
      for (std::size_t j = 0; j < order; ++j) factor *= Real(static_cast<long long>(k - j));
      sum = sum * q + coefficients[k] * factor;
    }
    return sum;
  }
};

}  // namespace simpson

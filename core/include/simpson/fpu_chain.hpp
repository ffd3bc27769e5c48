#pragma once
// The Fermi–Pasta–Ulam–Tsingou chain as Hairer, Lubich and Wanner pose it (Geometric Numerical
// Integration, §I.5.1 and chapter XIII): 2m unit masses between fixed walls, stiff linear springs
// inside each pair (q_{2i−1}, q_{2i}) alternating with soft cubic springs between the pairs and to
// the walls:
//   H(p, q) = ½ Σ p_i² + (ω²/4) Σ_{i=1..m} (q_{2i} − q_{2i−1})² + Σ_{i=0..m} (q_{2i+1} − q_{2i})⁴,
// q₀ = q_{2m+1} = 0. In x_{1,i} = (q_{2i} − q_{2i−1})/√2 (the stiff springs' elongations) and
// y_{1,i} = (p_{2i} − p_{2i−1})/√2 the stiff energies are I_i = ½ (y_{1,i}² + ω² x_{1,i}²); their
// sum I is an adiabatic invariant of the flow, I(t) = I(0) + O(ω⁻¹) over exponentially long times.

#include <simpson/separable_system.hpp>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace simpson {

/// V(q) of the chain with m stiff springs of frequency ω.
template <class Real>
struct fpu_potential {
  int m;
  Real omega;

  Real value(const dense_vector<Real>& q) const {
    Real v(0);
    for (int i = 1; i <= m; ++i) {
      const Real d = at(q, 2 * i) - at(q, 2 * i - 1);
      v += omega * omega / 4 * d * d;
    }
    for (int i = 0; i <= m; ++i) {
      const Real d = at(q, 2 * i + 1) - at(q, 2 * i);
      v += d * d * d * d;
    }
    return v;
  }
  dense_vector<Real> gradient(const dense_vector<Real>& q) const {
    dense_vector<Real> g = dense_vector<Real>::Zero(2 * m);
    for (int i = 1; i <= m; ++i) {
      const Real f = omega * omega / 2 * (at(q, 2 * i) - at(q, 2 * i - 1));
      g(2 * i - 1) += f;  // q_{2i} (0-based 2i − 1)
      g(2 * i - 2) -= f;  // q_{2i−1}
    }
    for (int i = 0; i <= m; ++i) {
      const Real d = at(q, 2 * i + 1) - at(q, 2 * i), f = 4 * d * d * d;
      if (2 * i + 1 <= 2 * m) g(2 * i) += f;      // q_{2i+1}
      if (2 * i >= 1) g(2 * i - 1) -= f;          // q_{2i}
    }
    return g;
  }
  // The split a trigonometric integrator takes (trigonometric_step.hpp): V = ½ ω² qᵀPq + U(q), the
  // stiff springs' part with P the projector on their elongations, P = Σ_i ½ (e_{2i} − e_{2i−1})(e_{2i} − e_{2i−1})ᵀ,
  // and U the soft cubic springs'.
  const Real& stiff_frequency() const { return omega; }
  dense_vector<Real> stiff_projection(const dense_vector<Real>& v) const {
    dense_vector<Real> out = dense_vector<Real>::Zero(v.size());
    for (int i = 1; i <= m; ++i) {
      const Real half_difference = (v(2 * i - 1) - v(2 * i - 2)) / 2;
      out(2 * i - 1) = half_difference;
      out(2 * i - 2) = -half_difference;
    }
    return out;
  }
  /// ∇U, the soft springs' part of ∇V.
  dense_vector<Real> slow_gradient(const dense_vector<Real>& q) const {
    dense_vector<Real> g = dense_vector<Real>::Zero(2 * m);
    for (int i = 0; i <= m; ++i) {
      const Real d = at(q, 2 * i + 1) - at(q, 2 * i), f = 4 * d * d * d;
      if (2 * i + 1 <= 2 * m) g(2 * i) += f;  // q_{2i+1}
      if (2 * i >= 1) g(2 * i - 1) -= f;      // q_{2i}
    }
    return g;
  }
  dense_matrix<Real> hessian(const dense_vector<Real>& q) const {
    dense_matrix<Real> H = dense_matrix<Real>::Zero(2 * m, 2 * m);
    const auto couple = [&H](int a, int b, const Real& k) {  // k (e_a − e_b)(e_a − e_b)ᵀ, 1-based, 0 = wall
      if (a >= 1) H(a - 1, a - 1) += k;
      if (b >= 1) H(b - 1, b - 1) += k;
      if (a >= 1 && b >= 1) {
        H(a - 1, b - 1) -= k;
        H(b - 1, a - 1) -= k;
      }
    };
    for (int i = 1; i <= m; ++i) couple(2 * i, 2 * i - 1, Real(omega * omega / 2));
    for (int i = 0; i <= m; ++i) {
      const Real d = at(q, 2 * i + 1) - at(q, 2 * i);
      couple(2 * i + 1 <= 2 * m ? 2 * i + 1 : 0, 2 * i, Real(12 * d * d));
    }
    return H;
  }

 private:
  /// q_k, 1-based, with the walls q₀ = q_{2m+1} = 0.
  Real at(const dense_vector<Real>& q, int k) const { return k < 1 || k > 2 * m ? Real(0) : q(k - 1); }
};

/// The chain as a separable system (unit masses).
template <class Real>
separable_system<Real, fpu_potential<Real>> fpu_system(int m, const Real& omega) {
  if (m < 1) throw std::invalid_argument("simpson::fpu_system: m must be >= 1");
  return {dense_matrix<Real>::Identity(2 * m, 2 * m), fpu_potential<Real>{m, omega}};
}

/// Hairer, Lubich and Wanner's start: x_{0,1} = 1, y_{0,1} = 1, x_{1,1} = 1/ω, y_{1,1} = 1, the rest
/// 0, with x_{0,i} = (q_{2i} + q_{2i−1})/√2 and x_{1,i} = (q_{2i} − q_{2i−1})/√2 (likewise y from p).
template <class Real>
ndof_state<Real> fpu_start(int m, const Real& omega) {
  using std::sqrt;
  ndof_state<Real> y{dense_vector<Real>::Zero(2 * m), dense_vector<Real>::Zero(2 * m)};
  const Real r = sqrt(Real(2)), x0 = 1, x1 = 1 / omega, y0 = 1, y1 = 1;
  y.q(1) = (x0 + x1) / r;  // q₂
  y.q(0) = (x0 - x1) / r;  // q₁
  y.p(1) = (y0 + y1) / r;
  y.p(0) = (y0 - y1) / r;
  return y;
}

/// The stiff springs' energies I_i = ½ (y_{1,i}² + ω² x_{1,i}²), i = 1..m.
template <class Real>
std::vector<Real> fpu_oscillatory_energies(const ndof_state<Real>& y, const Real& omega) {
  const Eigen::Index m = y.q.size() / 2;
  std::vector<Real> out;
  for (Eigen::Index i = 0; i < m; ++i) {
    const Real x1 = (y.q(2 * i + 1) - y.q(2 * i)), v1 = (y.p(2 * i + 1) - y.p(2 * i));  // √2 x_{1,i}, √2 y_{1,i}
    out.push_back((v1 * v1 + omega * omega * x1 * x1) / 4);
  }
  return out;
}

}  // namespace simpson

#pragma once
// A trigonometric integrator for q̈ = −Ω²q − ∇U(q) with unit masses whose stiff part is one frequency
// on a projector, Ω² = ω²P (P = Pᵀ = P²), as the FPU chain's stiff springs are (fpu_chain.hpp): the
// peer that Hairer, Lubich and Wanner (Geometric Numerical Integration, chapter XIII) set against
// implicit schemes at large ωh. Their one-step form (XIII.2.7),
//   q_{n+1} = cos(hΩ) q_n + Ω⁻¹ sin(hΩ) p_n + ½ h² Ψ g_n,
//   p_{n+1} = −Ω sin(hΩ) q_n + cos(hΩ) p_n + ½ h (Ψ₀ g_n + Ψ₁ g_{n+1}),   g_n = −∇U(Φ q_n),
// with the filters of method (C) of their Table XIII.2.1 (García-Archilla, Sanz-Serna and Skeel's
// mollified impulse method): φ(ξ) = sinc ξ, ψ(ξ) = sinc ξ φ(ξ) = sinc² ξ, ψ₁(ξ) = ψ(ξ)/sinc ξ = sinc ξ,
// ψ₀(ξ) = cos ξ ψ₁(ξ). ψ = sinc·φ makes it symplectic, and ψ₀, ψ₁ so make it symmetric (their
// Theorems XIII.2.9 and XIII.2.10). A function f of hΩ acts as f(0) off P and f(hω) on P:
// f(hΩ) v = f(0)(v − Pv) + f(hω) Pv. The linear stiff part alone is integrated exactly; with P = 0 the
// step is Störmer–Verlet's. One ∇U a step: the force at the step's end is the next step's start
// (first same as last, kept in a last_force).

#include <simpson/nonlinear_ndof_step.hpp>  // last_force
#include <simpson/separable_system.hpp>

#include <cmath>

namespace simpson {

/// The filters at ξ = hω: cos ξ, sin ξ / ω (h at ω = 0) and ω sin ξ, and sinc ξ = sin ξ / ξ (1 at ξ = 0).
template <class Real>
struct trigonometric_filters {
  Real cos_xi, sin_over_omega, omega_sin, sinc;
  trigonometric_filters(const Real& omega, const Real& h) {
    using std::cos;
    using std::sin;
    const Real xi = omega * h;
    cos_xi = cos(xi);
    sinc = xi == 0 ? Real(1) : Real(sin(xi) / xi);
    sin_over_omega = h * sinc;
    omega_sin = omega * sin(xi);
  }
};

/// f(0) (v − Pv) + f(hω) Pv, given Pv.
template <class Real>
dense_vector<Real> on_split(const dense_vector<Real>& v, const dense_vector<Real>& Pv, const Real& at_zero, const Real& at_omega) {
  return scaled(dense_vector<Real>(v - Pv), at_zero) + scaled(Pv, at_omega);
}

/// One step of method (C) for a split potential (stiff_frequency(), stiff_projection(v), slow_gradient(q)),
/// the gradient of U at Φq taken from `kept` when it was evaluated at this q.
template <class Real, class Split>
ndof_state<Real> trigonometric_step(const Split& split, const Real& h, const ndof_state<Real>& y, last_force<Real>& kept) {
  const trigonometric_filters<Real> f(split.stiff_frequency(), h);
  const auto filtered_gradient = [&](const dense_vector<Real>& q) {  // ∇U(Φq), Φ = sinc(hΩ)
    return dense_vector<Real>(split.slow_gradient(on_split(q, split.stiff_projection(q), Real(1), f.sinc)));
  };
  const dense_vector<Real> g0 = kept.at(y.q, filtered_gradient);
  const dense_vector<Real> Pq = split.stiff_projection(y.q), Pp = split.stiff_projection(y.p), Pg0 = split.stiff_projection(g0);
  ndof_state<Real> out;
  // q_{n+1} = cos(hΩ)q + Ω⁻¹sin(hΩ)p − ½h² sinc²(hΩ) ∇U(Φq)
  out.q = on_split(y.q, Pq, Real(1), f.cos_xi) + on_split(y.p, Pp, h, f.sin_over_omega) -
          scaled(on_split(g0, Pg0, Real(1), Real(f.sinc * f.sinc)), Real(h * h / 2));
  const dense_vector<Real> g1 = kept.keep(out.q, filtered_gradient);
  const dense_vector<Real> Pg1 = split.stiff_projection(g1);
  // p_{n+1} = −Ω sin(hΩ)q + cos(hΩ)p − ½h (cos(hΩ) sinc(hΩ) ∇U(Φq_n) + sinc(hΩ) ∇U(Φq_{n+1}))
  out.p = on_split(y.p, Pp, Real(1), f.cos_xi) - scaled(Pq, f.omega_sin) -
          scaled(dense_vector<Real>(on_split(g0, Pg0, Real(1), Real(f.cos_xi * f.sinc)) + on_split(g1, Pg1, Real(1), f.sinc)),
                 Real(h / 2));
  return out;
}

}  // namespace simpson

#pragma once
// Beyond the paper: the largest Lyapunov exponent of a flow, estimated from any one-step map of it
// (Benettin et al. 1980): two trajectories, the second displaced by δ₀, stepped together; every
// `steps_per_renormalisation` steps the distance d is measured, ln(d/δ₀) accumulated and the second
// trajectory pulled back to distance δ₀ along the current separation. λ ≈ Σ ln(d/δ₀) / t. With it a
// caller states a predictability horizon: an initial error ε grows to a tolerance τ in about
// ln(τ/ε)/λ time units.

#include <simpson/separable_system.hpp>

#include <cmath>
#include <stdexcept>

namespace simpson {

template <class Real>
struct lyapunov_estimate {
  Real exponent;         // per unit time
  Real time;             // over which it was averaged
  Real first_half;       // the estimate after half the renormalisations: how far it has settled
};

/// The estimate from y0 with steps of h by `step` (ndof_state → ndof_state), distance the Euclidean
/// norm in (p, q), the first displacement δ₀ along q₀. Throws std::invalid_argument for a
/// non-positive count, step or separation.
template <class Real, class Step>
lyapunov_estimate<Real> largest_lyapunov_exponent(const Step& step, const ndof_state<Real>& y0, const Real& h, int steps_per_renormalisation,
                                                  int renormalisations, const Real& separation) {
  using std::log;
  using std::sqrt;
  if (steps_per_renormalisation < 1 || renormalisations < 2 || !(h > 0) || !(separation > 0)) {
    throw std::invalid_argument("simpson::largest_lyapunov_exponent: counts, h and the separation must be positive");
  }
  ndof_state<Real> a = y0, b = y0;
  b.q(0) += separation;
  Real sum(0), half(0);
  const Real interval = h * steps_per_renormalisation;
  for (int r = 1; r <= renormalisations; ++r) {
    for (int j = 0; j < steps_per_renormalisation; ++j) {
      a = step(a);
      b = step(b);
    }
    const dense_vector<Real> dp = b.p - a.p, dq = b.q - a.q;
    const Real d = sqrt(Real(dp.squaredNorm() + dq.squaredNorm()));
    if (!(d > 0)) throw std::domain_error("simpson::largest_lyapunov_exponent: the trajectories met (separation 0)");
    sum += log(Real(d / separation));
    b.p = a.p + scaled(dense_vector<Real>(dp), Real(separation / d));
    b.q = a.q + scaled(dense_vector<Real>(dq), Real(separation / d));
    if (r == renormalisations / 2) half = sum / (interval * r);
  }
  return {Real(sum / (interval * renormalisations)), Real(interval * renormalisations), half};
}

/// ln(tolerance / initial_error) / exponent: the time over which an initial error ε stays below τ.
template <class Real>
Real predictability_horizon(const Real& exponent, const Real& initial_error, const Real& tolerance) {
  using std::log;
  if (!(exponent > 0) || !(initial_error > 0) || !(tolerance > initial_error)) {
    throw std::invalid_argument("simpson::predictability_horizon: needs exponent > 0 and 0 < initial_error < tolerance");
  }
  return log(Real(tolerance / initial_error)) / exponent;
}

}  // namespace simpson

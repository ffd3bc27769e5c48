#pragma once
// The harmonic oscillator m q'' + m ω² q = 0 and its time step h, validated once.

#include <simpson/scalar_traits.hpp>

#include <boost/multiprecision/number.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace simpson {

namespace detail {

/// Whether values of Real are ordered numbers that can be range-checked: the built-in floating
/// types and Boost.Multiprecision numbers (not numeric_limits::is_specialized, which is false for
/// mpfr with run-time digits). Symbolic scalars of the exact proofs (polynomials) are not.
template <class Real>
inline constexpr bool is_ordered_number_v =
    std::is_floating_point_v<Real> || boost::multiprecision::is_number<Real>::value;

template <class Real>
bool is_finite(const Real& v) {
  if constexpr (is_exact_v<Real>) {
    return true;
  } else {
    using std::isfinite;
    return isfinite(v);
  }
}

/// Throws std::invalid_argument "<where>: <name> must be positive and finite, got <v>" unless 0 < v < inf.
template <class Real>
void require_positive_finite(const char* where, const char* name, const Real& v) {
  if constexpr (is_ordered_number_v<Real>) {
    if (!is_finite(v) || !(v > 0)) {
      throw std::invalid_argument(std::string(where) + ": " + name + " must be positive and finite, got " +
                                  to_string(v));
    }
  }
}

/// Throws std::domain_error when a denominator of a formula vanishes (e.g. 1 - ω²h²/8 at ωh = 2√2).
template <class Real>
void require_nonzero(const char* where, const char* what, const Real& v) {
  if constexpr (is_interval_v<Real>) {
    // An interval's comparison with 0 is ambiguous when it holds 0 (Boost throws): ask for a sign.
    if (!(lower(v) > 0 || upper(v) < 0)) {
      throw std::domain_error(std::string(where) + ": " + what + " may be zero (its enclosure holds 0); the formula may be singular there");
    }
  } else if constexpr (is_ordered_number_v<Real>) {
    if (v == 0) {
      throw std::domain_error(std::string(where) + ": " + what + " is zero; the formula is singular there");
    }
  }
}

}  // namespace detail

/// Mass m, angular frequency ω and time step h of a discretised harmonic oscillator.
/// The constructor throws std::invalid_argument naming the parameter when it is not positive and
/// finite, so no formula ever sees a silent NaN from its inputs.
/// Note: omega_h() is the dimensionless step θ = ωh of the issues; the paper's θ in Section 3 is t/h.
template <class Real>
class oscillator_parameters {
 public:
  oscillator_parameters(Real m, Real omega, Real h) : m_(std::move(m)), omega_(std::move(omega)), h_(std::move(h)) {
    detail::require_positive_finite("simpson::oscillator_parameters", "m", m_);
    detail::require_positive_finite("simpson::oscillator_parameters", "omega", omega_);
    detail::require_positive_finite("simpson::oscillator_parameters", "h", h_);
  }

  const Real& m() const noexcept { return m_; }
  const Real& omega() const noexcept { return omega_; }
  const Real& h() const noexcept { return h_; }

  /// θ = ωh, the dimensionless step on which every result depends once p is scaled by mω.
  Real omega_h() const { return omega_ * h_; }
  /// x = ω²h², the variable of the characteristic polynomial and of the discriminant.
  Real omega2_h2() const { return omega_ * omega_ * h_ * h_; }

  /// (oscillateur harmonique) V(q) = m ω² q² / 2
  Real potential(const Real& q) const { return m_ * omega_ * omega_ * q * q / 2; }
  /// dV/dq = m ω² q
  Real force_gradient(const Real& q) const { return m_ * omega_ * omega_ * q; }

 private:
  Real m_;
  Real omega_;
  Real h_;
};

/// h = T / N for N steps over [0, T] (Section 2). Throws std::invalid_argument when T is not
/// positive and finite or N < 1.
template <class Real>
Real step_size(const Real& T, long long N) {
  detail::require_positive_finite("simpson::step_size", "T", T);
  if (N < 1) {
    throw std::invalid_argument("simpson::step_size: N must be at least 1, got " + std::to_string(N));
  }
  return T / Real(N);
}

}  // namespace simpson

#pragma once
// The Lagrange top (heavy symmetric top with a fixed point on its axis) in Euler angles
// q = (θ, φ, ψ) of the z-x-z convention (Goldstein, Classical Mechanics, 3rd ed., §4.4: the body
// frame is R = R_z(φ) R_x(θ) R_z(ψ) of the space frame, z vertical), its velocities v = (θ̇, φ̇, ψ̇):
//   L = ½ I₁ (θ̇² + φ̇² sin²θ) + ½ I₃ (ψ̇ + φ̇ cos θ)² − Mgl cos θ          (Goldstein §5.7)
// with I₁ the moment of inertia about a transverse axis through the pivot, I₃ the axial one, and Mgl
// the weight times the distance from the pivot to the centre of mass. φ and ψ are cyclic, so
//   p_φ = ∂L/∂φ̇ = I₁ φ̇ sin²θ + I₃ (ψ̇ + φ̇ cos θ) cos θ,   p_ψ = ∂L/∂ψ̇ = I₃ (ψ̇ + φ̇ cos θ)
// are conserved (Goldstein §5.7), and so is the energy
//   E = ½ I₁ (θ̇² + φ̇² sin²θ) + ½ I₃ (ψ̇ + φ̇ cos θ)² + Mgl cos θ.                (Goldstein §5.7)
// Beyond the paper: the tutorial's nonlinear example (arXiv 2512.03330), whose exact solution is
// lagrange_top_exact.hpp. Generic over the scalar (Real or an automatic-differentiation scalar over it).

#include <simpson/scalar_traits.hpp>

#include <Eigen/Core>
#include <boost/math/constants/constants.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace simpson {

/// A state of the top: the Euler angles and their rates.
template <class Real>
struct top_state {
  Real theta, phi, psi, theta_dot, phi_dot, psi_dot;
};

/// The three conjugate momenta p = ∂L/∂v.
template <class Real>
struct top_momenta {
  Real p_theta, p_phi, p_psi;
};

namespace detail {

/// Whether x is certainly positive (every point of an interval), and certainly finite.
template <class Real>
bool top_certainly_positive(const Real& x) {
  if constexpr (is_interval_v<Real>) {
    return lower(x) > 0;
  } else {
    return x > 0;
  }
}

template <class Real>
bool top_finite(const Real& x) {
  if constexpr (is_interval_v<Real>) {
    return isfinite(lower(x)) && isfinite(upper(x));  // Boost.Multiprecision's, found by argument-dependent lookup
  } else {
    using std::abs;
    return x == x && abs(x) <= (std::numeric_limits<Real>::max)();  // NaN fails the first, ±inf the second
  }
}

}  // namespace detail

/// The top's Lagrangian, with its parameters I₁ > 0, I₃ > 0 and Mgl (any finite sign: Mgl < 0 is a
/// top hanging below its pivot). Satisfies the Lagrangian concept of lagrangian.hpp: dof() and
/// L(q, v) for any scalar T constructible from Real.
template <class Real>
class lagrange_top {
 public:
  /// Throws std::invalid_argument naming the field unless I₁ > 0, I₃ > 0 and all three are finite
  /// (for intervals: proved positive, both ends finite).
  lagrange_top(Real I1, Real I3, Real Mgl) : I1_(std::move(I1)), I3_(std::move(I3)), Mgl_(std::move(Mgl)) {
    require(detail::top_finite(I1_) && detail::top_certainly_positive(I1_), "'I1' must be positive and finite");
    require(detail::top_finite(I3_) && detail::top_certainly_positive(I3_), "'I3' must be positive and finite");
    require(detail::top_finite(Mgl_), "'Mgl' must be finite");
  }

  const Real& I1() const { return I1_; }
  const Real& I3() const { return I3_; }
  const Real& Mgl() const { return Mgl_; }

  int dof() const { return 3; }

  /// (Goldstein §5.7; Landau & Lifshitz, Mechanics, §35) L(q, v), q = (θ, φ, ψ), v = (θ̇, φ̇, ψ̇); the parameters enter as T(I₁), T(I₃),
  /// T(Mgl). Throws std::invalid_argument unless q and v have 3 entries.
  template <class T>
  T operator()(const Eigen::Matrix<T, Eigen::Dynamic, 1>& q, const Eigen::Matrix<T, Eigen::Dynamic, 1>& v) const {
    using std::cos;
    using std::sin;
    require(q.size() == 3 && v.size() == 3, "q and v must have 3 entries (theta, phi, psi)");
    const T s = sin(q(0)), c = cos(q(0));
    const T spin = v(2) + v(1) * c;  // ω₃, the angular velocity about the axis
    return T(I1_) * (v(0) * v(0) + v(1) * v(1) * s * s) / 2 + T(I3_) * spin * spin / 2 - T(Mgl_) * c;
  }

  /// (Goldstein §5.7) p_θ = I₁ θ̇, p_φ = I₁ φ̇ sin²θ + p_ψ cos θ, p_ψ = I₃ (ψ̇ + φ̇ cos θ).
  top_momenta<Real> momenta(const top_state<Real>& x) const {
    using std::cos;
    using std::sin;
    const Real s = sin(x.theta), c = cos(x.theta);
    const Real p_psi = I3_ * (x.psi_dot + x.phi_dot * c);
    return {Real(I1_ * x.theta_dot), Real(I1_ * x.phi_dot * s * s + p_psi * c), p_psi};
  }

  /// (Goldstein §5.7) E = ½ I₁ (θ̇² + φ̇² sin²θ) + ½ I₃ (ψ̇ + φ̇ cos θ)² + Mgl cos θ.
  Real energy(const top_state<Real>& x) const {
    using std::cos;
    using std::sin;
    const Real s = sin(x.theta), c = cos(x.theta), spin = x.psi_dot + x.phi_dot * c;
    return I1_ * (x.theta_dot * x.theta_dot + x.phi_dot * x.phi_dot * s * s) / 2 + I3_ * spin * spin / 2 + Mgl_ * c;
  }

  /// Throws std::invalid_argument naming the field unless every field of x is finite and θ lies in
  /// (0, π), where the Euler chart is regular (for intervals: the whole interval inside). At θ = 0
  /// or π only φ + ψ, or φ − ψ, is defined.
  void check_state(const top_state<Real>& x) const {
    const Real pi = boost::math::constants::pi<Real>();
    require(detail::top_finite(x.theta) && detail::top_certainly_positive(x.theta) &&
                detail::top_certainly_positive(Real(pi - x.theta)),
            "'theta' must lie in (0, pi): the Euler angles are singular at the vertical");
    require(detail::top_finite(x.phi), "'phi' must be finite");
    require(detail::top_finite(x.psi), "'psi' must be finite");
    require(detail::top_finite(x.theta_dot), "'theta_dot' must be finite");
    require(detail::top_finite(x.phi_dot), "'phi_dot' must be finite");
    require(detail::top_finite(x.psi_dot), "'psi_dot' must be finite");
  }

 private:
  static void require(bool condition, const char* what) {
    if (!condition) throw std::invalid_argument(std::string("simpson::lagrange_top: ") + what);
  }

  Real I1_, I3_, Mgl_;
};

/// A top and its start.
template <class Real>
struct lagrange_top_problem {
  lagrange_top<Real> top;
  top_state<Real> start;
};

/// The default top, one that nutates visibly: I₁ = 1, I₃ = 1/2, Mgl = 1, released at θ₀ = π/3
/// with θ̇₀ = 0, φ̇₀ = 1/2, ψ̇₀ = 8, φ₀ = ψ₀ = 0 (p_ψ = 33/8, p_φ = 39/16, E = 1127/64). Its axis
/// nutates between θ = 60° and 53.58° (cos θ from 1/2 to 0.5936512131), with period 1.6265486753
/// (both enclosed by lagrange_top_exact.hpp), drawing small loops: φ̇ goes from 1/2 down to −0.0175.
template <class Real>
lagrange_top_problem<Real> nutating_lagrange_top() {
  const Real pi = boost::math::constants::pi<Real>();
  return {lagrange_top<Real>(Real(1), Real(1) / 2, Real(1)), top_state<Real>{Real(pi / 3), Real(0), Real(0), Real(0), Real(1) / 2, Real(8)}};
}

}  // namespace simpson

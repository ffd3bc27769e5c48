#pragma once
// The exact motion of the Lagrange top (lagrange_top.hpp) from (θ₀, φ₀, ψ₀, θ̇₀, φ̇₀, ψ̇₀) at t = 0,
// enclosed: every figure is an MPFI interval that holds the exact value (its elliptic functions and
// integrals by Arb, elliptic_enclosed.hpp). With u = cos θ,
// a = p_ψ/I₁, b = p_φ/I₁, β = 2 Mgl/I₁ and α = 2E'/I₁ = θ̇₀² + φ̇₀² sin²θ₀ + β cos θ₀ (E' = E − p_ψ²/(2I₃)),
//   u̇² = f(u) = (1 − u²)(α − βu) − (b − au)²                    (Goldstein §5.7; Landau–Lifshitz §35)
// a cubic with f(±1) = −(b ∓ a)² ≤ 0, f(u₀) = u̇₀² ≥ 0 and f → +∞: its roots u₁ ≤ u₀ ≤ u₂ ≤ 1 < u₃
// bracket the nutation. With f = β(u − u₁)(u − u₂)(u − u₃), m = (u₂ − u₁)/(u₃ − u₁), λ = ½√(β(u₃ − u₁)),
// u = u₁ + (u₂ − u₁)s² turns u̇² = f(u) into ṡ² = λ²(1 − s²)(1 − ms²), solved by s = sn (DLMF 22.13.1):
//   u(t) = u₁ + (u₂ − u₁) sn²(τ₀ + λt, m),
// the nutation period 2K(m)/λ, and from φ̇ = (b − au)/(1 − u²), ψ̇ = p_ψ/I₃ − φ̇u, split into
// partial fractions, φ̇ = ½(b − a)/(1 − u) + ½(b + a)/(1 + u), φ̇u = ½(b − a)/(1 − u) − ½(b + a)/(1 + u) + a:
//   φ(t) = φ₀ + ½(b − a) J₊(t) + ½(b + a) J₋(t),  ψ(t) = ψ₀ + (p_ψ/I₃ − a) t − ½(b − a) J₊(t) + ½(b + a) J₋(t),
//   J±(t) = ∫₀ᵗ dt'/(1 ∓ u) = [Π(n±; am τ) − Π(n±; am τ₀)] / (λ(1 ∓ u₁)),
//   1 ∓ u = (1 ∓ u₁)(1 − n± sn²τ), n₊ = (u₂ − u₁)/(1 − u₁), n₋ = −(u₂ − u₁)/(1 + u₁),
// third-kind integrals (elliptic_enclosed.hpp). The roots are enclosed by sign changes of f (which
// also prove each unique in its bracket), narrowed by bisection and then by Krawczyk's interval Newton
// (interval_newton.hpp); τ₀ from (u₀, u̇₀) by the first-kind integral around the nearer turning point.
//
// The degenerate cases. Steady precession, u₁ = u₂: no nutation band; θ is constant and φ, ψ are
// linear in t. It is what the enclosure switches to when it cannot prove f > 0 at a point between
// u₁ and u₂ (at u₀'s ends or at the vertex of the deflated quadratic f/(β(u − u₃))): then both roots
// lie in one band, enclosed from that quadratic, and the closed form θ ∈ θ(band), φ ∈ φ₀ + t φ̇(band),
// ψ ∈ ψ₀ + t ψ̇(band) holds for every motion the band allows (a nutation too narrow to resolve at the
// working digits included): a nutation of width δ in u is resolved once f's value between the roots,
// about β(u₃ − u)δ²/4, is above f's round-off, so for δ above about the square root of the unit
// round-off. The sleeping top, θ ≡ 0, is outside the Euler chart (θ₀ = 0 or π is refused by
// lagrange_top::check_state), and so is any motion through the vertical: p_φ = ±p_ψ makes the axis
// reach θ = 0 or π, where φ and ψ jump; a start whose b ∓ a is not proved nonzero is refused. Near
// the vertical (θ₀ → 0) the motion is the general one: b ∓ a and 1 ∓ u(t) are formed without
// cancellation, but the roots near u = 1 are found in u, so θ keeps about 2 log₁₀ θ₀ digits fewer.
// Beyond the paper: the reference solution of the tutorial on the Lagrange top (arXiv 2512.03330).
// Measured (Release, one core, 50 digits): construction 0.9 ms, at(t) 0.12 ms; widths at d digits
// about 10^(2 − d) for θ, θ̇, φ̇, ψ̇ and 10^(3 − d) for φ and ψ over t ≤ 10 (lagrange_top_exact_test.cpp).
// Pulls in MPFI and Arb (link simpson::interval and simpson::arb).

#include <simpson/elliptic_enclosed.hpp>
#include <simpson/interval.hpp>
#include <simpson/interval_newton.hpp>
#include <simpson/lagrange_top.hpp>

#include <boost/math/constants/constants.hpp>

#include <optional>
#include <stdexcept>

namespace simpson {

/// f(u) = (1 − u²)(α − βu) − (b − au)², u̇² = f(u) along the motion (Goldstein §5.7).
struct top_cubic {
  interval alpha, beta, a, b;

  interval operator()(const interval& u) const {
    return (1 - u) * (1 + u) * (alpha - beta * u) - square_enclosed(interval(b - a * u));
  }
  /// f'(u) = −2u(α − βu) − β(1 − u²) + 2a(b − au).
  interval derivative(const interval& u) const {
    return -2 * u * (alpha - beta * u) - beta * (1 - u) * (1 + u) + 2 * a * (b - a * u);
  }
};

/// What the enclosure found: a nutation between two proved-distinct roots, or a steady precession
/// (the two roots in one band, within the working digits).
enum class top_motion { nutation, steady_precession };

/// The state and momenta at one time.
struct top_point_enclosed {
  top_state<interval> state;
  top_momenta<interval> momenta;
};

/// (Goldstein §5.7) The rates of steady precession at inclination θ and spin rate ψ̇, the roots of
/// (I₁ − I₃) cos θ φ̇² − I₃ ψ̇ φ̇ + Mgl = 0 (the θ equation with θ̇ = θ̈ = 0), written without division by
/// the leading coefficient: φ̇ = 2 Mgl / (I₃ψ̇ ± sgn(ψ̇) √D), D = I₃²ψ̇² − 4 (I₁ − I₃) cos θ Mgl. The
/// slow rate always; the fast one unless its denominator may vanish (I₁ = I₃ or θ = π/2: one root).
struct steady_precession_rates {
  interval slow;
  std::optional<interval> fast;
};

inline steady_precession_rates steady_precession(const lagrange_top<interval>& top, const interval& theta, const interval& psi_dot) {
  const interval D = square_enclosed(interval(top.I3() * psi_dot)) - 4 * (top.I1() - top.I3()) * cos(theta) * top.Mgl();
  const int spin = certain_sign(psi_dot);
  if (spin == 0) throw std::domain_error("simpson::steady_precession: 'psi_dot' must be nonzero");
  if (!(lower(D) > 0)) throw std::domain_error("simpson::steady_precession: no steady precession at this spin ('psi_dot' too slow)");
  const interval root = spin * sqrt(D), spin_momentum = top.I3() * psi_dot;
  steady_precession_rates out{2 * top.Mgl() / (spin_momentum + root), std::nullopt};
  const interval fast_denominator = spin_momentum - root;
  if (certain_sign(fast_denominator) != 0) out.fast = 2 * top.Mgl() / fast_denominator;
  return out;
}

/// (Goldstein §5.7) I₃²ω₃² − 4 I₁ Mgl: the top spinning upright at ω₃ (the sleeping top) is stable
/// when it is positive (the fast top), and falls away from the vertical when it is negative.
inline interval sleeping_stability_margin(const lagrange_top<interval>& top, const interval& omega3) {
  return square_enclosed(interval(top.I3() * omega3)) - 4 * top.I1() * top.Mgl();
}

namespace detail {

/// The unique root of f in the bracket [lo, hi], where f has the certain sign `sign_lo` at lo and the
/// opposite at hi: bisection on points while f's sign at the midpoint is decided; from a third of the
/// working bits on, Krawczyk's test every 8 halvings (it proves nothing on a box that holds a
/// second root nearby, or f' = 0); the bracket itself when neither narrows further.
inline interval top_root_in_bracket(const top_cubic& f, interval lo, interval hi, int sign_lo) {
  const int bits = static_cast<int>(mpfi_get_prec(interval(1).backend().data()));
  const auto F = [&](const interval& u) { return f(u); };
  const auto dF = [&](const interval& u) { return f.derivative(u); };
  interval target = ldexp(interval(1), -bits / 3);
  for (int i = 0; i < 4 * bits; ++i) {
    if (upper(interval(hi - lo)) <= lower(target)) {
      const krawczyk_result k = krawczyk(F, dF, interval(lower(lo), upper(hi)));
      if (k.proved) return k.enclosure;
      target = ldexp(target, -8);
    }
    const interval mid(median(interval(lower(lo), upper(hi))));
    const int s = certain_sign(f(mid));
    if (s == 0) break;  // f's sign undecided at the midpoint: the root is within round-off of it
    (s == sign_lo ? lo : hi) = mid;
  }
  const interval bracket(lower(lo), upper(hi));
  const krawczyk_result k = krawczyk(F, dF, bracket);
  return k.proved ? k.enclosure : bracket;
}

}  // namespace detail

/// The exact motion of a top from its start, enclosed at the interval digits current at
/// construction (at() evaluates at those digits too). Throws std::invalid_argument for a bad top
/// or start (lagrange_top::check_state), std::domain_error for Mgl ≤ 0 (the cubic's roots are
/// bracketed for a top above its pivot) and for a motion through the vertical (b ∓ a not proved nonzero).
class lagrange_top_exact {
 public:
  lagrange_top_exact(const lagrange_top<interval>& top, const top_state<interval>& start)
      : top_(top), start_(start), digits_(interval::default_precision()) {
    top.check_state(start);
    if (!(lower(top.Mgl()) > 0)) {
      throw std::domain_error("simpson::lagrange_top_exact: 'Mgl' must be positive (a top above its pivot)");
    }
    const interval s = sin(start.theta), c = cos(start.theta), half = start.theta / 2;
    const interval s2 = square_enclosed(s);
    const interval one_minus_c = 2 * square_enclosed(interval(sin(half))), one_plus_c = 2 * square_enclosed(interval(cos(half)));
    p_psi_ = top.I3() * (start.psi_dot + start.phi_dot * c);
    f_.a = p_psi_ / top.I1();
    f_.b = start.phi_dot * s2 + f_.a * c;  // p_φ/I₁
    f_.beta = 2 * top.Mgl() / top.I1();
    f_.alpha = square_enclosed(start.theta_dot) + square_enclosed(start.phi_dot) * s2 + f_.beta * c;
    b_minus_a_ = start.phi_dot * s2 - f_.a * one_minus_c;  // without cancellation near θ = 0
    b_plus_a_ = start.phi_dot * s2 + f_.a * one_plus_c;    // and near θ = π
    if (certain_sign(b_minus_a_) == 0) {
      throw std::domain_error("simpson::lagrange_top_exact: p_phi = p_psi is not excluded: the axis may pass through the "
                              "upward vertical, where phi and psi leave the Euler chart");
    }
    if (certain_sign(b_plus_a_) == 0) {
      throw std::domain_error("simpson::lagrange_top_exact: p_phi = -p_psi is not excluded: the axis may pass through the "
                              "downward vertical, where phi and psi leave the Euler chart");
    }
    spin_drift_ = p_psi_ / top.I3() - f_.a;
    u0_ = c;
    u0_dot_ = -s * start.theta_dot;

    // u₃ in (1, U]: f(1) = −(b − a)² < 0, and U above Cauchy's bound on the roots, where f > 0.
    const interval c2 = -(f_.alpha + square_enclosed(f_.a)), c1 = 2 * f_.a * f_.b - f_.beta, c0 = f_.alpha - square_enclosed(f_.b);
    interval U = 1 + hull(hull(interval(abs(c2)), interval(abs(c1))), interval(abs(c0))) / f_.beta;
    U = interval(upper(U)) + 1;
    for (int i = 0; i < 64 && certain_sign(f_(U)) != 1; ++i) U = 2 * U;
    if (certain_sign(f_(U)) != 1) throw std::domain_error("simpson::lagrange_top_exact: no bracket found for the cubic's largest root");
    u3_ = detail::top_root_in_bracket(f_, interval(1), U, -1);

    // The deflated quadratic f/(β(u − u₃)) = u² + g₁u + g₀: its vertex separates u₁ from u₂, and its
    // roots −g₁/2 ± √D/2 are the band when they cannot be separated.
    const interval g1 = u3_ + c2 / f_.beta, g0 = -c0 / (f_.beta * u3_);
    const interval vertex = -g1 / 2, D = square_enclosed(g1) - 4 * g0;
    std::optional<interval> separation;
    for (const interval& point : {interval(lower(u0_)), interval(upper(u0_)), interval(median(vertex))}) {
      if (lower(point) > -1 && upper(point) < 1 && certain_sign(f_(point)) == 1) {
        separation = point;
        break;
      }
    }
    if (separation) {
      u1_ = detail::top_root_in_bracket(f_, interval(-1), *separation, -1);
      u2_ = detail::top_root_in_bracket(f_, *separation, interval(1), 1);
      du_ = u2_ - u1_;
    }
    if (!separation || !(lower(du_) > 0)) {
      // Steady precession: one band holds both roots, −g₁/2 ± √D/2 (and their brackets' hull when
      // each was found but their difference was not proved positive).
      motion_ = top_motion::steady_precession;
      const interval half_width = sqrt(interval(upper(D) > 0 ? interval(upper(D)) : interval(0))) / 2;
      const interval quadratic_band = hull(interval(vertex - half_width), interval(vertex + half_width));
      const interval band = separation ? intersect(hull(u1_, u2_), quadratic_band) : quadratic_band;
      u1_ = u2_ = intersect(band, interval(-1, 1));
      return;
    }
    motion_ = top_motion::nutation;
    const interval span = u3_ - u1_;
    parameter_.emplace(interval(du_ / span), interval((u3_ - u2_) / span));
    lambda_ = sqrt(interval(f_.beta * span)) / 2;
    n_plus_ = parameter_->characteristic(interval(du_ / (1 - u1_)));
    n_minus_ = parameter_->characteristic(interval(-du_ / (1 + u1_)));
    tau0_ = initial_phase();
    const reduced_argument r0 = parameter_->reduce(tau0_);
    const jacobi_values at_r0 = parameter_->jacobi(r0.r);
    excess_plus0_ = parameter_->third_kind_excess(n_plus_, r0, at_r0);
    excess_minus0_ = parameter_->third_kind_excess(n_minus_, r0, at_r0);
  }

  top_motion motion() const { return motion_; }
  const top_cubic& cubic() const { return f_; }
  const lagrange_top<interval>& top() const { return top_; }
  const top_state<interval>& start() const { return start_; }
  /// The cubic's roots u₁ ≤ u₂ ≤ 1 < u₃; in steady precession u₁ and u₂ are the same band.
  const interval& u1() const { return u1_; }
  const interval& u2() const { return u2_; }
  const interval& u3() const { return u3_; }
  /// p_φ = I₁ b and p_ψ, the conserved momenta.
  interval p_phi() const { return top_.I1() * f_.b; }
  const interval& p_psi() const { return p_psi_; }

  /// The nutation period 2K(m)/λ. In steady precession, the enclosure of 2K(m)/λ over every m the
  /// band allows (m = 0 included: the limit π/λ of small nutations).
  interval nutation_period() const {
    const scoped_interval_digits digits(digits_);
    if (motion_ == top_motion::nutation) return 2 * parameter_->K() / lambda_;
    const interval pi = boost::math::constants::pi<interval>();
    const interval lambda = sqrt(interval(f_.beta * (u3_ - u1_))) / 2;
    const interval m_max(upper(interval(interval(width(u1_)) / (u3_ - u1_))));
    const interval K_max = complete_first_kind(m_max);  // K increases with m, from K(0) = π/2
    return hull(interval(pi / lambda), interval(2 * K_max / lambda));
  }

  /// The state and momenta at time t (any real t, an interval or a point), enclosed.
  top_point_enclosed at(const interval& t) const {
    const scoped_interval_digits digits(digits_);
    return motion_ == top_motion::nutation ? nutating_at(t) : precessing_at(t);
  }

 private:
  /// τ₀ with u₀ = u₁ + (u₂ − u₁) sn²τ₀ and u̇₀ = 2(u₂ − u₁) λ sn cn dn(τ₀), from the nearer turning
  /// point, so that the sign of u̇₀ and not a square root near a turning point fixes it:
  ///   near u₁ (sn²τ₀ ≤ ½): τ₀ = F(am τ₀), sn τ₀ = u̇₀ / (2(u₂ − u₁) λ cn dn), cn² = (u₂ − u₀)/(u₂ − u₁);
  ///   near u₂: τ₀ = K − x, sn(K − x) = cd x (DLMF 22.4.3), so sn x = u̇₀ / (2(u₂ − u₁) λ sn τ₀ dn²τ₀),
  ///   cn²x = m' sn²τ₀ / dn²τ₀, dn²x = m' / dn²τ₀.
  interval initial_phase() const {
    const interval& m = parameter_->m();
    const interval zero_one(0, 1);
    const interval sn2 = intersect(interval((u0_ - u1_) / du_), zero_one), cn2 = intersect(interval((u2_ - u0_) / du_), zero_one);
    const interval dn2 = 1 - m * sn2;
    const interval scale = 2 * du_ * lambda_;
    if (median(sn2) <= boost::multiprecision::mpfr_float(1) / 2) {
      const interval sn = intersect(interval(u0_dot_ / (scale * sqrt(cn2) * sqrt(dn2))), interval(-1, 1));
      return parameter_->first_kind(sn, cn2, dn2);
    }
    const interval& m_complement = parameter_->m_complement();
    const interval sn_x = intersect(interval(u0_dot_ / (scale * sqrt(sn2) * dn2)), interval(-1, 1));
    return parameter_->K() - parameter_->first_kind(sn_x, interval(m_complement * sn2 / dn2), interval(m_complement / dn2));
  }

  /// The rates from 1 − u and 1 + u (each without cancellation): φ̇ and ψ̇ by their partial fractions.
  void set_rates(top_state<interval>& x, const interval& one_minus_u, const interval& one_plus_u) const {
    const interval upward = b_minus_a_ / (2 * one_minus_u), downward = b_plus_a_ / (2 * one_plus_u);
    x.phi_dot = upward + downward;
    x.psi_dot = spin_drift_ - upward + downward;
  }

  top_point_enclosed nutating_at(const interval& t) const {
    const interval tau = tau0_ + lambda_ * t;
    const reduced_argument r = parameter_->reduce(tau);
    const jacobi_values J = parameter_->jacobi(r.r);
    const interval zero_one(0, 1);
    const interval sn2 = intersect(square_enclosed(J.sn), zero_one), cn2 = intersect(square_enclosed(J.cn), zero_one);
    const interval one_minus_u = (1 - u2_) + du_ * cn2, one_plus_u = (1 + u1_) + du_ * sn2;
    const interval u_dot = 2 * du_ * lambda_ * J.sn * J.cn * J.dn;
    top_point_enclosed out;
    top_state<interval>& x = out.state;
    x.theta = 2 * atan(sqrt(interval(one_minus_u / one_plus_u)));
    x.theta_dot = -u_dot / sqrt(interval(one_minus_u * one_plus_u));
    set_rates(x, one_minus_u, one_plus_u);
    const interval J_plus = t / (1 - u1_) + (parameter_->third_kind_excess(n_plus_, r, J) - excess_plus0_) / (lambda_ * (1 - u1_));
    const interval J_minus = t / (1 + u1_) + (parameter_->third_kind_excess(n_minus_, r, J) - excess_minus0_) / (lambda_ * (1 + u1_));
    x.phi = start_.phi + b_minus_a_ / 2 * J_plus + b_plus_a_ / 2 * J_minus;
    x.psi = start_.psi + spin_drift_ * t - b_minus_a_ / 2 * J_plus + b_plus_a_ / 2 * J_minus;
    out.momenta = {interval(top_.I1() * x.theta_dot), p_phi(), p_psi_};
    return out;
  }

  /// Steady precession: u in the band for all t; θ(u) decreases in u, so its ends are the band's
  /// ends' images; θ̇² = f(u)/(1 − u²) is at most f's bound on the band over 1 − u²'s least value;
  /// φ̇ and ψ̇ are their partial fractions on the band, and φ, ψ their integrals, t times those.
  top_point_enclosed precessing_at(const interval& t) const {
    const interval& band = u1_;
    const auto theta_of = [](const interval& u) { return interval(2 * atan(sqrt(interval((1 - u) / (1 + u))))); };
    top_point_enclosed out;
    top_state<interval>& x = out.state;
    x.theta = hull(theta_of(interval(upper(band))), theta_of(interval(lower(band))));
    const interval one_minus_u = 1 - band, one_plus_u = 1 + band;
    // f on the band in its mean-value form, f(c) + f'(band)(band − c), c the band's midpoint: the
    // plain interval evaluation would hold every term's own spread, not f's, about the band's width.
    const interval centre(median(band));
    const boost::multiprecision::mpfr_float f_max = upper(interval(f_(centre) + f_.derivative(band) * (band - centre)));
    const interval rate_max = f_max > 0 ? interval(sqrt(interval(interval(f_max) / (one_minus_u * one_plus_u)))) : interval(0);
    x.theta_dot = interval(lower(interval(-rate_max)), upper(rate_max));
    set_rates(x, one_minus_u, one_plus_u);
    x.phi = start_.phi + t * x.phi_dot;
    x.psi = start_.psi + t * x.psi_dot;
    out.momenta = {interval(top_.I1() * x.theta_dot), p_phi(), p_psi_};
    return out;
  }

  lagrange_top<interval> top_;
  top_state<interval> start_;
  unsigned digits_;
  top_motion motion_ = top_motion::nutation;
  top_cubic f_;
  interval p_psi_, b_minus_a_, b_plus_a_, spin_drift_, u0_, u0_dot_;
  interval u1_, u2_, u3_, du_, lambda_, tau0_, excess_plus0_, excess_minus0_;
  third_kind_characteristic n_plus_, n_minus_;
  std::optional<elliptic_parameter_enclosed> parameter_;
};

}  // namespace simpson

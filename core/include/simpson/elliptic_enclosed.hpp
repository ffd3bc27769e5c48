#pragma once
// Jacobi's elliptic functions and Legendre's integrals of a real parameter m = k² in (0, 1),
// enclosed: MPFI intervals in and out (interval.hpp), computed by Arb's ball arithmetic (FLINT/Arb,
// Debian libflint-arb-dev), whose every function returns a ball proved to hold the exact value; a
// ball is widened to the MPFI interval that holds it, so the figures stay proved.
//   K(k) and K(k'), k' = √(1 − m): acb_elliptic_k (DLMF 19.2.8).
//   sn, cn, dn by Jacobi's theta functions of the nome q = exp(−π K'/K) (DLMF 22.2.4–6), v = πu/(2K):
//     sn = θ₃(0)/θ₂(0) · θ₁(v)/θ₄(v),  cn = θ₄(0)/θ₂(0) · θ₂(v)/θ₄(v),  dn = θ₄(0)/θ₃(0) · θ₃(v)/θ₄(v),
//     the thetas by acb_modular_theta(z = u/(2K), τ = iK'/K).
//   Carlson's R_F and R_J: acb_elliptic_rf, acb_elliptic_rj (DLMF 19.16.1–2).
//   F(φ, k) = sin φ R_F(cos²φ, 1 − m sin²φ, 1) (DLMF 19.25.5),
//   Π(n; φ, k) = F(φ, k) + (n/3) sin³φ R_J(cos²φ, 1 − m sin²φ, 1, 1 − n sin²φ) (DLMF 19.25.14), |φ| ≤ π/2.
// Arb rather than MPFI for these, measured side by side on 2026-12-02 (Release, 50 digits, one core)
// against an MPFI implementation of the same formulas with proved remainders (Carlson's duplication
// with a bounded tail, the theta series of pendulum_exact_enclosed.hpp): R_F 9.8 µs against 228,
// R_J 26 against 415, the four thetas 7.3 against 186; the Lagrange top's evaluation at one time
// 0.12 ms against 2.7, with the same widths or narrower (up to 4 times on the second test top).
// Beyond the paper: the reference of the Lagrange top (lagrange_top_exact.hpp). Pulls in MPFI and Arb
// (link simpson::interval and simpson::arb).

#include <simpson/interval.hpp>

#include <acb.h>
#include <acb_elliptic.h>
#include <acb_modular.h>
#include <arb.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace simpson {

namespace detail {

/// A complex Arb ball, owned.
class acb_ball {
 public:
  acb_ball() { acb_init(x_); }
  ~acb_ball() { acb_clear(x_); }
  acb_ball(const acb_ball&) = delete;
  acb_ball& operator=(const acb_ball&) = delete;
  acb_ptr get() { return x_; }
  acb_srcptr get() const { return x_; }
  arb_ptr real() { return acb_realref(x_); }
  arb_srcptr real() const { return acb_realref(x_); }

 private:
  acb_t x_;
};

/// The working bits of Arb: the intervals' precision and a few guard bits.
inline slong arb_bits() { return static_cast<slong>(mpfi_get_prec(interval(1).backend().data())) + 16; }

/// The real ball that holds the interval x (both ends exact in Arb's midpoint-radius form).
inline void to_arb(arb_ptr out, const interval& x) {
  arb_set_interval_mpfr(out, x.backend().left_data(), x.backend().right_data(), arb_bits());
}

/// The interval that holds the ball x, at the current interval precision (ends rounded outward).
inline interval from_arb(arb_srcptr x) {
  interval out;
  mpfr_t lo, hi;
  const mpfr_prec_t bits = mpfi_get_prec(out.backend().data());
  mpfr_init2(lo, bits);
  mpfr_init2(hi, bits);
  arb_get_interval_mpfr(lo, hi, x);
  mpfi_interv_fr(out.backend().data(), lo, hi);
  mpfr_clear(lo);
  mpfr_clear(hi);
  return out;
}

/// The real part of a complex ball whose exact value is real (the imaginary part's ball then holds 0).
inline interval real_from_acb(const acb_ball& z, const char* what) {
  if (!arb_contains_zero(acb_imagref(z.get()))) {
    throw std::domain_error(std::string("simpson::elliptic_enclosed: ") + what + " is not real");
  }
  if (!arb_is_finite(z.real())) throw std::domain_error(std::string("simpson::elliptic_enclosed: ") + what + " is not finite");
  return from_arb(z.real());
}

}  // namespace detail

/// (DLMF 19.16.1) Carlson's R_F(x, y, z) = ½ ∫₀^∞ dt / √((t+x)(t+y)(t+z)), x, y, z ≥ 0 with at most one
/// of them 0, enclosed (acb_elliptic_rf).
inline interval carlson_rf_enclosed(const interval& x, const interval& y, const interval& z) {
  if (!(lower(x) >= 0 && lower(y) >= 0 && lower(z) >= 0)) {
    throw std::domain_error("simpson::carlson_rf_enclosed: the arguments must be nonnegative");
  }
  detail::acb_ball ax, ay, az, r;
  detail::to_arb(ax.real(), x);
  detail::to_arb(ay.real(), y);
  detail::to_arb(az.real(), z);
  acb_elliptic_rf(r.get(), ax.get(), ay.get(), az.get(), 0, detail::arb_bits());
  return detail::real_from_acb(r, "R_F");
}

/// (DLMF 19.16.2) Carlson's R_J(x, y, z, p) = (3/2) ∫₀^∞ dt / ((t + p) √((t+x)(t+y)(t+z))), x, y, z ≥ 0
/// with at most one of them 0 and p > 0, enclosed (acb_elliptic_rj).
inline interval carlson_rj_enclosed(const interval& x, const interval& y, const interval& z, const interval& p) {
  if (!(lower(x) >= 0 && lower(y) >= 0 && lower(z) >= 0 && lower(p) > 0)) {
    throw std::domain_error("simpson::carlson_rj_enclosed: x, y, z must be nonnegative and p positive");
  }
  detail::acb_ball ax, ay, az, ap, r;
  detail::to_arb(ax.real(), x);
  detail::to_arb(ay.real(), y);
  detail::to_arb(az.real(), z);
  detail::to_arb(ap.real(), p);
  acb_elliptic_rj(r.get(), ax.get(), ay.get(), az.get(), ap.get(), 0, detail::arb_bits());
  return detail::real_from_acb(r, "R_J");
}

/// (DLMF 19.2.8) K(m) = ∫₀^(π/2) dθ/√(1 − m sin²θ), 0 ≤ m < 1, enclosed (acb_elliptic_k).
inline interval complete_first_kind(const interval& m) {
  if (!(lower(m) >= 0 && upper(m) < 1)) throw std::domain_error("simpson::complete_first_kind: m must lie in [0, 1)");
  detail::acb_ball am, K;
  detail::to_arb(am.real(), m);
  acb_elliptic_k(K.get(), am.get(), detail::arb_bits());
  return detail::real_from_acb(K, "K");
}

/// sn, cn, dn at one argument.
struct jacobi_values {
  interval sn, cn, dn;
};

/// An argument u written as 2jK + r, with r in [−K, K] when `inside`; otherwise r lies within its
/// own width (and K's) of `end` · K, end = ±1.
struct reduced_argument {
  long j = 0;
  interval r;
  bool inside = true;
  int end = 0;
};

/// A characteristic n < 1 of the third-kind integral, with Π(n, k) − K(k), computed once.
struct third_kind_characteristic {
  interval n, complete_excess;
};

/// Jacobi's elliptic functions and Legendre's integrals of one parameter m = k² in (0, 1), enclosed.
class elliptic_parameter_enclosed {
 public:
  /// m and m' = 1 − m, each enclosing its exact value (m' passed so that a caller who has it without
  /// cancellation keeps its digits). Throws std::domain_error unless 0 < m < 1 and 0 < m' < 1.
  elliptic_parameter_enclosed(const interval& m, const interval& m_complement) : m_(m), m_complement_(m_complement) {
    if (!(lower(m) > 0 && upper(m) < 1 && lower(m_complement) > 0 && upper(m_complement) < 1)) {
      throw std::domain_error("simpson::elliptic_parameter_enclosed: m must lie in (0, 1)");
    }
    const slong bits = detail::arb_bits();
    detail::acb_ball am, amc, K, Kc, zero, t1, t2, t3, t4;
    detail::to_arb(am.real(), m);
    detail::to_arb(amc.real(), m_complement);
    acb_elliptic_k(K.get(), am.get(), bits);
    acb_elliptic_k(Kc.get(), amc.get(), bits);
    K_ = detail::real_from_acb(K, "K");
    K_complement_ = detail::real_from_acb(Kc, "K'");
    // τ = i K'/K, and the thetas at 0 that scale sn, cn and dn.
    acb_div(tau_.get(), Kc.get(), K.get(), bits);
    acb_mul_onei(tau_.get(), tau_.get());
    acb_set(two_K_.get(), K.get());
    acb_mul_2exp_si(two_K_.get(), two_K_.get(), 1);
    acb_modular_theta(t1.get(), t2.get(), t3.get(), t4.get(), zero.get(), tau_.get(), bits);
    acb_div(sn_factor_.get(), t3.get(), t2.get(), bits);
    acb_div(cn_factor_.get(), t4.get(), t2.get(), bits);
    acb_div(dn_factor_.get(), t4.get(), t3.get(), bits);
  }

  elliptic_parameter_enclosed(const elliptic_parameter_enclosed& other) : m_(other.m_), m_complement_(other.m_complement_),
        K_(other.K_), K_complement_(other.K_complement_) {
    for (auto [to, from] : {std::pair{&tau_, &other.tau_}, {&two_K_, &other.two_K_}, {&sn_factor_, &other.sn_factor_},
                            {&cn_factor_, &other.cn_factor_}, {&dn_factor_, &other.dn_factor_}}) {
      acb_set(to->get(), from->get());
    }
  }
  elliptic_parameter_enclosed& operator=(const elliptic_parameter_enclosed&) = delete;

  const interval& m() const { return m_; }
  const interval& m_complement() const { return m_complement_; }
  /// (DLMF 19.2.8) K(k), the quarter period of sn.
  const interval& K() const { return K_; }
  /// K(k'), the quarter period of sn along the imaginary axis.
  const interval& K_complement() const { return K_complement_; }

  /// (DLMF 22.2.4–6) sn(u, k), cn(u, k), dn(u, k) for any real u.
  jacobi_values jacobi(const interval& u) const {
    const slong bits = detail::arb_bits();
    detail::acb_ball z, t1, t2, t3, t4, sn, cn, dn;
    detail::to_arb(z.real(), u);
    acb_div(z.get(), z.get(), two_K_.get(), bits);
    acb_modular_theta(t1.get(), t2.get(), t3.get(), t4.get(), z.get(), tau_.get(), bits);
    acb_mul(sn.get(), sn_factor_.get(), t1.get(), bits);
    acb_div(sn.get(), sn.get(), t4.get(), bits);
    acb_mul(cn.get(), cn_factor_.get(), t2.get(), bits);
    acb_div(cn.get(), cn.get(), t4.get(), bits);
    acb_mul(dn.get(), dn_factor_.get(), t3.get(), bits);
    acb_div(dn.get(), dn.get(), t4.get(), bits);
    return {detail::real_from_acb(sn, "sn"), detail::real_from_acb(cn, "cn"), detail::real_from_acb(dn, "dn")};
  }

  /// u = 2jK + r, j the nearest integer to u/(2K) at u's midpoint.
  reduced_argument reduce(const interval& u) const {
    reduced_argument out;
    const boost::multiprecision::mpfr_float ratio = median(interval(u / (2 * K_)));
    out.j = static_cast<long>(boost::multiprecision::lround(ratio));
    out.r = u - 2 * interval(out.j) * K_;
    out.inside = upper(out.r) <= lower(K_) && lower(out.r) >= -lower(K_);
    if (!out.inside) out.end = median(out.r) > 0 ? 1 : -1;
    return out;
  }

  /// (DLMF 19.25.5) F(φ, k) = sin φ R_F(cos²φ, 1 − m sin²φ, 1), given sin φ, cos²φ and 1 − m sin²φ
  /// (|φ| ≤ π/2): the argument u of sn with sn u = sin φ, cn u = cos φ ≥ 0.
  interval first_kind(const interval& sine, const interval& cosine_squared, const interval& delta_squared) const {
    return sine * carlson_rf_enclosed(cosine_squared, delta_squared, interval(1));
  }

  /// (DLMF 19.25.2) n with Π(n, k) − K(k) = (n/3) R_J(0, m', 1, 1 − n); throws std::domain_error unless n < 1.
  third_kind_characteristic characteristic(const interval& n) const {
    if (!(upper(n) < 1)) throw std::domain_error("simpson::elliptic_parameter_enclosed: the characteristic n must be below 1");
    return {n, interval(n / 3 * carlson_rj_enclosed(interval(0), m_complement_, interval(1), interval(1 - n)))};
  }

  /// Π(n; am u, k) − u = ∫₀^u n sn²v / (1 − n sn²v) dv, n < 1, for any real u (DLMF 19.25.14 on
  /// the reduced argument, 2j (Π(n) − K) for the whole half-periods): the third-kind integral's
  /// excess over the first-kind one, which is u itself. `at_r` are sn, cn, dn at `reduced.r`. When
  /// r straddles ±K, the mean value theorem on the integrand, whose values lie between 0 and n/(1 − n).
  interval third_kind_excess(const third_kind_characteristic& c, const reduced_argument& reduced, const jacobi_values& at_r) const {
    interval part;
    if (reduced.inside) {
      const interval sn2 = square_enclosed(at_r.sn);
      part = c.n / 3 * at_r.sn * sn2 *
             carlson_rj_enclosed(square_enclosed(at_r.cn), square_enclosed(at_r.dn), interval(1), interval(1 - c.n * sn2));
    } else {
      const interval slope = hull(interval(0), interval(c.n / (1 - c.n)));
      part = reduced.end * c.complete_excess + (reduced.r - reduced.end * K_) * slope;
    }
    return 2 * interval(reduced.j) * c.complete_excess + part;
  }

 private:
  interval m_, m_complement_, K_, K_complement_;
  detail::acb_ball tau_, two_K_, sn_factor_, cn_factor_, dn_factor_;
};

}  // namespace simpson

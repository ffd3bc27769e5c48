// The one-step bound lifted over n steps, and the total error (global_roundoff.hpp).

#include <simpson/verify/global_roundoff.hpp>

#include <simpson/verify/stepper_roundoff.hpp>

#include <simpson/interval.hpp>

#include <boost/math/constants/constants.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace simpson::verify {
namespace {

/// A rational r with r ≥ √v (upper) or r ≤ √v (lower), within about 2^-40 relative, checked exactly.
rational square_root_bound(const rational& v, bool upper) {
  if (v <= 0) return rational(0);
  double guess = std::sqrt(static_cast<double>(v));
  for (int k = 0; k < 64; ++k) {
    const double step = guess * std::ldexp(1.0, -40) * (k + 1);
    const rational r = exact_binary_value(upper ? guess + step : guess - step);
    if (upper ? r * r >= v : (r >= 0 && r * r <= v)) return r;
  }
  throw std::logic_error("square_root_bound: no bound found");
}

/// An interval holding x exactly (a dyadic rational: its numerator and denominator are exact at the
/// working precision as long as they fit; otherwise enclosed by outward rounding).
interval enclosure_of_rational(const rational& x) {
  return interval(interval(numerator(x).str()) / interval(denominator(x).str()));
}

/// The upper end of a non-negative enclosure as a rational, rounded up through double.
rational upper_as_rational(const interval& x) {
  const double up = static_cast<double>(boost::multiprecision::mpfr_float(upper(x)));
  return exact_binary_value(std::nextafter(up, HUGE_VAL));
}

/// ‖(a, b)‖₂ enclosed.
interval euclidean(const interval& a, const interval& b) { return sqrt(interval(a * a + b * b)); }

/// The errors of one n, enclosed.
struct errors_at {
  interval roundoff, discretization, total;
};

template <class Real>
std::vector<global_row> compare_in(const roundoff_problem& problem, const lifting_constants& lifting, const rational& h,
                                   const phase_point<rational>& y0, const std::vector<long long>& at, const flow_oscillator& flow,
                                   bool uniform) {
  std::map<std::string, Real> stored;
  for (const auto& [name, value] : problem.stored) stored[name] = static_cast<Real>(value);
  const scoped_interval_digits digits(40);
  // Φⁿy₀ in closed form: Φ is a rotation by φ in the coordinates u = (√w_p p, √w_q q), since it
  // conserves Q = |u|² with det 1 (so α = δ = cos φ and γ√(w_q/w_p) = sin φ). Iterating Φ in
  // intervals instead would widen each step by about 1 + |β| + |γ| (the wrapping effect): at 40
  // digits nothing would be left after a few hundred steps.
  const interval sw_p = sqrt(enclosure_of_rational(lifting.w_p)), sw_q = sqrt(enclosure_of_rational(lifting.w_q));
  const interval phi = atan2(interval(enclosure_of_rational(problem.exact.gamma) * sw_q / sw_p), enclosure_of_rational(problem.exact.alpha));
  const interval step = enclosure_of_rational(h), p0 = enclosure_of_rational(y0.p), q0 = enclosure_of_rational(y0.q);
  const interval u0p = p0 * sw_p, u0q = q0 * sw_q;
  const interval mass = enclosure_of_rational(flow.m);
  const interval omega = flow.two_pi ? interval(2 * boost::math::constants::pi<interval>()) : enclosure_of_rational(flow.omega);
  const interval stiffness = mass * omega;  // mω
  phase_point<Real> y{static_cast<Real>(y0.p), static_cast<Real>(y0.q)};  // exact: y₀ is chosen representable
  const auto errors = [&](long long n) {
    const interval angle = phi * interval(n), cos_n = cos(angle), sin_n = sin(angle);
    const phase_point<interval> z{interval((cos_n * u0p - sin_n * u0q) / sw_p), interval((sin_n * u0p + cos_n * u0q) / sw_q)};
    // p(t) = p₀ cos ωt − mω q₀ sin ωt, q(t) = q₀ cos ωt + p₀/(mω) sin ωt.
    const interval t = omega * step * interval(n), cosine = cos(t), sine = sin(t);
    const phase_point<interval> exact{interval(p0 * cosine - stiffness * q0 * sine), interval(q0 * cosine + p0 / stiffness * sine)};
    const phase_point<interval> computed{enclosure_of_rational(exact_binary_value(static_cast<double>(y.p))),
                                         enclosure_of_rational(exact_binary_value(static_cast<double>(y.q)))};
    return errors_at{euclidean(interval(computed.p - z.p), interval(computed.q - z.q)),
                     euclidean(interval(z.p - exact.p), interval(z.q - exact.q)),
                     euclidean(interval(computed.p - exact.p), interval(computed.q - exact.q))};
  };
  // A row from the round-off bound at n, the discretization's upper end, and the errors seen.
  const auto row_of = [&](long long n, const rational& discretization, const interval& roundoff_seen, const interval& total_seen) {
    const rational roundoff_bound = rational(n) * lifting.epsilon * lifting.to_euclidean;
    const rational total_bound = roundoff_bound + discretization;
    global_row row;
    row.n = n;
    row.uniform = uniform;
    row.roundoff_bound = decimal_rounded_up(roundoff_bound);
    row.roundoff_seen = boost::multiprecision::mpfr_float(median(roundoff_seen)).str(2, std::ios_base::scientific);  // three significant digits
    row.discretization = decimal_rounded_up(discretization);
    row.total_bound = decimal_rounded_up(total_bound);
    row.total_seen = boost::multiprecision::mpfr_float(lower(total_seen)).str(2, std::ios_base::scientific);  // three significant digits
    // The ratios are computed in double (shown to three digits).
    const double seen_total = static_cast<double>(boost::multiprecision::mpfr_float(lower(total_seen)));
    const double seen_roundoff = static_cast<double>(boost::multiprecision::mpfr_float(lower(roundoff_seen)));
    row.bound_over_seen = seen_total > 0 ? static_cast<double>(total_bound) / seen_total : 0;
    row.roundoff_bound_over_seen = seen_roundoff > 0 ? static_cast<double>(roundoff_bound) / seen_roundoff : 0;
    return row;
  };
  std::vector<global_row> rows;
  long long n = 0;
  for (const long long target : at) {
    if (!uniform) {
      for (; n < target; ++n) y = evaluate(problem.program, stored, y);
      const errors_at e = errors(n);
      rows.push_back(row_of(n, upper_as_rational(e.discretization), e.roundoff, e.total));
      continue;
    }
    // Over every n ≤ target: the bound nεc grows with n, so the target's is the largest; the
    // discretization's largest upper end; the largest round-off and total seen (as enclosures whose
    // lower end is the largest lower end, so that "seen" is never overstated).
    rational discretization(0);
    errors_at largest{interval(0), interval(0), interval(0)};
    for (; n < target;) {
      y = evaluate(problem.program, stored, y);
      const errors_at e = errors(++n);
      discretization = std::max(discretization, upper_as_rational(e.discretization));
      if (lower(e.roundoff) > lower(largest.roundoff)) largest.roundoff = e.roundoff;
      if (lower(e.total) > lower(largest.total)) largest.total = e.total;
    }
    rows.push_back(row_of(n, discretization, largest.roundoff, largest.total));
  }
  return rows;
}

/// A rational as a Coq real literal: "(n / d)".
std::string coq_real(const rational& x) {
  return "(" + numerator(x).str() + " / " + denominator(x).str() + ")";
}

}  // namespace

std::optional<lifting_constants> lifting_for(const roundoff_problem& problem, const claimed_bounds& one_step,
                                             const phase_point<rational>& y0) {
  const one_step_matrix<rational>& phi = problem.exact;
  if (phi.gamma * phi.delta == 0) return std::nullopt;
  lifting_constants out;
  out.w_p = 1;
  out.w_q = -phi.alpha * phi.beta / (phi.gamma * phi.delta);
  // ΦᵀWΦ = W, exactly, with W positive.
  if (out.w_q <= 0 || out.w_p * phi.alpha * phi.alpha + out.w_q * phi.gamma * phi.gamma != out.w_p ||
      out.w_p * phi.beta * phi.beta + out.w_q * phi.delta * phi.delta != out.w_q ||
      out.w_p * phi.alpha * phi.beta + out.w_q * phi.gamma * phi.delta != 0) {
    return std::nullopt;
  }
  out.epsilon = square_root_bound(out.w_p * one_step.p * one_step.p + out.w_q * one_step.q * one_step.q, true);
  out.radius0 = square_root_bound(out.w_p * y0.p * y0.p + out.w_q * y0.q * y0.q, true);
  const rational fits_p = square_root_bound(problem.p_bound * problem.p_bound * out.w_p, false);
  const rational fits_q = square_root_bound(problem.q_bound * problem.q_bound * out.w_q, false);
  out.fits = fits_p < fits_q ? fits_p : fits_q;
  if (out.fits > out.radius0) {
    const rational steps = (out.fits - out.radius0) / out.epsilon;
    out.valid_steps = static_cast<long long>(boost::multiprecision::cpp_int(numerator(steps) / denominator(steps)));
  }
  out.to_euclidean = square_root_bound(1 / (out.w_p < out.w_q ? out.w_p : out.w_q), true);
  return out;
}

std::vector<global_row> global_comparison(const roundoff_problem& problem, const lifting_constants& lifting, const rational& h,
                                          const phase_point<rational>& y0, const std::vector<long long>& at,
                                          const flow_oscillator& flow) {
  for (const long long n : at) {
    if (n > lifting.valid_steps) {
      throw std::invalid_argument("global_comparison: n = " + std::to_string(n) + " is beyond the " +
                                  std::to_string(lifting.valid_steps) + " steps the box holds");
    }
  }
  return problem.format.mantissa_bits == 24 ? compare_in<float>(problem, lifting, h, y0, at, flow, false)
                                            : compare_in<double>(problem, lifting, h, y0, at, flow, false);
}

global_row global_uniform(const roundoff_problem& problem, const lifting_constants& lifting, const rational& h,
                          const phase_point<rational>& y0, long long steps, const flow_oscillator& flow) {
  if (steps < 1 || steps > lifting.valid_steps) {
    throw std::invalid_argument("global_uniform: n <= " + std::to_string(steps) + " is not within the 1.." +
                                std::to_string(lifting.valid_steps) + " steps the box holds");
  }
  return problem.format.mantissa_bits == 24 ? compare_in<float>(problem, lifting, h, y0, {steps}, flow, true).front()
                                            : compare_in<double>(problem, lifting, h, y0, {steps}, flow, true).front();
}

std::string lifting_lemma_coq(const roundoff_problem& problem, const claimed_bounds& one_step, const lifting_constants& lifting) {
  const one_step_matrix<rational>& phi = problem.exact;
  std::string s = fmt::format(
      "(* The lifting lemma of {} in {} (simpson-verify, issue 29): Phi, the invariant form Q and the one-step\n"
      "   bound (Bp, Bq) are the harness's, exactly; Bp and Bq are Gappa's bound, proved in its own certificate.\n"
      "   The float iterate is y_(k+1) = Phi y_k + e_k with |e_k| <= (Bp, Bq) while y_k stays in the box; the error\n"
      "   d_k = y_k - Phi^k y_0 then obeys d_(k+1) = Phi d_k + e_k, and sqrt(Q(d_n)) <= n eps. *)\n"
      "Require Import Reals Lra.\nOpen Scope R_scope.\n\n",
      problem.program.name, problem.format.name);
  s += fmt::format("Definition a := {}.\nDefinition b := {}.\nDefinition c := {}.\nDefinition d := {}.\n", coq_real(phi.alpha),
                   coq_real(phi.beta), coq_real(phi.gamma), coq_real(phi.delta));
  s += fmt::format("Definition wp := {}.\nDefinition wq := {}.\nDefinition Bp := {}.\nDefinition Bq := {}.\nDefinition eps := {}.\n\n",
                   coq_real(lifting.w_p), coq_real(lifting.w_q), coq_real(one_step.p), coq_real(one_step.q),
                   coq_real(lifting.epsilon));
  s += R"coq(Definition Q (x y : R) := wp * x * x + wq * y * y.

Lemma Q_nonneg : forall x y, 0 <= Q x y.
Proof. intros. unfold Q, wp, wq. nra. Qed.

Lemma invariant : forall x y, Q (a * x + b * y) (c * x + d * y) = Q x y.
Proof. intros. unfold Q, a, b, c, d, wp, wq. field. Qed.

Lemma one_step : forall ex ey, -Bp <= ex <= Bp -> -Bq <= ey <= Bq -> Q ex ey <= eps * eps.
Proof. intros ex ey Hx Hy. unfold Q, wp, wq, Bp, Bq, eps in *. nra. Qed.

Lemma cauchy : forall x1 y1 x2 y2, wp * x1 * x2 + wq * y1 * y2 <= sqrt (Q x1 y1) * sqrt (Q x2 y2).
Proof.
  intros. rewrite <- sqrt_mult by apply Q_nonneg.
  destruct (Rle_or_lt (wp * x1 * x2 + wq * y1 * y2) 0) as [H | H].
  - apply Rle_trans with 0; [exact H | apply sqrt_pos].
  - apply Rsqr_incr_0_var; [| apply sqrt_pos].
    rewrite Rsqr_sqrt by (apply Rmult_le_pos; apply Q_nonneg).
    assert (W : 0 <= wp * wq) by (unfold wp, wq; lra).
    pose proof (Rle_0_sqr (x1 * y2 - x2 * y1)) as Sq. unfold Rsqr in Sq.
    assert (0 <= wp * wq * ((x1 * y2 - x2 * y1) * (x1 * y2 - x2 * y1))) by (apply Rmult_le_pos; assumption).
    unfold Rsqr, Q. nra.
Qed.

Lemma triangle : forall x1 y1 x2 y2, sqrt (Q (x1 + x2) (y1 + y2)) <= sqrt (Q x1 y1) + sqrt (Q x2 y2).
Proof.
  intros. apply Rsqr_incr_0_var; [| apply Rplus_le_le_0_compat; apply sqrt_pos].
  rewrite Rsqr_sqrt by apply Q_nonneg.
  pose proof (cauchy x1 y1 x2 y2) as C.
  pose proof (sqrt_sqrt (Q x1 y1) (Q_nonneg x1 y1)) as S1.
  pose proof (sqrt_sqrt (Q x2 y2) (Q_nonneg x2 y2)) as S2.
  unfold Rsqr. unfold Q in *. nra.
Qed.

Theorem lifting : forall (dp dq ep eq : nat -> R),
  dp 0%nat = 0 -> dq 0%nat = 0 ->
  (forall k, dp (S k) = a * dp k + b * dq k + ep k) ->
  (forall k, dq (S k) = c * dp k + d * dq k + eq k) ->
  (forall k, -Bp <= ep k <= Bp /\ -Bq <= eq k <= Bq) ->
  forall n, sqrt (Q (dp n) (dq n)) <= INR n * eps.
Proof.
  intros dp dq ep eq H0p H0q Hp Hq He n. induction n as [| n IH].
  - rewrite H0p, H0q. unfold Q. simpl. replace (wp * 0 * 0 + wq * 0 * 0) with 0 by ring. rewrite sqrt_0. lra.
  - rewrite Hp, Hq, S_INR.
    eapply Rle_trans; [apply triangle |].
    rewrite invariant.
    assert (sqrt (Q (ep n) (eq n)) <= eps).
    { destruct (He n) as [Hx Hy].
      rewrite <- (sqrt_square eps) by (unfold eps; lra).
      apply sqrt_le_1_alt. apply one_step; assumption. }
    lra.
Qed.
)coq";
  return s;
}

}  // namespace simpson::verify

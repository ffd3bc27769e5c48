#pragma once
// The nonlinear Simpson step in a form whose round-off over long runs is a random walk (Brouwer's
// law; Hairer, McLachlan and Razakarivony, BIT 48, 2008), beyond the paper. The step is the
// 3-stage Lobatto IIIA–IIIB step (claim nonlinear-lobatto-equivalence), written with h folded into
// its coefficients:
//   P_i = p − Σ_j Â_ij V'(Q_j),  Q_i = q + Σ_j A_ij P_j / m,
//   q' = q + Σ_i B_i P_i / m,    p' = p − Σ_i B_i V'(Q_i),
// symplectic whenever B_i Â_ij + B_j A_ji = B_i B_j for all i, j (and B = B̂). With
//   B = (b₁, b₂, b₁),  A = [[0, 0, 0], [5b₁/4, b₂/2, −b₁/4], [b₁, b₂, b₁]],
//   Â = [[b₁, −b₂/4, 0], [b₁, b₂/2, 0], [b₁, 5b₂/4, 0]],
// the nine conditions hold for every b₁, b₂ (b₁ = h/6, b₂ = 2h/3 gives Lobatto IIIA–IIIB). If b₁ and
// b₂ are floating-point numbers with at most p − 3 significant bits (p the precision's), every entry
// is one too (5 times a (p − 3)-bit integer has at most p bits; a product by 1/2 or 1/4 is exact), so the stored coefficients satisfy the conditions exactly, not to
// within a rounding: no drift from the coefficients. Q₁ = q, Q₃ = q' and Â's last column is 0, so
// the one unknown is Z = Q₂ − q, solved by Newton's method until its correction stops decreasing
// (iteration to stagnation: a tolerance would stop early and leave an error that does not average
// out). The increments of q and p are added with Kahan's compensated summation.

#include <simpson/nonlinear_simpson_step.hpp>  // detail::finite, max_newton_iterations
#include <simpson/shear_form.hpp>              // compensated_point, detail::compensated_add

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace simpson {

/// The coefficients B, A, Â of the Brouwer form with h folded in (the entries not stored are 0,
/// b₁ or b₂; see the header).
template <class Real>
struct brouwer_coefficients {
  Real b1, b2;             // B = (b₁, b₂, b₁)
  Real a21, a22, a23;      // A's second row: 5b₁/4, b₂/2, −b₁/4
  Real ah12, ah22, ah32;   // Â's second column: −b₂/4, b₂/2, 5b₂/4

  /// The same numbers in another scalar type (exact when To has at least Real's precision).
  template <class To>
  brouwer_coefficients<To> cast() const {
    return {To(b1), To(b2), To(a21), To(a22), To(a23), To(ah12), To(ah22), To(ah32)};
  }
};

namespace detail {
/// x rounded to nearest with three fewer significant bits (the high part of Veltkamp's splitting
/// with factor 2³ + 1), so that 5x/4 is exact; for an exact scalar it returns x.
template <class Real>
Real without_three_low_bits(const Real& x) {
  const Real scaled = 9 * x;
  const Real gap = scaled - x;
  return scaled - gap;
}
}  // namespace detail

/// The coefficients for step h: b₁ = h/6 and b₂ = 2h/3, each rounded in Real and then to three
/// fewer bits (≤ 4.5 eps relative in all); the other entries are exact multiples of them. They satisfy the symplecticity
/// conditions exactly; the method's order conditions hold to a few roundings (a nearby symplectic
/// method, conserving a nearby modified energy).
template <class Real>
brouwer_coefficients<Real> simpson_brouwer_coefficients(const Real& h) {
  const Real b1 = detail::without_three_low_bits(Real(h / 6)), b2 = detail::without_three_low_bits(Real(2 * h / 3));
  return {b1, b2, Real(b1 + b1 / 4), Real(b2 / 2), Real(-b1 / 4), Real(-b2 / 4), Real(b2 / 2), Real(b2 + b2 / 4)};
}

/// What a Brouwer step's Newton solve did.
struct brouwer_step_report {
  int newton_iterations = 0;
};

namespace detail {
/// The increments (Δq, Δp) of one step from (q, p), Z solved to stagnation. Throws
/// std::domain_error, as simpson_nonlinear_step, when a value is not finite, the slope vanishes, or
/// the corrections still decrease after max_newton_iterations.
template <class Real, class Potential>
phase_point<Real> brouwer_increments(const brouwer_coefficients<Real>& k, const Real& m, const Potential& V, const Real& q,
                                     const Real& p, brouwer_step_report& report) {
  using std::abs;
  const Real force_q = V.derivative(q);
  const Real kicked = p - k.b1 * force_q;  // p − b₁ V'(q): the part of every P_i without V'(Q₂)
  const Real row_sum = k.a21 + k.a22 + k.a23, coupling = k.a21 * k.ah12 + k.a22 * k.ah22 + k.a23 * k.ah32;
  Real z = row_sum * p / m;  // the drift to the midpoint: Q₂ = q + h p/(2m)
  Real last_correction(-1), force_z(0);
  for (;;) {
    force_z = V.derivative(Real(q + z));
    // R(Z) = Z − Σ_j A_2j P_j / m with P_j = p − b₁ V'(q) − Â_j2 V'(q + Z).
    const Real residual = z - (k.a21 * (kicked - k.ah12 * force_z) + k.a22 * (kicked - k.ah22 * force_z) +
                               k.a23 * (kicked - k.ah32 * force_z)) / m;
    const Real slope = 1 + coupling * V.second_derivative(Real(q + z)) / m;
    const Real correction = residual / slope;
    if (!finite(correction)) break;
    const Real size = abs(correction);
    if (size == 0 || (last_correction >= 0 && size >= last_correction)) {
      const Real P1 = kicked - k.ah12 * force_z, P2 = kicked - k.ah22 * force_z, P3 = kicked - k.ah32 * force_z;
      const Real dq = (k.b1 * P1 + k.b2 * P2 + k.b1 * P3) / m;
      const Real force_next = V.derivative(Real(q + dq));
      return {Real(-(k.b1 * force_q + k.b2 * force_z + k.b1 * force_next)), dq};
    }
    if (report.newton_iterations == max_newton_iterations) break;
    z -= correction;
    last_correction = size;
    ++report.newton_iterations;
  }
  std::ostringstream what;
  what << "simpson::simpson_brouwer_step: Newton's corrections did not stagnate after " << report.newton_iterations
       << " iterations (";
  if (last_correction >= 0) {
    what << "last finite correction " << std::setprecision(3) << std::scientific << static_cast<double>(last_correction) << ", then ";
  }
  what << (report.newton_iterations == max_newton_iterations ? "still decreasing)" : "a non-finite value or a zero slope)");
  throw std::domain_error(what.str());
}
}  // namespace detail

/// One step in the Brouwer form, the increments added in plain floating point.
template <class Real, class Potential>
brouwer_step_report simpson_brouwer_step(const brouwer_coefficients<Real>& k, const Real& m, const Potential& V, phase_point<Real>& y) {
  brouwer_step_report report;
  const phase_point<Real> d = detail::brouwer_increments(k, m, V, y.q, y.p, report);
  y.q += d.q;
  y.p += d.p;
  return report;
}

/// One step in the Brouwer form, the increments added with compensated summation.
template <class Real, class Potential>
brouwer_step_report simpson_brouwer_step_compensated(const brouwer_coefficients<Real>& k, const Real& m, const Potential& V,
                                                     compensated_point<Real>& z) {
  brouwer_step_report report;
  const phase_point<Real> d = detail::brouwer_increments(k, m, V, z.y.q, z.y.p, report);
  detail::compensated_add(z.y.q, z.carry.q, d.q);
  detail::compensated_add(z.y.p, z.carry.p, d.p);
  return report;
}

}  // namespace simpson

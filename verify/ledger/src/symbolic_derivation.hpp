#pragma once
// The scheme derived from first principles in GiNaC, every step performed by the kernel and none
// typed: the interpolants are solved for, the quadrature rules applied, the Lagrangians
// differentiated, the internal node solved for and substituted, q_{j-1} eliminated. For symbolic
// m, ω, h, the states, and V an uninterpreted function where the paper keeps V general. The
// printed formulas and the core's are compared with these.

#include <simpson/verify/tex_math.hpp>

#include <ginac/ginac.h>

#include <functional>
#include <string>
#include <vector>

namespace simpson::verify::detail {

using potential_function = std::function<GiNaC::ex(const GiNaC::ex&)>;

struct symbolic_derivation {
  GiNaC::ex m, omega, h, t, theta, q_l, q_m, q_r, p, q, q_prev, q_j, q_next, p_j, p_next;

  GiNaC::ex general_V(const GiNaC::ex& x) const;   // V, uninterpreted
  GiNaC::ex harmonic_V(const GiNaC::ex& x) const;  // (oscillateur harmonique): m ω² x²/2

  // §2: L_d from the affine interpolant and the midpoint rule (its momenta and Φ: newmark_derivation()).
  GiNaC::ex classical_lagrangian(const potential_function& V, const GiNaC::ex& l, const GiNaC::ex& r) const;

  // §3: the quadratic through (0, q_l), (h/2, q_m), (h, q_r), solved for; its velocity.
  GiNaC::ex interpolant, velocity, g_l, g_m, g_r;

  // §4: L_h by Simpson's rule on m/2 q'² − V(q) along the interpolant.
  GiNaC::ex simpson_lagrangian(const potential_function& V) const;
  GiNaC::ex lh_dqm;  // ∂L_h/∂q_m, V general

  // §5–6, V harmonic: q_m solved from ∂L_h/∂q_m = 0; L_hʳ; p_r; the Euler–Lagrange scheme; Φ₃.
  GiNaC::ex harmonic_qm, reduced_lagrangian, momentum;
  GiNaC::ex scheme(const GiNaC::ex& prev, const GiNaC::ex& at, const GiNaC::ex& next) const;
  GiNaC::matrix phi3{2, 2};

  /// The steps, in words, for the evidence.
  std::vector<std::string> steps;
  /// Seconds the derivation took (once per process).
  double seconds = 0;
};

/// The derivation, performed once per process in paper_symbols().
const symbolic_derivation& derivation();

/// §2, V harmonic: L_d's momenta and Newmark's Φ by eliminating q_{j-1}; once per process, on first use.
struct classical_derivation {
  GiNaC::ex momentum_right;  // ∂L_d/∂q_r (q_j, q_{j+1}): p_{j+1}
  GiNaC::ex momentum_left;   // −∂L_d/∂q_l (q_j, q_{j+1}): p_j by the Euler–Lagrange equation
  GiNaC::matrix newmark_phi{2, 2};
};
const classical_derivation& newmark_derivation();

/// The one-step matrix of a linear map (p_j, q_j) → (p', q'): the coefficients of p_j and q_j.
GiNaC::matrix one_step_matrix_of(const GiNaC::ex& p_next, const GiNaC::ex& q_next, const GiNaC::ex& p, const GiNaC::ex& q);

}  // namespace simpson::verify::detail

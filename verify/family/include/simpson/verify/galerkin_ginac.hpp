#pragma once
// The second kernel for the family (issue 30): each member derived again in GiNaC, with m, ω and h
// symbolic, independently of galerkin_member.cpp except for the member's definition:
//   - the rule's moments from its own nodal polynomial (τⁿ mod ω_k, integrated), not from
//     quadrature_rule.cpp;
//   - the discrete Lagrangian L_h = h Q[m/2 (q̇)² − m ω²/2 q²] along the interpolant, the
//     internal equations ∂L_h/∂Q_k = 0 solved by lsolve, p_j = −∂L_h/∂q_j solved for q_{j+1},
//     p_{j+1} = ∂L_h/∂q_{j+1}, and Φ as the Jacobian of (p_{j+1}, q_{j+1}) in (p_j, q_j).
// Then, with m, ω, h symbolic: det Φ = 1, ΦᵀWΦ = W, the scaling law
// Φ(m, ω, h) = diag(mω, 1) Φ(1, 1, ωh) diag(1/(mω), 1), and Φ(1, 1, θ) identical to our kernel's.
// For small s also with the internal nodes ν_k as symbols: Φ does not depend on where they sit
// (equispaced, Lobatto, Gauss or any distinct nodes).
// GiNaC stays inside the .cpp: this header is light.

#include <simpson/verify/galerkin_member.hpp>

#include <optional>
#include <string>

namespace simpson::verify {

struct ginac_member_check {
  bool derived = false;
  std::string failure;
  bool same_as_exact_kernel = false;  // Φ(1, 1, θ) is our kernel's Φ, entry by entry
  bool scaling = false;               // Φ(m, ω, h) = diag(mω, 1) Φ(1, 1, ωh) diag(1/(mω), 1)
  bool det_one = false;               // with m, ω, h symbolic
  bool form_conserved = false;        // with m, ω, h symbolic
  std::optional<bool> node_independent;  // checked for s <= node_check_degree
  std::string reduced_lagrangian;     // L_h(q_j, q_{j+1}) in m, ω, h (small members only)
  std::string alpha, beta, gamma, delta;  // Φ in m, ω, h
  /// tr Φ as a rational function of x = ω²h² (it depends on ωh alone, by the scaling law), and the
  /// discriminant (tr Φ)² − 4 of the characteristic polynomial r² − (tr Φ) r + 1, factored over Q.
  std::string trace, discriminant_factored;
  double seconds = 0;
};

/// Derives `ours.member` in GiNaC and checks it against `ours` (which must be derived).
ginac_member_check check_member_in_ginac(const member_analysis& ours, int node_check_degree = 3);

}  // namespace simpson::verify

#pragma once
// The partitioned Runge–Kutta pair of an interpolatory rule with k nodes c_i and weights b_i
// (verify/family): A the collocation matrix a_ij = ∫₀^{c_i} ℓ_j (Lobatto IIIA for a
// Lobatto rule, Gauss–Legendre for Gauss), and its symplectic partner Ā with
// b_i ā_ij + b_j a_ji = b_i b_j (Lobatto IIIB), applied to the oscillator q' = p, p' = −q
// (m = ω = 1, h = θ), exactly and without the nodes, which may be irrational:
//   a vector of stage values is the polynomial of degree < k interpolating it, an element of
//   R = Q[τ]/(ω_k) with ω_k the nodal polynomial; A is r ↦ ∫₀^τ r mod ω_k, the weights are the
//   functional r ↦ ∫₀¹ r (exact below degree k), Ā = 1·bᵀ − A* with A* the adjoint of A for the
//   form (x, y) ↦ Q[x y], whose Gram matrix in 1, τ, …, τ^{k−1} is the moments μ_{m+n}.
// All of it in rational matrices; the stage equations solved in rational functions of θ.

#include <simpson/verify/quadrature_rule.hpp>

#include <simpson/one_step_map.hpp>
#include <simpson/verify/rational_function.hpp>

namespace simpson::verify::family_detail {

/// Φ on (p, q) of the pair: Q = q 1 + θ A P, P = p 1 − θ Ā Q, q' = q + θ bᵀP, p' = p − θ bᵀQ.
one_step_matrix<rational_function> partitioned_pair_map(const quadrature_rule& rule);

}  // namespace simpson::verify::family_detail

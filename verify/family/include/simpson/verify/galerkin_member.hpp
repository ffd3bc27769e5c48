#pragma once
// One member of the family of Galerkin variational integrators (issue 30): the interpolant of
// degree s on [t_j, t_j + h], its end values q_j, q_{j+1} and s − 1 internal degrees of freedom,
// and a quadrature rule Q for the action. For the harmonic oscillator, derived exactly in our
// kernel (rational functions of θ = ωh, m = ω = 1, h = θ; the dimensional-scaling lemma restores
// m and ω):
//   1. the discrete Lagrangian L_h = (1/2θ) xᵀ K(θ) x, K = T − θ² M with T and M the quadrature's
//      stiffness and mass matrices of the basis (1 − τ, τ, τ(1 − τ), τ²(1 − τ), ...);
//   2. the discrete Euler–Lagrange equations ∂L_h/∂(internal) = 0, p_j = −∂L_h/∂q_j,
//      p_{j+1} = ∂L_h/∂q_{j+1};
//   3. the internal nodes eliminated (a Schur complement S of K): exact, or the member stops with
//      "internal system singular" when the quadrature cannot fix them;
//   4. the one-step map Φ in (p, q).
// Where the interpolant's internal nodes sit does not change Φ: the space of degree-s
// polynomials with the end values fixed is the same (the basis only reparametrises it).

#include <simpson/verify/json.hpp>
#include <simpson/verify/run_memo.hpp>
#include <simpson/verify/quadrature_rule.hpp>

#include <array>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace simpson::verify {

struct galerkin_member {
  int degree = 2;  // s
  quadrature_rule rule;
};

/// The rules the family takes for degree s: Newton–Cotes and Lobatto with 2 … s + 2 points, Gauss
/// with 1 … s + 1 (each up to one point beyond what order 2s needs).
std::vector<quadrature_rule> family_rules(int s);

/// "s = 2, Simpson".
std::string member_name(const galerkin_member& m);

/// One connected piece of a member's stable set in ωh: an open band, a band with a closed end
/// where Φ = ±I, or an isolated point (from == to, both closed). Ends as text (exact, or ≈ 10
/// digits of an isolated irrational root) and, for plots only, as doubles.
struct stable_piece {
  std::string from = "0", to;  // to: "" = infinity
  bool from_closed = false, to_closed = false;
  double from_value = 0, to_value = std::numeric_limits<double>::infinity();
};

/// "(0, 2 sqrt(2))", "[a, b)", "{a}".
std::string piece_text(const stable_piece& p);

/// What the harness proves of a member, as text and verdicts.
struct member_analysis {
  galerkin_member member;
  bool derived = false;
  std::string failure;  // why not derived
  std::string alpha, beta, gamma, delta;  // Φ's entries as rational functions of θ (m = ω = 1, h = θ)
  /// The same entries exactly: {numerator, denominator} coefficients in θ, constant first, "p/q".
  std::array<std::array<std::vector<std::string>, 2>, 4> map_coefficients;
  bool det_one = false;
  bool form_conserved = false;  // ΦᵀWΦ = W, W = [[−γ, (α−δ)/2], [(α−δ)/2, β]]
  std::string discriminant;     // (tr Φ)² − 4 as a rational function of x = θ²
  std::vector<stable_piece> stable_set;  // of ωh > 0, in increasing order
  int order = 0;                // of the three-term scheme's truncation error (2 cos θ − tr Φ)/h²
  std::string error_constant;   // c in (2 cos θ − tr Φ)/h² = c ω^(order+2) h^order + ...
  std::vector<std::string> equals;  // the known schemes whose Φ is identical
  long size = 0;                // the largest degree in θ of Φ's numerators and denominators
  double seconds = 0;
  json evidence = json::object();
};

/// Derives and analyses one member; a derivation that would pass `budget_degree` in θ stops
/// with a clear failure instead of running on.
member_analysis analyse_member(const galerkin_member& member, long budget_degree = 400, run_memo* memo = nullptr);

}  // namespace simpson::verify

#pragma once
// The family's claim (issue 30): every Galerkin variational integrator of the family up to a degree
// that gives a one-step map is symplectic and conserves its quadratic form, proved in both kernels
// with m, ω, h symbolic, and certified in Coq member by member.

#include "printed_check_support.hpp"
#include "check_registry.hpp"

#include <simpson/verify/claim.hpp>

#include <vector>

namespace simpson::verify::detail {

/// The degrees the claim covers: s = 1 … family_claim_degree.
inline constexpr int family_claim_degree = 6;

void add_family_checks(check_registry& checks);

/// The Coq goals: det Φ = 1 and ΦᵀWΦ = W for each member with a one-step map (GiNaC's Φ).
std::vector<proof_goal> family_symplectic_goals();

}  // namespace simpson::verify::detail

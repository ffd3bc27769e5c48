#pragma once
// The ledger's part "beyond the paper" (section "beyond"): the Simpson variational integrator for
// any potential V, where the authors' later work takes it. Not in the paper scene ("all" means the
// paper's claims); the scene key "claims": "beyond" selects them.

#include <simpson/verify/claim.hpp>

#include <vector>

namespace simpson::verify::detail {

void add_beyond_claims(std::vector<claim>& claims);
void add_beyond_ndof_claims(std::vector<claim>& claims);

}  // namespace simpson::verify::detail

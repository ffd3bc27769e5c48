#pragma once
// The ledger's part "beyond the paper" (section "beyond"): the Simpson variational integrator for
// any potential V, where the authors' later work takes it. Not in the paper scene ("all" means the
// paper's claims); the scene key "claims": "beyond" selects them.

#include <simpson/verify/claim.hpp>
#include "check_registry.hpp"

#include <vector>

namespace simpson::verify::detail {

void add_beyond_checks(check_registry& checks);
void add_beyond_ndof_checks(check_registry& checks);
void add_beyond_fpu_checks(check_registry& checks);

}  // namespace simpson::verify::detail

#pragma once
// Sections 6 and 7: the momentum p_r, Φ₃, its determinant, the quadratic invariant and H_d.

#include <simpson/verify/claim.hpp>
#include "check_registry.hpp"

#include <vector>

namespace simpson::verify::detail {

void add_section6_7_checks(check_registry& checks);

}  // namespace simpson::verify::detail

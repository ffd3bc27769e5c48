#pragma once
// Section 5: the internal node, the reduced Lagrangian, the three-term scheme, truncation and stability.

#include <simpson/verify/claim.hpp>
#include "check_registry.hpp"

#include <vector>

namespace simpson::verify::detail {

void add_section5_checks(check_registry& checks);

}  // namespace simpson::verify::detail

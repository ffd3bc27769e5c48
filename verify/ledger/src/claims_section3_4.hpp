#pragma once
// Sections 3 and 4: the quadratic interpolant, the Gear derivatives, Simpson's rule and L_h.

#include <simpson/verify/claim.hpp>
#include "check_registry.hpp"

#include <vector>

namespace simpson::verify::detail {

void add_section3_4_checks(check_registry& checks);

}  // namespace simpson::verify::detail

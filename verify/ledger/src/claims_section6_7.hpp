#pragma once
// Sections 4 to 6, where no proof shape decides yet: the derivation of Φ₃ from first principles.

#include <simpson/verify/claim.hpp>
#include "check_registry.hpp"

#include <vector>

namespace simpson::verify::detail {

void add_section6_7_checks(check_registry& checks);

}  // namespace simpson::verify::detail

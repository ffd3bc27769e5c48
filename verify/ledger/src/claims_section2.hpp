#pragma once
// Section 2: the classical variational scheme (Newmark), its momentum, matrix and energy.

#include <simpson/verify/claim.hpp>
#include "check_registry.hpp"

#include <vector>

namespace simpson::verify::detail {

void add_section2_checks(check_registry& checks);

}  // namespace simpson::verify::detail

#pragma once
// Section 2: the classical variational scheme (Newmark), its momentum, matrix and energy.

#include <simpson/verify/claim.hpp>

#include <vector>

namespace simpson::verify::detail {

void add_section2_claims(std::vector<claim>& claims);

}  // namespace simpson::verify::detail

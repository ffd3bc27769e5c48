#pragma once
// Prose the paper states without a formula: the abstract's "stable" and "explicit", and the
// conventions of Section 8's experiment.

#include <simpson/verify/claim.hpp>

#include <vector>

namespace simpson::verify::detail {

void add_abstract_claims(std::vector<claim>& claims);
void add_convention_claims(std::vector<claim>& claims);

}  // namespace simpson::verify::detail

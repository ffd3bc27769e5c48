#pragma once
// Prose the paper states without a formula: the abstract's "stable" and "explicit", and the
// conventions of Section 8's experiment.

#include <simpson/verify/claim.hpp>
#include "check_registry.hpp"

#include <vector>

namespace simpson::verify::detail {

void add_abstract_checks(check_registry& checks);
void add_convention_checks(check_registry& checks);

}  // namespace simpson::verify::detail

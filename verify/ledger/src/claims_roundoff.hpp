#pragma once
// The floating-point claims (issue 29): what a double program stepping Φ₃ can do to the paper's
// Table 1, proved by Gappa and the lifting lemma (verify/floating), not measured.

#include <simpson/verify/claim.hpp>
#include "check_registry.hpp"

#include <vector>

namespace simpson::verify::detail {

void add_roundoff_checks(check_registry& checks);

}  // namespace simpson::verify::detail

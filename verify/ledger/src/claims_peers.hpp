#pragma once
// Findings the paper does not print: how Φ₃ relates to the schemes a user would pick instead, and
// Φ₃ as a product of shears.

#include <simpson/verify/claim.hpp>
#include "check_registry.hpp"

#include <vector>

namespace simpson::verify::detail {

void add_peer_checks(check_registry& checks);
/// Φ₃ as a product of shears (claims_shear.cpp).
void add_shear_checks(check_registry& checks);

}  // namespace simpson::verify::detail

#pragma once
// A finding the paper does not print: how Φ₃ relates to the schemes a user would pick instead.

#include <simpson/verify/claim.hpp>

#include <vector>

namespace simpson::verify::detail {

void add_peer_claims(std::vector<claim>& claims);

}  // namespace simpson::verify::detail

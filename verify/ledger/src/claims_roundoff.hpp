#pragma once
// The floating-point claims (issue 29): what a double program stepping Φ₃ can do to the paper's
// Table 1, proved by Gappa and the lifting lemma (verify/floating), not measured.

#include <simpson/verify/claim.hpp>

#include <vector>

namespace simpson::verify::detail {

void add_roundoff_claims(std::vector<claim>& claims);

}  // namespace simpson::verify::detail

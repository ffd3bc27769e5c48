#pragma once
// Sections 8 and 9: Table 1, the conclusion's claims, and the dimensional-scaling lemma the exact proofs rest on.

#include <simpson/verify/claim.hpp>

#include <vector>

namespace simpson::verify::detail {

void add_section8_9_claims(std::vector<claim>& claims);
void add_scaling_lemma(std::vector<claim>& claims);

}  // namespace simpson::verify::detail

#pragma once
// Sections 8 and 9: Table 1, the conclusion's claims, and the dimensional-scaling lemma the exact proofs rest on.

#include <simpson/verify/claim.hpp>
#include "check_registry.hpp"

#include <vector>

namespace simpson::verify::detail {

void add_section8_9_checks(check_registry& checks);
void add_scaling_lemma_check(check_registry& checks);

}  // namespace simpson::verify::detail

#pragma once
// Each file claims_*.cpp appends the claims of its part of the paper, in the paper's order.

#include <simpson/verify/claim.hpp>

#include <vector>

namespace simpson::verify::detail {

void add_scaling_lemma(std::vector<claim>& claims);
void add_section2_claims(std::vector<claim>& claims);
void add_section3_4_claims(std::vector<claim>& claims);
void add_section5_claims(std::vector<claim>& claims);
void add_section6_7_claims(std::vector<claim>& claims);
void add_section8_9_claims(std::vector<claim>& claims);
void add_peer_claims(std::vector<claim>& claims);

}  // namespace simpson::verify::detail

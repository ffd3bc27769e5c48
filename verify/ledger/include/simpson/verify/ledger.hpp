#pragma once
// The claims ledger: every checkable statement of the paper, in the paper's order.

#include <simpson/verify/claim.hpp>

#include <string>
#include <vector>

namespace simpson::verify {

/// All claims, built once; ids are unique and stable.
const std::vector<claim>& ledger();

/// The claim with this id; throws std::invalid_argument naming the id when there is none.
const claim& find_claim(const std::string& id);

/// The ids that every run of the `paper` scene must contain.
inline const std::vector<std::string>& required_claim_ids() {
  static const std::vector<std::string> ids{"phi3-det", "discriminant-factorization", "hd-invariance", "truncation-1440"};
  return ids;
}

}  // namespace simpson::verify

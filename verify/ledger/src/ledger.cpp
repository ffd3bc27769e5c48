#include <simpson/verify/ledger.hpp>

#include "claims_section2.hpp"
#include "claims_section3_4.hpp"
#include "claims_section5.hpp"
#include "claims_section6_7.hpp"
#include "claims_section8_9.hpp"
#include "claims_peers.hpp"
#include "claims_roundoff.hpp"
#include "claims_beyond.hpp"
#include "claims_family.hpp"
#include "claims_unformulated.hpp"

#include <stdexcept>

namespace simpson::verify {

const std::vector<claim>& ledger() {
  static const std::vector<claim> claims = [] {
    std::vector<claim> all;
    detail::add_scaling_lemma(all);
    detail::add_abstract_claims(all);
    detail::add_section2_claims(all);
    detail::add_section3_4_claims(all);
    detail::add_section5_claims(all);
    detail::add_section6_7_claims(all);
    detail::add_convention_claims(all);
    detail::add_section8_9_claims(all);
    detail::add_roundoff_claims(all);
    detail::add_peer_claims(all);
    detail::add_shear_claims(all);
    detail::add_beyond_claims(all);
    detail::add_beyond_ndof_claims(all);
    detail::add_family_claims(all);
    return all;
  }();
  return claims;
}

const claim& find_claim(const std::string& id) {
  for (const claim& c : ledger()) {
    if (c.id == id) return c;
  }
  throw std::invalid_argument("unknown claim id '" + id + "' (see --list-claims)");
}

}  // namespace simpson::verify

#pragma once
// A member's one-step map Φ as GiNaC expressions in the caller's symbols m, ω, h (galerkin_ginac.cpp's
// derivation): for the ledger's Coq goals. It includes GiNaC, so only translation units that
// already use GiNaC include it.

#include <simpson/verify/galerkin_member.hpp>

#include <ginac/ginac.h>

#include <optional>

namespace simpson::verify {

/// Φ in (p, q), or nothing when the member gives no one-step map.
std::optional<GiNaC::matrix> ginac_one_step_map(const galerkin_member& member, const GiNaC::symbol& m, const GiNaC::symbol& omega,
                                                const GiNaC::symbol& h);

}  // namespace simpson::verify

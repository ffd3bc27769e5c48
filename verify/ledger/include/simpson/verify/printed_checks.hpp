#pragma once
// The claims whose statement is a formula take their printed side from the paper's source (the
// paper layer's reader) and compare it, in GiNaC, with the side our core derives, for symbolic m,
// ω, h, q_ℓ, q_r, p, q (and V uninterpreted): no scaling reduction and no sampling. The claim's own
// check (our kernel) and GiNaC must agree on the derived statement; a printed formula that differs
// from the derived one makes the claim an erratum (the derived formula is its correction), and a
// printed property that fails (det Φ₃ ≠ 1, H_d not conserved) makes it fail.

#include <simpson/verify/claim.hpp>
#include <simpson/verify/claim_book.hpp>  // check_claim

#include <cstddef>
#include <string>
#include <vector>

namespace simpson::verify {

/// True when the claim reads its formula from the paper.
bool reads_printed_formula(const claim& c);

/// The printed formulas the claim's bespoke check reads by name (its GiNaC facet's); none for a claim
/// a proof shape decides (its labels are the claim's labels_read).
std::vector<std::string> formulas_its_check_reads(const claim& c);

/// Seconds the GiNaC derivation from first principles took (performed once per process, on first use).
double ginac_derivation_seconds();

/// How many of `claims` read a formula from the paper.
std::size_t printed_formula_claim_count(const std::vector<claim>& claims);

}  // namespace simpson::verify

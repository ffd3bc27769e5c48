#pragma once
// The claims whose statement is a formula take their printed side from the paper's source (the
// paper layer's reader) and compare it, in GiNaC, with the side our core derives, for symbolic m,
// ω, h, q_ℓ, q_r, p, q (and V uninterpreted): no scaling reduction and no sampling. The claim's own
// check (our kernel) and GiNaC must agree on the derived statement; a printed formula that differs
// from the derived one makes the claim an erratum (the derived formula is its correction), and a
// printed property that fails (det Φ₃ ≠ 1, H_d not conserved) makes it fail.

#include <simpson/verify/claim.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace simpson::verify {

/// True when the claim reads its formula from the paper.
bool reads_printed_formula(const claim& c);

/// The claims of `claims` that read the printed formula `label` (a \label of the paper, or one of
/// its equations).
std::vector<std::string> claims_reading_formula(const std::vector<claim>& claims, const std::string& label);

/// Seconds the GiNaC derivation from first principles took (performed once per process, on first use).
double ginac_derivation_seconds();

/// How many of `claims` read a formula from the paper.
std::size_t printed_formula_claim_count(const std::vector<claim>& claims);

/// Runs the claim's check with the sentences it quotes recorded. A book's claim's check is its
/// decider (its shape, or its bespoke check with the GiNaC check of the printed formulas it reads),
/// its evidence made a verdict by decide() (decide.hpp): both kernels must prove the derived
/// statement (else kernels-disagree); the printed side then decides holds, erratum or fails.
claim_result check_claim(const claim& c, const run_context& ctx);

}  // namespace simpson::verify

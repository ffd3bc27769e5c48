#pragma once
// What the GiNaC kernel checks for one claim whose statement is a formula: the printed side read
// from the document against a side derived from first principles, and a core's formula against the
// same derived side; the goals a certificate states, and the two-kernel rule. Shared by every proof
// shape and bespoke check; nothing here knows the paper's derivation (the book's
// derivation_support.hpp adds that).

#include <simpson/verify/claim.hpp>

#include <simpson/verify/paper_reading.hpp>

#include <ginac/ginac.h>

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace simpson::verify::detail {

/// One identity the GiNaC kernel decided, every symbol free: lhs = rhs (matrices entry by entry).
/// The identities that hold are what a claim's Coq certificate states (coq_export.hpp).
struct proof_goal {
  std::string name;  // which side: "printed", "derived", "core"
  GiNaC::ex lhs, rhs;
  bool holds = false;
  /// A sign goal instead (sign −1: lhs < 0, +1: 0 < lhs; rhs unused) under 0 < e for each e in
  /// `positive`. Coq proves it by rewriting lhs as `factored` (field), each factor times its sign at
  /// `inside` (a point of the region) positive by `nra`, and their product one factor at a time.
  int sign = 0;
  std::vector<GiNaC::ex> positive{};
  GiNaC::ex factored{};
  GiNaC::exmap inside{};
  std::vector<GiNaC::ex> squares{};  // nra is told 0 <= e² for each
};

/// The sign goal `sign` · lhs > 0 on the region 0 < e (e in `positive`), `inside` one of its points,
/// lhs factored by GiNaC. `holds` says only that `inside` is in the region and the sign is right
/// there (a sample, not a proof): the claim's exact evidence is our kernel's Sturm proof, and coqc
/// decides the lemma on the whole region.
proof_goal sign_goal(const std::string& name, const GiNaC::ex& lhs, int sign, std::vector<GiNaC::ex> positive, GiNaC::exmap inside);

/// Why a claim has no Coq statement (its check has no Coq goals, or a formula claim whose GiNaC
/// check decides no identity): its record's `coq_none`, or `otherwise` when the record gives none.
std::string without_coq_statement(const std::string& coq_none,
                                  const std::string& otherwise = "its exact proof is our kernel's alone: no Coq statement yet");

/// What the GiNaC kernel found for one claim.
struct printed_outcome {
  bool holds = false;         // the printed formula is the derived one, or its printed property holds
  bool property = false;      // a property of the printed formula (det = 1, conservation): fails, not erratum
  std::string proved;         // what was shown of the printed side, in words and formulas
  std::string correction;     // the derived formula, when the printed one differs
  bool derived_holds = true;  // the derived statement holds and the core's formula is the derived one
  std::string derived;        // what was shown of the derived side
  std::vector<proof_goal> goals;  // the identities decided, in order
};

using printed_check = std::function<printed_outcome(const paper_reading&)>;

// ---- helpers ----

/// The paper's symbol `name` (paper_symbols()).
GiNaC::ex sym(const std::string& name);

std::string text_of(const GiNaC::ex& e);

/// normal(a − b), entry by entry for matrices.
GiNaC::ex normal_difference(const GiNaC::ex& a, const GiNaC::ex& b);
bool is_zero_expression(const GiNaC::ex& e);

/// The printed side `side` (index into formula_location::sides) of formula `name`.
const GiNaC::ex& printed_side(const paper_reading& r, const std::string& name, std::size_t side = 0);

/// The note of kernels-disagree on `what`: "GiNaC and our kernel reached different conclusions on …".
std::string kernels_differ_on(const std::string& what);

/// The goal lhs = rhs, decided by normal(lhs − rhs) = 0 (matrices entry by entry).
proof_goal decided(const std::string& name, const GiNaC::ex& lhs, const GiNaC::ex& rhs);

/// Adds `g` to `o`'s goals; a goal about the printed formula that fails makes it fail as printed.
void add_goal(printed_outcome& o, const proof_goal& g, bool about_printed);

/// a d − b c of a 2 × 2 matrix, as written (the statement a certificate proves, not its normal form).
GiNaC::ex determinant_2x2(const GiNaC::ex& e);

/// H(Φ y) for a form H in p, q and a 2 × 2 matrix Φ, as written (not normalised).
GiNaC::ex after_step(const GiNaC::ex& H, const GiNaC::ex& phi, const GiNaC::ex& p, const GiNaC::ex& q);

/// printed − derived = 0 decides holds (else erratum, the derived one its correction), and
/// core − derived = 0 decides derived_holds.
printed_outcome compare(const std::string& what, const GiNaC::ex& printed, const GiNaC::ex& derived, const GiNaC::ex& core);

/// The derived side alone: core − derived = 0.
void compare_core(printed_outcome& o, const std::string& what, const GiNaC::ex& derived, const GiNaC::ex& core);

/// Two equations E₁ = 0 and E₂ = 0 are the same when E₂/E₁ is a nonzero factor free of the
/// unknowns (checked by differentiating the normal form). Returns the factor, or nothing.
std::optional<GiNaC::ex> equation_factor(const GiNaC::ex& e1, const GiNaC::ex& e2, const std::vector<GiNaC::ex>& unknowns);

/// Merges two outcomes of the same claim: holds when both hold; texts joined.
printed_outcome both(const printed_outcome& a, const printed_outcome& b);

/// The polynomial part of e (its Order terms dropped) and the order k of its O(h^k), 0 when none.
std::pair<GiNaC::ex, int> split_order(const GiNaC::ex& e, const GiNaC::ex& h);

/// A state replaced by a smooth function of time: `state` becomes function(t + shift).
struct smooth_state {
  GiNaC::ex state;
  std::string function;  // "q" or "p"
  GiNaC::ex shift;       // 0, h, -h, h/2 ...
};

/// `e` with its states replaced by smooth functions, expanded by GiNaC in h: the lowest power of h
/// and its coefficient, with function(t) renamed to the paper's symbol (q, p) and its derivatives
/// to derivative_name(function, "t", k, k), as the reader names {{\dd^k q}\over{\dd t^k}}.
struct smooth_expansion {
  int lowest_power = 0;
  GiNaC::ex leading;  // the coefficient of h^lowest_power
  GiNaC::ex series;   // the whole expansion up to O(h^order), renamed
};
smooth_expansion expand_on_smooth(const GiNaC::ex& e, const std::vector<smooth_state>& states, const GiNaC::ex& h, int order = 4);

}  // namespace simpson::verify::detail

#pragma once
// The bespoke checks: the claims no proof shape decides, each named by its record (`check = "…"` in
// claims/paper.toml) and registered here under that name with every facet it has, in its one file:
// the check itself (our kernel), GiNaC's check of the printed formulas it reads, and the Coq goals of
// our kernel's proof. What they are: Table 1's experiment and its conventions, Maupertuis's name,
// the conclusion's measured order, words read in context (the abstract's "explicit"), the derivation
// of Φ₃ from first principles, and the harness's claims beyond the paper.

#include "check_registry.hpp"

#include <simpson/verify/printed_table1.hpp>
#include <simpson/verify/table1_conventions.hpp>

#include <optional>

namespace simpson::verify::detail {

/// The solution the run's text states for Table 1 (read_stated_solution); none when it states none
/// (its own claim, experiment-conventions, is then text-changed). unformulated.cpp.
std::optional<stated_solution> stated_table1_words(const run_context& ctx);

/// Where the convention search starts: the stated solution, or the search's defaults (q = sin ωt,
/// T = 1) when there is none.
table1_stated search_start(const std::optional<stated_solution>& s);

/// search_start(stated_table1_words(ctx)), for a check that needs only the start.
table1_stated stated_table1_solution(const run_context& ctx);

// Each file's checks, added to the registry (ledger.cpp calls each once).
void add_scaling_lemma_check(check_registry& checks);  // scaling.cpp: the reduction the exact proofs rest on
void add_abstract_checks(check_registry& checks);      // unformulated.cpp
void add_convention_checks(check_registry& checks);    // unformulated.cpp
void add_section2_checks(check_registry& checks);
void add_section5_checks(check_registry& checks);
void add_section6_7_checks(check_registry& checks);
void add_figure1_check(check_registry& checks);
void add_nonlinear_internal_node_check(check_registry& checks);
void add_roundoff_checks(check_registry& checks);
void add_peer_checks(check_registry& checks);
void add_shear_checks(check_registry& checks);
void add_beyond_checks(check_registry& checks);
void add_beyond_ndof_checks(check_registry& checks);
void add_family_checks(check_registry& checks);

}  // namespace simpson::verify::detail

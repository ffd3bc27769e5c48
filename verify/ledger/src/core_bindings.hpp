#pragma once
// Our core bound to the print: each formula of core/ that the paper prints, instantiated in GiNaC
// with the document's symbols and compared with the printed formula a record names
// (claims_file.hpp, core_binding). A changed coefficient in the core changes the verdict of the
// claim that binds it, and the verdict names the core, not the experiments downstream.

#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/claim.hpp>

#include "core_formulas.hpp"
#include <simpson/shapes/proof_shapes.hpp>

#include <vector>

namespace simpson::verify::detail {

/// Reads every binding of `record` from `document` as the run will (its formula, its variables and
/// parameters, declared), and instantiates the core formula with them; throws claims_file_error
/// naming the field (core.formula, core.variables, ...) when one does not read or does not fit.
void check_core_bindings(const claim_record& record, const std::string& file, const tex_document& document,
                         const claim_declarations& declared);

/// `e` with the record's bindings judged: each core formula's difference with the printed formula
/// it binds is zero in GiNaC's normal form and in our kernel, entry by entry. The claim's statement
/// then takes in "our core is the printed formula": a difference makes both kernels' answer no, and
/// the verdict `fails`, naming the core formula, the printed one and the entries that differ (the
/// kernels differing on a binding, kernels-disagree). `call` carries the record's `with` (its `where`
/// definitions are put in on both sides) and the run's corrections (a consequence judged again
/// compares the core with the corrected formula).
decider_evidence bound_to_core(decider_evidence e, const std::vector<core_binding>& bindings, const shape_call& call, const run_context& ctx);

}  // namespace simpson::verify::detail

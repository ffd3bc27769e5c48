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

/// `result` with the record's bindings judged: each core formula's difference with the printed
/// formula it binds is zero in GiNaC's normal form and in our kernel, entry by entry. A difference
/// makes the verdict `fails`, naming the core formula, the printed one and the entries that differ
/// (a harness fault when the two kernels disagree). `call` carries the record's `with` (its `where`
/// definitions are put in on both sides) and the run's corrections (a consequence judged again
/// compares the core with the corrected formula).
claim_result bound_to_core(claim_result result, const std::vector<core_binding>& bindings, const shape_call& call, const run_context& ctx);

}  // namespace simpson::verify::detail

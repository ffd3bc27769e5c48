// The invariance shapes (shape_support.hpp): what a quadratic form's invariance under a one-step map
// asks of the form's coefficients, as Section 7 of the paper derives its conserved form. The system
// (invariance-system), its determinant (invariance-determinant) and its singularity on a printed
// condition (invariance-singular); its kernel there is shapes_invariance_kernel.cpp's.

#include "invariance_support.hpp"

#include <simpson/shapes/shape_support.hpp>

#include <simpson/prove/coq_export.hpp>
#include <simpson/prove/printed_check_support.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace simpson::verify::detail {

using GiNaC::ex;

/// "Q(Φy) = Q(y) for all y iff Γ (ξ, η, ζ)ᵀ = 0": the printed system's rows are the coefficients of
/// the state's degree-2 monomials y_i y_j (i ≤ j, in the state's order: p², pq, q²) in
/// form(map y) − form(y), the form's coefficients its unknowns. Decided as one identity, the change
/// as written against Σ monomial × printed row, every symbol free (the state's too): GiNaC's normal
/// form, our kernel's grid, and the Coq lemma. An erratum's correction is the derived rows, whose
/// identity Coq checks beside the printed one's refutation.
decider_evidence invariance_system_shape(const shape_call& call, const run_context& ctx) {
  using namespace invariance;
  shape_reader read(call, document_of(ctx));
  const ex system = read.formula("system").evalm();
  const ex form = read.formula("form");
  const GiNaC::matrix m = as_square_matrix(read.formula("map"), reference_of(call, "map"));
  const std::vector<GiNaC::symbol> state = read.symbols("state"), unknowns = read.symbols("unknowns");
  const std::string system_ref = reference_of(call, "system"), form_ref = reference_of(call, "form"), map_ref = reference_of(call, "map");
  const invariance_rows d = derive_invariance_rows(form, m, state, unknowns);
  const std::vector<ex>& monomials = d.monomials;
  const std::vector<std::string>& named = d.named;
  const GiNaC::matrix& derived = d.derived;
  const ex& change = d.change;
  claim_result result;
  result.printed = read.printed();
  if (!GiNaC::is_a<GiNaC::matrix>(system) || GiNaC::ex_to<GiNaC::matrix>(system).cols() != 1 ||
      GiNaC::ex_to<GiNaC::matrix>(system).rows() != monomials.size()) {
    result.note = fmt::format("({}) is not a column of {} rows, one for each of {}.", system_ref, monomials.size(), fmt::join(named, ", "));
    return beyond_reach(std::move(result));
  }
  if (!d.not_quadratic.empty()) {
    result.note = fmt::format("({})(({}) y) − ({})(y) is not a quadratic form in the state: {} is left beyond the monomials {}.", form_ref, map_ref,
                              form_ref, d.not_quadratic, fmt::join(named, ", "));
    return beyond_reach(std::move(result));
  }
  const GiNaC::matrix& rows = GiNaC::ex_to<GiNaC::matrix>(system);
  ex printed_sum = 0;
  for (std::size_t k = 0; k < monomials.size(); ++k) printed_sum += monomials[k] * rows(static_cast<unsigned>(k), 0);
  // The entries that differ, first: what a reader corrects in the printed matrix.
  std::vector<std::string> differing;
  std::vector<amendment> amendments;
  for (unsigned k = 0; k < derived.rows(); ++k) {
    for (unsigned u = 0; u < derived.cols(); ++u) {
      const ex printed_entry = GiNaC::normal(GiNaC::expand(rows(k, 0)).coeff(unknowns[u], 1));
      if (!GiNaC::normal(printed_entry - derived(k, u)).is_zero()) {
        differing.push_back(fmt::format("entry ({}, {}) is {}, not {}", k + 1, u + 1, text_of(derived(k, u)), text_of(printed_entry)));
        if (auto a = amendment_between(fmt::format("entry ({}, {}) of the system's matrix", k + 1, u + 1), printed_entry, derived(k, u))) {
          amendments.push_back(*a);
        }
      }
    }
  }
  const std::string what = fmt::format("({})(({}) y) − ({})(y) = {} times the rows of ({})", form_ref, map_ref, form_ref, fmt::join(named, ", "), system_ref);
  decider_evidence e = identity_evidence(read, "system", what, change, printed_sum,
                            fmt::format("{}{}as derived from ({})(({}) y) − ({})(y), the coefficients of {} in the unknowns: {}", fmt::join(differing, "; "),
                                        differing.empty() ? "" : "; ", form_ref, map_ref, form_ref, fmt::join(named, ", "), text_of(derived)));
  e.found.evidence["exact"]["derived_rows"] = d.rows_text;
  if (e.found_false()) {  // the correction certified beside the refutation
    e.found.amendments = amendments;
    ex derived_sum = 0;
    for (std::size_t k = 0; k < monomials.size(); ++k) {
      for (std::size_t u = 0; u < unknowns.size(); ++u) {
        derived_sum += monomials[k] * derived(static_cast<unsigned>(k), static_cast<unsigned>(u)) * unknowns[u];
      }
    }
    e.goals = std::vector<proof_goal>{decided("system", change, printed_sum), decided("derived", change, derived_sum)};
    GiNaC::matrix column(derived.rows(), 1);  // the system as it should be printed: the derived rows times the unknowns
    for (unsigned k = 0; k < derived.rows(); ++k) {
      for (std::size_t u = 0; u < unknowns.size(); ++u) column(k, 0) += derived(k, static_cast<unsigned>(u)) * unknowns[u];
    }
    e.found.corrected_formulas.push_back(read.correction_of("system", column));
  }
  return e;
}

/// "We have det Γ = ...": the printed value against the determinant of the system a quadratic
/// form's invariance under the map gives, derived as `invariance-system` derives its rows (the system
/// as it should be printed: a misprinted entry of the printed system is that claim's finding, not
/// this one's). Decided in both kernels, one Coq lemma; an erratum's correction is the printed value
/// times a number when the two differ by one (certified beside the refutation), else the determinant.
decider_evidence invariance_determinant_shape(const shape_call& call, const run_context& ctx) {
  using namespace invariance;
  shape_reader read(call, document_of(ctx));
  const ex printed = read.formula("printed");
  const ex form = read.formula("form");
  const GiNaC::matrix m = as_square_matrix(read.formula("map"), reference_of(call, "map"));
  const std::vector<GiNaC::symbol> state = read.symbols("state"), unknowns = read.symbols("unknowns");
  const std::string form_ref = reference_of(call, "form"), map_ref = reference_of(call, "map");
  const invariance_rows d = derive_invariance_rows(form, m, state, unknowns);
  claim_result result;
  result.printed = read.printed();
  if (!d.not_quadratic.empty() || d.derived.rows() != d.derived.cols()) {
    result.note = d.not_quadratic.empty()
                      ? fmt::format("The system has {} rows ({}) and {} unknowns: no determinant.", d.derived.rows(), fmt::join(d.named, ", "),
                                    d.derived.cols())
                      : fmt::format("({})(({}) y) − ({})(y) is not a quadratic form in the state: {} is left.", form_ref, map_ref, form_ref, d.not_quadratic);
    return beyond_reach(std::move(result));
  }
  const ex det = d.derived.determinant(GiNaC::determinant_algo::laplace);
  const std::string printed_ref = reference_of(call, "printed");
  // A printed value off by a constant factor (a lost 1/4) is corrected as that multiple of itself,
  // which says what to change; otherwise by the determinant (in normal form: the report's canonical
  // text expands products).
  const ex ratio = is_zero_expression(GiNaC::normal(printed)) ? ex(0) : GiNaC::normal(det / printed);
  const bool multiple = GiNaC::is_a<GiNaC::numeric>(ratio) && !ratio.is_zero();
  const ex corrected = multiple ? ratio * printed : GiNaC::normal(det);
  const std::string what = fmt::format("det of the system ({})(({}) y) = ({})(y) asks of the unknowns = ({})", form_ref, map_ref, form_ref, printed_ref);
  decider_evidence e = identity_evidence(read, "determinant", what, det, printed,
                            multiple ? fmt::format("as derived: det = {} × ${}$ (as printed): a constant factor, the same zeros", text_of(ratio),
                                                   folded_space(read.raw("printed").sides.back()))
                                     : "as derived: det = " + text_of(corrected));
  claim_result& found = e.found;
  found.evidence["exact"]["derived_rows"] = d.rows_text;
  if (e.found_false()) {  // the correction certified beside the refutation
    e.goals = std::vector<proof_goal>{decided("determinant", det, printed), decided("derived", det, corrected)};
    found.constant_factor = multiple;
    found.amendments.push_back(multiple ? amendment{"the printed determinant, off by a constant factor (its zeros the same)",
                                                     folded_space(read.raw("printed").sides.back()), canonical_tex(ratio) + " \\times \\text{the printed}"}
                                         : *amendment_between("the printed determinant", printed, corrected));
    // What should stand where the determinant is printed: the claims that read it are judged again with it.
    found.corrected_formulas.push_back(read.correction_of("printed", corrected));
  }
  return e;
}

/// "det Γ vanishes when αδ − βγ = 1": the determinant of the printed system's coefficient matrix is
/// zero once the printed conditions are put in (each solved for its symbol in `solve_for`), decided
/// in both kernels and in Coq. An erratum when the system as derived (invariance-system) is singular
/// there and the printed one is not: the derived determinant's identity certified beside the
/// refutation. Fails when neither is.
decider_evidence invariance_singular_shape(const shape_call& call, const run_context& ctx) {
  using namespace invariance;
  shape_reader read(call, document_of(ctx));
  read.equations("conditions");  // read first: the principal formula the report lists
  const printed_system p = read_printed_system(call, read);
  const invariance_rows& d = p.d;
  const solved_conditions& solved = p.solved;
  claim_result result;
  result.printed = read.printed();
  if (!p.wrong.empty()) {
    result.note = p.wrong;
    return beyond_reach(std::move(result));
  }
  const ex det_printed = written_determinant(substituted(p.coefficients, solved.values));
  const ex det_derived = written_determinant(substituted(d.derived, solved.values));
  const bool derived_singular = is_zero_expression(GiNaC::normal(det_derived));
  const std::string on = fmt::format("{}", fmt::join(solved.text, ", "));
  const std::string what = fmt::format("det of the printed system's coefficients, with {}, = 0", on);
  decider_evidence e = identity_evidence(read, "printed", what, det_printed, 0,
                            derived_singular ? fmt::format("the system as derived (the rows invariance-system derives) is singular there: with {} its determinant is 0, "
                                                           "and the printed system's is {}",
                                                           on, text_of(GiNaC::factor(GiNaC::normal(det_printed))))
                                             : "",
                            derived_singular ? verdict::erratum : verdict::fails);
  e.found.evidence["exact"]["conditions_solved"] = solved.text;
  e.found.evidence["exact"]["derived_determinant_there"] = text_of(GiNaC::normal(det_derived));
  if (e.found_false() && !derived_singular) {
    e.found.note += fmt::format(" The system as derived is not singular there either: its determinant is {}.", text_of(GiNaC::normal(det_derived)));
  }
  if (e.found_false() && derived_singular) {
    // The conclusion holds of the system as derived; only its derivation from the printed system
    // fails (a consequence of the printed system's own erratum): it holds, with that remark.
    const json evidence = e.found.evidence;
    decider_evidence derived = identity_evidence(read, "derived", fmt::format("det of the system as derived (invariance-system's rows), with {}, = 0", on),
                                                 det_derived, 0, "", verdict::fails);
    derived.found.evidence["exact"]["printed_system"] = evidence["exact"];
    derived.found.evidence["exact"]["conditions_solved"] = solved.text;
    derived.found.remark_kind = finding::derivation_gap;
    derived.found.remark = fmt::format("The printed derivation fails only through {}; the conclusion holds of the system as derived (the rows "
                                       "invariance-system derives), singular with {}. With the printed entries the determinant there is {}, not 0.",
                                       entries_differing(p.coefficients, d.derived), on, text_of(GiNaC::factor(GiNaC::normal(det_printed))));
    derived.found.amendments.push_back(amendment_in_words("the system the conclusion is derived from", "the printed system",
                                                          "the system as derived (its entries corrected)"));
    return derived;
  }
  return e;
}


/// The shapes of this file, each one's name, summary, principal argument and parameters beside the
/// function that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> invariance_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  add({"invariance-system", "the printed system's rows are the coefficients of y_i y_j (i <= j, in the state's order) in form(map y) - form(y)",
       "system",
       with_where(with_invariance({"system", argument_kind::formula, true, "the printed system: a column with a row for each y_i y_j, linear in the unknowns"})),
       invariance_system_shape});
  add({"invariance-determinant", "printed = det of the system form(map y) = form(y) asks of the form's coefficients (the rows as invariance-system derives them)",
       "printed", with_where(with_invariance({"printed", argument_kind::formula, true, "the printed determinant"})), invariance_determinant_shape});
  add({"invariance-singular", "det of the printed system's coefficients is 0 once the printed conditions are put in (each solved for its symbol)",
       "conditions", with_where(with_conditions(with_invariance({"system", argument_kind::formula, true, "the printed system: a column linear in the unknowns"}))),
       invariance_singular_shape});
  return all;
}

}  // namespace simpson::verify::detail

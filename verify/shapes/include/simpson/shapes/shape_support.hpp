#pragma once
// What the proof shapes share (proof_shapes.hpp): reading a call's formulas from the run's
// document with its definitions put in and its symbols checked against the declared ones, the
// verdict on an identity in both kernels with its Coq certificate, and each shape's function, by
// family: identities (shapes_identities.cpp), quadratic forms (shapes_forms.cpp), a form's invariance (shapes_invariance.cpp), derivations (shapes_derivation.cpp), series
// (shapes_series.cpp), a map's explicitness (shapes_explicit.cpp), intervals (shapes_intervals.cpp), characteristic polynomials
// (shapes_characteristic.cpp), quadrature (shapes_quadrature.cpp), sums (shapes_sums.cpp), the prose
// itself (shapes_prose.cpp).

#include <simpson/prove/decide.hpp>
#include <simpson/prove/kernel_zero.hpp>
#include <simpson/shapes/proof_shapes.hpp>

#include <simpson/verify/formula_reference.hpp>

#include <ginac/ginac.h>

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace simpson::verify::detail {

/// The symbol a TeX name reads as ('q_0', '\omega', 'q_{j+1}'); throws std::invalid_argument.
GiNaC::symbol symbol_named(const std::string& tex);

/// The GiNaC names of the symbols (and functions) a file declares.
std::set<std::string> declared_names(const claim_declarations& d);

/// What is wrong with one argument of a call, found while reading it (its `entries`): the record's
/// check names that argument's field.
struct argument_error : std::invalid_argument {
  argument_error(std::string name, const std::string& what) : std::invalid_argument(what), argument(std::move(name)) {}
  std::string argument;
};

/// Reads the formulas of one call from the run's document, with the call's definitions put in, and
/// keeps what it read for the report.
class shape_reader {
 public:
  shape_reader(const shape_call& call, const tex_document& document);

  /// What the call's file declares, for the reader.
  const tex_declarations& reading() const { return call_.declared->reading; }

  bool has(const std::string& parameter) const { return call_.with.count(parameter) > 0; }

  /// The formula the argument names, definitions put in.
  GiNaC::ex formula(const std::string& parameter);

  /// The formula as read, no definition put in.
  referenced_formula raw(const std::string& parameter);

  std::vector<GiNaC::symbol> symbols(const std::string& parameter) const;

  /// The equations the argument names, as read (every side's TeX), each once recorded.
  std::vector<referenced_formula> equations(const std::string& parameter);

  /// Every side of one equation read, parsed, the definitions put in.
  std::vector<GiNaC::ex> sides(const referenced_formula& equation) const;

  /// `e` with the call's definitions put in.
  GiNaC::ex defined(const GiNaC::ex& e) const { return with_definitions(e, definitions_); }

  /// Whether a definition gives `name` a value.
  bool defines(const GiNaC::symbol& name) const;

  /// What was read, the principal formula first (each shape reads it first), the definitions last;
  /// `corrected: true` when a proved correction was read in place of a printed formula.
  json printed() const;

  /// The identity of the formula the argument names (referenced_formula::identity), once read.
  const std::string& identity_of(const std::string& parameter) const;

  /// A proved correction of the formula the argument names, `value` standing where it is printed:
  /// what the claims that read it are judged again with.
  std::shared_ptr<const corrected_formula> correction_of(const std::string& parameter, const GiNaC::ex& value) const;
  /// The same for side k (from 0) of an equation read by sides(): what it is judged again with.
  std::shared_ptr<const corrected_formula> correction_of_side(const referenced_formula& equation, std::size_t k, const GiNaC::ex& value) const;

 private:
  void read_entries(const std::vector<std::string>& references);
  void declared_only(const GiNaC::ex& e, const std::string& where) const;
  GiNaC::ex parsed_side(const referenced_formula& equation, std::size_t k) const;
  void record(const std::string& reference, const std::string& locator, int line, const std::string& tex, const std::optional<GiNaC::ex>& value);
  /// `f` with its value corrected when the call is judged again with a correction of it.
  referenced_formula corrected(referenced_formula f) const;

  const shape_call& call_;
  const tex_document& document_;
  std::set<std::string> declared_;
  std::vector<definition> definitions_;
  json read_ = json::array();
  json definitions_read_ = json::array();
  std::map<std::string, std::string> identities_;  // parameter: the identity of its formula
  /// Whether a proved correction was read in place of a printed formula (the call's corrections):
  /// said in printed(), so that a consequence's second judgment knows it read one.
  mutable bool corrected_ = false;
};

/// The run's document read as TeX (its paper, or a note's document); a harness fault when the run has
/// none.
const tex_document& document_of(const run_context& ctx);

/// Where e, as written, divides by zero once `values` are put in: the first denominator (a power
/// with a negative exponent, innermost first) whose base is 0 there, as text; none when e is defined
/// there. A record's values are put into a formula only after this says none: GiNaC's evaluation
/// throws on a division by zero (a harness fault, exit 3, where the statement is only undefined),
/// and leaks what it was building.
std::optional<std::string> vanishing_denominator(const GiNaC::ex& e, const GiNaC::exmap& values);

/// The evidence on a statement undefined at a record's values (`pole`, from vanishing_denominator):
/// GiNaC finds it fails, with nothing to correct it with; the note says where.
decider_evidence undefined_there(shape_reader& read, const std::string& what, const std::string& pole);

/// The evidence on an identity lhs = rhs: GiNaC's normal form and our kernel's grid each answer
/// whether lhs − rhs is zero; "no" means `when_false` (erratum, with `correction`); where our kernel
/// cannot decide, the note says GiNaC's proof stands alone. `own`, when given, is our kernel's
/// decision of an equivalent statement (the shape says which) instead of its decision of lhs − rhs.
/// The goal, lhs = rhs, names the Coq lemma (<claim>_<goal>).
decider_evidence identity_evidence(shape_reader& read, const std::string& goal, const std::string& what, const GiNaC::ex& lhs,
                                   const GiNaC::ex& rhs, const std::string& correction, verdict when_false = verdict::erratum,
                                   const std::optional<kernel_decision>& own = std::nullopt);

/// The evidence of equal-sides on `equations`: every side equals its equation's first, the call's
/// definitions and then `given` put in (`given_text` says what it puts in: ", with p_j = ..."), in
/// both kernels, one Coq lemma per side; an erratum's correction gives each side as derived.
decider_evidence equal_sides_evidence(const shape_call& call, shape_reader& read, const std::vector<referenced_formula>& equations, const GiNaC::exmap& given,
                                 const std::string& given_text);

/// The evidence of a shape whose two kernels each answered on its statement (`what`, named when they
/// differ): `correction` is the erratum's when GiNaC finds it false.
decider_evidence settled(claim_result found, answer ginac, answer own, const std::string& what, const std::string& correction);

/// "Printed X, should be Y" at `where`, at its simplest: one symbol for another when that is all
/// that differs in a term of several symbols (d^6q/dt^5 for d^6q/dt^6), a constant factor when a
/// long expression (over 40 characters of TeX) is off by one (1/4 × the printed), else the two
/// expressions; none when they are equal.
std::optional<amendment> amendment_between(const std::string& where, const GiNaC::ex& printed, const GiNaC::ex& derived);

/// A finding in words: the words printed, those that should stand (its math readable_math's,
/// readable_math.hpp).
amendment amendment_in_words(const std::string& where, const std::string& printed, const std::string& should_be);

/// e as a square matrix; throws std::invalid_argument naming `what` when it is not one.
GiNaC::matrix as_square_matrix(const GiNaC::ex& e, const std::string& what);

/// A linear three-term scheme's coefficients: scheme = previous q_{j-1} + current q_j + next q_{j+1}
/// (`sequence` = q_{j-1}, q_j, q_{j+1}), each free of the states (GiNaC's derivatives of the tree
/// as read, not normalised); none when the scheme is not one.
struct three_term_coefficients {
  GiNaC::ex previous, current, next;
};
std::optional<three_term_coefficients> linear_three_term(const GiNaC::ex& scheme, const std::vector<GiNaC::symbol>& sequence);

/// Whether the scheme is reversible, its q_{j+1} and q_{j-1} coefficients equal (the characteristic
/// roots' product is 1): in GiNaC's normal form, and not refuted by our kernel, whose decision is `own`.
bool reversible(const three_term_coefficients& terms, kernel_decision& own);

/// The discriminant of the characteristic polynomial divided by its leading coefficient squared,
/// (P₁² − 4P₀P₂)/P₂², in normal form: the sign of the discriminant, and a function of ωh alone for a
/// scheme in ω and h (the unscaled one carries powers of h).
GiNaC::ex monic_discriminant(const three_term_coefficients& terms);

/// The offset k of a state named <base>_<index>±k from the index ("q_j+1": 1, "q_j": 0,
/// "q_j-1/2": −1/2); none when the name is not one.
std::optional<GiNaC::numeric> index_offset(const std::string& name, const std::string& index);

/// The exact solution at the nodes, as the states a scheme puts on it: each application x(t_n + k h)
/// or x(t_{n+k}) of the function `base` that the claims file declares a solution ([symbols]
/// solutions) becomes the state x_{n+k} (the reader's "x_n+k"), `index` being n. Throws
/// argument_error(`parameter`) when `base` is applied and is no declared solution (the words do not
/// say whether x(t_n) is the exact solution or the scheme's value: the message says how to declare
/// it), or when a solution is applied at a point that is no node.
GiNaC::ex solution_at_nodes(const GiNaC::ex& e, const claim_declarations& declared, const std::string& base, const std::string& index,
                            const GiNaC::symbol& h, const std::string& parameter);

/// Whether `e` applies the function `base` (a reader's function) anywhere.
bool applies(const GiNaC::ex& e, const std::string& base);

/// The reference an argument gives.
std::string reference_of(const shape_call& call, const std::string& parameter);

/// The parameters the shapes' specs share: the definitions and the sentence every shape takes
/// (with_where), a sentence's pattern with its hole, the series', invariance's and conditions' own.
const std::vector<shape_parameter>& common_parameters();
std::vector<shape_parameter> with_where(std::vector<shape_parameter> parameters);
shape_parameter pattern_with_hole(std::string name, std::string meaning, std::string hole, bool required = true);
std::vector<shape_parameter> with_series(std::vector<shape_parameter> parameters);
std::vector<shape_parameter> with_invariance(shape_parameter printed);
std::vector<shape_parameter> with_conditions(std::vector<shape_parameter> parameters);

/// The series helpers (shape_support.cpp) of the oscillator's series shapes and the consistency
/// shapes: the Taylor degree that makes a scheme's series exact to an order, the lowest power of h
/// in an expression, and our kernel's decision that f = h^power times a function regular at h = 0.
int taylor_degree(const shape_call& call, const GiNaC::ex& scheme, const std::vector<GiNaC::symbol>& sequence, const GiNaC::symbol& h, int order);
std::optional<int> lowest_power(const GiNaC::ex& e, const GiNaC::symbol& h);
kernel_decision kernel_confirms_order(const GiNaC::ex& f, const GiNaC::symbol& h, int power, bool exact);

/// Each shapes_*.cpp file's shapes, their specs beside the functions that decide them; proof_shapes()
/// lists the files, one line each.
std::vector<proof_shape> identities_shape_specs();
std::vector<proof_shape> forms_shape_specs();
std::vector<proof_shape> invariance_shape_specs();
std::vector<proof_shape> invariance_kernel_shape_specs();
std::vector<proof_shape> stability_criteria_shape_specs();
std::vector<proof_shape> derivation_shape_specs();
std::vector<proof_shape> explicit_shape_specs();
std::vector<proof_shape> intervals_shape_specs();
std::vector<proof_shape> series_shape_specs();
std::vector<proof_shape> consistency_shape_specs();
std::vector<proof_shape> quadrature_shape_specs();
std::vector<proof_shape> sums_shape_specs();
std::vector<proof_shape> emerging_shape_specs();
std::vector<proof_shape> known_method_shape_specs();
std::vector<proof_shape> prose_shape_specs();
std::vector<proof_shape> characteristic_shape_specs();
std::vector<proof_shape> variational_shape_specs();

// The shapes.
decider_evidence identity_shape(const shape_call& call, const run_context& ctx);
decider_evidence equal_sides_shape(const shape_call& call, const run_context& ctx);
decider_evidence derivative_shape(const shape_call& call, const run_context& ctx);
decider_evidence solves_shape(const shape_call& call, const run_context& ctx);
decider_evidence determinant_shape(const shape_call& call, const run_context& ctx);
decider_evidence symplectic_shape(const shape_call& call, const run_context& ctx);
decider_evidence linear_shape(const shape_call& call, const run_context& ctx);
decider_evidence conserved_shape(const shape_call& call, const run_context& ctx);
decider_evidence proportional_shape(const shape_call& call, const run_context& ctx);
decider_evidence invariance_system_shape(const shape_call& call, const run_context& ctx);
decider_evidence invariance_determinant_shape(const shape_call& call, const run_context& ctx);
decider_evidence invariance_singular_shape(const shape_call& call, const run_context& ctx);
decider_evidence invariance_kernel_shape(const shape_call& call, const run_context& ctx);
decider_evidence euler_lagrange_shape(const shape_call& call, const run_context& ctx);
decider_evidence stationary_shape(const shape_call& call, const run_context& ctx);
decider_evidence discrete_momenta_shape(const shape_call& call, const run_context& ctx);
decider_evidence explicit_map_shape(const shape_call& call, const run_context& ctx);
decider_evidence explicit_scheme_shape(const shape_call& call, const run_context& ctx);
decider_evidence sign_iff_shape(const shape_call& call, const run_context& ctx);
decider_evidence discrete_map_shape(const shape_call& call, const run_context& ctx);
decider_evidence truncation_shape(const shape_call& call, const run_context& ctx);
decider_evidence stated_order_shape(const shape_call& call, const run_context& ctx);
decider_evidence map_order_shape(const shape_call& call, const run_context& ctx);
decider_evidence stability_interval_shape(const shape_call& call, const run_context& ctx);
decider_evidence sign_on_interval_shape(const shape_call& call, const run_context& ctx);
decider_evidence factor_signs_shape(const shape_call& call, const run_context& ctx);
decider_evidence characteristic_shape(const shape_call& call, const run_context& ctx);
decider_evidence discriminant_shape(const shape_call& call, const run_context& ctx);
decider_evidence characteristic_roots_shape(const shape_call& call, const run_context& ctx);
decider_evidence root_criterion_shape(const shape_call& call, const run_context& ctx);
decider_evidence quadrature_exactness_shape(const shape_call& call, const run_context& ctx);
decider_evidence discrete_lagrangian_shape(const shape_call& call, const run_context& ctx);
decider_evidence consistency_shape(const shape_call& call, const run_context& ctx);
decider_evidence taylor_expansion_shape(const shape_call& call, const run_context& ctx);
decider_evidence sum_range_shape(const shape_call& call, const run_context& ctx);
decider_evidence unconditional_stability_shape(const shape_call& call, const run_context& ctx);
decider_evidence spelling_shape(const shape_call& call, const run_context& ctx);
decider_evidence emerging_condition_shape(const shape_call& call, const run_context& ctx);
decider_evidence known_method_shape(const shape_call& call, const run_context& ctx);
decider_evidence citations_shape(const shape_call& call, const run_context& ctx);

/// J = [[0, I], [-I, 0]] of n degrees of freedom (2n x 2n): the symplectic form on (q, p).
GiNaC::matrix canonical_j(unsigned n);

/// An expression's terms by their part that `depends` holds for (q_m, sin(q_m), D[1](L)(q_l, v_l)),
/// each such part (by its text) with its coefficient: the product of the term's other factors.
std::map<std::string, std::pair<GiNaC::ex, GiNaC::ex>> terms_by_parts(const GiNaC::ex& e, const std::function<bool(const GiNaC::ex&)>& depends);

/// Where a printed expression and the derived one differ in the coefficient of an application of a
/// function the document leaves general (∂L/∂q̇ at a node): " (the coefficient of X: printed a,
/// derived b; ...)", or nothing when either holds none or they agree on each.
std::string differing_application_coefficients(const GiNaC::ex& printed, const GiNaC::ex& derived);

}  // namespace simpson::verify::detail

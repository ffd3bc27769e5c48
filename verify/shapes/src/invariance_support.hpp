#pragma once
// What the invariance shapes share (shapes_invariance.cpp, shapes_invariance_kernel.cpp): the system
// a quadratic form's invariance under a map asks of its coefficients, derived; the printed system
// read with its conditions solved; and the matrix work both do on them.

#include <simpson/shapes/shape_support.hpp>

#include <optional>
#include <string>
#include <vector>

namespace simpson::verify::detail::invariance {

using GiNaC::ex;

/// What a quadratic form's invariance under a map asks of its coefficients: form(map y) − form(y)
/// as written, the monomials y_i y_j (i ≤ j, in the state's order), and the derived system, the
/// coefficient of each monomial (a row) in each unknown; `not_quadratic` says what is left when the
/// change is not a quadratic form in the state.
struct invariance_rows {
  std::vector<ex> monomials;
  std::vector<std::string> named;
  ex change;
  GiNaC::matrix derived;
  std::vector<std::string> rows_text;
  std::string not_quadratic;
};

invariance_rows derive_invariance_rows(const ex& form, const GiNaC::matrix& m, const std::vector<GiNaC::symbol>& state,
                                       const std::vector<GiNaC::symbol>& unknowns);

/// The system's coefficient matrix: row k's coefficient of each unknown, in normal form; none when a
/// row is not linear and homogeneous in the unknowns.
std::optional<GiNaC::matrix> coefficient_matrix(const GiNaC::matrix& column, const std::vector<GiNaC::symbol>& unknowns);

/// What the printed conditions give: each solved for its symbol (linear in it once the earlier
/// solutions are put in), the later solutions put back into the earlier ones; `not_solved` says which
/// one could not be.
struct solved_conditions {
  GiNaC::exmap values;
  std::vector<std::string> text;  // "delta = alpha", in the order solved
  std::string not_solved;
};

solved_conditions solve_conditions(shape_reader& read, const std::string& conditions, const std::string& solve_for);

/// What the two shapes on a printed system read and check alike: the printed system's coefficient
/// matrix, the rows as derived (invariance-system) and the printed conditions solved; `wrong` says
/// why they cannot be judged (the note of a fails verdict).
struct printed_system {
  ex form;
  std::vector<GiNaC::symbol> state, unknowns;
  invariance_rows d;
  solved_conditions solved;
  GiNaC::matrix coefficients;
  std::string wrong;
};

printed_system read_printed_system(const shape_call& call, shape_reader& read);

/// Where the printed system's matrix differs from the one derived (invariance-system): "entry (i, j),
/// printed X where derived Y", each; the rest agree.
std::string entries_differing(const GiNaC::matrix& printed, const GiNaC::matrix& derived);

/// m with the values put in, as written (not normalised: our kernel and Coq decide the tree).
GiNaC::matrix substituted(const GiNaC::matrix& m, const GiNaC::exmap& values);

GiNaC::matrix normalised(const GiNaC::matrix& m);

/// m without row r and column c.
GiNaC::matrix minor_matrix(const GiNaC::matrix& m, unsigned r, unsigned c);

/// The determinant by cofactors of the first row, as written (GiNaC's determinant normalises, and a
/// zero it finds leaves Coq nothing to check).
ex written_determinant(const GiNaC::matrix& m);

/// Σ_k monomial_k × (m v)_k: zero for every state exactly when m v = 0 (the monomials are distinct),
/// one identity for both kernels and Coq.
ex rows_times(const std::vector<ex>& monomials, const GiNaC::matrix& m, const std::vector<ex>& v);

/// Whether an n × n matrix has rank exactly n − 1 given that its kernel holds a nonzero vector:
/// GiNaC's rank over the rational functions, and our kernel's decision that one (n − 1)-minor is not
/// zero; `where` is the gcd of the minors' numerators (the rank is n − 1 wherever it is not zero).
struct corank_one {
  bool ginac = false;
  kernel_decision own;
  std::string where;
};

corank_one decide_corank_one(const GiNaC::matrix& m);

}  // namespace simpson::verify::detail::invariance

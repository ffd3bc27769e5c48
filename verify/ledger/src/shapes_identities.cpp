// The identity shapes (shape_support.hpp): identity, determinant, symplectic, conserved.

#include "shape_support.hpp"

#include "printed_check_support.hpp"

#include <fmt/format.h>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

GiNaC::matrix canonical_j(unsigned n) {
  GiNaC::matrix j(2 * n, 2 * n);
  for (unsigned k = 0; k < n; ++k) {
    j(k, n + k) = 1;
    j(n + k, k) = -1;
  }
  return j;
}

}  // namespace

claim_result identity_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex rhs = read.formula("rhs"), lhs = read.formula("lhs");
  const std::string what = fmt::format("({}) = ({})", reference_of(call, "lhs"), reference_of(call, "rhs"));
  return identity_verdict(call, read, what, lhs, rhs,
                          fmt::format("as derived from ({}): ({}) = {}", reference_of(call, "lhs"), reference_of(call, "rhs"), text_of(lhs)));
}

claim_result determinant_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex equals = read.formula("equals");
  const GiNaC::matrix m = as_square_matrix(read.formula("matrix"), reference_of(call, "matrix"));
  // As written (a d − b c for 2 × 2): the statement a certificate proves, not GiNaC's evaluated value.
  const ex det = m.rows() == 2 ? determinant_2x2(m) : m.determinant(GiNaC::determinant_algo::laplace);
  const std::string what = fmt::format("det ({}) = {}", reference_of(call, "matrix"), text_of(equals));
  return identity_verdict(call, read, what, det, equals,
                          fmt::format("det ({}) = {}", reference_of(call, "matrix"), text_of(GiNaC::normal(det))));
}

claim_result symplectic_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const GiNaC::matrix m = as_square_matrix(read.formula("matrix"), reference_of(call, "matrix"));
  if (m.rows() % 2 != 0) throw std::invalid_argument(reference_of(call, "matrix") + " has an odd dimension: no symplectic form");
  const GiNaC::matrix j = canonical_j(m.rows() / 2);
  const ex lhs = (m.transpose() * j * m).evalm();
  const std::string what = fmt::format("({})^T J ({}) = J", reference_of(call, "matrix"), reference_of(call, "matrix"));
  GiNaC::matrix normal = GiNaC::ex_to<GiNaC::matrix>(lhs);
  for (unsigned r = 0; r < normal.rows(); ++r) {
    for (unsigned c = 0; c < normal.cols(); ++c) normal(r, c) = GiNaC::normal(normal(r, c));
  }
  return identity_verdict(call, read, what, lhs, ex(j), fmt::format("({})^T J ({}) = {}", reference_of(call, "matrix"), reference_of(call, "matrix"), text_of(normal)));
}

claim_result conserved_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex h = read.formula("function");
  const GiNaC::matrix m = as_square_matrix(read.formula("map"), reference_of(call, "map"));
  const std::vector<GiNaC::symbol> state = read.symbols("state");
  if (state.size() != m.rows()) {
    throw std::invalid_argument(fmt::format("the state has {} symbols and the map {} rows", state.size(), m.rows()));
  }
  GiNaC::matrix y(m.rows(), 1);
  for (unsigned k = 0; k < m.rows(); ++k) y(k, 0) = state[k];
  const GiNaC::matrix next = GiNaC::ex_to<GiNaC::matrix>((m * y).evalm());
  GiNaC::lst step;
  for (unsigned k = 0; k < m.rows(); ++k) step.append(state[k] == next(k, 0));
  const ex after = h.subs(step);
  const std::string what = fmt::format("({})(({}) y) = ({})(y)", reference_of(call, "function"), reference_of(call, "map"), reference_of(call, "function"));
  return identity_verdict(call, read, what, after, h,
                          fmt::format("({})(({}) y) − ({})(y) = {}", reference_of(call, "function"), reference_of(call, "map"),
                                      reference_of(call, "function"), text_of(GiNaC::normal(after - h))));
}

}  // namespace simpson::verify::detail

#pragma once
// Our kernel's decision that an expression GiNaC read from a document is zero, independently of
// GiNaC's normal form: the expression tree as read (not normalised) is evaluated in our exact
// arithmetic (rational functions of one variable θ over cpp_rational) on a grid of rational values
// of every other symbol. The grid lemma: a polynomial of degree ≤ d_i in each grid variable that
// vanishes on d_i + 1 values of each is zero. Its premise is computed by GiNaC (the degrees of the
// numerator of the normal form, and its denominator, evaluated by our kernel at each grid point,
// not zero there), as for the ledger's other grid proofs (grid_lemma.hpp).

#include <ginac/ginac.h>

#include <string>

namespace simpson::verify::detail {

struct kernel_decision {
  enum class result { zero, nonzero, not_applicable };
  result outcome = result::not_applicable;
  std::string evidence;  // one line: the grid and its premise, the point where it is not zero, or why the kernel cannot decide
};

/// Decides e = 0 (a matrix entry by entry). Not applicable when e holds what our kernel does not
/// compute (a square root, a function such as V) or the grid would exceed `most_points`.
kernel_decision kernel_decides_zero(const GiNaC::ex& e, std::size_t most_points = 20000);

}  // namespace simpson::verify::detail

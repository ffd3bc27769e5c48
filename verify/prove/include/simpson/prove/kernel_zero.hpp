#pragma once
// Our kernel's decision that an expression GiNaC read from a document is zero, independently of
// GiNaC's normal form: the expression tree as read (not normalised) is evaluated in our exact
// arithmetic (rational functions of one variable θ over cpp_rational) on a grid of rational values
// of every other symbol. The grid lemma: a polynomial of degree ≤ d_i in each grid variable that
// vanishes on d_i + 1 values of each is zero. Its premise is our kernel's too: d_i bounds the degree
// of the numerator the tree builds (a sum over the product of its terms' denominators, products
// adding degrees, integer powers multiplying them), read from the tree, not from GiNaC's normal
// form; and every denominator in the tree is nonzero at each grid point, or the evaluation there
// stops (a pole) and the grid is moved. GiNaC is not consulted, so a wrong normal form cannot make
// our kernel's grid too small.

#include <ginac/ginac.h>

#include <string>

namespace simpson::verify::detail {

struct kernel_decision {
  enum class result { zero, nonzero, not_applicable };
  result outcome = result::not_applicable;
  std::string evidence;  // one line: the grid and its premise, the point where it is not zero, or why the kernel cannot decide
};

/// Decides e = 0 (a matrix entry by entry). An uninterpreted function of one argument, V, when e is
/// linear in its applications (and their derivatives): zero for each monomial V(x) = x^k, k ≤ 4, so
/// for every polynomial V of degree ≤ 4, the evidence says so. Not applicable when e holds what our
/// kernel does not compute (a square root, two such functions, one not linearly) or the grid would
/// exceed `most_points`.
kernel_decision kernel_decides_zero(const GiNaC::ex& e, std::size_t most_points = 20000);

/// e with the function `name` (as GiNaC registered it) defined as the monomial x^power, its
/// derivatives at each argument too (the paper layer's definitions, as a document's V(q) = ...).
GiNaC::ex with_monomial(const GiNaC::ex& e, const std::string& name, int power);

/// A bound, from the tree as read, on the degree in `symbol` of the denominator e is written over
/// (the product of the factors it divides by): 0 when the symbol is in no denominator; at least the
/// order of e's pole in that symbol at 0.
long kernel_denominator_degree(const GiNaC::ex& e, const std::string& symbol);

}  // namespace simpson::verify::detail

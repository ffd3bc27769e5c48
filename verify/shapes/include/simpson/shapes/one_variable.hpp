#pragma once
// A printed function of one variable on a printed interval 0 < v < c, for the interval shapes
// (shapes_intervals.cpp, shapes_characteristic.cpp): the function reduced to v alone by v's scaling
// (GiNaC), its roots and poles by our kernel's Sturm sequences, the printed end compared exactly, and
// GiNaC's own decision of a sign there, without our kernel.

#include <simpson/prove/coq_export.hpp>

#include <simpson/verify/formula_reference.hpp>
#include <simpson/verify/stability_analysis.hpp>

#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <vector>

namespace simpson::verify::detail {

/// GiNaC's polynomial in t (rational coefficients) as our kernel's; throws std::invalid_argument on
/// a coefficient that is not a rational number.
polynomial as_polynomial(const GiNaC::ex& p, const GiNaC::symbol& t);

/// Our kernel's rational as GiNaC's.
GiNaC::numeric as_numeric(const rational& r);

/// Our kernel's polynomial as GiNaC's, in `x`.
GiNaC::ex as_ginac(const polynomial& p, const GiNaC::symbol& x);

/// A function of the condition's variable v alone, for our kernel: every symbol of v but one
/// eliminated by v's scaling (s = t / (v / s) for a symbol s of v with exponent 1), its numerator
/// and denominator as polynomials in t = v, or in x = v² when both are even (roots exact more often).
struct one_variable {
  GiNaC::symbol t{"interval_variable"};
  GiNaC::ex of_t;  // normal form in t
  polynomial numerator, denominator;
  bool in_square = false;
  std::vector<positive_root> ends;  // positive roots of both, increasing

  /// The sign at x (in the kernel's variable: v, or v²).
  int sign_at(const rational& x) const;
  std::string text(const positive_root& r) const;
  /// The first root or pole inside (0, c), if any; `ambiguous` when one's isolating interval holds c
  /// without c being a root or pole (it lies within 2^-40 of the end, on a side not known).
  struct inside_of {
    std::optional<positive_root> first;
    bool ambiguous = false;
  };
  inside_of first_inside(const rational& c) const;
  /// What Coq is asked (coq_export.hpp): `sign` times the function is positive on 0 < v < c, stated
  /// in the kernel's variable (x = v² when both polynomials are even, else t = v) with the end
  /// `end` (c² or c) rational. The reduction of the printed expression to this one-variable function
  /// (v's scaling) is GiNaC's; nra proves each factor's sign from the two bounds.
  proof_goal sign_goal_on(const std::string& name, int sign, const rational& end) const;
  /// The same on from < (v or v²) < to, both rational.
  proof_goal sign_goal_between(const std::string& name, int sign, const rational& from, const rational& to) const;
  /// The printed end c as our kernel's rational (c, or c² in x), when it is one.
  std::optional<rational> exact(const GiNaC::ex& c) const;
};

/// `f` as a function of v alone, or nothing when it is not one.
std::optional<one_variable> in_variable(const GiNaC::ex& f, const GiNaC::ex& v);

/// The printed condition 0 < v < c: c, or std::invalid_argument naming the condition when it is not so.
GiNaC::ex interval_end(const referenced_formula& condition, const GiNaC::ex& v, const tex_declarations& declared);

/// GiNaC's own decision of the sign of g(v) on 0 < v < end, without our kernel: g as G(u) (u = v,
/// or u = v² when g is even, G = g(sqrt(u)) in normal form), u = E s/(1 + s) mapping s > 0 onto
/// the interval (E = end, or end²); the numerator and the denominator of G, times (1 + s)^degree,
/// have coefficients of one sign each. Sufficient, not necessary: 0 when the coefficients do not
/// decide, with why in `proof`.
int ginac_sign_on(const one_variable& g, const GiNaC::ex& v, const GiNaC::ex& end, std::string& proof);

}  // namespace simpson::verify::detail

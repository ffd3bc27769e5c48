#pragma once
// The stability of a reversible linear three-term scheme on v > 0, from its discriminant as a
// function of v alone: the regions between its positive roots and poles and its sign on each (a
// negative one is a stable band: simple conjugate roots of modulus 1). Shared by the shapes that
// judge what a text says of stability (shapes_characteristic.cpp, shapes_emerging.cpp).

#include <simpson/shapes/one_variable.hpp>
#include <simpson/shapes/shape_support.hpp>

#include <optional>
#include <string>
#include <vector>

namespace simpson::verify::detail {

/// A reversible linear three-term scheme's monic discriminant as a function of the variable alone
/// (what root-criterion and unconditional-stability judge): none, `result`'s note saying why, when
/// the scheme is not one or the discriminant is not such a function (beyond the shape's reach).
struct reversible_scheme {
  three_term_coefficients terms;
  kernel_decision reversible_own;
  GiNaC::ex delta;
  std::optional<one_variable> g;
};
std::optional<reversible_scheme> reversible_premise(const GiNaC::ex& scheme, const std::vector<GiNaC::symbol>& q, const GiNaC::ex& v,
                                                   const std::string& scheme_ref, claim_result& result);

/// A region of v > 0 between consecutive positive roots or poles of the discriminant g (0 first, the
/// last reaching infinity), with g's sign at an inner point: negative is a stable band.
struct discriminant_region {
  std::size_t index;  // the region ends at g.ends[index]; index == g.ends.size() for the last
  bool last;
  rational from;
  std::string from_text, to_text;
  bool negative;
  std::string text() const { return "(" + from_text + ", " + to_text + ")"; }
};
std::vector<discriminant_region> regions_of(const one_variable& g);

/// Coq's goal that g is negative on a stable band, the `number`-th: none when the band reaches
/// infinity or an end is only enclosed (Coq gets rational ends).
std::optional<proof_goal> stable_band_goal(const one_variable& g, const discriminant_region& band, std::size_t number);

}  // namespace simpson::verify::detail

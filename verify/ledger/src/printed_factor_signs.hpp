#pragma once
// The GiNaC side of `discriminant-negative`: the factors of Δ as the paper prints them
// (discriminant-factorized), and the sign of each on the band 0 < ω²h² < hi, proved without
// sampling: each factor is a polynomial F(x) in x = ω²h² (checked), and x = hi·t/(1 + t) maps
// t > 0 onto the band, so F has one sign there when the numerator of F(hi·t/(1 + t))(1 + t)^deg,
// a polynomial in t, has coefficients all of that sign.

#include <string>
#include <vector>

namespace simpson::verify {
struct paper_reading;
}

namespace simpson::verify::detail {

struct printed_factor_sign {
  std::string factor;  // its text (the non-binomial factors multiplied into one prefactor)
  bool prefactor = false;
  int sign = 0;        // +1, -1, or 0 when no sign could be proved on the band
  std::string proof;   // the polynomial in t whose coefficients decide it, or why none
};

std::vector<printed_factor_sign> printed_discriminant_factor_signs(const paper_reading& paper, long band_end);

/// The same proof, in GiNaC, for the core's factors (discriminant_factors), first the prefactor:
/// what our kernel's Sturm proof must agree with.
std::vector<printed_factor_sign> core_discriminant_factor_signs(long band_end);

}  // namespace simpson::verify::detail

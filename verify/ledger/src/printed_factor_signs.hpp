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

/// The band (stabilite) prints, 0 < omega h < U, as x = omega^2 h^2 in (0, U^2): U^2 as a fraction,
/// and the printed bound's text. Throws text_changed when the display is not of that form, or U^2
/// is not a positive rational: a claim that judges "under the stability condition" reads its band here.
struct printed_stability_band {
  long numerator = 0, denominator = 1;  // U^2
  std::string bound;                    // U, as printed
  std::string text() const;             // "0 < omega^2 h^2 < 8 (stabilite: 0 < omega h < 2*sqrt(2))"
};
printed_stability_band read_stability_band(const paper_reading& paper);

std::vector<printed_factor_sign> printed_discriminant_factor_signs(const paper_reading& paper, const printed_stability_band& band);

/// The same proof, in GiNaC, for the core's factors (discriminant_factors), first the prefactor:
/// what our kernel's Sturm proof must agree with.
std::vector<printed_factor_sign> core_discriminant_factor_signs(const printed_stability_band& band);

}  // namespace simpson::verify::detail

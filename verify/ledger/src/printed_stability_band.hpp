#pragma once
// The band (stabilite) prints, as the bespoke claims that judge "under the stability condition" read
// it (roots-product-one): 0 < omega h < U, as x = omega^2 h^2 in (0, U^2).

#include <string>

namespace simpson::verify {
struct paper_reading;
}

namespace simpson::verify::detail {

/// U^2 as a fraction, and the printed bound's text. read_stability_band throws text_changed when the
/// display is not of that form, or U^2 is not a positive rational.
struct printed_stability_band {
  long numerator = 0, denominator = 1;  // U^2
  std::string bound;                    // U, as printed
  std::string text() const;             // "0 < omega^2 h^2 < 8 (stabilite: 0 < omega h < 2*sqrt(2))"
};
printed_stability_band read_stability_band(const paper_reading& paper);

}  // namespace simpson::verify::detail

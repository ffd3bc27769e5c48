#include "printed_stability_band.hpp"

#include "printed_check_support.hpp"

#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/quoted_words.hpp>

namespace simpson::verify::detail {

using GiNaC::ex;

std::string printed_stability_band::text() const {
  const std::string end = denominator == 1 ? std::to_string(numerator) : std::to_string(numerator) + "/" + std::to_string(denominator);
  return "0 < omega^2 h^2 < " + end + " ((stabilite) as printed: 0 < omega h < " + bound + ")";
}

printed_stability_band read_stability_band(const paper_reading& paper) {
  const ex lower = printed_side(paper, "stabilite", 0), middle = printed_side(paper, "stabilite", 1), upper = printed_side(paper, "stabilite", 2);
  const ex square = GiNaC::normal(GiNaC::pow(upper, 2));
  const bool form = GiNaC::normal(lower).is_zero() && GiNaC::normal(middle - sym("omega") * sym("h")).is_zero();
  if (!form || !GiNaC::is_a<GiNaC::numeric>(square) || !GiNaC::ex_to<GiNaC::numeric>(square).is_rational() ||
      !GiNaC::ex_to<GiNaC::numeric>(square).is_positive()) {
    throw text_changed("(stabilite) reads " + text_of(lower) + " < " + text_of(middle) + " < " + text_of(upper) +
                       ", not 0 < omega h < U with U^2 a positive rational: the band a claim judges under it is not read");
  }
  const GiNaC::numeric q = GiNaC::ex_to<GiNaC::numeric>(square);
  printed_stability_band band;
  band.numerator = q.numer().to_long();
  band.denominator = q.denom().to_long();
  band.bound = text_of(upper);
  return band;
}

}  // namespace simpson::verify::detail

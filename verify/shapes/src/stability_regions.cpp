// The stability regions of a reversible three-term scheme: see stability_regions.hpp.

#include <simpson/shapes/stability_regions.hpp>

#include <simpson/prove/printed_check_support.hpp>

namespace simpson::verify::detail {

using GiNaC::ex;

std::optional<reversible_scheme> reversible_premise(const ex& scheme, const std::vector<GiNaC::symbol>& q, const ex& v, const std::string& scheme_ref,
                                                   claim_result& result) {
  reversible_scheme out;
  const std::optional<three_term_coefficients> terms = linear_three_term(scheme, q);
  if (!terms || GiNaC::normal(terms->next).is_zero() || !reversible(*terms, out.reversible_own)) {
    result.note = "The shape judges linear three-term schemes whose first and last coefficients are equal; (" + scheme_ref + ") is not one.";
    return std::nullopt;
  }
  out.terms = *terms;
  out.delta = monic_discriminant(*terms);
  out.g = in_variable(out.delta, v);
  if (!out.g) {
    result.note = "The discriminant " + text_of(out.delta) + " is not a function of " + text_of(v) + " alone.";
    return std::nullopt;
  }
  return out;
}

std::vector<discriminant_region> regions_of(const one_variable& g) {
  std::vector<discriminant_region> out;
  rational from = 0;
  std::string from_text = "0";
  for (std::size_t k = 0; k <= g.ends.size(); ++k) {
    const bool last = k == g.ends.size();
    const rational inner = last ? rational(from + 1) : rational((from + g.ends[k].low) / 2);
    const std::string to_text = last ? "infinity" : g.text(g.ends[k]);
    out.push_back({k, last, from, from_text, to_text, g.sign_at(inner) < 0});
    if (!last) {
      from = g.ends[k].high;
      from_text = to_text;
    }
  }
  return out;
}

std::optional<proof_goal> stable_band_goal(const one_variable& g, const discriminant_region& band, std::size_t number) {
  const std::size_t k = band.index;
  if (band.last || !g.ends[k].exact() || (k > 0 && !g.ends[k - 1].exact())) return std::nullopt;
  return g.sign_goal_between("stable_band_" + std::to_string(number), -1, band.from, g.ends[k].low);
}

}  // namespace simpson::verify::detail

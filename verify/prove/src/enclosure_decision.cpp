// An enclosure's verdict: see enclosure_decision.hpp.

#include <simpson/verify/enclosure_decision.hpp>

#include <simpson/scalar_traits.hpp>

namespace simpson::verify {

interval judged_scale(const residual_and_bound<interval>& r) {
  // k·cond = bound / eps, at the digits the residual was computed in.
  return r.zero_claimed ? interval(r.bound / eps<interval>() * interval(identity_resolution)) : r.bound;
}

enclosure_outcome decide(const residual_and_bound<interval>& r) {
  if (r.zero_claimed) {
    if (certain_sign(r.residual) != 0) return enclosure_outcome::fails;
    return width(r.residual) <= lower(judged_scale(r)) ? enclosure_outcome::holds : enclosure_outcome::undecided;
  }
  const interval magnitude = abs(r.residual);
  if (upper(magnitude) <= lower(r.bound)) return enclosure_outcome::holds;
  if (lower(magnitude) > upper(r.bound)) return enclosure_outcome::fails;
  return enclosure_outcome::undecided;
}

std::string enclosure_rule(bool zero_claimed) {
  if (zero_claimed) {
    return std::string("identity: fails when the enclosure of the residual excludes 0; holds when it contains 0 and is narrower "
                       "than ") + identity_resolution + " k cond (the check's round-off bound over eps), so that it excludes every "
                       "larger residual; otherwise undecided and the digits double";
  }
  return "bound: holds when every point of |residual| is below every point of the bound's enclosure, fails when every point is "
         "above; otherwise undecided and the digits double";
}

}  // namespace simpson::verify

#pragma once
// A numeric claim decided by an enclosure, not by a tolerance. The residual is computed in interval
// arithmetic from exact inputs, so the exact residual lies in the interval; then
// - an identity (residual = 0) fails when the interval excludes 0, and holds when it contains 0 and
//   is narrow enough to have excluded any residual above identity_resolution · k·cond (the check's
//   own condition factor): 10¹⁴ times below what a double recheck can see;
// - a bound (|residual| ≤ bound, the bound itself enclosed) holds when every point of |residual| is
//   below every point of the bound, and fails when every point is above;
// - otherwise the precision is not enough: undecided, and the caller raises it.

#include <simpson/verify/enclosure_undecided.hpp>

#include <simpson/interval.hpp>
#include <simpson/residual.hpp>

#include <string>

namespace simpson::verify {

enum class enclosure_outcome { holds, fails, undecided };

/// An identity's enclosure must be narrower than this times its check's k·cond (bound / eps).
inline constexpr const char* identity_resolution = "1e-30";

/// What r is judged against: the bound, or for an identity identity_resolution · bound / eps (the
/// width its enclosure must stay under), at the current interval digits.
interval judged_scale(const residual_and_bound<interval>& r);

/// Decides r at the interval precision it was computed in (eps is read at the current digits).
enclosure_outcome decide(const residual_and_bound<interval>& r);

/// The rule of decide() in words, for the evidence.
std::string enclosure_rule(bool zero_claimed);

}  // namespace simpson::verify

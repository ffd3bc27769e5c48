#pragma once
// The convention search's parts shared by its files (convention_search.cpp, convention_extent.cpp):
// a continuous parameter's value in the unit interval the optimisers move in (log-uniform where the
// parameter is a scale), and the joint extent of a fitted parameter.

#include <simpson/verify/convention_search.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace simpson::verify::detail {

inline double to_unit(const continuous_parameter& p, double v) {
  return p.log_scale ? std::log(v / p.low) / std::log(p.high / p.low) : (v - p.low) / (p.high - p.low);
}

inline double from_unit(const continuous_parameter& p, double u) {
  u = std::clamp(u, 0.0, 1.0);
  return p.log_scale ? p.low * std::pow(p.high / p.low, u) : p.low + u * (p.high - p.low);
}

/// How far one parameter reaches, jointly with the others, over the values that reproduce every entry:
/// NLopt's COBYLA maximises `direction` times its unit coordinate subject to every residual <= 1, all
/// parameters free, from `start` (which reproduces the table). Returns the farthest value at which a
/// full run reproduced every entry: each end of the extent is attained, so the joint region is at
/// least this wide (an inner bound: a region of several pieces may reach farther).
double joint_end(const std::vector<printed_entry>& printed, const convention_choice& choice, const std::vector<continuous_parameter>& continuous,
                 const parametrised_experiment& experiment, const parameter_values& start, std::size_t which, int direction,
                 std::size_t& evaluations);

}  // namespace simpson::verify::detail

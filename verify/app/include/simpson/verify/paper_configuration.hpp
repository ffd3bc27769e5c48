#pragma once
// Φ₃ at the paper's configuration in each precision of a scene: the table report.md opens with.

#include <simpson/precision.hpp>
#include <simpson/verify/json.hpp>

#include <vector>

namespace simpson::verify {

/// Φ_3, det Φ_3 − 1, Δ and H_d(Φ_3 y) − H_d(y) at m = 1, ω = 2π, h = 1/15 in each precision.
json paper_configuration(const std::vector<precision>& precisions);

}  // namespace simpson::verify

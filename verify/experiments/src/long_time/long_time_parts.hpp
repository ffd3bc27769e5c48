#pragma once
// The parts of the long_time section (long_time_section.cpp assembles them).

#include <simpson/verify/long_time_section.hpp>

namespace simpson::verify::detail {

/// Φ₃'s three forms in double: matrix, shear, shear with compensated summation (Brouwer's law).
void add_long_time_forms(const long_time_settings& s, section_result& out);

}  // namespace simpson::verify::detail

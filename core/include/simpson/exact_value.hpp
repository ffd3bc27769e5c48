#pragma once
// The exact rational value of a floating-point number of any of the precisions: what a test or a
// claim uses to check a floating-point identity without rounding.

#include <simpson/precision.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <type_traits>

namespace simpson {

/// The exact rational value of a floating-point number.
template <class Real>
rational to_rational(const Real& v) {
  if constexpr (std::is_floating_point_v<Real>) {
    int exponent = 0;
    const Real mantissa = std::frexp(v, &exponent);  // v = mantissa 2^exponent, |mantissa| in [0.5, 1)
    const Real scaled = std::ldexp(mantissa, std::numeric_limits<Real>::digits);  // an integer
    // |scaled| < 2^64: split into two 32-bit halves so that long double's 64-bit mantissa fits.
    const Real high = std::trunc(std::ldexp(scaled, -32));
    const Real low = scaled - std::ldexp(high, 32);
    rational r = rational(static_cast<long long>(high)) * rational(4294967296LL) + rational(static_cast<long long>(low));
    const int shift = exponent - std::numeric_limits<Real>::digits;
    const rational two(2);
    for (int k = 0; k < std::abs(shift); ++k) r = shift > 0 ? rational(r * two) : rational(r / two);
    return r;
  } else {
    return v.template convert_to<rational>();
  }
}

}  // namespace simpson

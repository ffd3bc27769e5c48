#pragma once
// What generic code needs to know of its scalar: whether it is exact, its unit round-off, and its
// decimal text. Header-only and free of any backend. The headers of the formulas used with the
// whole precision list also include precision_types.hpp, to declare their instances extern.

#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

namespace simpson {

/// Carries a scalar type into a generic lambda: `[](auto tag) { using Real = typename decltype(tag)::type; }`.
template <class Real>
struct precision_tag {
  using type = Real;
};

/// True when arithmetic in Real never rounds (rational): its epsilon is zero and checks are equalities.
template <class Real>
inline constexpr bool is_exact_v = std::numeric_limits<Real>::is_exact;

/// True for an interval scalar (interval.hpp specialises it): its arithmetic rounds outward, so
/// round-off is inside the value and needs no bound of its own.
template <class Real>
inline constexpr bool is_interval_v = false;

/// Unit round-off of Real at the current working precision; zero for exact types.
/// For `mpfr` it follows the digits set by the innermost scoped_mpfr_digits.
template <class Real>
Real eps() {
  if constexpr (is_exact_v<Real>) {
    return Real(0);
  } else {
    return std::numeric_limits<Real>::epsilon();
  }
}

/// Decimal text of a value: `digits` significant digits in scientific notation; exact for rational
/// (numerator/denominator).
template <class Real>
std::string to_string(const Real& value, int digits = std::numeric_limits<double>::max_digits10) {
  std::ostringstream out;
  if constexpr (!is_exact_v<Real>) {
    out << std::scientific << std::setprecision(digits > 1 ? digits - 1 : 0);
  }
  out << value;
  return out.str();
}

}  // namespace simpson

#pragma once
// Figures with guaranteed digits for the sections' runs above double: a value a run computed in its
// precision (an iterate: an exact binary number) enters an interval exactly, the quantity reported
// is evaluated on it in MPFI, and the figure shows only the digits the enclosure guarantees
// (figure::enclosed). Pulls in MPFI: for the experiments' .cpp files only.

#include <simpson/verify/figure.hpp>

#include <simpson/interval.hpp>
#include <simpson/precision.hpp>

#include <cmath>
#include <type_traits>

namespace simpson::verify::detail {

/// True for the precisions whose figures are enclosed: those carrying more digits than double.
template <class Real>
constexpr bool enclosed_above_double_v = !std::is_same_v<Real, double> && !std::is_same_v<Real, float>;

/// The decimal digits an interval needs to hold every value of Real exactly, and 10 more for the
/// evaluation: binary digits · log10(2), rounded up.
template <class Real>
unsigned enclosure_digits_for() {
  if constexpr (std::is_same_v<Real, mpfr>) {
    return mpfr::default_precision() + 10;
  } else {
    return static_cast<unsigned>(std::numeric_limits<Real>::digits * 0.30103) + 11;
  }
}

/// v as an interval, exactly (the interval's precision must hold Real's digits: see
/// enclosure_digits_for): for mpfr by MPFI's own conversion, for a binary format by 32-bit pieces
/// of its mantissa, each an exact integer in Real.
template <class Real>
interval exact_interval(const Real& v) {
  if constexpr (std::is_same_v<Real, mpfr>) {
    interval out;
    mpfi_set_fr(out.backend().data(), v.backend().data());
    return out;
  } else if constexpr (std::is_same_v<Real, double>) {
    return interval(v);
  } else {
    using std::frexp;
    using std::ldexp;
    using std::trunc;
    if (v == 0) return interval(0);
    int exponent = 0;
    Real mantissa = frexp(v, &exponent);  // v = mantissa 2^exponent, |mantissa| in [0.5, 1)
    interval out(0);
    for (int shift = 32; mantissa != 0; shift += 32) {
      mantissa = ldexp(mantissa, 32);
      const Real piece = trunc(mantissa);
      mantissa -= piece;
      out += ldexp(interval(static_cast<long long>(piece)), exponent - shift);
    }
    return out;
  }
}

/// The figure of an enclosure: only its guaranteed digits, and its radius.
inline figure enclosed_figure(const interval& x) {
  const enclosure_parts parts = enclosure_of(x);
  return figure::enclosed(parts.midpoint, parts.radius);
}

}  // namespace simpson::verify::detail

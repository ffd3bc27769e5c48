#pragma once
// Intervals for the core's generic formulas: MPFI through Boost.Multiprecision's mpfi_float. Every
// operation rounds outward, so the exact value of a formula at exact (or enclosed) inputs lies in
// the interval computed, in any precision. A statement is then decided, not toleranced: an
// enclosure proves it, proves its negation, or says that the precision is not enough. Pulls in
// MPFI: include it only where intervals are used (link simpson::interval).

#include <simpson/scalar_traits.hpp>

#include <boost/multiprecision/mpfi.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace simpson {

using interval = boost::multiprecision::mpfi_float;

template <>
inline constexpr bool is_interval_v<interval> = true;

/// The unit round-off at the current interval digits, 2^(1 − bits): Boost's numeric_limits gives 0
/// for a precision chosen at run time.
template <>
inline interval eps<interval>() {
  const interval one(1);
  return ldexp(one, 1 - static_cast<int>(mpfi_get_prec(one.backend().data())));
}

/// The decimal digits of the intervals created in a scope (Boost's default precision), restored after it.
class scoped_interval_digits {
 public:
  explicit scoped_interval_digits(unsigned digits) : previous_(interval::default_precision()) { interval::default_precision(digits); }
  ~scoped_interval_digits() { interval::default_precision(previous_); }
  scoped_interval_digits(const scoped_interval_digits&) = delete;
  scoped_interval_digits& operator=(const scoped_interval_digits&) = delete;

 private:
  unsigned previous_;
};

/// The whole real line: what is known of a value nothing was proved about.
inline interval entire_line() {
  interval x;
  mpfi_interv_d(x.backend().data(), -HUGE_VAL, HUGE_VAL);
  return x;
}

/// +1 when every point of x is positive, −1 when every point is negative, 0 when x contains 0 (the
/// sign is not decided at this precision, or the value is 0).
inline int certain_sign(const interval& x) {
  if (lower(x) > 0) return 1;
  if (upper(x) < 0) return -1;
  return 0;
}

/// An enclosure of max(a, b) for every a in x and b in y: [max of the lower ends, max of the upper ends].
inline interval enclosed_max(const interval& x, const interval& y) {
  using real = boost::multiprecision::mpfr_float;
  const real lo = lower(x) > lower(y) ? real(lower(x)) : real(lower(y));
  const real hi = upper(x) > upper(y) ? real(upper(x)) : real(upper(y));
  return interval(lo, hi);
}

/// x² enclosed as MPFI's mpfi_sqr does it: never below 0. Boost's x * x of one object is too, but the
/// product of two copies (an expression evaluated twice) of an interval holding 0 is not.
inline interval square_enclosed(const interval& x) {
  interval r;
  mpfi_sqr(r.backend().data(), x.backend().data());
  return r;
}

/// Whether the interval x contains every point of `value`.
inline bool encloses(const interval& x, const interval& value) { return lower(x) <= lower(value) && upper(value) <= upper(x); }

/// An enclosure as decimal text in two parts: the midpoint with only the digits the radius leaves
/// (one more), and the radius, plus the midpoint's own rounding, rounded up to one digit: every
/// point of x lies within `radius` of `midpoint`. The midpoint is "0" when x holds 0 and no digit of
/// it is guaranteed. At most `max_digits` digits of the midpoint: fewer widen the radius by the
/// rounding, so the parts still enclose x.
struct enclosure_parts {
  std::string midpoint;
  std::string radius;
};

inline enclosure_parts enclosure_of(const interval& x, long max_digits = 60) {
  using real = boost::multiprecision::mpfr_float;
  // An end that is infinite (or not a number): nothing is known, and "0 ± inf" says so (the digits
  // below would take the logarithm of an infinite radius).
  if (!boost::multiprecision::isfinite(lower(x)) || !boost::multiprecision::isfinite(upper(x))) return {"0", "inf"};
  // The midpoint and radius in x's own precision and more: in fewer digits the midpoint's rounding
  // would swamp the radius.
  struct scoped_real_digits {
    unsigned saved = real::default_precision();
    explicit scoped_real_digits(unsigned digits) { real::default_precision(digits); }
    ~scoped_real_digits() { real::default_precision(saved); }
  } digits_scope(x.precision() + 10);
  // A radius rounded up to one significant digit, as text.
  const auto rounded_up = [](const real& r) -> std::string {
    if (r <= 0) return "0";
    long e = static_cast<long>(std::floor(static_cast<double>(log10(r))));
    real leading = ceil(r / pow(real(10), e));
    if (leading >= 10) leading = 1, ++e;
    return leading.str(1) + "e" + std::to_string(e);
  };
  const real mid = median(x);
  const real radius = upper(x) - mid > mid - lower(x) ? real(upper(x) - mid) : real(mid - lower(x));
  if (radius > 0 && abs(mid) <= radius) {  // no digit guaranteed: centred on 0, wide enough for both ends
    return {"0", rounded_up(abs(lower(x)) > abs(upper(x)) ? real(abs(lower(x))) : real(abs(upper(x))))};
  }
  long digits = 17;
  if (radius > 0) digits = static_cast<long>(std::floor(static_cast<double>(log10(abs(mid) / radius)))) + 1;
  digits = std::max(1L, std::min(digits, std::max(1L, max_digits)));
  // The printed midpoint is itself rounded: its rounding error joins the radius, so that the text
  // is an enclosure too.
  const std::string printed = mid.str(digits, std::ios_base::scientific);
  return {printed, rounded_up(radius + abs(mid - real(printed)))};
}

/// "1.4427e-14 ± 3e-31" (enclosure_of's two parts): the text is an enclosure of x; "0 ± 2e-50"
/// when no digit is guaranteed.
inline std::string enclosure_text(const interval& x, long max_digits = 60) {
  const enclosure_parts parts = enclosure_of(x, max_digits);
  return parts.midpoint + " ± " + parts.radius;
}

}  // namespace simpson

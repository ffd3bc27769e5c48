#pragma once
// A figure of a report as it was computed: a number kept as decimal text with the significant
// digits of the precision it was computed in, an exact rational, an integer, a word, or a fault
// with its reason. Nothing here converts a multiprecision value to double: a value of 1e-2990
// computed in mpfr:3000 stays "1.0…e-2990" from the computation to every rendered file.

#include <simpson/precision.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>

namespace simpson::verify {

class figure {
 public:
  enum class kind {
    empty,    // no value (a cell left blank)
    number,   // a floating-point value in the precision it was computed in
    exact,    // an exact rational ("1/1440", "8")
    integer,  // a count: steps, N, runs
    flag,     // yes / no
    text,     // a word or a label
    fault,    // overflow, underflow, non-finite, unstable (at step j), failed: <why>
  };

  figure() = default;

  /// A number computed in Real. NaN is `non-finite`, ±inf `overflow`, and a non-zero value below
  /// Real's smallest normal number (where Real has subnormals) `underflow`: all decided in Real's
  /// own range. Otherwise the decimal text carries the digits Real carries (round-trip digits
  /// for the built-in types, digits10 for multiprecision), and `computed_in` names Real.
  template <class Real>
  static figure of(const Real& v);

  static figure exact(const rational& r) { return figure(kind::exact, simpson::to_string(r)); }
  static figure integer(long long n) { return figure(kind::integer, std::to_string(n)); }
  static figure flag(bool b) { return figure(kind::flag, b ? "yes" : "no"); }
  static figure text(std::string t) { return figure(kind::text, std::move(t)); }
  static figure fault(std::string why) { return figure(kind::fault, std::move(why)); }
  /// A number known by an enclosure (simpson::enclosure_of in interval.hpp): the midpoint with only
  /// guaranteed digits ("1.4427e-14", or "0" when none is) and the radius ("3e-31").
  static figure enclosed(std::string midpoint, std::string radius) {
    figure f(kind::number, std::move(midpoint));
    f.radius_ = std::move(radius);
    return f;
  }

  kind what() const noexcept { return kind_; }
  bool is_fault() const noexcept { return kind_ == kind::fault; }
  bool is_number() const noexcept { return kind_ == kind::number; }
  /// The decimal text (number, exact, integer), the word (flag, text) or the fault's reason.
  const std::string& value() const noexcept { return text_; }
  /// The radius of an enclosed number (figure::enclosed), else empty.
  const std::string& radius() const noexcept { return radius_; }
  /// value(), and " ± radius" for an enclosed number: the text of every file but the tables for people.
  std::string full_text() const { return radius_.empty() ? text_ : text_ + " ± " + radius_; }
  /// The value itself when it was computed in double (JSON writes it as a number).
  const std::optional<double>& as_computed_double() const noexcept { return double_; }
  /// For plots only (gnuplot reads doubles): the value when it lies within double's normal range,
  /// else nothing. Never used for a figure that is printed.
  std::optional<double> plottable() const;
  /// For plots of values beyond double's range: log10 |value|, from the decimal exponent and the
  /// leading digits of the text (so 3.1e-2987 gives -2986.5); nothing for a zero, a fault or a word.
  std::optional<double> log10_magnitude() const;

  friend bool operator==(const figure& a, const figure& b) {
    return a.kind_ == b.kind_ && a.text_ == b.text_ && a.radius_ == b.radius_;
  }

 private:
  figure(kind k, std::string t) : kind_(k), text_(std::move(t)) {}
  kind kind_ = kind::empty;
  std::string text_;
  std::string radius_;
  std::optional<double> double_;
};

/// The decimal `text` (as written by figure::of: [-]d.ddd…e±x, or any plain decimal) rounded to
/// `digits` significant digits, in the form printf's %.{digits-1}e gives: "1.44e-14", "3.1e-2987".
/// Rounding is done on the decimal digits, so no value passes through double.
std::string round_decimal(const std::string& text, int digits);

/// The decimal `text` in fixed notation with `decimals` decimals ("12.3"), rounded on its digits.
std::string fixed_decimal(const std::string& text, int decimals);

/// Figure text for people: numbers rounded to `digits` significant digits (or, when `fixed`, to
/// `digits` decimals), the rest as they are. An enclosed number with fewer guaranteed digits than
/// that is shown with its radius ("1.4e-14 ± 3e-16", "0 ± 2e-50"): no digit shown is unguaranteed.
/// With digits = 0: a double as its shortest round-trip decimal (2.8, 2.8284271247461898), so that an
/// input such as ωh shows every digit that tells it from its neighbours; other figures as they are.
std::string display(const figure& f, int digits, bool fixed = false);

/// What display shows of the value itself, without the radius it may add, for a text that states
/// the radius on its own ("0.5001 ± 3e-5 (enclosed)").
std::string display_value(const figure& f, int digits, bool fixed = false);

/// The fault of a state that left its bounded orbit: "unstable (step j)".
inline figure unstable_at(long long step) { return figure::fault("unstable (step " + std::to_string(step) + ")"); }

/// True for the fault recorded by unstable_at.
inline bool is_unstable(const figure& f) { return f.is_fault() && f.value().rfind("unstable", 0) == 0; }

template <class Real>
figure figure::of(const Real& v) {
  using std::abs;
  using std::isinf;
  using std::isnan;
  if (isnan(v)) return fault("non-finite");
  if (isinf(v)) return fault("overflow");
  if constexpr (std::numeric_limits<Real>::is_specialized && std::numeric_limits<Real>::has_denorm == std::denorm_present) {
    if (v != 0 && abs(v) < (std::numeric_limits<Real>::min)()) return fault("underflow");
  }
  int digits = 0;
  if constexpr (std::is_floating_point_v<Real>) {
    digits = std::numeric_limits<Real>::max_digits10;
  } else if constexpr (std::is_same_v<Real, mpfr>) {
    // The working precision of the run (set by precision::visit), not the value's own: a value
    // converted from an exact rational may carry far more digits than were computed.
    digits = static_cast<int>(std::min(v.precision(), mpfr::default_precision()));
  } else {
    digits = std::numeric_limits<Real>::digits10;
  }
  figure f(kind::number, simpson::to_string(v, digits));
  if constexpr (std::is_same_v<Real, double>) f.double_ = v;
  return f;
}

}  // namespace simpson::verify

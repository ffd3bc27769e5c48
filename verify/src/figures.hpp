#pragma once
// Figures of the experiments as they enter a report: checked finite first, so that an overflow or a
// NaN becomes a named entry and never a bare nan in a normal-looking table.

#include <simpson/precision.hpp>
#include <simpson/verify/claim.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace simpson::verify::detail {

/// "ok", or the fault of a value: "overflow" (±inf, or beyond double's range), "non-finite" (NaN),
/// "underflow" (non-zero but below double's smallest normal number, so not reportable as a double).
template <class Real>
std::string fault_of(const Real& v) {
  using std::isinf;
  using std::isnan;
  using std::abs;
  if (isnan(v)) return "non-finite";
  if (isinf(v)) return "overflow";
  if (abs(v) > Real(std::numeric_limits<double>::max())) return "overflow";
  if (v != 0 && abs(v) < Real(std::numeric_limits<double>::min())) return "underflow";
  return "ok";
}

/// A JSON number when the value is finite and within double's range, else its fault as a string.
template <class Real>
json figure(const Real& v) {
  const std::string fault = fault_of(v);
  if (fault != "ok") return fault;
  return static_cast<double>(v);
}

/// The same for tables: 3 significant digits, or the fault.
template <class Real>
std::string figure_text(const Real& v) {
  const std::string fault = fault_of(v);
  return fault == "ok" ? simpson::to_string(static_cast<double>(v), 3) : fault;
}

inline std::string figure_text(const json& v) {
  if (v.is_number()) return simpson::to_string(v.get<double>(), 3);
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

/// Text for a data file read by gnuplot: the number, or "NaN" (gnuplot skips it) for a fault.
inline std::string plot_value(const json& v) {
  return v.is_number() ? simpson::to_string(v.get<double>(), 6) : std::string("NaN");
}

/// A least-squares slope of log(y) against log(x) over the points flagged `use` (NaN when fewer than 2).
inline double log_log_slope(const std::vector<double>& x, const std::vector<double>& y, const std::vector<bool>& use) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (!use[k] || !(x[k] > 0) || !(y[k] > 0)) continue;
    const double lx = std::log(x[k]), ly = std::log(y[k]);
    n += 1;
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  if (n < 2) return std::numeric_limits<double>::quiet_NaN();
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

/// precision::visit for the experiments, which need cos, sin and a round-off to measure: exact
/// rationals are refused (the scene parser already refuses them; this keeps rational code from
/// being compiled for them).
template <class F>
decltype(auto) visit_floating(const precision& p, F&& f) {
  return p.visit([&](auto tag) -> decltype(f(precision_tag<double>{})) {
    using Real = typename decltype(tag)::type;
    if constexpr (is_exact_v<Real>) {
      throw std::invalid_argument("precision '" + p.name() + "': the experiments need a floating precision");
    } else {
      return f(tag);
    }
  });
}

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

/// A decimal string as a Real (built-in floating types through long double).
template <class Real>
Real from_decimal(const std::string& text) {
  if constexpr (std::is_floating_point_v<Real>) {
    return static_cast<Real>(std::stold(text));
  } else {
    return Real(text);
  }
}

}  // namespace simpson::verify::detail

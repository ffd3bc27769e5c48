#pragma once
// Numerical helpers the experiment sections share: a log-log slope, the floating precisions, exact
// rationals of floating values, decimal strings into a Real. Figures themselves are figure.hpp's.

#include <simpson/exact_value.hpp>  // to_rational
#include <simpson/precision.hpp>
#include <boost/multiprecision/cpp_int.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace simpson::verify {

/// A least-squares slope of log(y) against log(x) over the points flagged `use` (NaN when fewer
/// than 2), computed in Real: the logarithms of values far below double's range are ordinary numbers.
template <class Real>
Real log_log_slope(const std::vector<Real>& x, const std::vector<Real>& y, const std::vector<bool>& use) {
  using std::log;
  Real n(0), sx(0), sy(0), sxx(0), sxy(0);
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (!use[k] || !(x[k] > 0) || !(y[k] > 0)) continue;
    const Real lx = log(x[k]), ly = log(y[k]);
    n += 1;
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  if (n < 2) return std::numeric_limits<Real>::quiet_NaN();
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

/// f(precision_tag<mpfr>{}) with `digits` working digits, for the parts that always run in mpfr:
/// unlike visit_floating it compiles f for mpfr alone, not for every floating precision.
template <class F>
decltype(auto) visit_mpfr(unsigned digits, F&& f) {
  const scoped_mpfr_digits scope(precision::mpfr_digits(digits).digits10());
  return std::forward<F>(f)(precision_tag<mpfr>{});
}

/// A rational rounded to Real at the working precision: numerator and denominator are each rounded
/// once and divided (Boost's convert_to would give a variable-precision mpfr the precision needed
/// to hold the rational exactly, which for a long run's det − 1 is millions of digits).
template <class Real>
Real to_real(const rational& r) {
  if constexpr (std::is_floating_point_v<Real>) {
    return r.template convert_to<Real>();
  } else {
    return Real(boost::multiprecision::numerator(r).str()) / Real(boost::multiprecision::denominator(r).str());
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

}  // namespace simpson::verify

#pragma once
// The scalar types of the precision list, and a macro that applies a declaration to each of them.
// The headers of the paper's formulas use it to declare their instances `extern template`; each is
// instantiated once per precision in core/src/, so no other unit compiles it again (STYLE.md, 1).

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/cpp_int.hpp>
#include <boost/multiprecision/float128.hpp>
#include <boost/multiprecision/mpfr.hpp>

namespace simpson {

using float128 = boost::multiprecision::float128;
using bin50 = boost::multiprecision::cpp_bin_float_50;
using bin100 = boost::multiprecision::cpp_bin_float_100;
/// MPFR float whose number of decimal digits is chosen at run time (see scoped_mpfr_digits).
using mpfr = boost::multiprecision::mpfr_float;
/// Exact rationals: every formula that is rational in its inputs evaluates without rounding.
using rational = boost::multiprecision::cpp_rational;

}  // namespace simpson

/// SIMPSON_FOR_EACH_FLOATING_TYPE(M) expands to M(T) for each floating type of the precision list,
/// in precision_kind's order; SIMPSON_FOR_EACH_PRECISION_TYPE(M) adds exact rationals.
#define SIMPSON_FOR_EACH_FLOATING_TYPE(M) \
  M(double) M(long double) M(::simpson::float128) M(::simpson::bin50) M(::simpson::bin100) M(::simpson::mpfr)
#define SIMPSON_FOR_EACH_PRECISION_TYPE(M) SIMPSON_FOR_EACH_FLOATING_TYPE(M) M(::simpson::rational)

// The core's formulas in interval arithmetic against mpfr:1000: over random (ω, h) in both stable
// bands, the 40-digit enclosure of H_d(Φ₃y) − H_d(y) and of det Φ₃ − 1 contains the 1000-digit
// value, and a finer precision gives a narrower enclosure; a formula off by 1e-35 is refuted.

#include <simpson/interval.hpp>

#include <simpson/energy.hpp>
#include <simpson/precision.hpp>
#include <simpson/simpson_map.hpp>

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

namespace simpson::props {
namespace {

/// The two quantities, in any scalar, at ω h = omega_h (ω = 1 + k/8, m = 1), y = (p, q).
template <class Real>
std::array<Real, 2> identities(const Real& omega_h, int k, const Real& p, const Real& q) {
  const Real omega = 1 + Real(k) / 8;
  const oscillator_parameters<Real> par{Real(1), omega, Real(omega_h / omega)};
  const one_step_matrix<Real> phi = simpson_map(par);
  const phase_point<Real> y{p, q};
  return {Real(discrete_energy(par, phi * y) - discrete_energy(par, y)), Real(determinant(phi) - 1)};
}

RC_GTEST_PROP(IntervalProps, EnclosuresContainTheThousandDigitValueAndNarrowWithThePrecision,
              (unsigned thousandths, bool second_band, unsigned k, int p_num, int q_num)) {
  // ω h in (0, 2√2) or (2√3, 2√6), as exact decimals: 2.8 and 2√3 ≈ 3.464 .. 2√6 ≈ 4.899.
  const std::string omega_h = second_band ? "3.47" + std::to_string(100 + thousandths % 900) : "0." + std::to_string(1000 + thousandths % 9000);
  const int kk = static_cast<int>(k % 16);
  const std::string p = std::to_string(p_num % 1000 + 1001) + "/97", q = std::to_string(q_num % 1000 - 1001) + "/89";  // never 0
  using mpfr = boost::multiprecision::mpfr_float;
  const scoped_mpfr_digits thousand(1000);
  const auto fraction = [](const std::string& f) {
    const std::size_t slash = f.find('/');
    return std::make_pair(f.substr(0, slash), f.substr(slash + 1));
  };
  const auto [pn, pd] = fraction(p);
  const auto [qn, qd] = fraction(q);
  const auto reference = identities<mpfr>(mpfr(omega_h), kk, mpfr(pn) / mpfr(pd), mpfr(qn) / mpfr(qd));
  boost::multiprecision::mpfr_float widths[2];
  for (const unsigned digits : {40u, 80u}) {
    const scoped_interval_digits scope(digits);
    const auto enclosed = identities<interval>(interval(omega_h), kk, interval(pn) / interval(pd), interval(qn) / interval(qd));
    for (std::size_t n = 0; n < 2; ++n) {
      RC_ASSERT(lower(enclosed[n]) <= reference[n]);
      RC_ASSERT(reference[n] <= upper(enclosed[n]));
      RC_ASSERT(certain_sign(enclosed[n]) == 0);  // both identities hold: 0 is inside
    }
    widths[digits == 40u ? 0 : 1] = width(enclosed[0]);
  }
  RC_ASSERT(widths[1] <= widths[0] * mpfr("1e-30"));
}

RC_GTEST_PROP(IntervalProps, AWrongFormulaGivesAnEnclosureThatExcludesTheClaimedValue, (unsigned thousandths, bool second_band, unsigned k)) {
  // Φ₃ with α off by a relative 1e-35 (invisible in double and float128): det − 1 = 0 is refuted.
  const std::string omega_h = second_band ? "3.47" + std::to_string(100 + thousandths % 900) : "0." + std::to_string(1000 + thousandths % 9000);
  const scoped_interval_digits digits(60);
  const interval omega = 1 + interval(static_cast<int>(k % 16)) / 8;
  const oscillator_parameters<interval> par{interval(1), omega, interval(interval(omega_h) / omega)};
  one_step_matrix<interval> phi = simpson_map(par);
  RC_ASSERT(certain_sign(interval(determinant(phi) - 1)) == 0);
  phi.alpha *= 1 + interval(1) / interval("1e35");
  RC_ASSERT(certain_sign(interval(determinant(phi) - 1)) != 0);
}

}  // namespace
}  // namespace simpson::props

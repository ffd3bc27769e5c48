#pragma once
// Iteration of a one-step map: y_{j+1} = Φ y_j (systeme-symplectique-ordre-2).

#include <simpson/one_step_map.hpp>

#include <boost/multiprecision/mpfr.hpp>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace simpson {

/// Applies Φ n times to y0 and returns y_n, calling visit(j, y_j) for j = 0, ..., n on the way
/// (O(1) memory, for long runs). Throws std::invalid_argument when n < 1.
template <class Real, class Visitor>
phase_point<Real> iterate(const one_step_matrix<Real>& phi, phase_point<Real> y, std::size_t n, Visitor&& visit) {
  if (n < 1) {
    throw std::invalid_argument("simpson::iterate: N must be at least 1, got " + std::to_string(n));
  }
  visit(std::size_t{0}, static_cast<const phase_point<Real>&>(y));
  for (std::size_t j = 1; j <= n; ++j) {
    y = phi * y;
    visit(j, static_cast<const phase_point<Real>&>(y));
  }
  return y;
}

/// The same for MPFR numbers, with no allocation per step: Φ y is computed in place by the 4
/// products and 2 sums of the matrix (mpfr_mul, mpfr_add, rounding to nearest) into temporaries
/// allocated once, at the precision Boost gives a new number (the current default), to which the
/// state is rounded first. About the speed of a raw MPFR loop (bench/iterate_bench.cpp), where the
/// generic loop creates and frees numbers at every step.
template <boost::multiprecision::expression_template_option ET, class Visitor>
phase_point<boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>, ET>> iterate(
    const one_step_matrix<boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>, ET>>& phi,
    phase_point<boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>, ET>> y, std::size_t n, Visitor&& visit) {
  using Real = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>, ET>;
  if (n < 1) {
    throw std::invalid_argument("simpson::iterate: N must be at least 1, got " + std::to_string(n));
  }
  Real t1, t2, t3, t4;  // at the default precision
  const mpfr_prec_t precision = mpfr_get_prec(t1.backend().data());
  mpfr_prec_round(y.p.backend().data(), precision, MPFR_RNDN);
  mpfr_prec_round(y.q.backend().data(), precision, MPFR_RNDN);
  visit(std::size_t{0}, static_cast<const phase_point<Real>&>(y));
  const auto a = phi.alpha.backend().data(), b = phi.beta.backend().data(), c = phi.gamma.backend().data(),
             d = phi.delta.backend().data();
  const auto p = y.p.backend().data(), q = y.q.backend().data();
  const auto r1 = t1.backend().data(), r2 = t2.backend().data(), r3 = t3.backend().data(), r4 = t4.backend().data();
  for (std::size_t j = 1; j <= n; ++j) {
    mpfr_mul(r1, a, p, MPFR_RNDN);
    mpfr_mul(r2, b, q, MPFR_RNDN);
    mpfr_mul(r3, c, p, MPFR_RNDN);
    mpfr_mul(r4, d, q, MPFR_RNDN);
    mpfr_add(p, r1, r2, MPFR_RNDN);
    mpfr_add(q, r3, r4, MPFR_RNDN);
    visit(j, static_cast<const phase_point<Real>&>(y));
  }
  return y;
}

/// The n + 1 states y_0, ..., y_n of n steps of Φ from y0. Throws std::invalid_argument when n < 1.
template <class Real>
std::vector<phase_point<Real>> trajectory(const one_step_matrix<Real>& phi, const phase_point<Real>& y0,
                                          std::size_t n) {
  std::vector<phase_point<Real>> states;
  if (n >= 1) states.reserve(n + 1);
  iterate(phi, y0, n, [&states](std::size_t, const phase_point<Real>& y) { states.push_back(y); });
  return states;
}

}  // namespace simpson

#pragma once
// Iteration of a one-step map: y_{j+1} = Φ y_j (systeme-symplectique-ordre-2).

#include <simpson/one_step_map.hpp>

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

// Quadrature rules' exact moments (quadrature_rule.hpp).

#include <simpson/verify/quadrature_rule.hpp>

#include "family_algebra.hpp"

#include <stdexcept>

namespace simpson::verify {
namespace {

using family_detail::coefficients;
using family_detail::derivative;
using family_detail::power_modulo;
using family_detail::times_tau_modulo;
using family_detail::product;

/// Legendre's P_n(2τ − 1) on [0, 1] (shifted), by the three-term recurrence.
coefficients shifted_legendre(int n) {
  coefficients previous{rational(1)}, current{rational(-1), rational(2)};  // P_0, P_1(2τ − 1)
  if (n == 0) return previous;
  for (int k = 1; k < n; ++k) {
    // (k + 1) P_{k+1}(x) = (2k + 1) x P_k(x) − k P_{k−1}(x), x = 2τ − 1.
    coefficients next(current.size() + 1, rational(0));
    for (std::size_t i = 0; i < current.size(); ++i) {
      next[i + 1] += rational(2 * k + 1) * 2 * current[i];
      next[i] -= rational(2 * k + 1) * current[i];
    }
    for (std::size_t i = 0; i < previous.size(); ++i) next[i] -= rational(k) * previous[i];
    for (rational& c : next) c /= (k + 1);
    previous = current;
    current = next;
  }
  return current;
}

/// ∫₀¹ of (τⁿ mod nodal) for each n: the moments of the interpolatory rule on the nodal polynomial's
/// roots, exact for degrees up to the rule's exactness.
std::vector<rational> moments_by_reduction(coefficients nodal, int max_power) {
  while (nodal.back() == 0) nodal.pop_back();
  const std::size_t k = nodal.size() - 1;  // the number of nodes
  for (rational& c : nodal) c /= nodal.back();  // monic
  std::vector<rational> out;
  coefficients power = power_modulo(nodal, k, 0);  // τⁿ mod nodal, degree < k
  for (int n = 0; n <= max_power; ++n) {
    rational integral(0);
    for (std::size_t i = 0; i < k; ++i) integral += power[i] / rational(static_cast<long>(i + 1));
    out.push_back(integral);
    times_tau_modulo(power, nodal);
  }
  return out;
}

}  // namespace

std::string rule_name(const quadrature_rule& rule) {
  const int n = rule.points;
  switch (rule.family) {
    case quadrature_family::newton_cotes:
      if (n == 2) return "trapezoid";
      if (n == 3) return "Simpson";
      if (n == 4) return "3/8";
      return "Newton–Cotes " + std::to_string(n);
    case quadrature_family::lobatto: return "Lobatto " + std::to_string(n);
    case quadrature_family::gauss: return n == 1 ? "midpoint" : "Gauss " + std::to_string(n);
  }
  return "?";
}

int exactness_degree(const quadrature_rule& rule) {
  const int n = rule.points;
  switch (rule.family) {
    case quadrature_family::newton_cotes: return n % 2 == 1 ? n : n - 1;
    case quadrature_family::lobatto: return 2 * n - 3;
    case quadrature_family::gauss: return 2 * n - 1;
  }
  return 0;
}

std::vector<rational> nodal_polynomial(const quadrature_rule& rule) {
  const int n = rule.points;
  switch (rule.family) {
    case quadrature_family::newton_cotes: {
      if (n < 2) throw std::invalid_argument("Newton–Cotes needs at least 2 points");
      coefficients nodal{rational(1)};
      for (int j = 0; j < n; ++j) nodal = product(nodal, coefficients{rational(-j, n - 1), rational(1)});
      return nodal;
    }
    case quadrature_family::lobatto:
      if (n < 2) throw std::invalid_argument("Lobatto needs at least 2 points");
      // τ(1 − τ) P'_{n−1}(2τ − 1): the end points and the roots of the derivative.
      return product(coefficients{rational(0), rational(1), rational(-1)}, derivative(shifted_legendre(n - 1)));
    case quadrature_family::gauss:
      if (n < 1) throw std::invalid_argument("Gauss needs at least 1 point");
      return shifted_legendre(n);
  }
  throw std::invalid_argument("unknown quadrature family");
}

std::vector<rational> quadrature_moments(const quadrature_rule& rule, int max_power) {
  return moments_by_reduction(nodal_polynomial(rule), max_power);
}

}  // namespace simpson::verify

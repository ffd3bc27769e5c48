#pragma once
// Shared by the family's exact derivations (private to verify/family): polynomials in τ as
// coefficient lists (product, derivative, τⁿ modulo a monic nodal polynomial), and rational functions
// of θ in canonical form (gcd and lcm over Q, N/D reduced with D monic).

#include <simpson/verify/exact_proof.hpp>

#include <vector>

namespace simpson::verify::family_detail {

using coefficients = std::vector<rational>;  // a polynomial in τ, constant term first

inline coefficients product(const coefficients& a, const coefficients& b) {
  coefficients out(a.size() + b.size() - 1, rational(0));
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) out[i + j] += a[i] * b[j];
  }
  return out;
}

inline coefficients derivative(const coefficients& p) {
  coefficients out;
  for (std::size_t i = 1; i < p.size(); ++i) out.push_back(rational(static_cast<long>(i)) * p[i]);
  return out.empty() ? coefficients{rational(0)} : out;
}

/// r ← τ r modulo a monic polynomial of degree k = r.size() (`monic`, constant first, leading 1):
/// times τ, then τ^k replaced by −Σ monic_i τ^i.
inline void times_tau_modulo(coefficients& r, const coefficients& monic) {
  const std::size_t k = r.size();
  const rational top = r[k - 1];
  for (std::size_t i = k - 1; i > 0; --i) r[i] = r[i - 1] - top * monic[i];
  r[0] = -top * monic[0];
}

/// τⁿ modulo a monic polynomial of degree k, as k coefficients.
inline coefficients power_modulo(const coefficients& monic, std::size_t k, std::size_t n) {
  coefficients power(k, rational(0));
  power[0] = 1;
  for (std::size_t step = 0; step < n; ++step) times_tau_modulo(power, monic);
  return power;
}

/// The monic greatest common divisor of two polynomials over Q (Euclid).
inline polynomial gcd_of(polynomial a, polynomial b) {
  while (!is_zero(b)) {
    polynomial r = a % b;
    a = std::move(b);
    b = std::move(r);
  }
  const long d = degree(a);
  if (d < 0) return make_polynomial({rational(1)});
  const rational lead = a[static_cast<std::size_t>(d)];
  for (std::size_t k = 0; k < a.size(); ++k) a[k] /= lead;
  return a;
}

/// N/D with their common factor removed and D monic: the canonical form, for text and degrees.
inline symbolic reduced(const symbolic& f) {
  const polynomial g = gcd_of(f.numerator(), f.denominator());
  polynomial n = f.numerator() / g, d = f.denominator() / g;
  const rational lead = d[static_cast<std::size_t>(degree(d))];
  for (std::size_t k = 0; k < n.size(); ++k) n[k] /= lead;
  for (std::size_t k = 0; k < d.size(); ++k) d[k] /= lead;
  return {n, d};
}

inline polynomial lcm_of(const polynomial& a, const polynomial& b) { return a / gcd_of(a, b) * b; }

}  // namespace simpson::verify::family_detail

#pragma once
// Rational functions of θ in canonical form, shared by the family's exact derivations (private to
// verify/family): gcd and lcm over Q, N/D reduced with D monic.

#include <simpson/verify/exact_proof.hpp>

namespace simpson::verify::family_detail {

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

// Tools of the exact proofs (exact_proof.hpp).

#include <simpson/verify/exact_proof.hpp>

namespace simpson::verify {

oscillator_parameters<symbolic> unit_oscillator_in_theta() {
  return {symbolic(1), symbolic(1), symbolic::variable()};
}

std::vector<polynomial> sturm_sequence(const polynomial& p) {
  std::vector<polynomial> seq{p, p.prime()};
  while (degree(seq.back()) > 0) {
    const polynomial remainder = boost::math::tools::quotient_remainder(seq[seq.size() - 2], seq.back()).second;
    if (is_zero(remainder)) break;
    seq.push_back(polynomial() - remainder);
  }
  return seq;
}

std::size_t sign_changes(const std::vector<polynomial>& seq, const rational& at) {
  std::size_t changes = 0;
  int previous = 0;
  for (const polynomial& s : seq) {
    const rational v = s.evaluate(at);
    const int sign = v > 0 ? 1 : (v < 0 ? -1 : 0);
    if (sign == 0) continue;
    if (previous != 0 && sign != previous) ++changes;
    previous = sign;
  }
  return changes;
}

std::size_t count_real_roots(const polynomial& p, const rational& a, const rational& b) {
  const std::vector<polynomial> seq = sturm_sequence(p);
  return sign_changes(seq, a) - sign_changes(seq, b);
}

rational cauchy_root_bound(const polynomial& p) {
  const long n = degree(p);
  rational largest = 0;
  for (long k = 0; k < n; ++k) {
    rational r = p[static_cast<std::size_t>(k)] / p[static_cast<std::size_t>(n)];
    if (r < 0) r = -r;
    if (r > largest) largest = r;
  }
  return 1 + largest;
}

polynomial cos_taylor(int degree_bound) {
  std::vector<rational> c(static_cast<std::size_t>(degree_bound) + 1, rational(0));
  rational term = 1;  // θ^k / k!
  for (int k = 0; k <= degree_bound; ++k) {
    if (k > 0) term /= k;
    if (k % 2 == 0) c[static_cast<std::size_t>(k)] = (k / 2) % 2 == 0 ? term : rational(-term);
  }
  return polynomial(c.begin(), c.end());
}

polynomial sin_taylor(int degree_bound) {
  std::vector<rational> c(static_cast<std::size_t>(degree_bound) + 1, rational(0));
  rational term = 1;
  for (int k = 0; k <= degree_bound; ++k) {
    if (k > 0) term /= k;
    if (k % 2 == 1) c[static_cast<std::size_t>(k)] = ((k - 1) / 2) % 2 == 0 ? term : rational(-term);
  }
  return polynomial(c.begin(), c.end());
}

std::string series_to_string(const std::vector<std::pair<long, rational>>& terms, const std::string& var) {
  std::string out;
  for (const auto& [power, c] : terms) {
    const bool negative = c < 0;
    out += out.empty() ? (negative ? "-" : "") : (negative ? " - " : " + ");
    out += simpson::to_string(negative ? rational(-c) : c);
    if (power != 0) out += " " + var + (power != 1 ? "^" + std::to_string(power) : "");
  }
  return out.empty() ? "0" : out;
}

}  // namespace simpson::verify

// Exact linear stability of a symmetric three-term scheme (stability_analysis.hpp): positive roots
// of polynomials over Q by Sturm sequences in integers.

#include <simpson/verify/stability_analysis.hpp>

#include <boost/multiprecision/cpp_int.hpp>

namespace simpson::verify {

polynomial even_in_theta_to_x(const polynomial& p) {
  std::vector<rational> c;
  for (long k = 0; k <= degree(p); ++k) {
    const rational& v = p[static_cast<std::size_t>(k)];
    if (k % 2 == 1) {
      if (v != 0) throw std::logic_error("even_in_theta_to_x: odd power of theta");
      continue;
    }
    c.push_back(v);
  }
  return c.empty() ? polynomial() : polynomial(c.begin(), c.end());
}

namespace detail {

using boost::multiprecision::cpp_int;

/// p multiplied by the positive constant that makes its coefficients coprime integers: the same
/// signs everywhere, so Sturm counts are unchanged.
std::vector<cpp_int> primitive_integer(const polynomial& p) {
  cpp_int common_denominator = 1, content = 0;
  for (long k = 0; k <= degree(p); ++k) {
    const cpp_int d = boost::multiprecision::denominator(p[static_cast<std::size_t>(k)]);
    common_denominator = common_denominator / boost::multiprecision::gcd(common_denominator, d) * d;
  }
  std::vector<cpp_int> out;
  for (long k = 0; k <= degree(p); ++k) {
    const rational& c = p[static_cast<std::size_t>(k)];
    out.push_back(boost::multiprecision::numerator(c) * (common_denominator / boost::multiprecision::denominator(c)));
    content = boost::multiprecision::gcd(content, out.back());
  }
  if (content > 1) {
    for (cpp_int& c : out) c /= content;
  }
  return out;
}

/// Integer polynomials, constant term first, without trailing zeros (empty = 0).
void trim(std::vector<cpp_int>& p) {
  while (!p.empty() && p.back() == 0) p.pop_back();
}

/// p divided by the gcd of its coefficients (a positive constant).
std::vector<cpp_int> primitive_part(std::vector<cpp_int> p) {
  trim(p);
  cpp_int content = 0;
  for (const cpp_int& c : p) content = boost::multiprecision::gcd(content, c);
  if (content > 1) {
    for (cpp_int& c : p) c /= content;
  }
  return p;
}

std::vector<cpp_int> derivative(const std::vector<cpp_int>& p) {
  std::vector<cpp_int> out;
  for (std::size_t k = 1; k < p.size(); ++k) out.push_back(p[k] * static_cast<unsigned long>(k));
  return out;
}

/// A positive multiple of rem(a, b), primitive: a scaled by lc(b) before each reduction step, the
/// sign restored when lc(b) < 0 was used an odd number of times.
std::vector<cpp_int> positive_pseudo_remainder(std::vector<cpp_int> a, const std::vector<cpp_int>& b) {
  trim(a);
  const cpp_int& lead = b.back();
  std::size_t steps = 0;
  while (a.size() >= b.size() && !a.empty()) {
    const cpp_int top = a.back();
    const std::size_t shift = a.size() - b.size();
    for (cpp_int& c : a) c *= lead;
    for (std::size_t k = 0; k < b.size(); ++k) a[k + shift] -= top * b[k];
    ++steps;
    trim(a);
  }
  if (lead < 0 && steps % 2 == 1) {
    for (cpp_int& c : a) c = -c;
  }
  return primitive_part(std::move(a));
}

/// p / gcd(p, p'): the same roots, each simple (primitive remainder sequence, exact division).
std::vector<cpp_int> square_free_part(const std::vector<cpp_int>& p) {
  std::vector<cpp_int> g = p, r = primitive_part(derivative(p));
  while (!r.empty()) {
    std::vector<cpp_int> next = positive_pseudo_remainder(g, r);
    g = std::move(r);
    r = std::move(next);
  }
  if (g.size() <= 1) return p;
  // Exact division p / g over Q, scaled back to a primitive integer polynomial: long division with
  // the numerator multiplied by lc(g) at each step (a positive multiple of the quotient when lc(g) > 0).
  if (g.back() < 0) {
    for (cpp_int& c : g) c = -c;
  }
  std::vector<cpp_int> a = p, quotient(p.size() - g.size() + 1, cpp_int(0));
  for (std::size_t k = quotient.size(); k-- > 0;) {
    // invariant: a has degree k + deg g; scale everything so the leading division is exact
    const cpp_int top = a[k + g.size() - 1];
    for (cpp_int& c : a) c *= g.back();
    for (cpp_int& c : quotient) c *= g.back();
    quotient[k] = top;
    for (std::size_t j = 0; j < g.size(); ++j) a[j + k] -= top * g[j];
  }
  return primitive_part(std::move(quotient));
}

/// The sign of p(a/b), b > 0, for integer coefficients: of Σ c_k a^k b^(n−k) = bⁿ p(a/b), by
/// Horner in integers (no rational normalisation, which is what made isolation slow).
int sign_at(const std::vector<cpp_int>& c, const cpp_int& a, const std::vector<cpp_int>& b_powers) {
  if (c.empty()) return 0;
  const std::size_t n = c.size() - 1;
  cpp_int v = c[n];
  for (std::size_t k = n; k-- > 0;) v = v * a + c[k] * b_powers[n - k];
  return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

/// A Sturm sequence computed once, each member scaled to a primitive integer polynomial.
class integer_sturm_sequence {
 public:
  /// p, p', then −rem by integer pseudo-remainders: the same signs as the rational sequence.
  explicit integer_sturm_sequence(const std::vector<cpp_int>& p) {
    members_.push_back(p);
    members_.push_back(primitive_part(derivative(p)));
    while (members_.back().size() > 1) {
      std::vector<cpp_int> r = positive_pseudo_remainder(members_[members_.size() - 2], members_.back());
      if (r.empty()) break;
      for (cpp_int& c : r) c = -c;
      members_.push_back(std::move(r));
    }
    for (const auto& m : members_) largest_ = std::max(largest_, m.size());
  }
  const std::vector<cpp_int>& first() const { return members_.front(); }
  /// The sign of the sequence's first member at `at`.
  int sign(const rational& at) const { return sign_at(members_.front(), numerator(at), powers(at)); }
  std::size_t changes(const rational& at) const {
    const std::vector<cpp_int> b_powers = powers(at);
    const cpp_int a = numerator(at);
    std::size_t count = 0;
    int previous = 0;
    for (const std::vector<cpp_int>& m : members_) {
      const int s = sign_at(m, a, b_powers);
      if (s == 0) continue;
      if (previous != 0 && s != previous) ++count;
      previous = s;
    }
    return count;
  }
  /// Distinct real roots in (a, b].
  std::size_t count(const rational& a, const rational& b) const { return changes(a) - changes(b); }

 private:
  static cpp_int numerator(const rational& r) { return boost::multiprecision::numerator(r); }
  std::vector<cpp_int> powers(const rational& at) const {
    std::vector<cpp_int> out(largest_ + 1, cpp_int(1));
    const cpp_int b = boost::multiprecision::denominator(at);
    for (std::size_t k = 1; k < out.size(); ++k) out[k] = out[k - 1] * b;
    return out;
  }
  std::vector<std::vector<cpp_int>> members_;
  std::size_t largest_ = 0;
};

/// The rational of smallest denominator in [lo, hi], 0 <= lo < hi (continued fractions).
rational simplest_rational_between(const rational& lo, const rational& hi) {
  const cpp_int floor_lo = boost::multiprecision::numerator(lo) / boost::multiprecision::denominator(lo);
  if (rational(floor_lo) == lo) return lo;
  const cpp_int floor_hi = boost::multiprecision::numerator(hi) / boost::multiprecision::denominator(hi);
  if (floor_hi > floor_lo) return rational(floor_lo + 1);
  return rational(floor_lo) + 1 / simplest_rational_between(1 / (hi - floor_lo), 1 / (lo - floor_lo));
}

/// The smallest power of two above every root's modulus (Fujiwara: |z| <= 2 max |a_{n-k}/a_n|^{1/k}),
/// so that every bisection point is dyadic.
rational dyadic_root_bound(const std::vector<cpp_int>& c) {
  const std::size_t n = c.size() - 1;
  const cpp_int lead = boost::multiprecision::abs(c[n]);
  unsigned e = 1;
  for (std::size_t k = 1; k <= n; ++k) {
    const cpp_int a = boost::multiprecision::abs(c[n - k]);
    // the smallest e with 2^((e-1) k) |a_n| >= |a_{n-k}|
    while ((lead << static_cast<unsigned>((e - 1) * k)) < a) ++e;
  }
  return rational(cpp_int(1) << e);
}

}  // namespace detail


/// Positive roots of p, in increasing order: the square-free part's roots separated by bisection
/// on Sturm counts (the sequence computed once, evaluated in integers), each simple root then
/// narrowed by the sign of p alone.
std::vector<positive_root> positive_roots(const polynomial& p) {
  std::vector<positive_root> roots;
  if (degree(p) < 1) return roots;
  // Divide out the root at 0, so that Sturm's theorem applies at the left end.
  polynomial q = p;
  while (degree(q) >= 1 && q[0] == 0) q = boost::math::tools::quotient_remainder(q, make_polynomial({rational(0), rational(1)})).first;
  if (degree(q) < 1) return roots;
  // The square-free part q / gcd(q, q'): the same roots, each simple, so its sign changes at each.
  const detail::integer_sturm_sequence sturm(detail::square_free_part(detail::primitive_integer(q)));
  std::vector<std::pair<rational, rational>> pending{{rational(0), detail::dyadic_root_bound(sturm.first())}};
  const rational width = rational(1) / rational(1099511627776LL);  // 2^-40
  while (!pending.empty()) {
    auto [lo, hi] = pending.back();
    pending.pop_back();
    const std::size_t n = sturm.count(lo, hi);
    if (n == 0) continue;
    if (n > 1) {
      const rational mid = (lo + hi) / 2;
      pending.emplace_back(mid, hi);
      pending.emplace_back(lo, mid);
      continue;
    }
    // One simple root in (lo, hi]: where p's sign is that of p(hi), the root lies to the left.
    const int at_hi = sturm.sign(hi);
    if (at_hi == 0) {
      lo = hi;
    } else {
      while (hi - lo >= width) {
        const rational mid = (lo + hi) / 2;
        const int at_mid = sturm.sign(mid);
        if (at_mid == 0) {
          lo = hi = mid;
          break;
        }
        (at_mid == at_hi ? hi : lo) = mid;
      }
    }
    if (lo != hi) {
      // Identify a rational root: at most one fraction n/d with d <= 1000 lies in an interval
      // narrower than 1/d², the simplest one, and it is the root exactly when p vanishes there.
      const rational candidate = detail::simplest_rational_between(lo, hi);
      if (boost::multiprecision::denominator(candidate) <= 1000 && sturm.sign(candidate) == 0) lo = hi = candidate;
    }
    roots.push_back({lo, hi});
  }
  std::sort(roots.begin(), roots.end(), [](const positive_root& a, const positive_root& b) { return a.low < b.low; });
  return roots;
}

/// "8", "22/7", or "[a, b]" for an isolated irrational root.
std::string root_text(const positive_root& r) {
  if (r.exact()) return simpson::to_string(r.low);
  return "[" + simpson::to_string(r.low) + ", " + simpson::to_string(r.high) + "]";
}

/// ωh at the root x: "2 sqrt(2)" style when x = k² n.
std::string omega_h_text(const positive_root& r) {
  if (!r.exact()) return "sqrt(" + root_text(r) + ")";
  using boost::multiprecision::denominator;
  using boost::multiprecision::numerator;
  if (denominator(r.low) != 1 || numerator(r.low) > 1000000) return "sqrt(" + simpson::to_string(r.low) + ")";
  const long v = static_cast<long>(numerator(r.low));
  long outer = 1, inner = v;
  for (long k = 2; k * k <= inner; ++k) {
    while (inner % (k * k) == 0) {
      inner /= k * k;
      outer *= k;
    }
  }
  if (inner == 1) return std::to_string(outer);
  return (outer == 1 ? "" : std::to_string(outer) + " ") + "sqrt(" + std::to_string(inner) + ")";
}

}  // namespace simpson::verify

#pragma once
// Exact linear stability of a symmetric three-term scheme a q_{j+1} + b q_j + c q_{j-1} = 0 whose
// coefficients are functions of x = ω²h²: the characteristic polynomial a r² + b r + c read off
// the scheme's own residual, its discriminant as a rational function of x, the exact positive
// roots (Sturm sequences), and the sign of Δ between them.

#include <simpson/verify/exact_proof.hpp>
#include <simpson/verify/json.hpp>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace simpson::verify {

/// A polynomial in θ with only even powers, as a polynomial in x = θ². Throws if an odd power appears.
inline polynomial even_in_theta_to_x(const polynomial& p) {
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

/// A positive real root of a polynomial in x: exact when rational (found as a small-denominator
/// rational in its isolating interval), else an isolating interval of width < 2^-40.
struct positive_root {
  rational low, high;  // equal when exact
  bool exact() const { return low == high; }
};

namespace detail {

using boost::multiprecision::cpp_int;

/// p multiplied by the positive constant that makes its coefficients coprime integers: the same
/// signs everywhere, so Sturm counts are unchanged.
inline std::vector<cpp_int> primitive_integer(const polynomial& p) {
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
inline void trim(std::vector<cpp_int>& p) {
  while (!p.empty() && p.back() == 0) p.pop_back();
}

/// p divided by the gcd of its coefficients (a positive constant).
inline std::vector<cpp_int> primitive_part(std::vector<cpp_int> p) {
  trim(p);
  cpp_int content = 0;
  for (const cpp_int& c : p) content = boost::multiprecision::gcd(content, c);
  if (content > 1) {
    for (cpp_int& c : p) c /= content;
  }
  return p;
}

inline std::vector<cpp_int> derivative(const std::vector<cpp_int>& p) {
  std::vector<cpp_int> out;
  for (std::size_t k = 1; k < p.size(); ++k) out.push_back(p[k] * static_cast<unsigned long>(k));
  return out;
}

/// A positive multiple of rem(a, b), primitive: a scaled by lc(b) before each reduction step, the
/// sign restored when lc(b) < 0 was used an odd number of times.
inline std::vector<cpp_int> positive_pseudo_remainder(std::vector<cpp_int> a, const std::vector<cpp_int>& b) {
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
inline std::vector<cpp_int> square_free_part(const std::vector<cpp_int>& p) {
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
inline int sign_at(const std::vector<cpp_int>& c, const cpp_int& a, const std::vector<cpp_int>& b_powers) {
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
inline rational simplest_rational_between(const rational& lo, const rational& hi) {
  const cpp_int floor_lo = boost::multiprecision::numerator(lo) / boost::multiprecision::denominator(lo);
  if (rational(floor_lo) == lo) return lo;
  const cpp_int floor_hi = boost::multiprecision::numerator(hi) / boost::multiprecision::denominator(hi);
  if (floor_hi > floor_lo) return rational(floor_lo + 1);
  return rational(floor_lo) + 1 / simplest_rational_between(1 / (hi - floor_lo), 1 / (lo - floor_lo));
}

/// The smallest power of two above every root's modulus (Fujiwara: |z| <= 2 max |a_{n-k}/a_n|^{1/k}),
/// so that every bisection point is dyadic.
inline rational dyadic_root_bound(const std::vector<cpp_int>& c) {
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
inline std::vector<positive_root> positive_roots(const polynomial& p) {
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
inline std::string root_text(const positive_root& r) {
  if (r.exact()) return simpson::to_string(r.low);
  return "[" + simpson::to_string(r.low) + ", " + simpson::to_string(r.high) + "]";
}

/// ωh at the root x: "2 sqrt(2)" style when x = k² n.
inline std::string omega_h_text(const positive_root& r) {
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

/// An interval of x = ω²h² between consecutive positive roots of Δ (the last one unbounded).
struct stability_band {
  rational x_from;                  // 0, or an exact root
  std::optional<positive_root> to;  // the next root; none for +infinity
  std::string omega_h_from, omega_h_to;
  bool discriminant_negative = false;
  bool stable = false;
};

struct stability_report {
  json evidence = json::object();
  std::vector<positive_root> roots;  // positive roots of Δ in x, increasing
  std::vector<stability_band> bands;
  /// Open intervals of x > 0 on which Δ < 0 (two simple roots on the unit circle); an empty
  /// upper end means +infinity.
  std::vector<std::pair<std::string, std::string>> stable_intervals;
  bool product_of_roots_is_one = false;
};

/// `residual(q_prev, q, q_next)` evaluates the scheme with m = ω = 1, h = θ.
template <class Residual>
stability_report analyse_three_term_scheme(Residual&& residual) {
  // R(r) = residual(1, r, r²) = (a r² + b r + c)/h²: read a, b, c off r = 0, 1, −1.
  const symbolic r0 = residual(symbolic(1), symbolic(0), symbolic(0));
  const symbolic r1 = residual(symbolic(1), symbolic(1), symbolic(1));
  const symbolic rm = residual(symbolic(1), symbolic(-1), symbolic(1));
  const symbolic c = r0;
  const symbolic a = (r1 + rm) / 2 - c;
  const symbolic b = (r1 - rm) / 2;
  const symbolic delta = (b * b - 4 * a * c) / (a * a);  // discriminant of r² + (b/a) r + c/a
  stability_report report;
  report.product_of_roots_is_one = (c - a).is_zero();

  const polynomial numerator = even_in_theta_to_x(delta.numerator());
  const polynomial denominator = even_in_theta_to_x(delta.denominator());
  std::vector<positive_root> roots = positive_roots(numerator);
  const std::vector<positive_root> poles = positive_roots(denominator);

  json& e = report.evidence;
  e["method"] = "exact (Sturm sequences)";
  e["reduction"] = "m = omega = 1, h = theta; characteristic polynomial a r^2 + b r + c read off the scheme at "
                   "(q_{j-1}, q_j, q_{j+1}) = (1, r, r^2); x = theta^2";
  e["product_of_roots_c_over_a"] = report.product_of_roots_is_one ? "1 identically" : "not identically 1";
  e["discriminant_over_a2_numerator"] = to_string(numerator, "x");
  e["discriminant_over_a2_denominator"] = to_string(denominator, "x");
  json root_list = json::array();
  for (const positive_root& r : roots) root_list.push_back(root_text(r));
  e["positive_roots_of_discriminant"] = root_list;
  e["positive_poles"] = poles.size();

  // Sign of Δ on each interval between consecutive roots (poles are none here; reported if any).
  std::vector<rational> cuts{rational(0)};
  for (const positive_root& r : roots) cuts.push_back(r.low);
  json bands = json::array();
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    const rational lo = cuts[k];
    const rational probe = k + 1 < cuts.size() ? rational((lo + cuts[k + 1]) / 2) : rational(lo + 1);
    const rational value = numerator.evaluate(probe) / denominator.evaluate(probe);
    const bool stable = report.product_of_roots_is_one && value < 0;
    const std::string hi = k + 1 < cuts.size() ? root_text(roots[k]) : std::string();
    const std::string lo_text = k == 0 ? "0" : root_text(roots[k - 1]);
    bands.push_back({{"x_from", lo_text},
                     {"x_to", hi.empty() ? "infinity" : hi},
                     {"omega_h_from", k == 0 ? std::string("0") : omega_h_text(roots[k - 1])},
                     {"omega_h_to", hi.empty() ? std::string("infinity") : omega_h_text(roots[k])},
                     {"sign_of_discriminant", value < 0 ? "negative" : "positive"},
                     {"stable", stable}});
    if (stable) report.stable_intervals.emplace_back(lo_text, hi);
    report.bands.push_back({lo, k + 1 < cuts.size() ? std::optional<positive_root>(roots[k]) : std::nullopt,
                            bands.back()["omega_h_from"], bands.back()["omega_h_to"], value < 0, stable});
  }
  report.roots = roots;
  e["bands"] = bands;
  e["at_each_root"] = roots.empty() ? "no positive root"
                                    : "double root r = -b/(2a) of modulus 1: q_j = (A + B j) r^j grows linearly, unstable";
  return report;
}

}  // namespace simpson::verify

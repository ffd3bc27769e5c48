#pragma once
// Exact linear stability of a symmetric three-term scheme a q_{j+1} + b q_j + c q_{j-1} = 0 whose
// coefficients are functions of x = ω²h²: the characteristic polynomial a r² + b r + c read off
// the scheme's own residual, its discriminant as a rational function of x, the exact positive
// roots (Sturm sequences), and the sign of Δ between them.

#include <simpson/verify/exact_proof.hpp>
#include <simpson/verify/json.hpp>

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

/// Positive roots of p, in increasing order, isolated by bisection on Sturm counts.
inline std::vector<positive_root> positive_roots(const polynomial& p) {
  std::vector<positive_root> roots;
  if (degree(p) < 1) return roots;
  // Divide out the root at 0, so that Sturm's theorem applies at the left end.
  polynomial q = p;
  while (degree(q) >= 1 && q[0] == 0) q = boost::math::tools::quotient_remainder(q, make_polynomial({rational(0), rational(1)})).first;
  if (degree(q) < 1) return roots;
  const rational bound = cauchy_root_bound(q);
  std::vector<std::pair<rational, rational>> pending{{rational(0), bound}};
  while (!pending.empty()) {
    auto [lo, hi] = pending.back();
    pending.pop_back();
    const std::size_t n = count_real_roots(q, lo, hi);
    if (n == 0) continue;
    if (n == 1) {
      // Narrow down; stop early at an exact rational root.
      for (int it = 0; it < 200; ++it) {
        if (q.evaluate(hi) == 0) {
          lo = hi;
          break;
        }
        const rational mid = (lo + hi) / 2;
        if (q.evaluate(mid) == 0) {
          lo = hi = mid;
          break;
        }
        if (count_real_roots(q, lo, mid) == 1) {
          hi = mid;
        } else {
          lo = mid;
        }
        if (hi - lo < rational(1) / rational(1099511627776LL)) break;  // 2^-40
      }
      if (lo != hi) {
        // Identify a rational root: at most one fraction n/d with d <= 1000 lies in an interval
        // narrower than 1/d², and it is the root exactly when p vanishes there.
        for (long d = 1; d <= 1000 && lo != hi; ++d) {
          const rational scaled = (lo + hi) / 2 * d;
          const rational n = rational(boost::multiprecision::cpp_int(boost::multiprecision::numerator(scaled) /
                                                                     boost::multiprecision::denominator(scaled)));
          for (const rational& candidate : {rational(n / d), rational((n + 1) / d)}) {
            if (candidate >= lo && candidate <= hi && q.evaluate(candidate) == 0) lo = hi = candidate;
          }
        }
      }
      roots.push_back({lo, hi});
      continue;
    }
    const rational mid = (lo + hi) / 2;
    pending.emplace_back(mid, hi);
    pending.emplace_back(lo, mid);
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

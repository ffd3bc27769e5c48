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
polynomial even_in_theta_to_x(const polynomial& p);

/// A positive real root of a polynomial in x: exact when rational (found as a small-denominator
/// rational in its isolating interval), else an isolating interval of width < 2^-40.
struct positive_root {
  rational low, high;  // equal when exact
  bool exact() const { return low == high; }
};

/// Positive roots of p, in increasing order: the square-free part's roots separated by bisection
/// on Sturm counts (the sequence computed once, evaluated in integers), each simple root then
/// narrowed by the sign of p alone.
std::vector<positive_root> positive_roots(const polynomial& p);

/// "8", "22/7", or "[a, b]" for an isolated irrational root.
std::string root_text(const positive_root& r);

/// ωh at the root x: "2 sqrt(2)" style when x = k² n.
std::string omega_h_text(const positive_root& r);

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

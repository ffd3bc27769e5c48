// The stability section's stiff linear system: a chain of unit masses whose stiff and soft springs
// alternate, so that its fast and slow frequencies lie a factor r apart. The step is set by the
// fast modes' ωh, placed in the middle of each region of Φ₃'s exact stable set; the prediction is
// exact (the modes' x = ω_k²h² counted in each band by Sturm sequences of det(h²K − xI)), and a
// run of 2^30 steps of the mpfr:50 map (the 2n × 2n map squared 30 times), enclosed in MPFI,
// confirms or refutes it.

#include "enclosed_figures.hpp"
#include "stability_parts.hpp"

#include <simpson/verify/exact_proof.hpp>
#include <simpson/verify/floating_tools.hpp>
#include <simpson/verify/interruption.hpp>

#include <simpson/ndof_linear.hpp>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace simpson::verify::detail {
namespace {

constexpr int chain_masses = 4;

/// Springs from the left wall to the right one: soft 1, stiff k, soft 1, stiff k, soft 1.
std::vector<rational> chain_springs(const rational& stiff) {
  std::vector<rational> k;
  for (int i = 0; i <= chain_masses; ++i) k.push_back(i % 2 == 1 ? stiff : rational(1));
  return k;
}

/// det(h²K − xI) of the chain (K tridiagonal: K_ii = k_i + k_{i+1}, K_{i,i+1} = −k_{i+1}) by the
/// continuant recurrence, exact in x.
polynomial mode_polynomial(const std::vector<rational>& springs, const rational& h2) {
  const polynomial minus_x({rational(0), rational(-1)});
  polynomial before({rational(1)}), current = polynomial({h2 * (springs[0] + springs[1])}) + minus_x;
  for (int i = 1; i < chain_masses; ++i) {
    const rational off = h2 * springs[static_cast<std::size_t>(i)];
    polynomial next = (polynomial({h2 * (springs[static_cast<std::size_t>(i)] + springs[static_cast<std::size_t>(i) + 1])}) + minus_x) * current -
                      polynomial({off * off}) * before;
    before = current;
    current = next;
  }
  return current;
}

/// The exact prediction: the modes counted in each band of the region, and the growth they imply.
struct mode_prediction {
  std::string modes;     // "2 in (0, 8), 2 in (12, 24)"
  std::string growth;    // bounded or exponential
};

mode_prediction predict(const stability_report& region, const polynomial& c) {
  mode_prediction out;
  std::size_t counted = 0, unstable = 0;
  for (const stability_band& band : region.bands) {
    if (band.to && !band.to->exact()) throw std::logic_error("stiff chain: an endpoint of the region is not exact");
    // h is aimed at a band's middle: a mode exactly at an endpoint (a double eigenvalue ±1 of its
    // block) would need the Jordan analysis of the endpoint table, and is refused as a harness fault.
    if (band.x_from > 0 && c.evaluate(band.x_from) == 0) throw std::logic_error("stiff chain: a mode lies exactly at x = " + simpson::to_string(band.x_from));
    const rational upper = band.to ? band.to->low : std::max(rational(2) * band.x_from, cauchy_root_bound(c));
    const std::size_t n = count_real_roots(c, band.x_from, upper);
    if (n == 0) continue;
    counted += n;
    if (!band.stable) unstable += n;
    out.modes += fmt::format("{}{} in ({}, {})", out.modes.empty() ? "" : ", ", n, simpson::to_string(band.x_from),
                             band.to ? simpson::to_string(band.to->low) : std::string("infinity"));
  }
  if (counted != static_cast<std::size_t>(chain_masses)) {
    throw std::logic_error(fmt::format("stiff chain: {} distinct modes found of {} (a repeated frequency)", counted, chain_masses));
  }
  out.growth = unstable ? "exponential" : "bounded";
  return out;
}

/// The growth of the run of 2^doublings steps, enclosed: the largest amplitude's log10 up to
/// 2^fit_from steps and up to the end, and the log-log exponent between them.
struct enclosed_growth {
  interval at_fit, at_end, exponent;
};

/// The run, enclosed: the map's entries as the run computed them in mpfr (exact binary numbers) enter
/// intervals exactly, and the squarings run in MPFI, each followed by an exact rescaling by a power of
/// two (counted, so no entry leaves the range), so every figure holds for the map that runs. y₀ is the
/// first mass displaced: y_n = Φⁿ y₀ is the column `start_column` of Φⁿ. Widths: each squaring widens an
/// entry by at most 2n ‖P‖ times, about 16 here, so 30 squarings lose about 36 of the interval's digits.
enclosed_growth enclosed_run(const dense_matrix<mpfr>& phi, const mpfr& fast, int doublings, int fit_from, Eigen::Index start_column) {
  const Eigen::Index size = phi.rows();
  const scoped_interval_digits digits(enclosure_digits_for<mpfr>() + 40);
  std::vector<interval> P(static_cast<std::size_t>(size * size));
  const auto at = [size](std::vector<interval>& m, Eigen::Index a, Eigen::Index b) -> interval& {
    return m[static_cast<std::size_t>(a * size + b)];
  };
  for (Eigen::Index a = 0; a < size; ++a) {
    for (Eigen::Index b = 0; b < size; ++b) at(P, a, b) = exact_interval(phi(a, b));
  }
  const interval fast_i = exact_interval(fast), ln2 = log(interval(2)), ln10 = log(interval(10));
  const Eigen::Index masses = size / 2;
  long long scale = 0;  // P is Φ^(2^j) / 2^scale
  interval running = interval(-1e300), at_fit = running;
  for (int j = 0; j <= doublings; ++j) {
    // |q|₁ + |p|₁/ω_max of y = Φ^(2^j) y₀; |y₀| = 1.
    interval amplitude(0);
    for (Eigen::Index i = 0; i < masses; ++i) amplitude += abs(at(P, masses + i, start_column)) + abs(at(P, i, start_column)) / fast_i;
    if (certain_sign(amplitude) > 0) running = enclosed_max(running, interval(interval(scale) * ln2 + log(amplitude)));
    if (j == fit_from) at_fit = running;
    if (j == doublings) break;
    std::vector<interval> square(P.size(), interval(0));
    for (Eigen::Index a = 0; a < size; ++a) {
      for (Eigen::Index c = 0; c < size; ++c) {
        for (Eigen::Index b = 0; b < size; ++b) at(square, a, b) += at(P, a, c) * at(P, c, b);
      }
    }
    double largest = 0;
    for (const interval& x : square) largest = std::max(largest, static_cast<double>(upper(interval(abs(x)))));
    const int shift = std::ilogb(largest);  // entries up to 64 ‖P‖² before the shift: in double's range
    // MPFI's own exact scaling by 2^−shift (Boost 1.74's ldexp of an mpfi_float by 0 gives NaN under
    // clang: found by the sanitizer suite).
    for (interval& x : square) mpfi_mul_2si(x.backend().data(), x.backend().data(), -shift);
    scale = 2 * scale + shift;
    P = std::move(square);
    throw_if_interrupted();
  }
  return {at_fit / ln10, running / ln10, (running - at_fit) / (interval(doublings - fit_from) * ln2)};
}

/// The growth class of an enclosed exponent: decided when the whole enclosure lies in one class
/// (growth_class's thresholds), else undecided.
std::string enclosed_class(const interval& exponent) {
  const std::string low = growth_class(static_cast<double>(lower(exponent))), high = growth_class(static_cast<double>(upper(exponent)));
  return low == high ? low : "undecided (" + low + " to " + high + ")";
}

}  // namespace

void add_stiff_chain(const stability_report& region, const std::vector<double>& ratios, int doublings, section_result& out) {
  const int fit_from = std::max(0, doublings - 10);  // three decades: 2^10 ≈ 10³
  table t{"stiff_chain",
          fmt::format("Stiff linear chain: {} unit masses, springs 1, k, 1, k, 1 from wall to wall (ω_max/ω_min = r), run "
                      "2^{} steps of the mpfr:50 map, enclosed",
                      chain_masses, doublings),
          "",
          {{"ratio", "r = ω_max/ω_min", "", 4},
           {"k", "stiff spring k"},
           {"fast_x", "fast ω²h² aimed at"},
           {"h", "h", "", 6},
           {"slow_omega_h", "slow ωh", "", 3},
           {"modes", "modes x = ω_k²h² (exact)"},
           {"predicted", "growth predicted"},
           {fmt::format("log10_max_amplitude_2_{}", fit_from), fmt::format("log10 max |y|/|y₀|, n ≤ 2^{}", fit_from), "", 4},
           {fmt::format("log10_max_amplitude_2_{}", doublings), fmt::format("log10 max |y|/|y₀|, n ≤ 2^{}", doublings), "", 4},
           // Three significant digits (the enclosure, every digit, in the JSON): an exponential rise's exponent is large.
           column("growth_exponent", fmt::format("log-log exponent, n = 2^{}..2^{}", fit_from, doublings)),
           {"fitted", "growth fitted"}}};
  for (const double r : ratios) {
    // k = r²/4: the slow modes move the stiff pairs as rigid bodies of mass 2 on soft springs
    // (ω² = 1/2, 3/2), the fast ones stretch the stiff springs (ω² ≈ 2k); the row shows the r obtained.
    const rational k = rational(r) * rational(r) / 4;
    const std::vector<rational> springs = chain_springs(k);
    Eigen::MatrixXd K_double = Eigen::MatrixXd::Zero(chain_masses, chain_masses);
    for (int i = 0; i < chain_masses; ++i) {
      K_double(i, i) = (springs[static_cast<std::size_t>(i)] + springs[static_cast<std::size_t>(i) + 1]).convert_to<double>();
      if (i + 1 < chain_masses) K_double(i, i + 1) = K_double(i + 1, i) = -springs[static_cast<std::size_t>(i) + 1].convert_to<double>();
    }
    const Eigen::VectorXd omega2 = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K_double).eigenvalues();  // in double: to aim h only
    const double ratio = std::sqrt(omega2.maxCoeff() / omega2.minCoeff());
    for (const stability_band& band : region.bands) {
      throw_if_interrupted();
      // The fast modes aimed at the middle of the band (twice its start for the last, unbounded one);
      // h is a double, taken exactly as a rational, so the prediction below is for the h that runs.
      const rational aim = band.to ? rational((band.x_from + band.to->low) / 2) : rational(2 * band.x_from);
      const double h_double = std::sqrt(aim.convert_to<double>() / omega2.maxCoeff());
      const rational h(h_double);
      const mode_prediction predicted = predict(region, mode_polynomial(springs, h * h));
      figure start_value, end_value, exponent_figure;
      std::string fitted;
      visit_mpfr(50, [&](auto tag) {
        using Real = typename decltype(tag)::type;
        using std::sqrt;
        const dense_matrix<Real> M = dense_matrix<Real>::Identity(chain_masses, chain_masses);
        dense_matrix<Real> K = dense_matrix<Real>::Zero(chain_masses, chain_masses);
        for (int i = 0; i < chain_masses; ++i) {
          K(i, i) = to_real<Real>(springs[static_cast<std::size_t>(i)] + springs[static_cast<std::size_t>(i) + 1]);
          if (i + 1 < chain_masses) K(i, i + 1) = K(i + 1, i) = -to_real<Real>(springs[static_cast<std::size_t>(i) + 1]);
        }
        const Real fast = sqrt(to_real<Real>(rational(omega2.maxCoeff())));
        // y₀: the first mass displaced, every mode excited; amplitude |q|₁ + |p|₁/ω_max. The run is
        // enclosed (MPFI) from the map's mpfr entries: its figures and its class are what the table shows.
        const enclosed_growth enclosed = enclosed_run(ndof_simpson_map(M, K, to_real<Real>(h)), fast, doublings, fit_from, chain_masses);
        start_value = enclosed_figure(enclosed.at_fit);
        end_value = enclosed_figure(enclosed.at_end);
        exponent_figure = enclosed_figure(enclosed.exponent);
        fitted = enclosed_class(enclosed.exponent);
      });
      const double slow_omega_h = std::sqrt(omega2.minCoeff()) * h_double;  // in double, as h was aimed
      t.add({figure::of(ratio), figure::exact(k), figure::exact(aim), figure::of(h_double), figure::of(slow_omega_h), figure::text(predicted.modes),
             figure::text(predicted.growth), start_value, end_value, exponent_figure, figure::text(fitted)});
      out.expect({fmt::format("stiff-chain-r{}-x{}", simpson::to_string(r, 3), simpson::to_string(aim)),
                  fmt::format("The stiff chain (r = {}) with its fast modes at ω²h² ≈ {} grows as its modes predict.", simpson::to_string(ratio, 4),
                              simpson::to_string(aim)),
                  fmt::format("{}: the modes' x = ω_k²h² of the h that runs, {} (Sturm, exact)", predicted.growth, predicted.modes),
                  fmt::format("{}: log-log exponent {} (enclosed, ± {}) over n = 2^{}..2^{}", fitted, display_value(exponent_figure, 3),
                              exponent_figure.radius(), fit_from, doublings),
                  fitted == predicted.growth});
    }
  }
  t.intro = fmt::format(
      "A stiff system as the field poses it: several time scales, the step set by the slow one. The slow modes are "
      "resolved (slow ωh small); the fast modes' ωh decides. Predicted exactly, before any run: the roots of det(h²K − xI) "
      "counted in each band of the region above by Sturm sequences; any root in an unstable band means exponential growth. "
      "Then Φ for the whole chain (ndof_simpson_map, the 2n × 2n step) in mpfr:50 is squared {} times, so y_n is computed for "
      "n = 2^j up to 2^{} ≈ {:.2e} steps, and its largest amplitude fitted as in the endpoint table. Each row is an "
      "expectation of this section. The run is enclosed: the mpfr:50 map's entries enter intervals exactly and the "
      "squarings run in MPFI with exact rescalings by powers of two, so the amplitudes and the exponent shown are "
      "guaranteed for the map that runs, and a class is given only when the exponent's whole enclosure lies in it.",
      doublings, doublings, std::ldexp(1.0, doublings));
  out.add(std::move(t));
}

}  // namespace simpson::verify::detail

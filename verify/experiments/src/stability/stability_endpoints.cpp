// The stability section's endpoints: at and around each exact endpoint of Φ₃'s stable set, the
// powers Φ₃ⁿ y₀ in closed form (one_step_power.hpp) for n up to 10⁹, their growth fitted over the
// last three decades, and the fitted class held against the class the exact region predicts.

#include "stability_parts.hpp"

#include <simpson/verify/floating_tools.hpp>
#include <simpson/verify/interruption.hpp>

#include <simpson/one_step_power.hpp>
#include <simpson/simpson_map.hpp>

#include <boost/math/constants/constants.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace simpson::verify::detail {
namespace {

/// Where ωh lies relative to the endpoint, and the offset of its row: θ = θ_e (1 + side · 10⁻⁶).
constexpr long long offset_denominator = 1000000;

/// n = 1, then 10 per decade up to `last`, and `last`.
std::vector<long long> power_samples(long long last) {
  std::vector<long long> out{1};
  for (int k = 1; std::pow(10.0, k / 10.0) < static_cast<double>(last); ++k) {
    const long long n = std::llround(std::pow(10.0, k / 10.0));
    if (n > out.back()) out.push_back(n);
  }
  out.push_back(last);
  return out;
}

}  // namespace

// The powers of a linear map are bounded, grow like a polynomial of integer degree (a Jordan block
// of size d + 1 gives n^d) or grow exponentially; so the log-log exponent of their running maximum
// over three decades is classed at the midpoints between those degrees. The margin is for what a
// sparse sampling does to a bounded orbit of several incommensurate modes: its sampled running
// maximum keeps rising while new phases are met (0.05 over 2^10..2^20 steps for the stiff chain).
std::string growth_class(double exponent) {
  if (exponent > 3) return "exponential";
  if (exponent >= 0.5 && exponent < 1.5) return "linear";
  if (exponent < 0.5) return "bounded";
  return "none of these";
}

namespace {

/// 10⁶ for a power of ten, else the digits.
std::string count_text(long long n) {
  static const char* const superscripts[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  int k = 0;
  long long m = n;
  while (m >= 10 && m % 10 == 0) {
    m /= 10;
    ++k;
  }
  if (m != 1 || k == 0) return std::to_string(n);
  std::string exponent;
  for (const char digit : std::to_string(k)) exponent += superscripts[digit - '0'];
  return "10" + exponent;
}

}  // namespace

void add_endpoint_growth(const stability_report& report, long long last_power, section_result& out) {
  const long long fit_from = std::max<long long>(1, last_power / 1000);
  std::vector<long long> samples = power_samples(last_power);
  samples.push_back(fit_from);
  std::sort(samples.begin(), samples.end());
  samples.erase(std::unique(samples.begin(), samples.end()), samples.end());
  // The running maximum is shown at 10³ (what a run of a thousand steps sees) and at the last power.
  std::vector<long long> shown;
  for (const long long n : {1000LL, last_power}) {
    if (n <= last_power && std::find(shown.begin(), shown.end(), n) == shown.end()) shown.push_back(n);
  }
  table t{"endpoints",
          fmt::format("At and around each endpoint: Φ₃ⁿ y₀ in closed form up to n = {} (mpfr:50, m = ω = 1, y₀ = (0.6, 0.8), "
                      "amplitude A = |q| + |p|/(mω))",
                      last_power),
          "",
          {{"omega_h", "ωh"},
           {"eigenvalues", "eigenvalues"},
           {"jordan_block", "Jordan block (Φ₃ − λI ≠ 0)"},
           {"beat_period", "period of |y| (steps)"}}};
  for (const long long n : shown) t.columns.push_back({fmt::format("max_amplitude_to_{}", n), fmt::format("max |y|/A, n ≤ {}", count_text(n))});
  // Three significant digits (every digit in the JSON): an exponential rise's exponent is large.
  t.columns.push_back(column("growth_exponent", fmt::format("log-log exponent, n = {}..{}", count_text(fit_from), count_text(last_power))));
  t.columns.push_back({"growth_rate", "fitted rate ln M / n", "", 6});
  t.columns.push_back({"log_growth_factor", "ln |λ| max", "", 6});
  t.columns.push_back({"fitted", "growth fitted"});
  t.columns.push_back({"predicted", "growth predicted"});
  std::vector<std::string> by_class[3];  // bounded, linear, exponential rows, for the prose
  long long longest_period = 0;
  visit_mpfr(50, [&](auto tag) {
    using Real = typename decltype(tag)::type;
    using std::abs;
    using std::acos;
    using std::acosh;
    using std::ceil;
    using std::exp;
    using std::log;
    using std::sqrt;
    const Real pi = boost::math::constants::pi<Real>();
    for (const positive_root& root : report.roots) {
      if (!root.exact()) throw std::logic_error("stability: endpoint x = " + root_text(root) + " is not exact");
      const rational& x_end = root.low;
      const Real theta_end = sqrt(to_real<Real>(x_end));
      for (const int side : {-1, 0, 1}) {
        throw_if_interrupted();
        const Real theta = theta_end * (1 + Real(side) / offset_denominator);
        const one_step_matrix<Real> phi = simpson_map(oscillator_parameters<Real>{Real(1), Real(1), theta});
        // The prediction, from the exact region alone: the band that holds x = x_e (1 + side 10⁻⁶)².
        const rational x = x_end * rational(offset_denominator + side, offset_denominator) * rational(offset_denominator + side, offset_denominator);
        std::string predicted = "linear";
        std::string because = "x = " + simpson::to_string(x_end) + " is a root of Δ: a double eigenvalue ±1";
        if (side != 0) {
          const auto band = std::find_if(report.bands.begin(), report.bands.end(),
                                         [&](const stability_band& b) { return x > b.x_from && (!b.to || x < b.to->low); });
          if (band == report.bands.end()) throw std::logic_error("stability: no band holds x = " + simpson::to_string(x));
          predicted = band->stable ? "bounded" : "exponential";
          because = fmt::format("x = {} (1 {} 10⁻⁶)² lies in the band {} < ωh < {}, where Δ is {}", simpson::to_string(x_end), side < 0 ? "−" : "+",
                                band->omega_h_from, band->omega_h_to, band->discriminant_negative ? "negative (stable)" : "positive (unstable)");
        }
        // Eigenvalues of Φ₃ = ((α, β), (γ, α)), det 1: α ± sqrt(α² − 1).
        const Real a = phi.alpha, d = a * a - 1;
        figure eigenvalues, period = figure::text("n/a"), log_factor = figure::text("n/a");
        Real psi(0);
        if (d <= 0) {
          eigenvalues = figure::text(fmt::format("{} ± {} i", simpson::to_string(a, 8), simpson::to_string(Real(sqrt(Real(-d))), 8)));
          // |y| beats with the eigenvalue's angle from the real axis: φ near 0 (α near 1) or π − φ
          // near π (α near −1, where y also flips sign each step, which |y| does not see).
          const Real angle = acos(a);
          if (side != 0) {
            const Real steps = 2 * pi / std::min(angle, Real(pi - angle));
            period = figure::of(steps);
            longest_period = std::max(longest_period, static_cast<long long>(ceil(steps)));
          }
        } else {
          const Real r = sqrt(d);
          eigenvalues = figure::text(fmt::format("{}, {}", simpson::to_string(Real(a + r), 8), simpson::to_string(Real(a - r), 8)));
          psi = acosh(Real(abs(a)));
          log_factor = figure::of(psi);
        }
        // At the endpoint α = ±1 up to round-off: θ carries one rounding, and α(x) has slope
        // |dα/dx| <= 1 on (0, 24], so |α − λ| <= 64 eps x covers θ², the formula's ~20 roundings and room.
        // A Jordan block: the double root λ with Φ₃ − λI ≠ 0 (β or γ non-zero).
        const Real lambda = a > 0 ? Real(1) : Real(-1), x_run = theta * theta;
        const bool jordan = abs(phi.beta) + abs(phi.gamma) > 0 && abs(Real(a - lambda)) <= 64 * eps<Real>() * x_run;
        // The running maximum of ln A(Φ₃ⁿ y₀) over the samples.
        Real running = -std::numeric_limits<Real>::infinity(), at_fit_start(0);
        std::vector<figure> shown_values;
        for (const long long n : samples) {
          const scaled_phase_point<Real> y = power_apply(phi, phase_point<Real>{Real(Real(6) / 10), Real(Real(8) / 10)}, n);
          const Real size = abs(y.direction.q) + abs(y.direction.p);
          if (size > 0) running = std::max(running, Real(y.log_scale + log(size)));
          if (n == fit_from) at_fit_start = running;
          if (std::find(shown.begin(), shown.end(), n) != shown.end()) shown_values.push_back(figure::of(Real(exp(running))));
        }
        const Real rise = running - at_fit_start;
        const Real exponent = rise / log(Real(last_power) / Real(fit_from)), rate = rise / Real(last_power - fit_from);
        const std::string fitted = growth_class(static_cast<double>(exponent));
        // An exponential fit also matches its rate: ln M(n) = nψ + O(1), so over 10⁹ − 10⁶ steps the
        // fitted rate is ψ to a relative 10⁻³ once ψ(n₁ − n₀) exceeds the O(1) term's change 10³-fold.
        const bool rate_agrees = fitted != "exponential" || abs(Real(rate / psi - 1)) < Real(1) / 1000;
        const std::string row_name = side == 0 ? fmt::format("sqrt({}) = {}", simpson::to_string(x_end), simpson::to_string(theta, 12))
                                               : fmt::format("sqrt({}) (1 {} 1e-6)", simpson::to_string(x_end), side < 0 ? "-" : "+");
        table_row row{figure::text(row_name), eigenvalues, side == 0 ? figure::flag(jordan) : figure::text("n/a"), period};
        row.insert(row.end(), shown_values.begin(), shown_values.end());
        row.insert(row.end(), {figure::of(exponent), figure::of(rate), log_factor, figure::text(fitted), figure::text(predicted)});
        t.add(std::move(row));
        const int cls = fitted == "bounded" ? 0 : fitted == "linear" ? 1 : fitted == "exponential" ? 2 : -1;
        if (cls >= 0) by_class[cls].push_back(row_name);
        const std::string key = fmt::format("endpoint-x{}-{}", simpson::to_string(x_end), side < 0 ? "below" : side == 0 ? "at" : "above");
        out.expect({key,
                    fmt::format("At ωh = {}, the powers of Φ₃ grow as the exact region predicts.", row_name),
                    predicted + (side == 0 ? std::string(jordan ? " (Jordan block: Φ₃ − λI ≠ 0)" : " (but Φ₃ = λI here: no Jordan block)") : "") +
                        ": " + because,
                    fmt::format("{}: max |y|/A rises with the log-log exponent {} from n = {} to {}{}", fitted, simpson::to_string(exponent, 4),
                                fit_from, last_power,
                                fitted == "exponential" ? fmt::format(", rate {} against ln |λ| = {}", simpson::to_string(rate, 6), simpson::to_string(psi, 6))
                                                        : std::string()),
                    fitted == predicted && rate_agrees && (side != 0 || jordan)});
      }
    }
  });
  const auto list = [](const std::vector<std::string>& rows) { return rows.empty() ? std::string("none") : fmt::format("{}", fmt::join(rows, "; ")); };
  t.intro = fmt::format(
      "Φ₃ⁿ = U_(n−1)(α) Φ₃ − U_(n−2)(α) I (Cayley–Hamilton, det Φ₃ = 1) gives y_n for any n without iterating; the "
      "largest amplitude over n (10 samples per decade) is fitted over the last three decades, n = {} to {}, by the log-log "
      "exponent of its rise (a linear map's powers are bounded, grow like n^d for an integer d, or grow exponentially). "
      "Fitted as bounded (exponent < 0.5): {}. Linear (exponent in [0.5, 1.5), a Jordan block): {}. Exponential (exponent > 3, its "
      "rate against ln |λ|): {}. Inside a band |y| beats with a period of P steps, and a run shorter than P cannot tell "
      "bounded from growing: near the endpoints P is up to {} steps, so n = {} covers {} periods or more. Each row's "
      "prediction comes from the exact region (the table above) and is an expectation of this section.",
      count_text(fit_from), count_text(last_power), list(by_class[0]), list(by_class[1]), list(by_class[2]), longest_period, count_text(last_power),
      longest_period > 0 ? std::to_string(last_power / longest_period) : std::string("many"));
  out.add(std::move(t));
}

}  // namespace simpson::verify::detail

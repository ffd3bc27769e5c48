// Table 1 in interval arithmetic: see table1_enclosed.hpp.

#include <simpson/verify/table1_enclosed.hpp>

#include <simpson/verify/paper_table.hpp>

#include <simpson/interval.hpp>

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <string>

namespace simpson::verify {
namespace {

/// The errors of one run as enclosures (the fields of table_errors).
struct enclosed_errors {
  interval p{0}, q{0}, energy{0}, discrete_energy{0};
};

/// An exact start's values as enclosures: m, and y_0 = (p_0, q_0) = (m ω A, 0) or (0, A).
interval rational_times_pi(long num, long den, int pi_power) {
  interval x = interval(num) / interval(den);
  for (int k = 0; k < pi_power; ++k) x *= boost::math::constants::pi<interval>();
  for (int k = 0; k > pi_power; --k) x /= boost::math::constants::pi<interval>();
  return x;
}

/// The experiment under the stated discrete conventions (paper_table.hpp's table_errors): ω = 2π,
/// h = 1/N, maximum over j = 0..N, from `start` (the stated one: m = 1, y_0 = (mω, 0)).
enclosed_errors enclosed_run(bool simpson_scheme, long long N, const exact_start& start = {}) {
  const interval m = interval(start.m_num) / interval(start.m_den), omega = 2 * boost::math::constants::pi<interval>();
  const interval A = rational_times_pi(start.amplitude_num, start.amplitude_den, start.amplitude_pi_power);
  const oscillator_parameters<interval> par{m, omega, interval(interval(1) / interval(N))};
  const phase_point<interval> y0 = start.at_rest ? phase_point<interval>{interval(0), A} : phase_point<interval>{interval(m * omega * A), interval(0)};
  const one_step_matrix<interval> phi = simpson_scheme ? simpson_map(par) : newmark_map(par);
  const interval H0 = energy(par, y0), Hd0 = discrete_energy(par, y0);
  enclosed_errors e;
  phase_point<interval> y = y0;
  for (long long j = 0; j <= N; ++j) {
    const phase_point<interval> exact = exact_solution(par, y0, interval(interval(j) * par.h()));
    e.p = enclosed_max(e.p, abs(interval(y.p - exact.p)));
    e.q = enclosed_max(e.q, abs(interval(y.q - exact.q)));
    e.energy = enclosed_max(e.energy, abs(interval(energy(par, y) - H0)));
    e.discrete_energy = enclosed_max(e.discrete_energy, abs(interval(discrete_energy(par, y) - Hd0)));
    y = phi * y;
  }
  return e;
}

/// Both schemes' runs at the paper's meshes from `start` ([newmark, simpson][N = 10, 20, 40]), in
/// the digits in scope; once per run with its memo.
using enclosed_runs = std::array<std::array<enclosed_errors, 3>, 2>;
enclosed_runs runs_from(const exact_start& start, unsigned digits, run_memo* memo) {
  const std::string key = fmt::format("table1: the exact schemes' runs enclosed from m = {}/{}, A = {}/{} pi^{}{}, {} digits", start.m_num,
                                      start.m_den, start.amplitude_num, start.amplitude_den, start.amplitude_pi_power,
                                      start.at_rest ? " at rest" : "", digits);
  return remembered<enclosed_runs>(memo, key, [&] {
    enclosed_runs runs;
    for (int s = 0; s < 2; ++s) {
      for (std::size_t k = 0; k < 3; ++k) runs[static_cast<std::size_t>(s)][k] = enclosed_run(s == 1, published_meshes[k], start);
    }
    return runs;
  });
}

interval enclosed_errors::*field_of(double table_errors::*field) {
  if (field == &table_errors::p) return &enclosed_errors::p;
  if (field == &table_errors::q) return &enclosed_errors::q;
  if (field == &table_errors::energy) return &enclosed_errors::energy;
  return &enclosed_errors::discrete_energy;
}

/// The integer n with log₂(ratio) proved in (n − ½, n + ½), or none.
std::optional<long> proved_order(const interval& log2_ratio) {
  const long n = std::lround(static_cast<double>(boost::multiprecision::mpfr_float(median(log2_ratio))));
  if (lower(log2_ratio) > n - 0.5 && upper(log2_ratio) < n + 0.5) return n;
  return std::nullopt;
}

/// Where x lies against the bound a/b.
bound_decision against(const interval& x, const std::pair<long, long>& bound) {
  const interval b = interval(bound.first) / interval(bound.second);
  if (upper(x) <= lower(b)) return bound_decision::at_most;
  if (lower(x) > upper(b)) return bound_decision::above;
  return bound_decision::undecided;
}

}  // namespace

std::vector<entry_decision> enclosed_stated_entries(const std::vector<printed_value>& printed, unsigned digits, run_memo* memo) {
  return enclosed_entries(printed, exact_start{}, digits, memo);
}

std::vector<entry_decision> enclosed_entries(const std::vector<printed_value>& printed, const exact_start& start, unsigned digits,
                                            run_memo* memo) {
  const scoped_interval_digits scope(digits);
  const enclosed_runs runs = runs_from(start, digits, memo);
  std::vector<entry_decision> out;
  for (std::size_t r = 0; r < published_rows().size(); ++r) {
    const published_row& row = published_rows()[r];
    for (std::size_t k = 0; k < published_meshes.size(); ++k) {
      const std::size_t index = r * published_meshes.size() + k;
      if (index >= printed.size()) return out;
      const printed_value& p = printed[index];
      const interval error = runs[row.simpson_scheme ? 1 : 0][k].*field_of(row.field);
      if (p.round_off) {
        // Conserved by the exact scheme (the enclosure holds 0), and printed at round-off for the
        // quantity's size (H_0 of the run: (m omega A)^2 / (2 m) from a sine start, m omega^2 A^2 / 2 at rest).
        const double H0 = stated_H0() * start.energy_factor();
        const bool printed_at_round_off = at_round_off_floor(std::abs(p.value), published_meshes[k], H0);
        out.push_back(certain_sign(error) == 0 && printed_at_round_off ? entry_decision::reproduced : entry_decision::not_reproduced);
        continue;
      }
      // The printed decimal and half a unit of its last digit, both exact decimals, enclosed.
      const std::string mantissa = fmt::format("{:.{}e}", p.value, std::max(p.digits - 1, 0));
      const long exponent = std::stol(mantissa.substr(mantissa.find('e') + 1));
      const interval centre(mantissa), half(fmt::format("5e{}", exponent - p.digits));
      const interval low = centre - half, high = centre + half;
      if (lower(error) >= upper(low) && upper(error) <= lower(high)) {
        out.push_back(entry_decision::reproduced);
      } else if (upper(error) < lower(low) || lower(error) > upper(high)) {
        out.push_back(entry_decision::not_reproduced);
      } else {
        out.push_back(entry_decision::undecided);
      }
    }
  }
  return out;
}

bounded_errors enclosed_errors_within(bool simpson_scheme, long long N, const std::vector<std::pair<long, long>>& bounds,
                                      unsigned digits) {
  const scoped_interval_digits scope(digits);
  const enclosed_errors e = enclosed_run(simpson_scheme, N);
  const interval m_omega = 2 * boost::math::constants::pi<interval>();  // m = 1
  const interval p = e.p / m_omega, worst = enclosed_max(p, e.q);
  bounded_errors out{enclosure_text(p, 6), enclosure_text(e.q, 6), {}, {}};
  for (const std::pair<long, long>& bound : bounds) {
    out.p_within.push_back(against(p, bound));
    out.worst_within.push_back(against(worst, bound));
  }
  return out;
}

std::array<enclosed_table_row, 8> enclosed_table1(unsigned digits, long shown_digits, run_memo* memo) {
  const scoped_interval_digits scope(digits);
  const enclosed_runs runs = runs_from(exact_start{}, digits, memo);
  std::array<enclosed_table_row, 8> rows;
  for (std::size_t r = 0; r < published_rows().size(); ++r) {
    const published_row& row = published_rows()[r];
    std::array<interval, 3> errors;
    bool all_hold_zero = true, none_holds_zero = true;
    for (std::size_t k = 0; k < 3; ++k) {
      errors[k] = runs[row.simpson_scheme ? 1 : 0][k].*field_of(row.field);
      rows[r].values[k] = enclosure_text(errors[k], shown_digits);
      rows[r].short_values[k] = enclosure_text(errors[k], 12);
      all_hold_zero = all_hold_zero && certain_sign(errors[k]) == 0;
      none_holds_zero = none_holds_zero && certain_sign(errors[k]) != 0;
    }
    if (all_hold_zero) {
      rows[r].order = "exact";
      rows[r].order_evidence = "every error's enclosure holds 0: the exact scheme conserves it (widest " + rows[r].values[2] + ")";
      continue;
    }
    if (!none_holds_zero) {
      rows[r].order = "undecided (some errors' enclosures hold 0, others do not)";
      continue;
    }
    const interval first = log2(interval(errors[0] / errors[1])), second = log2(interval(errors[1] / errors[2]));
    const std::optional<long> a = proved_order(first), b = proved_order(second);
    rows[r].order_evidence = "log2 ratios " + enclosure_text(first) + " and " + enclosure_text(second);
    if (a && b && *a == *b) {
      rows[r].order = std::to_string(*a);
    } else if (a && b) {
      rows[r].order = "inconsistent (" + std::to_string(*a) + ", " + std::to_string(*b) + ")";
    } else {
      rows[r].order = "undecided (a log2 ratio is not within 1/2 of an integer)";
    }
  }
  return rows;
}

std::array<enclosed_table_row, 8> enclosed_table1_of_run(run_memo* memo) { return enclosed_table1(table1_enclosure_digits, 60, memo); }

}  // namespace simpson::verify

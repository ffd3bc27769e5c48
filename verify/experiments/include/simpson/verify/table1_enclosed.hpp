#pragma once
// Table 1's experiment under the stated conventions, in exact arithmetic, enclosed: the schemes'
// maps and the exact solution in interval arithmetic (MPFI, π enclosed), so that each error is an
// interval holding the error of the exact scheme. The order column is decided from the enclosures:
// an integer when both log₂ ratios of successive errors are proved within ½ of it, "exact" when
// every error's enclosure holds 0 (the quantity is conserved by the exact scheme), else undecided.
// Header free of MPFI: enclosures leave as text (enclosure_text: only guaranteed digits).

#include <simpson/verify/run_memo.hpp>

#include <boost/math/constants/constants.hpp>

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace simpson::verify {

struct enclosed_table_row {
  std::array<std::string, 3> values;  // N = 10, 20, 40: "1.4427e-14 ± 3e-31", or "0 ± 2e-50"
  std::array<std::string, 3> short_values;  // the same with at most 12 digits, for a table
  std::string order;                  // "2", "4", "exact", or "undecided (…)"
  std::string order_evidence;         // the log₂ ratios' enclosures, or why exact
};

/// The rows of published_rows() (paper_table.hpp), in order, computed in `digits` decimal digits;
/// each value printed with at most `shown_digits` digits (its radius widened by that rounding).
/// With a run's memo, the runs are enclosed once per run, for this and the entries' judgments below.
std::array<enclosed_table_row, 8> enclosed_table1(unsigned digits = 40, long shown_digits = 60, run_memo* memo = nullptr);

/// Digits of Table 1's enclosed runs: far more than its orders need (they are decided at 40 with
/// margins of 0.4 and more), few enough for a fast run.
inline constexpr unsigned table1_enclosure_digits = 40;

/// enclosed_table1() at table1_enclosure_digits, its runs enclosed once per run (the run's memo;
/// every time without one): the table1 section and the records that observe its facts read the
/// same enclosures.
std::array<enclosed_table_row, 8> enclosed_table1_of_run(run_memo* memo);

/// How an enclosure compares with a bound a/b: proved at most the bound, proved above it, or neither
/// at this precision.
enum class bound_decision { at_most, above, undecided };

/// One run under the stated conventions at N, enclosed: max_j |p_j − p(t_j)|/(mω) and the larger of
/// that and max_j |q_j − q(t_j)| (the amplitude is 1 in both), each compared with every bound
/// (numerator, denominator).
struct bounded_errors {
  std::string p_over_m_omega, q;
  std::vector<bound_decision> p_within, worst_within;  // one per bound
};
/// Table 1's printed entries (table1_printed's order: published_rows() by published_meshes) judged
/// against the exact schemes under the stated conventions, enclosed: an entry printed with d digits
/// is reproduced when the error's enclosure lies inside the half-unit interval of its last digit
/// (the printed decimal, exactly), not reproduced when it lies outside, undecided when it straddles
/// an end. An entry printed at round-off is reproduced when the enclosure holds 0 (the exact scheme
/// conserves the quantity: what remains in a floating run is round-off) and not reproduced when it
/// excludes 0.
enum class entry_decision { reproduced, not_reproduced, undecided };
struct printed_value {
  double value = 0;  // the printed decimal, as read
  int digits = 3;
  bool round_off = false;
};
std::vector<entry_decision> enclosed_stated_entries(const std::vector<printed_value>& printed, unsigned digits = 40, run_memo* memo = nullptr);

/// An exact solution of the oscillator with ω = 2π, exactly: m = m_num/m_den, amplitude A =
/// (amplitude_num/amplitude_den) π^amplitude_pi_power, started at q_0 = 0 with p_0 = m ω A (the
/// stated q = sin ωt when A = m = 1) or released from rest at q_0 = A.
struct exact_start {
  long m_num = 1, m_den = 1;
  long amplitude_num = 1, amplitude_den = 1;
  int amplitude_pi_power = 0;
  bool at_rest = false;
  /// m and A in double (the start a double program holds).
  double mass() const { return double(m_num) / double(m_den); }
  double amplitude() const {
    return double(amplitude_num) / double(amplitude_den) * std::pow(boost::math::constants::pi<double>(), amplitude_pi_power);
  }
  /// H_0 over the stated one's (m A² in both starts, ω fixed), in double: for the round-off floor.
  double energy_factor() const { return mass() * amplitude() * amplitude(); }
};
/// The same judgment (enclosed_stated_entries) under the stated discrete conventions from `start`.
std::vector<entry_decision> enclosed_entries(const std::vector<printed_value>& printed, const exact_start& start, unsigned digits = 40,
                                            run_memo* memo = nullptr);

bounded_errors enclosed_errors_within(bool simpson_scheme, long long N, const std::vector<std::pair<long, long>>& bounds,
                                      unsigned digits = 40);

}  // namespace simpson::verify

#pragma once
// When a printed table disagrees: which conventions, if any, reproduce it. A printed table (values
// with the digits they were printed with), a parametrised experiment, discrete conventions to
// enumerate and continuous parameters to fit. A printed value with d significant digits says that
// the true value lies within half a unit of its last digit: an entry is reproduced when the computed
// value lies in that interval; an entry printed at round-off is reproduced when the computed value
// is at round-off too (below the bound the experiment gives), and only when its printed value is at
// round-off as well. Table 1 is the first user (table1_conventions.hpp); nothing here knows about it.

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace simpson::verify {

/// One printed number: its value, how many significant digits it was printed with, and whether it is
/// printed at round-off (an "exact" row: judged as round-off, not digit by digit).
struct printed_entry {
  std::string row, column;
  double value = 0;
  int digits = 3;
  bool round_off = false;
};

/// What the experiment computed for an entry, and below what a value is round-off for it.
struct computed_entry {
  double value = 0;
  double round_off_bound = 0;
};

/// A convention the search enumerates: its name, its options, and the one the paper states.
struct discrete_convention {
  std::string name;
  std::vector<std::string> options;
  std::string stated;
};

/// A parameter the search fits within [low, high] (log-uniform when log_scale), `stated` the value
/// the paper states or implies. A `scale` parameter is one every computed entry is homogeneous in (an
/// entry proportional to a power of it, as errors are in an amplitude): the search measures each
/// entry's power and fits it in closed form; the others are scanned on a dense grid.
struct continuous_parameter {
  std::string name;
  double low = 0, high = 0, stated = 0;
  bool log_scale = true;
  bool scale = false;
};

using convention_choice = std::map<std::string, std::string>;
using parameter_values = std::map<std::string, double>;

/// The experiment under a convention: one computed entry per printed entry, in the same order.
using parametrised_experiment = std::function<std::vector<computed_entry>(const convention_choice&, const parameter_values&)>;

struct entry_score {
  double computed = 0;
  double residual = 0;  // |computed − printed| in half-units of the last printed digit (round-off: computed / bound)
  bool reproduced = false;
};

struct convention_candidate {
  convention_choice choice;
  parameter_values values;
  /// For a simple hypothesis: each parameter's value in words ("pi/2"); empty for a fitted candidate.
  std::map<std::string, std::string> value_names;
  /// For a simple hypothesis: how far it is from the stated conventions (a discrete convention that
  /// departs from the stated one counts 1, a simple value its rank in its list); 0 for the stated.
  int complexity = 0;
  std::vector<entry_score> entries;
  std::size_t reproduced = 0;  // entries reproduced
  double worst = 0;            // the largest residual
  /// For the best candidate when it reproduces every entry: for each fitted parameter, how far it
  /// reaches with the others free (NLopt on the constraints "every entry reproduced"), each end
  /// attained by values a full run reproduces the table with: the joint region is at least this wide.
  std::map<std::string, std::pair<double, double>> joint_extent;
};

/// A simple value a parameter is tried at before any fit: the value and its name in words ("pi/2").
struct simple_value {
  std::string name;
  double value = 0;
};
/// For each continuous parameter, its simple values, simplest first.
using simple_values = std::map<std::string, std::vector<simple_value>>;

struct convention_search_result {
  convention_candidate stated;           // the stated conventions and values, unfitted
  /// Every combination of the discrete conventions and the simple values, judged by a full run, best
  /// first: most entries reproduced, then the least complex, then the smallest worst residual.
  std::vector<convention_candidate> simple;
  std::vector<convention_candidate> tried;  // every discrete combination, fitted, best first
  std::size_t evaluations = 0;           // experiment runs
  parameter_values fixed;                // values every run was made with and none searched (Table 1's period)
  double seconds = 0;
  bool stated_reproduces() const;
  /// The best candidate, when it reproduces every entry.
  const convention_candidate* reproducing() const;
  /// The simplest hypothesis that explains the most entries (null when none was tried).
  const convention_candidate* simplest() const { return simple.empty() ? nullptr : &simple.front(); }
};

/// A missed entry's distance past the nearer boundary of its printed digits' interval, in the units
/// of the value (|computed − printed| − half a unit of the last digit), and that boundary.
struct entry_miss {
  double past = 0;
  double boundary = 0;
};
entry_miss miss_of(const printed_entry& printed, double computed);

/// Every combination of the discrete conventions and of `simple` (a parameter missing there stays at
/// its stated value), each judged by a full run of the experiment; best first, as
/// convention_search_result::simple.
std::vector<convention_candidate> simple_hypotheses(const std::vector<printed_entry>& printed, const std::vector<discrete_convention>& discrete,
                                                    const std::vector<continuous_parameter>& continuous, const simple_values& simple,
                                                    const parametrised_experiment& experiment, std::size_t& evaluations);

/// Half a unit of the last printed digit of `value` printed with `digits` significant digits.
double half_unit_of_last_digit(double value, int digits);

/// Scores a computed table against the printed one.
std::vector<entry_score> score_entries(const std::vector<printed_entry>& printed, const std::vector<computed_entry>& computed);

/// Enumerates every combination of the discrete conventions; for each, finds the global fit of the
/// continuous parameters:
///   1. each entry's power in each scale parameter is measured (two runs per parameter, checked to be
///      an integer; an entry at round-off or not homogeneous is left out of the fit, not the verdict);
///   2. the other parameters are scanned on a dense grid (scan_points in all), and at each point the
///      scale parameters that minimise the sum of squared log ratios follow in closed form (least
///      squares, within their bounds);
///   3. the four best local minima of that scan are refined (a finer scan, then golden sections), then polished by NLopt's COBYLA on the
///      largest residual in half-units, the quantity the verdict judges.
/// Every candidate is judged by a full run of the experiment, never by the fit. Candidates sorted by
/// entries reproduced, then by worst residual.
/// First every simple hypothesis (simple_hypotheses), then the fit above.
convention_search_result search_conventions(const std::vector<printed_entry>& printed, const std::vector<discrete_convention>& discrete,
                                            const std::vector<continuous_parameter>& continuous, const parametrised_experiment& experiment,
                                            const simple_values& simple = {}, std::size_t scan_points = 128);

/// "momentum: p/(m omega), m = 2.05": a candidate in words (a simple value by its name; a fitted one
/// with the digits that reproduce what the candidate reproduces: see shortest_reproducing).
std::string describe(const convention_candidate& c);

}  // namespace simpson::verify

#pragma once
// The scene sections beside the claims: the paper's experiment (table1), error against run time
// (work_precision), stiff and extreme cases (stability) and long runs (long_time). Each is
// computed only when its scene asks for it, and returns a section_result: its tables and plots as
// data (result_model.hpp), rendered by section_render.hpp. Run times are timing columns, which
// report.json keeps in members named "timing" (left out when reports are compared).

#include <simpson/precision.hpp>
#include <simpson/scheme.hpp>
#include <simpson/verify/claim.hpp>
#include <simpson/verify/result_model.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace simpson::verify {

/// Every scheme of scheme_list, in its order (work_precision's "all").
inline std::vector<scheme_id> all_schemes() {
  std::vector<scheme_id> ids;
  for (const scheme_traits& s : scheme_list) ids.push_back(s.id);
  return ids;
}

struct table1_settings {
  std::vector<long long> meshes{10, 20, 40};  // N, one period each
  long long figure_meshes = 15;               // N of Figure 1
  double m = 1;
};

struct timing_policy {
  unsigned max_runs = 20;    // after one warm-up
  double max_seconds = 2;    // stop repeating once this much time is spent
};

struct work_precision_settings {
  std::vector<scheme_id> schemes = all_schemes();
  std::vector<precision> precisions;
  std::vector<long long> meshes{16, 64, 256, 1024, 4096};  // N per period
  long long periods = 1;
  timing_policy timing;
};

struct stability_settings {
  std::vector<precision> precisions;
  std::vector<double> stiff_omegas{1, 1e2, 1e4, 1e6, 1e8};  // at omega h = stiff_omega_h
  double stiff_omega_h = 1;
  std::vector<double> omega_h{1e-8, 1e-6, 1e-4, 1e-3, 1e-2, 1e-1, 1, 2, 2.8};
  std::vector<double> masses{1e-300, 1e-150, 1, 1e150, 1e300};
  long long steps = 1000;  // steps of each run
};

struct long_time_settings {
  long long steps_double = 10'000'000;
  long long steps_mpfr = 100'000;
  unsigned mpfr_digits = 50;
  double omega_h = 0.1;
  long long windows = 100;
};

/// The sections a scene asks for (each absent section is not computed).
struct experiment_settings {
  std::optional<table1_settings> table1;
  std::optional<work_precision_settings> work_precision;
  std::optional<stability_settings> stability;
  std::optional<long_time_settings> long_time;
  bool any() const { return table1 || work_precision || stability || long_time; }
};

/// Estimated cost of a scene's experiments in double-step equivalents (one step of Φ₃ in double
/// = 1), with a line per section; compared with the budget before anything runs.
struct cost_estimate {
  double units = 0;
  std::vector<std::string> lines;
};
inline constexpr double default_cost_budget = 2.5e10;  // about 2 minutes on the 2-core machine (~5 ns per unit)
cost_estimate estimate_cost(const experiment_settings& e);

/// Seconds one cost unit takes on the 2-core machine the costs were calibrated on.
inline constexpr double seconds_per_cost_unit = 5e-9;
/// "about 15 s", "about 2.1 min", "about 3.5 h": an estimate in calibrated wall time.
std::string seconds_text(double units);

section_result run_table1(const table1_settings& s);
section_result run_work_precision(const work_precision_settings& s);
section_result run_stability(const stability_settings& s);
section_result run_long_time(const long_time_settings& s);

}  // namespace simpson::verify

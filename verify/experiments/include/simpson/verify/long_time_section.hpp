#pragma once
// The long_time section: energy drift over long runs, bounded oscillation against drift, and the
// phase error against the frequency predicted by the exact characteristic roots.

#include <simpson/verify/experiment_section.hpp>

#include <memory>
#include <simpson/verify/progress.hpp>
#include <simpson/verify/result_model.hpp>

#include <string>

namespace simpson::verify {

struct long_time_settings {
  /// Where the section reports each unit of work done (progress.hpp); none: nowhere.
  progress_sink progress;
  long long steps_double = 10'000'000;
  long long steps_mpfr = 100'000;
  unsigned mpfr_digits = 50;
  double omega_h = 0.1;
  long long windows = 100;
};

section_result run_long_time(const long_time_settings& s);

/// The long_time section as a registry entry (experiment_section.hpp).
std::unique_ptr<experiment_section> make_long_time_section();

/// An energy's change against t, classed by its log-log slope at the midpoints between the three laws:
/// bounded (0), a random walk of round-off (½), a linear drift (1); above 1.5 "faster than linear".
std::string energy_drift_class(double slope);

}  // namespace simpson::verify

#pragma once
// The long_time section: energy drift over long runs, bounded oscillation against drift, and the
// phase error against the frequency predicted by the exact characteristic roots.

#include <simpson/verify/result_model.hpp>

namespace simpson::verify {

struct long_time_settings {
  long long steps_double = 10'000'000;
  long long steps_mpfr = 100'000;
  unsigned mpfr_digits = 50;
  double omega_h = 0.1;
  long long windows = 100;
};

section_result run_long_time(const long_time_settings& s);

}  // namespace simpson::verify

#pragma once
// The stability section: the exact stability region of Φ₃, the behaviour at and around each
// endpoint, stiff ω at fixed ωh, extreme ωh in each precision, and extreme masses.

#include <simpson/precision.hpp>
#include <simpson/verify/result_model.hpp>

#include <vector>

namespace simpson::verify {

struct stability_settings {
  std::vector<precision> precisions;
  std::vector<double> stiff_omegas{1, 1e2, 1e4, 1e6, 1e8};  // at omega h = stiff_omega_h
  double stiff_omega_h = 1;
  std::vector<double> omega_h{1e-8, 1e-6, 1e-4, 1e-3, 1e-2, 1e-1, 1, 2, 2.8};
  std::vector<double> masses{1e-300, 1e-150, 1, 1e150, 1e300};
  long long steps = 1000;  // steps of each run
};

section_result run_stability(const stability_settings& s);

}  // namespace simpson::verify

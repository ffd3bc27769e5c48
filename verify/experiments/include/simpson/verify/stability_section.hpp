#pragma once
// The stability section: the exact stability region of Φ₃, the behaviour at and around each
// endpoint, a stiff linear chain, extreme ωh in each precision, and extreme masses.

#include <simpson/verify/experiment_section.hpp>

#include <memory>
#include <simpson/verify/progress.hpp>
#include <simpson/precision.hpp>
#include <simpson/verify/result_model.hpp>
#include <simpson/verify/stability_analysis.hpp>

#include <vector>

namespace simpson::verify {

struct stability_settings {
  /// Where the section reports each unit of work done (progress.hpp); none: nowhere.
  progress_sink progress;
  std::vector<precision> precisions;
  std::vector<double> stiff_ratios{1e3, 1e6};  // ω_max/ω_min of the stiff chain
  int stiff_doublings = 30;                     // the stiff chain runs 2^stiff_doublings steps
  std::vector<double> omega_h{1e-8, 1e-6, 1e-4, 1e-3, 1e-2, 1e-1, 1, 2, 2.8};
  std::vector<double> masses{1e-300, 1e-150, 1, 1e150, 1e300};
  long long steps = 1000;  // steps of each run
  long long endpoint_power = 1000000000;  // the largest n of Φ₃ⁿ at the endpoints (closed form)
};

section_result run_stability(const stability_settings& s);

/// The stability section as a registry entry (experiment_section.hpp).
std::unique_ptr<experiment_section> make_stability_section();

/// Φ₃'s exact stability region (m = ω = 1, x = ω²h²), from the Sturm-sequence analysis of its
/// discriminant, as the ledger's stability claims decide it.
stability_report simpson_exact_region();

}  // namespace simpson::verify

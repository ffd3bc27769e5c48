#pragma once
// The work_precision section: error against run time for the Simpson scheme and its peers, in
// several precisions, each scheme advancing by its general step and by its own 2 × 2 matrix.

#include <simpson/verify/experiment_section.hpp>

#include <memory>
#include <simpson/verify/progress.hpp>
#include <simpson/precision.hpp>
#include <simpson/scheme.hpp>
#include <simpson/verify/result_model.hpp>

#include <string>
#include <vector>

namespace simpson::verify {

/// Every scheme of scheme_list, in its order (work_precision's "all").
inline std::vector<scheme_id> all_schemes() {
  std::vector<scheme_id> ids;
  for (const scheme_traits& s : scheme_list) ids.push_back(s.id);
  return ids;
}

/// How each configuration is timed: one warm-up run, then up to max_runs runs, stopping early once
/// max_seconds are spent. max_runs = 0 times nothing (--no-timing): no run time is measured, and
/// the section has no timing table or plot.
struct timing_policy {
  unsigned max_runs = 20;
  double max_seconds = 2;
};

struct work_precision_settings {
  /// Where the section reports each unit of work done (progress.hpp); none: nowhere.
  progress_sink progress;
  std::vector<scheme_id> schemes = all_schemes();
  std::vector<precision> precisions;
  std::vector<long long> meshes{16, 64, 256, 1024, 4096};  // N per period
  long long periods = 1;
  timing_policy timing;
  bool benchmark = false;  // the timing table also shows steps per second
  // How each scheme advances: "step", its general algorithm (what it runs for any force: Simpson its
  // nonlinear step, Newton on the internal node; the implicit peers their stage equations), and
  // "matrix", its own exact 2 × 2 one-step matrix, one product a step, as Φ₃ runs in the paper.
  std::vector<std::string> forms{"step", "matrix"};
};

section_result run_work_precision(const work_precision_settings& s);

/// The work_precision section as a registry entry (experiment_section.hpp).
std::unique_ptr<experiment_section> make_work_precision_section();

}  // namespace simpson::verify

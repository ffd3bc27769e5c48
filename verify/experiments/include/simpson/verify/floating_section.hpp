#pragma once
// The floating section (issue 29, first part): each stepper's one-step round-off in float32 and
// double, proved by Gappa from its rounded program and checked by coqc, beside the largest error
// seen on random states (verify/floating).

#include <simpson/verify/experiment_section.hpp>

#include <memory>
#include <simpson/verify/progress.hpp>
#include <simpson/verify/result_model.hpp>

#include <string>
#include <vector>

namespace simpson::verify {

struct floating_settings {
  /// Where the section reports each unit of work done (progress.hpp); none: nowhere.
  progress_sink progress;
  std::vector<std::string> steppers{"phi3-matrix", "phi3-shear", "newmark-matrix", "leapfrog-verinum"};
  std::vector<std::string> formats{"float32", "double"};
  long long h_denominator = 10;  // h = 1/h_denominator for Φ₃ and Newmark (m = ω = 1); leapfrog: VeriNum's 1/32
  int samples = 20000;           // random states per row for the errors seen
  bool check_with_coqc = true;   // coqc on every certificate (when installed)
  bool global = true;            // the lifted bounds over n steps (tables global, plot floating_roundoff)
  bool paper_configuration = true;  // with global: Φ₃ also at the paper's m = 1, ω = 2π, h = 1/15
};

section_result run_floating(const floating_settings& s);

/// The floating section as a registry entry (experiment_section.hpp).
std::unique_ptr<experiment_section> make_floating_section();

/// The steppers the section proves (stepper_roundoff.hpp's proved_steppers), for the scene's check.
const std::vector<std::string>& floating_stepper_names();

}  // namespace simpson::verify

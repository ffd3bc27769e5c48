#pragma once
// The scene sections beside the claims: the paper's experiment (table1), error against run time
// (work_precision), stiff and extreme cases (stability; fpu, the FPU chain), long runs (long_time), and beyond the
// paper, any potential and several degrees of freedom (nonlinear), the floating-point programs'
// round-off proved (floating). Each is
// computed only when its scene asks for it, and returns a section_result: its tables and plots as
// data (result_model.hpp), rendered by section_render.hpp. Run times are timing columns, which
// report.json keeps in members named "timing" (left out when reports are compared).

#include <simpson/verify/family_section.hpp>
#include <simpson/verify/floating_section.hpp>
#include <simpson/verify/fpu_section.hpp>
#include <simpson/verify/long_time_section.hpp>
#include <simpson/verify/nonlinear_section.hpp>
#include <simpson/verify/stability_section.hpp>
#include <simpson/verify/table1_section.hpp>
#include <simpson/verify/work_precision_section.hpp>

#include <optional>
#include <string>
#include <vector>

namespace simpson::verify {

/// The sections a scene asks for (each absent section is not computed).
struct experiment_settings {
  std::optional<table1_settings> table1;
  std::optional<work_precision_settings> work_precision;
  std::optional<stability_settings> stability;
  std::optional<long_time_settings> long_time;
  std::optional<nonlinear_settings> nonlinear;
  std::optional<floating_settings> floating;
  std::optional<family_settings> family;
  std::optional<fpu_settings> fpu;
  bool any() const { return table1 || work_precision || stability || long_time || nonlinear || floating || family || fpu; }
};

}  // namespace simpson::verify

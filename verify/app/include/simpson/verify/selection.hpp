#pragma once
// What a command line selects from a scene: its claims and its experiment sections. A CI job asks
// for one claim and gets that claim only, with the run's title and report.json saying so.

#include <simpson/verify/scene.hpp>

#include <optional>
#include <string>
#include <vector>

namespace simpson::verify {

/// The experiment sections by name, in the order a run computes them.
std::vector<std::string> section_names(const std::vector<const experiment_section*>& registry);

struct scene_selection {
  std::optional<std::vector<std::string>> claims;    // --claims: ids (spaces around them ignored)
  std::optional<std::vector<std::string>> sections;  // --sections: names, or {"none"}
};

/// Applies the selection to the scene: --claims alone runs those claims and no section, --sections
/// alone those sections and no claim, both both. A section the scene does not define runs with its
/// defaults. Records what changed in `s.overrides` ("claims", "sections") and in `s.selection` (for
/// the title: "claims phi3-det only; no sections"). Throws std::invalid_argument naming an unknown
/// claim or section.
void apply_selection(scene& s, const scene_selection& selection, const claim_book& book);

/// --precisions (after apply_selection): replaces the precisions of the claims' numeric rechecks and
/// of every section of the run that has a precision list (work_precision, stability). table1 runs
/// in double, as the paper did, and has none. long_time compares double with mpfr:<mpfr_digits> by
/// design: a run that includes it is refused, as is 'rational' for a run with sections (they need
/// cos and sin). Records "precisions" and "precisions_applied_to" in `s.overrides`. Throws
/// std::invalid_argument with a one-line message.
void apply_precisions(scene& s, const std::vector<std::string>& names);

}  // namespace simpson::verify

#pragma once
// Where a run writes its report. A run of a whole scene writes reports/out/<scene>; a run of a
// selection (--claims, --sections) writes a directory named after what it selected, so that it never
// replaces the scene's full report by default. An explicit --out is taken as given, except that a
// selection is refused a directory holding a report with claims or sections it lacks.

#include <simpson/verify/scene.hpp>

#include <filesystem>
#include <optional>
#include <string>

namespace simpson::verify {

/// reports/out/<scene> for the whole scene; reports/out/<scene>-claims-<id>+<id>... or
/// <scene>-sections-<name>+... (both parts when both were selected; a name longer than 80
/// characters ends in the first 12 hex digits of the selection's SHA-256 instead).
std::filesystem::path default_output_directory(const scene& s);

/// The report directory of a run: `given` (the --out value, std::nullopt when not passed) or the
/// default. Throws std::invalid_argument naming --out when it is empty, or when the run is a
/// selection and the directory holds a report with claims or sections the run lacks.
std::filesystem::path output_directory(const scene& s, const std::optional<std::string>& given);

}  // namespace simpson::verify

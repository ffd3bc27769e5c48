#pragma once
// What a report was made with and from: the tool's version and commit, the machine, the libraries
// and programs it used, when and how it was run, and digests of the scene and the paper it read.

#include <simpson/verify/json.hpp>
#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/scene.hpp>

#include <string>

namespace simpson::verify {

/// "simpson-verify 0.1.0 (commit 0123abc…, clean)": what --version prints.
std::string version_line();

/// The UTC time of the run as ISO 8601 ("2026-11-22T06:40:00Z") and where it came from:
/// SOURCE_DATE_EPOCH when it is set to a non-negative integer (the reproducible-builds convention,
/// so that two runs can be compared byte for byte), else the clock (saying so when the variable
/// was set but not usable).
struct run_timestamp {
  std::string utc;
  std::string source;
};
run_timestamp run_timestamp_utc();

/// The SHA-256 of the scene as resolved: the canonical JSON (sorted keys, no spaces) of
/// {"scene": its JSON as read, "overrides": what the command line changed}.
std::string resolved_scene_sha256(const scene& s);

/// report.json's "environment": tool version, git commit and dirty flag, OS, kernel, CPU, compiler,
/// flags, library versions (Boost, MPFR, GMP, Eigen, GiNaC, cmark-gfm), gnuplot's version, the UTC
/// timestamp, the command line, and the SHA-256 of the resolved scene and of the paper's source.
json build_environment(const scene& s, const paper_reading& paper);

}  // namespace simpson::verify

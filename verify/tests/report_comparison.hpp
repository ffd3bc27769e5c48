#pragma once
// What two reports of the same scene and seed must share: everything but run times, the timing
// policy and the build environment. Used by the determinism and the reference-report tests.

#include <simpson/verify/report.hpp>

#include <regex>
#include <string>

namespace simpson::verify::test {

/// The report without its "environment" and without every member named "timing", at any depth.
inline json without_volatile(json j) {
  if (j.is_object()) {
    j.erase("timing");
    j.erase("environment");
    for (auto& item : j.items()) item.value() = without_volatile(item.value());
  } else if (j.is_array()) {
    for (auto& item : j) item = without_volatile(item);
  }
  return j;
}

/// report.md with run times ("1.23e-04 s") and run counts ("20 runs") masked.
inline std::string without_times(const std::string& markdown) {
  static const std::regex seconds(R"([0-9][0-9.]*e[-+][0-9]+ s\b)"), runs(R"(\b[0-9]+ runs\b)");
  return std::regex_replace(std::regex_replace(markdown, seconds, "<t> s"), runs, "<n> runs");
}

}  // namespace simpson::verify::test

#pragma once
// What two reports of the same scene and seed must share: everything but the environment (build,
// machine, timestamp, command line). Run times are not in report.json (timing.json holds them).
// Used by the determinism and the reference-report tests.

#include <simpson/verify/report.hpp>

#include <string>

namespace simpson::verify::test {

/// The report without its "environment", at any depth.
inline json without_volatile(json j) {
  if (j.is_object()) {
    j.erase("environment");
    for (auto& item : j.items()) item.value() = without_volatile(item.value());
  } else if (j.is_array()) {
    for (auto& item : j) item = without_volatile(item);
  }
  return j;
}

}  // namespace simpson::verify::test

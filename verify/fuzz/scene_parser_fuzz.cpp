// libFuzzer target: the scene parser must turn any input into a scene or a std::invalid_argument,
// never crash, hang, leak or throw anything else.

#include <simpson/verify/experiments.hpp>
#include <simpson/verify/scene.hpp>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace simpson::verify;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const simpson::verify::scene s = simpson::verify::parse_scene(text, "fuzz", simpson::verify::paper_book());
    // Validation let a hole through: a scene must ask for something, and every experiment parameter is in range.
    if (s.name.empty() || (s.claims.empty() && !s.experiments.any()) || s.precisions.empty()) __builtin_trap();
    if (s.experiments.find<table1_settings>() && (s.experiments.find<table1_settings>()->meshes.empty() || !(s.experiments.find<table1_settings>()->m > 0))) __builtin_trap();
    if (s.experiments.find<work_precision_settings>() && s.experiments.find<work_precision_settings>()->precisions.empty()) __builtin_trap();
    if (s.experiments.find<stability_settings>()) {
      for (const double x : s.experiments.find<stability_settings>()->omega_h) {
        if (!(x > 0)) __builtin_trap();
      }
    }
  } catch (const std::invalid_argument&) {
  }
  return 0;
}

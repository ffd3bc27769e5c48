// libFuzzer target: the scene parser must turn any input into a scene or a std::invalid_argument,
// never crash, hang, leak or throw anything else.

#include <simpson/verify/scene.hpp>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const simpson::verify::scene s = simpson::verify::parse_scene(text, "fuzz");
    if (s.name.empty() || s.claims.empty() || s.precisions.empty()) __builtin_trap();  // validation let a hole through
  } catch (const std::invalid_argument&) {
  }
  return 0;
}

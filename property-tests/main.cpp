// The property tests' main: a pinned seed and case count unless told otherwise.
//   (default)                      RC_PARAMS="seed=20230830 max_success=200"
//   SIMPSON_PROPERTY_RANDOM=1      a random seed (printed on failure) and ten times the cases
//   RC_PARAMS=... set by the user  used as given (e.g. the reproduce string of a failure)

#include <gtest/gtest.h>

#include <cstdlib>
#include <random>
#include <string>

int main(int argc, char** argv) {
  constexpr int pinned_cases = 200;
  if (std::getenv("RC_PARAMS") == nullptr) {
    std::string params;
    if (std::getenv("SIMPSON_PROPERTY_RANDOM") != nullptr) {
      params = "seed=" + std::to_string(std::random_device{}()) + " max_success=" + std::to_string(10 * pinned_cases);
    } else {
      params = "seed=20230830 max_success=" + std::to_string(pinned_cases);
    }
    setenv("RC_PARAMS", params.c_str(), 1);
  }
  std::printf("RC_PARAMS=\"%s\"\n", std::getenv("RC_PARAMS"));
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}

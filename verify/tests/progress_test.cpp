// Progress on stderr, and the stop it gives (verify/base/progress.hpp).

#include <simpson/verify/interruption.hpp>
#include <simpson/verify/progress.hpp>

#include <gtest/gtest.h>

#include <csignal>
#include <string>

namespace simpson::verify {
namespace {

TEST(Progress, AStepReportsToTheSinkAndStopsAnInterruptedRun) {
  std::string seen;
  const progress_sink previous = set_progress_sink([&](const std::string& section, const std::string& what, double) {
    seen += section + ": " + what + "\n";
  });
  progress_step("floating", "phi3-matrix double");
  EXPECT_EQ(seen, "floating: phi3-matrix double\n");
  // A run asked to stop stops at its next step, and reports nothing more.
  interruption_signal().store(SIGINT);
  EXPECT_THROW(progress_step("family", "s = 6, Gauss 7"), interrupted);
  interruption_signal().store(0);
  EXPECT_EQ(seen, "floating: phi3-matrix double\n");
  set_progress_sink(previous);
}

}  // namespace
}  // namespace simpson::verify

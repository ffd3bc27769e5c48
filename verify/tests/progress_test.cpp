// Progress on stderr, and the stop it gives (verify/base/progress.hpp).

#include <simpson/verify/interruption.hpp>
#include <simpson/verify/progress.hpp>
#include <simpson/verify/run.hpp>
#include <simpson/verify/scene.hpp>

#include <gtest/gtest.h>

#include <csignal>
#include <string>

namespace simpson::verify {
namespace {

TEST(Progress, AStepReportsToItsSinkAndStopsAnInterruptedRun) {
  std::string seen;
  const progress_sink sink = [&](const std::string& section, const std::string& what, double) { seen += section + ": " + what + "\n"; };
  progress_step(sink, "floating", "phi3-matrix double");
  EXPECT_EQ(seen, "floating: phi3-matrix double\n");
  progress_step(progress_sink{}, "floating", "no sink: reported to no one");
  // A run asked to stop stops at its next step, and reports nothing more.
  interruption_signal().store(SIGINT);
  EXPECT_THROW(progress_step(sink, "family", "s = 6, Gauss 7"), interrupted);
  interruption_signal().store(0);
  EXPECT_EQ(seen, "floating: phi3-matrix double\n");
}

TEST(Progress, ARunGivesEachSectionItsSinkAndTwoRunsDoNotShareOne) {
  // The sink is the run's, passed to its sections: a run given none reports nothing, whatever
  // another run in the process was given.
  const scene s = parse_scene(R"({"name": "progress", "stability": {"precisions": ["double"], "stiff_ratios": [4], "stiff_doublings": 10,
                                                        "omega_h": [1], "masses": [1], "steps": 10}})", "t", paper_book());
  std::string seen;
  run(s, {}, {}, [&](const std::string& section, const std::string&, double) { seen += section + "\n"; });
  EXPECT_NE(seen.find("stability\n"), std::string::npos) << seen;
  const std::string first = seen;
  run(s);
  EXPECT_EQ(seen, first);
}

}  // namespace
}  // namespace simpson::verify

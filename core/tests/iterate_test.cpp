#include <simpson/iterate.hpp>

#include <simpson/simpson_map.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <string>

namespace simpson {
namespace {

using R = rational;

const one_step_matrix<R> sample_map() { return simpson_map(oscillator_parameters<R>(R(3, 2), R(7, 3), R(1, 5))); }

TEST(Iterate, TrajectoryHoldsEveryStateInOrder) {
  const one_step_matrix<R> phi = sample_map();
  const phase_point<R> y0{R(-3, 2), R(5, 7)};
  const std::vector<phase_point<R>> states = trajectory(phi, y0, 6);
  ASSERT_EQ(states.size(), 7u);
  EXPECT_EQ(states.front().p, y0.p);
  EXPECT_EQ(states.front().q, y0.q);
  for (std::size_t j = 1; j < states.size(); ++j) {
    const phase_point<R> expected = (phi * states[j - 1]);
    EXPECT_EQ(states[j].p, expected.p);
    EXPECT_EQ(states[j].q, expected.q);
  }
}

TEST(Iterate, StreamingVisitsEveryIndexAndEndsWhereTheMatrixPowerDoes) {
  const one_step_matrix<R> phi = sample_map();
  const phase_point<R> y0{R(-3, 2), R(5, 7)};
  std::size_t visits = 0;
  const phase_point<R> last = iterate(phi, y0, 8, [&](std::size_t j, const phase_point<R>&) {
    EXPECT_EQ(j, visits);
    ++visits;
  });
  EXPECT_EQ(visits, 9u);
  const one_step_matrix<R> phi2 = phi * phi, phi4 = phi2 * phi2, phi8 = phi4 * phi4;
  const phase_point<R> by_power = phi8 * y0;
  EXPECT_EQ(last.p, by_power.p);
  EXPECT_EQ(last.q, by_power.q);
}

TEST(Iterate, RejectsZeroSteps) {
  try {
    trajectory(sample_map(), phase_point<R>{R(1), R(0)}, 0);
    ADD_FAILURE() << "accepted N = 0";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("N must be at least 1, got 0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace simpson

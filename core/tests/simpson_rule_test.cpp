#include <simpson/simpson_rule.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

namespace simpson {
namespace {

using R = rational;

TEST(SimpsonRule, ExactForEveryCubic) {
  // ∫_0^1 (c0 + c1 s + c2 s² + c3 s³) ds = c0 + c1/2 + c2/3 + c3/4, for several cubics.
  const R coefficients[][4] = {{R(1), R(0), R(0), R(0)}, {R(0), R(1), R(0), R(0)}, {R(0), R(0), R(1), R(0)},
                               {R(0), R(0), R(0), R(1)}, {R(-3, 2), R(7), R(-5, 9), R(11, 4)}};
  for (const auto& c : coefficients) {
    const auto cubic = [&](const R& s) -> R { return c[0] + c[1] * s + c[2] * s * s + c[3] * s * s * s; };
    EXPECT_EQ(simpson_rule<R>(cubic), c[0] + c[1] / 2 + c[2] / 3 + c[3] / 4);
  }
}

TEST(SimpsonRule, NotExactForAQuartic) {
  // ∫ s⁴ = 1/5, Simpson gives (0 + 4/16 + 1)/6 = 5/24: error 1/120 = f⁽⁴⁾/2880 with f⁽⁴⁾ = 24.
  const auto quartic = [](const R& s) -> R { return s * s * s * s; };
  EXPECT_EQ(simpson_rule<R>(quartic), R(5, 24));
  EXPECT_EQ(simpson_rule<R>(quartic) - R(1, 5), R(1, 120));
}

}  // namespace
}  // namespace simpson

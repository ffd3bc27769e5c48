#include <simpson/one_step_power.hpp>

#include <simpson/simpson_map.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace simpson {
namespace {

/// Φⁿ y by n products, against the closed form, relative to the larger of the two.
double power_gap(const one_step_matrix<long double>& phi, long long n) {
  const phase_point<long double> y{0.6L, 0.8L};
  phase_point<long double> iterated = y;
  for (long long j = 0; j < n; ++j) iterated = phi * iterated;
  const scaled_phase_point<long double> closed = power_apply(phi, y, n);
  const long double scale = std::exp(closed.log_scale);
  const long double p = scale * closed.direction.p, q = scale * closed.direction.q;
  const long double size = std::max(std::abs(iterated.p) + std::abs(iterated.q), std::abs(p) + std::abs(q));
  return static_cast<double>((std::abs(p - iterated.p) + std::abs(q - iterated.q)) / size);
}

TEST(OneStepPower, ClosedFormIsTheIteratedProductInEveryRegime) {
  // Φ₃ (m = ω = 1) inside the first band, in the gap (8, 12) where it grows, in the second band,
  // and beyond 24; then the two parabolic cases τ = ±1 with a Jordan block.
  for (const long double theta : {0.5L, 3.1L, 4.0L, 5.5L}) {
    const one_step_matrix<long double> phi = simpson_map(oscillator_parameters<long double>{1.0L, 1.0L, theta});
    for (const long long n : {0LL, 1LL, 2LL, 3LL, 17LL, 60LL}) EXPECT_LT(power_gap(phi, n), 1e-14) << "theta " << static_cast<double>(theta) << ", n " << n;
  }
  for (const one_step_matrix<long double>& jordan : {one_step_matrix<long double>{1, 0.3L, 0, 1}, one_step_matrix<long double>{-1, 0, 0.7L, -1}}) {
    for (const long long n : {1LL, 2LL, 5LL, 40LL}) EXPECT_LT(power_gap(jordan, n), 1e-16) << "n " << n;
  }
}

TEST(OneStepPower, GrowthIsReturnedAsALogarithmBeyondTheRange) {
  // Outside the band: e^{nψ} with ψ = acosh|τ| for n = 10⁹, far beyond long double's range.
  const one_step_matrix<long double> phi = simpson_map(oscillator_parameters<long double>{1.0L, 1.0L, 3.1L});
  const long double tau = phi.alpha;
  const scaled_phase_point<long double> far = power_apply(phi, phase_point<long double>{0.6L, 0.8L}, 1000000000LL);
  EXPECT_NEAR(static_cast<double>(far.log_scale / 1e9L), static_cast<double>(std::acosh(std::abs(tau))), 1e-9);
  EXPECT_TRUE(std::isfinite(static_cast<double>(far.direction.p)));
  EXPECT_GT(std::abs(far.direction.p) + std::abs(far.direction.q), 0.1L);
}

TEST(OneStepPower, RejectsANegativePower) {
  EXPECT_THROW(power_apply(one_step_matrix<double>{1, 0, 0, 1}, phase_point<double>{1, 0}, -1), std::invalid_argument);
}

}  // namespace
}  // namespace simpson

// The same trajectory in double and in mpfr:100: their difference is double round-off.

#include "property_support.hpp"

#include <simpson/energy.hpp>
#include <simpson/iterate.hpp>
#include <simpson/simpson_map.hpp>

namespace simpson::props {
namespace {

RC_GTEST_PROP(TrajectoryProps, DoubleStaysWithinItsRoundOffOfMpfr100, ()) {
  // Measured in the norm that Φ_3 preserves, |y|² = (p/(mω))² + k q² with k the q² weight of H_d:
  // each double step adds an error of at most 64 eps (1 + 1/|1 − x/8|) |y| (γ and k contain
  // 1 − x/8) and the exact map does not amplify errors in that norm, so after n steps the two
  // trajectories differ by at most 64 n eps (1 + 1/|1 − x/8|) |y_0|.
  const oscillator_case c = *gen::oscillator_cases();
  classify(c);
  constexpr std::size_t n = 100;
  const phase_point<double> in_double =
      iterate(simpson_map(parameters<double>(c)), phase_point<double>{c.p, c.q}, n, [](std::size_t, const phase_point<double>&) {});
  const scoped_mpfr_digits digits(100);
  const oscillator_parameters<mpfr> par = parameters<mpfr>(c);
  const phase_point<mpfr> y0{mpfr(c.p), mpfr(c.q)};
  const phase_point<mpfr> in_mpfr = iterate(simpson_map(par), y0, n, [](std::size_t, const phase_point<mpfr>&) {});
  const mpfr m_omega = par.m() * par.omega(), x = par.omega2_h2();
  const mpfr weight = (1 - x / 12) * (1 - x / 24) / (1 - x / 8);
  const auto norm = [&](const mpfr& p, const mpfr& q) -> mpfr {
    using std::sqrt;
    return sqrt(mpfr(p / m_omega * p / m_omega + weight * q * q));
  };
  const mpfr difference = norm(mpfr(mpfr(in_double.p) - in_mpfr.p), mpfr(mpfr(in_double.q) - in_mpfr.q));
  const mpfr bound = 64 * n * mpfr(std::numeric_limits<double>::epsilon()) * (1 + boundary_amplification(par)) * norm(y0.p, y0.q);
  RC_ASSERT(within("|y_n(double) - y_n(mpfr:100)|", difference, mpfr(0), bound));
}

}  // namespace
}  // namespace simpson::props

// The nonlinear_inseparable section's check of the Lagrange top's exact motion (enclosed with Arb,
// lagrange_top_exact.hpp) against an independent route: the Hamiltonian equations integrated in
// MPFR (reference_flow.hpp), compared at T with the reference's own agreement as the allowance.

#include "inseparable_parts.hpp"

#include <simpson/verify/progress.hpp>

#include <simpson/interval.hpp>
#include <simpson/lagrange_top.hpp>
#include <simpson/lagrange_top_exact.hpp>
#include <simpson/legendre_hamiltonian.hpp>
#include <simpson/reference_flow.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace simpson::verify::detail {

/// The exact motion's enclosure against an independent route: the Legendre Hamiltonian's equations
/// integrated in MPFR (rkf78, step halving), compared at T.
void add_top_reference_check(const inseparable_settings& s, const lagrange_top_exact& exact, section_result& out) {
  const unsigned ref_digits = static_cast<unsigned>(std::ceil(s.reference_digits)) + 10;
  const scoped_mpfr_digits mdigits(ref_digits);
  const lagrange_top<mpfr> Lm(mpfr(s.top.I1), mpfr(s.top.I3), mpfr(s.top.Mgl));
  dense_vector<mpfr> q(3), v(3);
  q << mpfr(s.top.theta0), mpfr(0), mpfr(0);
  v << mpfr(s.top.theta_dot0), mpfr(s.top.phi_dot0), mpfr(s.top.psi_dot0);
  const ndof_state<mpfr> ym{lagrangian_gradient_at(Lm, q, v).dv, q};
  const reference_state ref = lagrangian_reference(Lm, ym, mpfr(s.top_end_time), s.reference_digits, 32, 6);
  progress_step(s.progress, "nonlinear_inseparable", "top: the MPFR reference");
  const top_point_enclosed at = exact.at(interval(s.top_end_time));
  interval theta = at.state.theta;
  if (s.perturb_exact != 0) theta += interval(s.perturb_exact);
  const std::array<interval, 6> ex{theta, at.state.phi, at.state.psi, at.momenta.p_theta, at.momenta.p_phi, at.momenta.p_psi};
  const std::array<mpfr, 6> rf{ref.state.q(0), ref.state.q(1), ref.state.q(2), ref.state.p(0), ref.state.p(1), ref.state.p(2)};
  const std::array<const char*, 6> names{"θ", "φ", "ψ", "p_θ", "p_φ", "p_ψ"};
  bool agree = true;
  std::vector<std::string> gaps;
  // The reference's own error: its two finest runs agree to `agreed_digits` relative to max(1, |state|);
  // allowed: 10 times that, relative to max(1, |value|).
  const double allowed_relative = 10 * std::pow(10.0, -ref.agreed_digits);
  double worst = 0;
  for (std::size_t k = 0; k < 6; ++k) {
    const interval gap = abs(interval(ex[k] - interval(rf[k])));
    const double g = static_cast<double>(upper(gap)), scale = std::max(1.0, std::abs(static_cast<double>(rf[k])));
    worst = std::max(worst, g / scale);
    agree = agree && g <= allowed_relative * std::max(1.0, std::abs(static_cast<double>(rf[k])));
    gaps.push_back(fmt::format("{} {:.2g}", names[k], g));
  }
  out.text(fmt::format("The enclosure against an independent route: the top's Hamiltonian equations integrated in MPFR ({} digits) by "
                       "Fehlberg's 7(8) at fixed steps, halved until two runs agree to {:.1f} digits ({} steps). At T = {} the largest "
                       "distances from the enclosure are {}.",
                       ref_digits, ref.agreed_digits, ref.steps, s.top_end_time, fmt::join(gaps, ", ")));
  out.expect({"top-exact-agrees-with-reference",
              "The Lagrange top's exact motion, enclosed with Arb, agrees at T with an independent MPFR integration of its Hamiltonian "
              "equations.",
              fmt::format("every angle and momentum within 10 times the reference's own agreement ({:.1f} digits), relative to max(1, |x|)",
                          ref.agreed_digits),
              fmt::format("largest relative distance {:.2g}", worst), agree});
}

}  // namespace simpson::verify::detail

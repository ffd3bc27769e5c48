// Properties of the energies (HH-exact), (hamiltonien-discret) and the Newmark map.

#include "property_support.hpp"

#include <simpson/energy.hpp>
#include <simpson/iterate.hpp>
#include <simpson/newmark_map.hpp>
#include <simpson/simpson_map.hpp>

namespace simpson::props {
namespace {

template <class Policy>
class EnergyProps : public property_fixture<Policy> {};
TYPED_TEST_SUITE(EnergyProps, property_precisions, precision_names);

/// The condition factor of H_d's round-off: 1 + 1/|1 − x/8|. The weight of q² in H_d and the entry γ
/// of Φ_3 both contain 1 − x/8, whose relative error grows like eps/(1 − x/8) near ωh = 2√2.
template <class Real>
Real hd_condition(const oscillator_parameters<Real>& par) {
  return 1 + boundary_amplification(par);
}

SIMPSON_PROPERTY(EnergyProps, DiscreteEnergyIsConservedByOneStep) {
  using Real = typename Policy::real;
  const oscillator_parameters<Real> par = parameters<Real>(c);
  const phase_point<Real> y{Real(c.p), Real(c.q)};
  const Real H = discrete_energy(par, y);
  RC_ASSERT(within("H_d(Phi3 y)", discrete_energy(par, simpson_map(par) * y), H, Real(64 * eps<Real>() * hd_condition(par) * H)));
}

SIMPSON_PROPERTY(EnergyProps, DiscreteEnergyDriftIsBoundedLinearlyInTheSteps) {
  // Over n steps the rounding of each step adds at most 64 eps (1 + 1/|1 − x/8|) H_d, and the exact
  // map preserves H_d, so the drift is at most n times that: a bound linear in n. (Typical drift,
  // with errors of random sign, grows like sqrt(n); the long-time report measures it.)
  using Real = typename Policy::real;
  const oscillator_parameters<Real> par = parameters<Real>(c);
  const phase_point<Real> y0{Real(c.p), Real(c.q)};
  const Real H = discrete_energy(par, y0);
  constexpr std::size_t n = 200;
  const phase_point<Real> yn = iterate(simpson_map(par), y0, n, [](std::size_t, const phase_point<Real>&) {});
  RC_ASSERT(within("H_d after 200 steps", discrete_energy(par, yn), H, Real(64 * n * eps<Real>() * hd_condition(par) * H)));
}

SIMPSON_PROPERTY(EnergyProps, DiscreteEnergyIsPositiveDefinite) {
  using Real = typename Policy::real;
  const oscillator_parameters<Real> par = parameters<Real>(c);
  const Real x = par.omega2_h2();
  // On 0 < x < 8 every factor of the q² weight (1 − x/12)(1 − x/24)/(1 − x/8) is positive.
  RC_ASSERT((1 - x / 12) * (1 - x / 24) / (1 - x / 8) > 0);
  RC_ASSERT(discrete_energy(par, phase_point<Real>{Real(c.p), Real(c.q)}) > 0);
  RC_ASSERT(discrete_energy(par, phase_point<Real>{Real(0), Real(c.q)}) > 0);
  RC_ASSERT(discrete_energy(par, phase_point<Real>{Real(c.p), Real(0)}) > 0);
}

SIMPSON_PROPERTY(EnergyProps, NewmarkHasUnitDeterminantAndConservesH) {
  using Real = typename Policy::real;
  const oscillator_parameters<Real> par = parameters<Real>(c);
  const one_step_matrix<Real> phi = newmark_map(par);
  using std::abs;
  // Entries carry at most 8 roundings each; H is a sum of squares preserved by a rotation in
  // (p/(mω), q), so 32 eps H bounds its round-off.
  const Real condition = abs(Real(phi.alpha * phi.delta)) + abs(Real(phi.beta * phi.gamma));
  RC_ASSERT(within("det Phi", determinant(phi), Real(1), Real(16 * eps<Real>() * condition)));
  const phase_point<Real> y{Real(c.p), Real(c.q)};
  const Real H = energy(par, y);
  RC_ASSERT(within("H(Phi y)", energy(par, phi * y), H, Real(32 * eps<Real>() * H)));
}

}  // namespace
}  // namespace simpson::props

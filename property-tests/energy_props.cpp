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

SIMPSON_PROPERTY(EnergyProps, DiscreteEnergyIsConservedByOneStep) {
  using Real = typename Policy::real;
  RC_ASSERT(holds("H_d(Phi3 y) - H_d(y)", discrete_energy_step_check(parameters<Real>(c), phase_point<Real>{Real(c.p), Real(c.q)})));
}

SIMPSON_PROPERTY(EnergyProps, DiscreteEnergyDriftIsBoundedLinearlyInTheSteps) {
  // Over n steps the rounding of each step adds at most the one-step bound of
  // discrete_energy_step_check, and the exact map preserves H_d, so the drift is at most n times
  // that: a bound linear in n. (Typical drift, with errors of random sign, grows like sqrt(n).)
  using Real = typename Policy::real;
  const oscillator_parameters<Real> par = parameters<Real>(c);
  const phase_point<Real> y0{Real(c.p), Real(c.q)};
  const Real H = discrete_energy(par, y0);
  constexpr std::size_t n = 200;
  const phase_point<Real> yn = iterate(simpson_map(par), y0, n, [](std::size_t, const phase_point<Real>&) {});
  const Real one_step = discrete_energy_step_check(par, y0).bound;
  RC_ASSERT(within("H_d after 200 steps", discrete_energy(par, yn), H, Real(n * one_step)));
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
  RC_ASSERT(holds("det Phi - 1", newmark_map_determinant_check(par)));
  RC_ASSERT(holds("H(Phi y) - H(y)", newmark_energy_step_check(par, phase_point<Real>{Real(c.p), Real(c.q)})));
}

}  // namespace
}  // namespace simpson::props

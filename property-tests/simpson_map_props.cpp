// Properties of Φ_3 (Phi3): determinant, the elimination route, time reversibility, dependence on
// ωh alone (its eigenvalues: simpson_map_spectrum_props.cpp).

#include "property_support.hpp"

#include <simpson/simpson_elimination.hpp>
#include <simpson/simpson_map.hpp>

namespace simpson::props {
namespace {

template <class Policy>
class SimpsonMapProps : public property_fixture<Policy> {};
TYPED_TEST_SUITE(SimpsonMapProps, property_precisions, precision_names);

SIMPSON_PROPERTY(SimpsonMapProps, DeterminantIsOne) {
  using Real = typename Policy::real;
  RC_ASSERT(holds("det Phi3 - 1", simpson_map_determinant_check(parameters<Real>(c))));
}

SIMPSON_PROPERTY(SimpsonMapProps, EqualsTheMapObtainedByElimination) {
  using Real = typename Policy::real;
  RC_ASSERT(holds("|dq| + (h/m)|dp|, formula against elimination",
                  elimination_check(parameters<Real>(c), phase_point<Real>{Real(c.p), Real(c.q)})));
}

SIMPSON_PROPERTY(SimpsonMapProps, IsTimeReversible) {
  using Real = typename Policy::real;
  const oscillator_parameters<Real> par = parameters<Real>(c);
  const one_step_matrix<Real> forward = simpson_map(par), product = forward * simpson_map_backward(par);
  using std::abs;
  // Φ_3(h)Φ_3(−h) has diagonal α² − βγ = det Φ_3 and off-diagonal αβ − βα; the diagonal errs by
  // 2·14 eps (α² + |βγ|), the off-diagonal only by the rounding of the two products.
  const Real diagonal = forward.alpha * forward.alpha + abs(Real(forward.beta * forward.gamma));
  RC_ASSERT(within("(Phi3(h) Phi3(-h))_11", product.alpha, Real(1), Real(32 * eps<Real>() * diagonal)));
  RC_ASSERT(within("(Phi3(h) Phi3(-h))_22", product.delta, Real(1), Real(32 * eps<Real>() * diagonal)));
  RC_ASSERT(within("(Phi3(h) Phi3(-h))_12", product.beta, Real(0), Real(4 * eps<Real>() * abs(Real(forward.alpha * forward.beta)))));
  RC_ASSERT(within("(Phi3(h) Phi3(-h))_21", product.gamma, Real(0), Real(4 * eps<Real>() * abs(Real(forward.alpha * forward.gamma)))));
}

SIMPSON_PROPERTY(SimpsonMapProps, DependsOnOmegaHAloneOnceMomentumIsScaled) {
  using Real = typename Policy::real;
  const oscillator_parameters<Real> par = parameters<Real>(c);
  const oscillator_parameters<Real> unit(Real(1), Real(1), par.omega_h());
  const one_step_matrix<Real> full = simpson_map(par), reduced = simpson_map(unit);
  const Real m_omega = par.m() * par.omega();
  using std::abs;
  // x is ω·ω·h·h in one and fl(ωh)² in the other (a few eps apart); α and β/(mω) are smooth in x
  // with |x dF/dx| = O(1 + x) on the band, γ·mω has 1 − x/8 in it, hence the 1/|1 − x/8| factor.
  const Real x = par.omega2_h2();
  RC_ASSERT(within("alpha", full.alpha, reduced.alpha, Real(32 * eps<Real>() * (1 + x))));
  RC_ASSERT(within("beta/(m omega)", Real(full.beta / m_omega), reduced.beta, Real(32 * eps<Real>() * (1 + x) * abs(reduced.beta))));
  RC_ASSERT(within("gamma m omega", Real(full.gamma * m_omega), reduced.gamma,
                   Real(32 * eps<Real>() * (1 + x * boundary_amplification(par)) * abs(reduced.gamma))));
}

}  // namespace
}  // namespace simpson::props

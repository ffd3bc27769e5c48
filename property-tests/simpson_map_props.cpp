// Properties of Φ_3 (Phi3): determinant, the elimination route, time reversibility, dependence on
// ωh alone, and eigenvalues on the unit circle.

#include "property_support.hpp"

#include <simpson/simpson_elimination.hpp>
#include <simpson/simpson_map.hpp>

#include <Eigen/Eigenvalues>
#include <boost/multiprecision/eigen.hpp>

namespace simpson::props {
namespace {

template <class Policy>
class SimpsonMapProps : public property_fixture<Policy> {};
TYPED_TEST_SUITE(SimpsonMapProps, property_precisions, precision_names);

SIMPSON_PROPERTY(SimpsonMapProps, DeterminantIsOne) {
  using Real = typename Policy::real;
  const one_step_matrix<Real> phi = simpson_map(parameters<Real>(c));
  using std::abs;
  // Each entry carries at most 14 roundings (with 1 − x/8 entering γ as an absolute error ~eps),
  // so |αδ − βγ − 1| ≤ 2·14·eps·(|αδ| + |βγ|): the condition of the difference.
  const Real condition = abs(Real(phi.alpha * phi.delta)) + abs(Real(phi.beta * phi.gamma));
  RC_ASSERT(within("det Phi3", determinant(phi), Real(1), Real(32 * eps<Real>() * condition)));
}

SIMPSON_PROPERTY(SimpsonMapProps, EqualsTheMapObtainedByElimination) {
  using Real = typename Policy::real;
  const oscillator_parameters<Real> par = parameters<Real>(c);
  const phase_point<Real> y{Real(c.p), Real(c.q)};
  const phase_point<Real> by_formula = simpson_map(par) * y, by_elimination = simpson_step_by_elimination(par, y);
  using std::abs;
  // The elimination sums terms of size (|q| + h|p|/m)(1 + x/|1 − x/8|) and divides by slopes of
  // size m/h; 256 eps times that scale covers its ~40 roundings with room, the x/|1 − x/8| factor
  // being the growth of the momentum formula's terms near ωh = 2√2.
  const Real x = par.omega2_h2();
  const Real scale = (abs(y.q) + abs(by_formula.q) + par.h() * abs(y.p) / par.m()) * (1 + x * boundary_amplification(par));
  RC_ASSERT(within("q_{j+1}", by_elimination.q, by_formula.q, Real(256 * eps<Real>() * scale)));
  RC_ASSERT(within("p_{j+1} h/m", Real(by_elimination.p * par.h() / par.m()), Real(by_formula.p * par.h() / par.m()),
                   Real(256 * eps<Real>() * scale)));
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

SIMPSON_PROPERTY(SimpsonMapProps, EigenvaluesAreConjugateOnTheUnitCircle) {
  using Real = typename Policy::real;
  const oscillator_parameters<Real> par = parameters<Real>(c);
  const one_step_matrix<Real> phi = simpson_map(par);
  // Eigenvalues of S⁻¹ Φ_3 S, S = diag(mω, 1): a similarity, so the same eigenvalues, with entries
  // of size O(1) instead of (mω)^±1 (Eigen does not balance, and would lose eps·(mω)² otherwise).
  const Real m_omega = par.m() * par.omega();
  Eigen::Matrix<Real, 2, 2> scaled;
  scaled << phi.alpha, Real(phi.beta / m_omega), Real(phi.gamma * m_omega), phi.delta;
  const Eigen::EigenSolver<Eigen::Matrix<Real, 2, 2>> solver(scaled, false);
  RC_ASSERT(solver.info() == Eigen::Success);
  const std::complex<Real> l1 = solver.eigenvalues()(0), l2 = solver.eigenvalues()(1);
  using std::abs;
  // Exactly: λ = α ± i sqrt(1 − α²) with Im λ = sqrt(−Δ)/(2a) > 0 on the band. The computed pair is
  // conjugate; its modulus errs by ~eps ‖Φ‖² / |Im λ| (eigenvalue condition of a non-normal 2×2
  // whose eigenvalues are 2|Im λ| apart), ‖Φ‖ ≤ 4 on the band.
  RC_ASSERT(l1.imag() != 0);
  RC_ASSERT(l1.real() == l2.real() && l1.imag() == -l2.imag());
  const Real modulus2 = l1.real() * l1.real() + l1.imag() * l1.imag();
  RC_ASSERT(within("|lambda|^2", modulus2, Real(1), Real(64 * 16 * eps<Real>() * (1 + 1 / abs(l1.imag())))));
}

}  // namespace
}  // namespace simpson::props

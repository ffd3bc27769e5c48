// Properties of the spectrum of Φ_3 (Phi3): its eigenvalues, computed by Eigen in the scalar itself,
// are conjugate and on the unit circle. A file of its own: Eigen's eigensolver is most of the property
// tests' compile time, and this way it compiles beside the other properties.
//
// In double and long double, the precisions whose round-off a computed spectrum shows: Eigen's solver
// in mpfr was half of this file's compile time in the Release build (70 s of CPU with it), and what
// it tests there is Eigen's generic code, not ours; Φ₃'s eigenvalues on the unit circle exactly are
// proved (det Φ₃ = 1 and a negative discriminant: phi3-det, discriminant-negative, in both kernels
// and Coq). Φ_3 itself in the other precisions (its determinant, the elimination, time reversal, the
// invariant H_d) is in simpson_map_props.cpp and energy_props.cpp.

#include "property_support.hpp"

#include <simpson/simpson_map.hpp>

#include <Eigen/Eigenvalues>

#include <complex>

namespace simpson::props {
namespace {

template <class Policy>
class SimpsonMapSpectrumProps : public property_fixture<Policy> {};
using spectrum_precisions = ::testing::Types<precision_policy<double>, precision_policy<long double>>;
TYPED_TEST_SUITE(SimpsonMapSpectrumProps, spectrum_precisions, precision_names);

SIMPSON_PROPERTY(SimpsonMapSpectrumProps, EigenvaluesAreConjugateOnTheUnitCircle) {
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

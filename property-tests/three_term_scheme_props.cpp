// Properties of the three-term scheme (schema-ordre-3), its discriminant and truncation error,
// the internal node (qm-oscillateur-harmonique) and the reduced Lagrangian (Lagrangien-reduit).

#include "property_support.hpp"

#include <simpson/exact_solution.hpp>
#include <simpson/internal_node.hpp>
#include <simpson/reduced_lagrangian.hpp>
#include <simpson/simpson_lagrangian.hpp>
#include <simpson/three_term_scheme.hpp>

namespace simpson::props {
namespace {

template <class Policy>
class SchemeProps : public property_fixture<Policy> {};
TYPED_TEST_SUITE(SchemeProps, property_precisions, precision_names);

SIMPSON_PROPERTY(SchemeProps, DiscriminantEqualsItsFactorizationAndIsNegative) {
  using Real = typename Policy::real;
  const Real x = parameters<Real>(c).omega2_h2();
  const residual_and_bound<Real> check = discriminant_factorization_check(x);
  RC_ASSERT(holds("b^2 - 4ac - factorised", check));
  // Negative on the band: the factored form's sign is that of x(x−24)(x−12)(x−8), exact in any
  // precision; b² − 4ac may only sit within its round-off of zero, never above it.
  RC_ASSERT(discriminant_factorized(x) < 0);
  RC_ASSERT(discriminant(x) < check.bound);
}

SIMPSON_PROPERTY(SchemeProps, InternalNodeSolvesTheInternalEquation) {
  using Real = typename Policy::real;
  RC_ASSERT(holds("(equation-milieu-intervalle)",
                  harmonic_internal_node_check(parameters<Real>(c), Real(c.q), Real(c.p / (c.m * c.omega)))));
}

SIMPSON_PROPERTY(SchemeProps, ReducedLagrangianIsTheSimpsonLagrangianAtTheInternalNode) {
  using Real = typename Policy::real;
  RC_ASSERT(holds("L_h^r - L_h at q_m", reduced_lagrangian_check(parameters<Real>(c), Real(c.q), Real(c.p / (c.m * c.omega)))));
}

template <class Policy>
class TruncationProps : public property_fixture<Policy> {};
using mpfr_precisions = ::testing::Types<precision_policy<mpfr, 40>, precision_policy<mpfr, 200>>;
TYPED_TEST_SUITE(TruncationProps, mpfr_precisions, precision_names);

SIMPSON_PROPERTY(TruncationProps, CoefficientIsOneOver1440UpToOrderOmega2H2) {
  // (T_h(q_j)/q_j)/(ω⁶h⁴) − 1/1440 = −x/15120 + 11x²/7257600 − ..., an alternating series with
  // decreasing terms for 0 < x ≤ 8 (ledger: truncation-1440), so its modulus is at most C x with
  // C = 1/15120. Round-off: q_{j±1} carry ~8 roundings of the amplitude A = |q| + |p|/(mω); the
  // second difference divides them by h², so the quotient errs by 64 eps A (4/h² + ω²(2 + x)) /
  // (ω⁶h⁴|q_j|). In mpfr:200 that is far below C x for every ωh ≥ 1e-6; in mpfr:40 it dominates
  // for ωh below ~1e-4 (classified below).
  using Real = typename Policy::real;
  const oscillator_parameters<Real> par = parameters<Real>(c);
  const phase_point<Real> y{Real(c.p), Real(c.q)};
  const Real q_prev = exact_solution(par, y, Real(-par.h())).q, q_next = exact_solution(par, y, par.h()).q;
  const Real T = three_term_residual(par, q_prev, y.q, q_next);
  const Real omega2 = par.omega() * par.omega(), x = par.omega2_h2();
  const Real scaled = T / (y.q * omega2 * x * x);
  using std::abs;
  const Real amplitude = abs(y.q) + abs(y.p) / (par.m() * par.omega());
  const Real round_off =
      64 * eps<Real>() * amplitude * (4 / (par.h() * par.h()) + omega2 * (2 + x)) / (omega2 * x * x * abs(y.q));
  const Real truncation = x / 15120;
  RC_CLASSIFY(round_off < truncation / 100, "truncation term resolved above round-off");
  RC_ASSERT(within("T_h/(q_j omega^6 h^4)", scaled, Real(Real(1) / 1440), Real(truncation + round_off)));
}

}  // namespace
}  // namespace simpson::props

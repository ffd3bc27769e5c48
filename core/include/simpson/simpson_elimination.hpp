#pragma once
// Section 6's route to the one-step map, without (Phi3): the derivation the paper describes,
// kept as an independent way to compute y_{j+1} from y_j.

#include <simpson/one_step_map.hpp>
#include <simpson/residual.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/simpson_momentum.hpp>
#include <simpson/three_term_scheme.hpp>

namespace simpson {

/// y_{j+1} from y_j = (p_j, q_j): q_{j−1} from p_j by (moment-ordre-3), q_{j+1} from
/// (schema-ordre-3), then p_{j+1} by (moment-ordre-3). Both relations are affine in their unknown,
/// so each is solved from its values at 0 and at a probe. The probe has the size of the solution,
/// |q_j| + h|p_j|/m: a unit probe would difference two values of size |q_j| m/h to get a slope of
/// size m/h, losing a factor |q_j| of accuracy (symbolic scalars, which have no abs, use 1).
/// Throws std::domain_error at ω²h² = 8.
template <class Real>
phase_point<Real> simpson_step_by_elimination(const oscillator_parameters<Real>& par, const phase_point<Real>& y) {
  Real probe(1);
  if constexpr (detail::is_ordered_number_v<Real>) {
    using std::abs;
    const Real scale = abs(y.q) + par.h() * abs(y.p) / par.m();
    if (scale != 0) probe = scale;
  }
  const Real p0 = simpson_momentum(par, Real(0), y.q);
  const Real q_prev = (y.p - p0) / (simpson_momentum(par, probe, y.q) - p0) * probe;
  const Real r0 = three_term_residual(par, q_prev, y.q, Real(0));
  const Real q_next = -r0 / (three_term_residual(par, q_prev, y.q, probe) - r0) * probe;
  return {simpson_momentum(par, y.q, q_next), q_next};
}

/// |Δq_{j+1}| + (h/m)|Δp_{j+1}| between (Phi3) and the elimination route. The elimination sums
/// terms of size (|q| + h|p|/m)(1 + x/|1 − x/8|) (x = ω²h², the growth of the momentum formula's
/// terms near ωh = 2√2) and divides by slopes of size m/h; 256 eps times that scale covers its
/// ~40 roundings with room.
template <class Real>
residual_and_bound<Real> elimination_check(const oscillator_parameters<Real>& par, const phase_point<Real>& y) {
  using std::abs;
  const phase_point<Real> by_formula = simpson_map(par) * y, by_elimination = simpson_step_by_elimination(par, y);
  const Real x = par.omega2_h2();
  const Real scale = (abs(y.q) + abs(by_formula.q) + par.h() * abs(y.p) / par.m()) * (1 + x / abs(Real(1 - x / 8)));
  return {Real(abs(Real(by_elimination.q - by_formula.q)) + par.h() / par.m() * abs(Real(by_elimination.p - by_formula.p))),
          Real(256 * eps<Real>() * scale)};
}

}  // namespace simpson

#pragma once
// A nonlinear partitioned Runge–Kutta step enclosed: its stage positions Q proved to exist and be
// unique in a stated box by krawczyk_system() on the stage equations R(Q) = 0
// (nonlinear_partitioned_rk.hpp), then the update in interval arithmetic. For Lobatto IIIA–IIIB it
// is the enclosed twin of simpson_enclosed_step (claim nonlinear-lobatto-equivalence).
// Pulls in MPFI (link simpson::interval).

#include <simpson/krawczyk_system.hpp>
#include <simpson/nonlinear_partitioned_rk.hpp>

namespace simpson {

struct enclosed_prk_step {
  krawczyk_system_result stages;
  phase_point<interval> state;
};

/// The step from y (an enclosure: every state in it is covered). The box is centred on Newton's
/// approximation from Q_i = q + c_i h p/m (box_around_newton); unproved, `state` is y unchanged and
/// must not be used.
template <class Potential>
enclosed_prk_step prk_enclosed_step(const butcher_tableau<interval>& for_q, const butcher_tableau<interval>& for_p,
                                    const stage_coupling<interval>& c, const interval& m, const interval& h, const Potential& V,
                                    const phase_point<interval>& y) {
  const std::size_t s = c.nodes.size();
  const auto R = [&](const interval_vector& Q) {
    interval_vector forces(s), r(s);
    for (std::size_t k = 0; k < s; ++k) forces[k] = V.derivative(Q[k]);
    detail::stage_residuals_into(c, m, h, y.q, y.p, Q, forces, r, s);
    return r;
  };
  const auto dR = [&](const interval_vector& Q) {  // δ_ik + (h²/m)(A Â)_ik V''(Q_k)
    interval_matrix J(s, interval_vector(s));
    for (std::size_t i = 0; i < s; ++i) {
      for (std::size_t k = 0; k < s; ++k) {
        J[i][k] = interval(i == k ? 1 : 0) + h * h / m * c.product[i][k] * V.second_derivative(Q[k]);
      }
    }
    return J;
  };
  interval_vector start(s);
  for (std::size_t i = 0; i < s; ++i) start[i] = y.q + c.nodes[i] * h * y.p / m;
  enclosed_prk_step out{krawczyk_system(R, dR, box_around_newton(R, dR, start)), y};
  if (out.stages.proved) {
    interval_vector forces(s);
    for (std::size_t k = 0; k < s; ++k) forces[k] = V.derivative(out.stages.enclosure[k]);
    out.state = detail::update_from(for_q, for_p, m, h, y.q, y.p, forces, s);
  }
  return out;
}

}  // namespace simpson

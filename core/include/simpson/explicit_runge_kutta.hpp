#pragma once
// Explicit Runge–Kutta methods on the oscillator, run as their users write them: stage after stage,
// one force evaluation each, no system to solve (HLW, Geometric Numerical Integration, II.1.1). The
// method is its tableau (runge_kutta_tableaux.hpp), strictly lower triangular; classic RK4 is the
// first user (the work-precision comparison's peer).

#include <simpson/one_step_map.hpp>
#include <simpson/oscillator_parameters.hpp>
#include <simpson/partitioned_runge_kutta.hpp>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <utility>

namespace simpson {

/// Whether `t` is explicit: a_ik = 0 for k >= i.
template <class Real>
bool is_explicit(const butcher_tableau<Real>& t) {
  for (std::size_t i = 0; i < t.stages(); ++i) {
    for (std::size_t k = i; k < t.stages(); ++k) {
      if (!(t.a[i][k] == Real(0))) return false;
    }
  }
  return true;
}

/// An explicit tableau of at most 4 stages, checked once when made (not at every step): what
/// explicit_runge_kutta_step runs. Throws std::invalid_argument for an implicit tableau or more than
/// 4 stages.
template <class Real>
class explicit_tableau {
 public:
  explicit_tableau() = default;  // no stages: a step leaves the state as it is
  explicit explicit_tableau(butcher_tableau<Real> t) : t_(std::move(t)) {
    if (t_.stages() == 0 || t_.stages() > 4) throw std::invalid_argument("simpson::explicit_tableau: 1 to 4 stages");
    if (!is_explicit(t_)) throw std::invalid_argument("simpson::explicit_tableau: an implicit tableau");
  }
  const butcher_tableau<Real>& tableau() const noexcept { return t_; }

 private:
  butcher_tableau<Real> t_;
};

/// One step of the explicit method `e` on q' = p/m, p' = −m ω² q:
///   Y_i = y_j + h Σ_{k<i} a_ik K_k,  K_i = f(Y_i) = (−m ω² Y_i.q, Y_i.p / m),  y_{j+1} = y_j + h Σ_i b_i K_i.
/// The same map as partitioned_runge_kutta_step with the same tableau for q and p (whose system is
/// then triangular), by the stages instead of a solve.
template <class Real>
phase_point<Real> explicit_runge_kutta_step(const oscillator_parameters<Real>& par, const explicit_tableau<Real>& e, const phase_point<Real>& y) {
  const butcher_tableau<Real>& t = e.tableau();
  const std::size_t s = t.stages();
  const Real stiffness = par.m() * par.omega() * par.omega();
  const Real& h = par.h();
  std::array<phase_point<Real>, 4> K{};
  for (std::size_t i = 0; i < s; ++i) {
    phase_point<Real> stage = y;
    for (std::size_t k = 0; k < i; ++k) {
      stage.p += h * t.a[i][k] * K[k].p;
      stage.q += h * t.a[i][k] * K[k].q;
    }
    K[i] = {-stiffness * stage.q, stage.p / par.m()};
  }
  phase_point<Real> next = y;
  for (std::size_t i = 0; i < s; ++i) {
    next.p += h * t.b[i] * K[i].p;
    next.q += h * t.b[i] * K[i].q;
  }
  return next;
}

}  // namespace simpson

#pragma once
// A run of a one-step matrix that watches itself: the largest relative change of an energy, and
// the step at which the state leaves its orbit (grows past 10⁶ times its amplitude), where the run
// stops. Every decision is made in the precision of the run.

#include <simpson/verify/figure.hpp>
#include <simpson/verify/interruption.hpp>

#include <simpson/one_step_map.hpp>
#include <simpson/oscillator_parameters.hpp>

#include <stdexcept>
#include <string>

namespace simpson::verify::detail {

template <class Real>
struct guarded_summary {
  phase_point<Real> end;           // the last state computed
  Real max_relative_drift{0};      // max_j |E(y_j) − E(y_0)| / |E(y_0)|
  long long steps_done = 0;
  figure status = figure::text("ok");  // or unstable (step j), underflow, failed: <why>
  bool ok() const { return !status.is_fault(); }
};

/// Growth past this factor times the amplitude |q| + |p|/(mω) of y_0 is `unstable`.
inline constexpr long growth_limit = 1000000;

/// Runs `steps` steps of `phi` from y0, calling energy(y) after each; stops at the first state
/// whose amplitude passes growth_limit × the initial one. An energy that rounds to zero at y0
/// (a non-zero state) is `underflow`; a formula that throws std::domain_error is `failed: <why>`.
template <class Real, class Energy>
guarded_summary<Real> guarded_iterate(const one_step_matrix<Real>& phi, const oscillator_parameters<Real>& par,
                                      const phase_point<Real>& y0, long long steps, Energy&& energy) {
  using std::abs;
  guarded_summary<Real> out;
  out.end = y0;
  const Real scale = par.m() * par.omega();
  const Real amplitude = abs(y0.q) + abs(y0.p) / scale;
  try {
    const Real E0 = energy(y0);
    if (E0 == 0 && amplitude != 0) {
      out.status = figure::fault("underflow");
      return out;
    }
    if (const figure e0 = figure::of(E0); e0.is_fault()) {  // overflow, non-finite, or a subnormal energy
      out.status = e0;
      return out;
    }
    for (long long j = 1; j <= steps; ++j) {
      if ((j & 0xFFFF) == 0) throw_if_interrupted();
      out.end = phi * out.end;
      out.steps_done = j;
      if (abs(out.end.q) + abs(out.end.p) / scale > growth_limit * amplitude) {
        out.status = unstable_at(j);
        return out;
      }
      const Real drift = abs(Real(energy(out.end) - E0)) / abs(E0);
      if (!(drift == drift)) {
        out.status = figure::fault("non-finite");
        return out;
      }
      if (drift > out.max_relative_drift) out.max_relative_drift = drift;
    }
  } catch (const std::domain_error& e) {
    out.status = figure::fault(std::string("failed: ") + e.what());
  }
  return out;
}

}  // namespace simpson::verify::detail

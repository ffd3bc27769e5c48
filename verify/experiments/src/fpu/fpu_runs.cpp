// The fpu section's runs of the chain: see fpu_runs.hpp.

#include "fpu_runs.hpp"

#include "../nonlinear/counting_potential.hpp"

#include <simpson/verify/interruption.hpp>

#include <simpson/energy.hpp>
#include <simpson/nonlinear_ndof_step.hpp>
#include <simpson/runge_kutta_tableaux.hpp>
#include <simpson/trigonometric_step.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace simpson::verify::detail {
namespace {

/// A method's step on the chain; adds its Newton iterations, and counts its force evaluations.
class stepper_on_chain {
 public:
  stepper_on_chain(fpu_method m, const system_type& s, detail::evaluation_count& count)
      : method_(m), system_(s.mass(), detail::counting_potential<fpu_potential<double>>(s.potential(), count)) {
    const butcher_tableau<double> t = m == fpu_method::implicit_midpoint ? implicit_midpoint_tableau<double>() : gauss_legendre2_tableau<double>();
    tableau_ = t;
    coupling_ = couple(tableau_, tableau_);
  }
  ndof_state<double> step(double h, const ndof_state<double>& y, long long& iterations) {
    switch (method_) {
      case fpu_method::simpson: return counted(simpson_ndof_step(system_, h, y, kept_), iterations);
      case fpu_method::stormer_verlet: return stormer_verlet_ndof_step(system_, h, y, kept_);
      case fpu_method::implicit_midpoint:
      case fpu_method::gauss_legendre_2: return counted(prk_ndof_step(tableau_, tableau_, coupling_, system_, h, y), iterations);
      case fpu_method::trigonometric: return trigonometric_step(system_.potential(), h, y, kept_);
    }
    return y;
  }

 private:
  static ndof_state<double> counted(const ndof_step_result<double>& r, long long& iterations) {
    iterations += r.newton_iterations;
    return r.state;
  }
  fpu_method method_;
  // ∇V, and the trigonometric step's ∇U, each one force evaluation; ∇²V apart.
  separable_system<double, detail::counting_potential<fpu_potential<double>>> system_;
  butcher_tableau<double> tableau_;
  stage_coupling<double> coupling_;
  last_force<double> kept_;  // the force at the step's end (Simpson's impulse, the explicit kicks): the next step's start
};

}  // namespace

chain_run run_chain(fpu_method m, const system_type& s, const fpu_settings& settings, double omega_h, double end_time, int samples) {
  const double h = omega_h / settings.omega;
  const long long steps = std::max(1LL, std::llround(end_time / h));
  const long long every = std::max(1LL, steps / samples);
  detail::evaluation_count count;
  stepper_on_chain method(m, s, count);
  const auto start = std::chrono::steady_clock::now();
  ndof_state<double> y = fpu_start(settings.m, settings.omega);
  const double H0 = s.energy(y), I0 = 1;  // I(0) = I₁(0) = 1 (fpu_start)
  // I_d: each stiff spring's (hamiltonien-discret), the core's discrete_energy, of a unit-mass
  // oscillator of frequency ω in its elongation x₁ = (q_{2i} − q_{2i−1})/√2 and its momentum
  // y₁ = (p_{2i} − p_{2i−1})/√2: the quadratic form Φ₃ conserves for a spring alone.
  const oscillator_parameters<double> spring{1, settings.omega, h};
  const auto discrete_invariant = [&](const ndof_state<double>& z) {
    double sum = 0;
    for (int i = 0; i < settings.m; ++i) {
      const double dq = z.q(2 * i + 1) - z.q(2 * i), dp = z.p(2 * i + 1) - z.p(2 * i);
      sum += discrete_energy(spring, phase_point<double>{dp / std::sqrt(2.0), dq / std::sqrt(2.0)});
    }
    return sum;
  };
  const double Id0 = discrete_invariant(y);
  chain_run out;
  const auto record = [&](long long j) {
    const std::vector<double> I = fpu_oscillatory_energies(y, settings.omega);
    const double total = std::accumulate(I.begin(), I.end(), 0.0), dH = std::abs(s.energy(y) - H0) / H0;
    out.max_discrete_invariant_error = std::max(out.max_discrete_invariant_error, std::abs(discrete_invariant(y) - Id0) / std::abs(Id0));
    out.max_energy_error = std::max(out.max_energy_error, dH);
    out.max_invariant_error = std::max(out.max_invariant_error, std::abs(total - I0) / I0);
    out.t.push_back(static_cast<double>(j) * h);
    out.energy_error.push_back(dH);
    out.I1.push_back(I[0]);
    out.I2.push_back(I[1]);
    out.I3.push_back(I.size() > 2 ? I[2] : 0);  // the first three springs are drawn
    out.I.push_back(total);
  };
  record(0);
  // The drift of I: its mean over every step of the last tenth of the run against the first tenth
  // (every step: I oscillates with the stiff springs' phase, which samples far apart would alias).
  const long long tenth = std::max(1LL, steps / 10);
  double first_sum = 0, last_sum = 0, first_discrete = 0, last_discrete = 0;
  const auto total_now = [&] {
    const std::vector<double> I = fpu_oscillatory_energies(y, settings.omega);
    return std::accumulate(I.begin(), I.end(), 0.0);
  };
  for (long long j = 1; j <= steps; ++j) {
    if (j % 4096 == 0) throw_if_interrupted();
    try {
      y = method.step(h, y, out.newton_iterations);
    } catch (const std::domain_error&) {
      out.status = figure::fault(fmt::format("failed: Newton (step {})", j));
      break;
    }
    if (!(y.q.cwiseAbs().maxCoeff() < 1e3) || !(y.p.cwiseAbs().maxCoeff() < 1e3 * settings.omega)) {
      out.status = unstable_at(j);
      break;
    }
    out.steps = j;
    if (j <= tenth) {
      first_sum += total_now();
      first_discrete += discrete_invariant(y);
    }
    if (j > steps - tenth) {
      last_sum += total_now();
      last_discrete += discrete_invariant(y);
    }
    if (j % every == 0 || j == steps) record(j);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.gradients = count.gradients;
  out.hessians = count.hessians;
  out.start_gradients = m == fpu_method::simpson || m == fpu_method::stormer_verlet || m == fpu_method::trigonometric ? 1 : 0;
  if (out.ok()) {
    out.invariant_drift = (last_sum - first_sum) / static_cast<double>(tenth) / I0;
    out.discrete_invariant_drift = (last_discrete - first_discrete) / static_cast<double>(tenth) / std::abs(Id0);
  }
  return out;
}


}  // namespace simpson::verify::detail

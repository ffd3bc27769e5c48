// The fpu section's runs of the chain: see fpu_runs.hpp.

#include "fpu_runs.hpp"

#include "../nonlinear/counting_potential.hpp"

#include <simpson/verify/integration_driver.hpp>

#include <simpson/energy.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace simpson::verify::detail {
namespace {

using counted_chain = separable_system<double, counting_potential<fpu_potential<double>>>;

/// The chain's stop rule: a state beyond 10³ (the displacements are of order 1, the momenta of order
/// ω) is unstable; a Newton failure names its step.
struct chain_stop : never_stop {
  double omega;
  std::optional<figure> check(long long j, const ndof_state<double>& y) const {
    if (!(y.q.cwiseAbs().maxCoeff() < 1e3) || !(y.p.cwiseAbs().maxCoeff() < 1e3 * omega)) return unstable_at(j);
    return std::nullopt;
  }
  figure failed(long long j, const std::domain_error&) const { return figure::fault(fmt::format("failed: Newton (step {})", j)); }
};

/// I = I₁ + I₂ + …, the stiff springs' oscillatory energies summed.
double oscillatory_total(const ndof_state<double>& y, double omega) {
  const std::vector<double> I = fpu_oscillatory_energies(y, omega);
  return std::accumulate(I.begin(), I.end(), 0.0);
}

/// At each sample: t, I₁, I₂, I₃ (the first three springs are drawn) and I, and max |I − I(0)|/I(0)
/// with I(0) = I₁(0) = 1 (fpu_start).
struct oscillatory_samples : observer {
  double omega, h;
  chain_run* out;
  void sample(long long j, const ndof_state<double>& y) {
    constexpr double I0 = 1;
    const std::vector<double> I = fpu_oscillatory_energies(y, omega);
    const double total = std::accumulate(I.begin(), I.end(), 0.0);
    out->max_invariant_error = std::max(out->max_invariant_error, std::abs(total - I0) / I0);
    out->t.push_back(static_cast<double>(j) * h);
    out->I1.push_back(I[0]);
    out->I2.push_back(I[1]);
    out->I3.push_back(I.size() > 2 ? I[2] : 0);
    out->I.push_back(total);
  }
};

}  // namespace

chain_run run_chain(const integration_method& m, const system_type& s, const fpu_settings& settings, double omega_h, double end_time, int samples) {
  const double h = omega_h / settings.omega;
  const long long steps = std::max(1LL, std::llround(end_time / h));
  const long long every = std::max(1LL, steps / samples);
  detail::evaluation_count count;
  // ∇V, and the trigonometric step's ∇U, each one force evaluation; ∇²V apart.
  const counted_chain counted(s.mass(), counting_potential<fpu_potential<double>>(s.potential(), count));
  ndof_stepper<double, counting_potential<fpu_potential<double>>> method(m, counted);
  const auto start = std::chrono::steady_clock::now();
  ndof_state<double> y = fpu_start(settings.m, settings.omega);
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
  const auto total = [&](const ndof_state<double>& z) { return oscillatory_total(z, settings.omega); };
  chain_run out;
  // H and I_d relative to their start at the samples; the drifts of I and I_d over every step.
  auto energy = relative_change_of<double>([&s](const ndof_state<double>& z) { return s.energy(z); }, observed_at::samples, true);
  auto discrete = relative_change_of<double>(discrete_invariant, observed_at::samples);
  oscillatory_samples exchange{{}, settings.omega, h, &out};
  auto invariant_drift = mean_drift_of(total, steps);
  auto discrete_drift = mean_drift_of(discrete_invariant, steps);
  const run_end end = integrate_n_steps([&](const ndof_state<double>& z) { return method.step(h, z, out.newton_iterations); }, y,
                                        steps, every, chain_stop{{}, settings.omega}, energy, discrete, exchange, invariant_drift,
                                        discrete_drift);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.steps = end.steps;
  out.status = end.status;
  out.energy_error = std::move(energy.at_samples);
  out.max_energy_error = energy.maximum;
  out.max_discrete_invariant_error = discrete.maximum;
  out.gradients = count.gradients;
  out.hessians = count.hessians;
  out.start_gradients = m.keeps_last_force ? 1 : 0;
  if (out.ok()) {
    out.invariant_drift = invariant_drift.drift(1);  // I(0) = 1
    out.discrete_invariant_drift = discrete_drift.drift(std::abs(discrete.initial));
  }
  return out;
}

}  // namespace simpson::verify::detail

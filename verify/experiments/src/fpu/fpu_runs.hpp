#pragma once
// The fpu section's runs of the chain (fpu_section.cpp): a method of the sections' list
// (integration_methods.hpp) run by the driver (integration_driver.hpp) to an end time, its force
// evaluations counted, H and the oscillatory energies sampled.

#include <simpson/verify/fpu_section.hpp>
#include <simpson/verify/integration_methods.hpp>
#include <simpson/verify/result_model.hpp>

#include <simpson/fpu_chain.hpp>
#include <simpson/separable_system.hpp>

#include <array>
#include <vector>

namespace simpson::verify::detail {

using system_type = separable_system<double, fpu_potential<double>>;

/// The methods the section runs on the chain, from the sections' one list (integration_methods.hpp),
/// in the order its tables list them.
inline constexpr std::array<const integration_method*, 5> chain_methods{
    &method_of(method_id::simpson), &method_of(method_id::stormer_verlet), &method_of(method_id::implicit_midpoint),
    &method_of(method_id::gauss_legendre_2), &method_of(method_id::trigonometric)};

/// One run: H and the I_j sampled over time, the largest relative errors, and how it ended.
struct chain_run {
  std::vector<double> t, energy_error, I1, I2, I3, I;
  double max_energy_error = 0, max_invariant_error = 0, invariant_drift = 0;
  double max_discrete_invariant_error = 0, discrete_invariant_drift = 0;  // of I_d, the stiff springs' part of Simpson's H_d
  long long steps = 0, newton_iterations = 0, gradients = 0, hessians = 0;
  double seconds = 0;  // the steps' wall time (the sampling's bookkeeping included)
  long long start_gradients = 0;  // an explicit method's force at the start, evaluated once for the run
  figure status = figure::text("ok");
  bool ok() const { return !status.is_fault(); }
  /// Force evaluations a step, the start's one-off evaluation left out.
  double gradients_per_step() const { return static_cast<double>(gradients - start_gradients) / static_cast<double>(std::max(1LL, steps)); }
};

/// Runs to `end_time` with ωh = omega_h, sampling `samples` times; stops at a state beyond 10³ (the
/// chain's displacements are of order 1: unstable) or a Newton failure.
chain_run run_chain(const integration_method& m, const system_type& s, const fpu_settings& settings, double omega_h, double end_time, int samples);

}  // namespace simpson::verify::detail

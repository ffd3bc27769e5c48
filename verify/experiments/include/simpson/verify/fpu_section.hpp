#pragma once
// The fpu section: a stiff problem as the field poses it, the Fermi–Pasta–Ulam–Tsingou chain of
// Hairer, Lubich and Wanner (fpu_chain.hpp): stiff springs of frequency ω between soft cubic ones,
// the step set by the slow motion. Simpson's scheme for a general potential (implicit, the Lobatto
// IIIA–IIIB pair's step), Störmer–Verlet, the implicit midpoint rule, Gauss–Legendre 2 and a
// trigonometric integrator (Hairer, Lubich and Wanner's method (C), the field's peer at large ωh), at
// several ωh across Φ₃'s bands, over long times: the energy error, the oscillatory energy I (an
// adiabatic invariant) and the exchange between its parts I₁, I₂, I₃; and each at equal cost.

#include <simpson/verify/experiment_section.hpp>

#include <memory>
#include <simpson/verify/progress.hpp>
#include <simpson/verify/published_fact.hpp>
#include <simpson/verify/result_model.hpp>

#include <string>
#include <vector>

namespace simpson::verify {

struct fpu_settings {
  /// Where the section reports each unit of work done (progress.hpp); none: nowhere.
  progress_sink progress;
  int m = 3;           // stiff springs (2m masses)
  double omega = 50;   // their frequency
  std::vector<double> omega_h{0.5, 1.5, 3.0, 4.0};  // the runs followed over time: ωh of the stiff springs
  double end_time = 10000;                          // of those runs: 10⁴ slow periods of order 1
  double scan_from = 0.1, scan_to = 5, scan_step = 0.1;  // the ωh scanned for the largest errors
  double scan_end_time = 100;
  int samples = 1000;  // points of each curve over time
  double exchange_time = 200;         // the exchange of I₁, I₂, I₃ is drawn over t up to this
  double reference_omega_h = 0.1;     // the exchange's reference run (Gauss–Legendre 2)
  std::vector<int> resonances{3, 4, 6};  // the scan adds each method's ωh where its rotation angle θ is 2π/k
  /// The costs compared: Störmer–Verlet's force evaluations per unit time at these ωh (ω/ωh), each
  /// method spending as many on its own step.
  std::vector<double> equal_cost_omega_h{0.5, 1.5};
  bool timed = true;  // the equal-cost runs' seconds in the run-time report (--no-timing: none)
};

section_result run_fpu(const fpu_settings& s);

/// The fpu section as a registry entry (experiment_section.hpp).
std::unique_ptr<experiment_section> make_fpu_section();

/// One method's run on the chain (s.m, s.omega), summarised as the section's runs table shows it.
struct fpu_run_summary {
  double max_energy_error = 0, max_invariant_error = 0, invariant_drift = 0;
  double max_discrete_invariant_error = 0, discrete_invariant_drift = 0;  // I_d, with Φ₃'s weight at x = (ωh)²
  long long steps = 0;
  std::string status;  // "ok", "unstable (step j)" or "failed: ..."
};

/// `method`: simpson, stormer-verlet, implicit-midpoint, gauss-legendre-2 or trigonometric (std::invalid_argument otherwise).
fpu_run_summary run_fpu_chain(const fpu_settings& s, const std::string& method, double omega_h, double end_time);

/// The section's published fact "fpu.second-band-invariant": in its second stable band (the middle of
/// (2√3, 2√6)) Simpson's scheme keeps its own oscillatory energy I_d within 5% over t ≤ 300 at the
/// default settings, but not the flow's adiabatic invariant I, which departs from I(0) by more than
/// I(0); the run in the first band beside it (fpu_facts.cpp).
published_fact fpu_second_band_fact();

}  // namespace simpson::verify

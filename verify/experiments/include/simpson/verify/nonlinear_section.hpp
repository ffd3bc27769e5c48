#pragma once
// The nonlinear section (beyond the paper): the Simpson variational integrator for any potential
// and several degrees of freedom. The pendulum's convergence table in multiprecision; error against
// N, against force evaluations and against run time on the paper's oscillator, the pendulum, the Kepler
// problem, Hénon–Heiles and the FPU chain for Simpson and its peers, every implicit one solved by the same Newton rule; the
// linearized double pendulum of the authors' 2024 work, with its discrete energy.

#include <simpson/verify/experiment_section.hpp>

#include <memory>
#include <simpson/verify/progress.hpp>
#include <simpson/verify/published_fact.hpp>
#include <simpson/verify/result_model.hpp>
#include <simpson/verify/work_precision_section.hpp>  // timing_policy

#include <string>
#include <vector>

namespace simpson::verify {

/// The section's parts, by scene name: the pendulum's convergence table, Brouwer's law, the problems'
/// error against N, force evaluations and run time, the linearized double pendulum.
inline const std::vector<std::string>& nonlinear_part_names() {
  static const std::vector<std::string> names{"pendulum", "brouwer", "problems", "double-pendulum"};
  return names;
}

/// The problems of the error-against-run-time part, by scene name.
inline const std::vector<std::string>& nonlinear_problem_names() {
  static const std::vector<std::string> names{"oscillator", "pendulum", "kepler", "henon-heiles", "fpu"};
  return names;
}

struct nonlinear_settings {
  /// Where the section reports each unit of work done (progress.hpp); none: nowhere.
  progress_sink progress;
  std::vector<std::string> parts = nonlinear_part_names();  // the parts run (the paper scene: "problems" alone)
  // The pendulum V = m ω² (1 − cos q), m = ω = 1, released from rest at q0 (0 < q0 < π).
  double pendulum_q0 = 1;
  double pendulum_T = 10;
  std::vector<long long> pendulum_N{10, 20, 40, 80, 160};
  unsigned mpfr_digits = 50;        // the pendulum table's and the double pendulum's precision
  long long energy_steps = 100'000;  // the runs in double that watch the energy
  // Brouwer's law: the pendulum's energy round-off in the step's three forms, in double.
  double brouwer_h = 0.05;
  long long brouwer_steps = 10'000'000;
  // Error against N and run time, in double.
  std::vector<std::string> problems = nonlinear_problem_names();
  std::vector<long long> N{64, 128, 256, 512, 1024, 2048, 4096};
  double eccentricity = 0.9;      // Kepler: GeometricProblems.jl's set-up, e = 0.9 over 10 periods
  int kepler_periods = 10;
  unsigned reference_digits = 32;  // the exact solutions and Hénon–Heiles' reference run
  double fpu_T = 2;                // the FPU chain (the fpu section's m, ω and start) up to T
  timing_policy timing{20, 0.25};
  // The linearized double pendulum.
  std::vector<long long> double_pendulum_N{10, 20, 40, 80, 160};
};

section_result run_nonlinear(const nonlinear_settings& s);

/// The nonlinear section as a registry entry (experiment_section.hpp).
std::unique_ptr<experiment_section> make_nonlinear_section();

/// The section's published fact "nonlinear.pendulum-order-4": the Simpson scheme's global order is 4
/// on the pendulum V = m ω² (1 − cos q), m = ω = 1, q(0) = 1, T = 10, proved by enclosures of the
/// scheme (q_m proved unique at every step) and of the exact solution, N = 10 … 320; the energy of a
/// double run of 1e5 steps beside it (nonlinear_order_fact.cpp). Enclosed in `digits` decimal digits;
/// what they decide neither way throws enclosure_undecided.
published_fact pendulum_order_fact(unsigned digits = 60);

}  // namespace simpson::verify

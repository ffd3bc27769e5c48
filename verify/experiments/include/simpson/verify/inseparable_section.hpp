#pragma once
// The nonlinear_inseparable section: two systems whose Hamiltonian is not separable (a kinetic
// energy that depends on the configuration), as the authors' tutorial (arXiv 2512.03330) poses
// them. The Lagrange top (lagrange_top.hpp) against its exact motion enclosed with Arb
// (lagrange_top_exact.hpp), and the nonlinear double pendulum (double_pendulum.hpp) against an MPFR
// reference (reference_flow.hpp) inside its predictability horizon (lyapunov_exponent.hpp). Simpson's
// variational step for any L, the implicit midpoint variational integrator, Lobatto IIIA–IIIB and
// RK4 on the Legendre Hamiltonian, and GeometricIntegrators' VPRK form, each in double: error
// against N and against run time, the orders, the cost of an accuracy, the momenta of the top's
// cyclic angles and its energy over long runs.

#include <simpson/verify/experiment_section.hpp>
#include <simpson/verify/progress.hpp>
#include <simpson/verify/published_fact.hpp>
#include <simpson/verify/result_model.hpp>

#include <memory>
#include <string>
#include <vector>

namespace simpson::verify {

/// The top's parameters and start (lagrange_top.hpp); φ₀ = ψ₀ = 0. The defaults are
/// nutating_lagrange_top(): a top that nutates visibly between 60° and 53.6°, period 1.63.
struct inseparable_top_settings {
  double I1 = 1, I3 = 0.5, Mgl = 1;
  double theta0 = 1.0471975511965976;  // π/3 rounded to double: the start is this double, exactly
  double theta_dot0 = 0, phi_dot0 = 0.5, psi_dot0 = 8;
};

/// The double pendulum's parameters and start (angles from the downward vertical, their rates).
struct inseparable_pendulum_settings {
  double m1 = 1, m2 = 1, l1 = 1, l2 = 1, g = 1;
  double theta1 = 2, theta2 = 2.5, omega1 = 0, omega2 = 0;
};

struct inseparable_settings {
  /// Where the section reports each unit of work done (progress.hpp); none: nowhere.
  progress_sink progress;
  inseparable_top_settings top;
  double top_end_time = 10;                                   // the convergence runs' T
  std::vector<long long> top_N{50, 100, 200, 400, 800, 1600, 3200};  // their step counts
  std::vector<double> long_h{0.1, 0.05, 0.025};               // the long runs' steps
  long long long_steps = 50000;                               // the long runs' length
  int samples = 400;                                          // points of a curve over time
  unsigned exact_digits = 30;                                 // the top's exact motion enclosed at these digits
  double reference_digits = 14;  // the top's MPFR reference (a check of the enclosure) agrees to these digits
  inseparable_pendulum_settings pendulum;
  double pendulum_end_time = 4;
  std::vector<long long> pendulum_N{50, 100, 200, 400, 800, 1600, 3200};
  double pendulum_reference_digits = 16;  // the MPFR reference's two finest runs agree to these digits
  double lyapunov_time = 200;             // the Lyapunov estimate's averaging time
  bool timed = true;                      // seconds and the cost in seconds (--no-timing: none)
  /// Moves the exact θ by this much wherever it is compared (never from a scene: the tests' way to
  /// show that a wrong exact solution breaks the agreement and the orders).
  double perturb_exact = 0;
};

/// The size the published facts run at: T = 10, N = 100 … 800, 2000 steps of each long h (about 2 s).
inseparable_settings inseparable_fact_settings();

section_result run_inseparable(const inseparable_settings& s);

/// The nonlinear_inseparable section as a registry entry (experiment_section.hpp).
std::unique_ptr<experiment_section> make_inseparable_section();

/// Throws std::invalid_argument naming the field ('I1', 'theta0', ...) for a top that is not
/// physical: I₁ ≤ 0, I₃ ≤ 0, θ₀ outside (0, π), or a field not finite.
void check_inseparable_top(const inseparable_top_settings& top);

/// The largest step of `h` (each positive) at which one implicit step of every method from the
/// top's start fails to converge, and why; empty when every step converges. What the scene reader
/// refuses, naming the field, before anything runs.
std::string first_newton_failure(const inseparable_top_settings& top, const std::vector<double>& h);

/// "nonlinear_inseparable.simpson-order": on the top, Simpson's order is 4 and the midpoint rule's
/// 2, in nutation θ, decided by the enclosed errors of double runs against the exact motion
/// enclosed (each local order's enclosure within 1/2 of the order, the pairs above round-off).
published_fact inseparable_order_fact(const inseparable_settings& s);

/// "nonlinear_inseparable.top-momenta-exact": p_φ and p_ψ, the top's cyclic momenta, change under
/// Simpson's and the midpoint step only within the sum of the steps' Noether bounds (the Newton
/// residual at the stated tolerance and the update's rounding), at each long step size.
published_fact inseparable_momenta_fact(const inseparable_settings& s);

}  // namespace simpson::verify

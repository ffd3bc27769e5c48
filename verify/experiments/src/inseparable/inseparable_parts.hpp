#pragma once
// The nonlinear_inseparable section's shared parts: its methods as one list, one step of each on any
// Lagrangian of lagrangian.hpp, and a run that stops with a message (never a step that did not
// converge, never a non-finite state).

#include <simpson/verify/inseparable_section.hpp>
#include <simpson/verify/result_model.hpp>
#include <simpson/verify/scheme_style.hpp>

#include <simpson/interval.hpp>
#include <simpson/lagrange_top_exact.hpp>
#include <simpson/discrete_lagrangian_step.hpp>
#include <simpson/hamiltonian_prk_step.hpp>
#include <simpson/vprk_step.hpp>

#include <fmt/format.h>

#include <array>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace simpson::verify::detail {

/// The methods, each in its natural form: Simpson's and the midpoint rule's variational steps
/// (position–momentum form, discrete_lagrangian_step.hpp), the Lobatto IIIA–IIIB pair and RK4 on the
/// Legendre Hamiltonian (hamiltonian_prk_step.hpp), and GeometricIntegrators' VPRK form of Lobatto
/// IIIA–IIIB(3) with its null vector (vprk_step.hpp), which is Simpson's map in velocity form.
enum class ins_method { simpson, midpoint, lobatto, rk4, vprk };
constexpr std::array<ins_method, 5> ins_methods{ins_method::simpson, ins_method::midpoint, ins_method::lobatto, ins_method::rk4,
                                                ins_method::vprk};

inline std::string name_of(ins_method m) {
  switch (m) {
    case ins_method::simpson: return "simpson";
    case ins_method::midpoint: return "implicit-midpoint";
    case ins_method::lobatto: return "lobatto-iiia-iiib";
    case ins_method::rk4: return "rk4";
    case ins_method::vprk: return "vprk-lobatto3";
  }
  return "";
}

/// The classical order of each method.
inline int order_of(ins_method m) { return m == ins_method::midpoint ? 2 : 4; }

/// Each method's colour and points: Simpson's, Newmark's for the midpoint rule (the same map on the
/// oscillator), RK4's; Lobatto and VPRK their own.
inline scheme_style style_for(ins_method m) {
  switch (m) {
    case ins_method::simpson: return style_of(scheme_id::simpson);
    case ins_method::midpoint: return style_of(scheme_id::newmark);
    case ins_method::rk4: return style_of(scheme_id::rk4);
    case ins_method::lobatto: return {6, 9, line_style::lines_points, 1};
    case ins_method::vprk: return {9, 12, line_style::lines_points, 2};
  }
  return style_of(scheme_id::simpson);
}

inline series styled_series(ins_method m, const std::string& title) {
  const scheme_style st = style_for(m);
  return series(title, st.line, st.color, st.point, st.dash);
}

/// One step: the state, Newton's iterations, and for the variational steps their Noether bound per
/// coordinate (discrete_lagrangian_step.hpp; zero for the others, whose update adds h Σ b_i ∂H/∂q_k,
/// exactly 0 for a cyclic q_k).
struct ins_step {
  ndof_state<double> state;
  int newton_iterations = 0;
  dense_vector<double> noether_bound;
};

template <class Lag>
ins_step take_step(ins_method m, const Lag& L, double h, const ndof_state<double>& y) {
  const auto lagrangian = [](const lagrangian_step_result<double>& r) { return ins_step{r.state, r.newton_iterations, r.noether_bound}; };
  const auto hamiltonian = [&](const ndof_step_result<double>& r) {
    return ins_step{r.state, r.newton_iterations, dense_vector<double>::Zero(y.q.size())};
  };
  switch (m) {
    case ins_method::simpson: return lagrangian(simpson_lagrangian_step(L, h, y));
    case ins_method::midpoint: return lagrangian(midpoint_lagrangian_step(L, h, y));
    case ins_method::lobatto: return hamiltonian(lobatto_hamiltonian_step(L, h, y));
    case ins_method::rk4: return hamiltonian(rk4_hamiltonian_step(L, h, y));
    case ins_method::vprk: {
      ins_step out = lagrangian(vprk_lobatto3_step(L, h, y));
      out.noether_bound.setZero();  // p' = p + h Σ b̄_i F_i: F_k is exactly 0 for a cyclic q_k
      return out;
    }
  }
  throw std::logic_error("take_step: unknown method");
}

/// How a run went: its last state, its counts and seconds, and the reason it stopped early.
struct ins_run {
  ndof_state<double> state;
  long long steps = 0, newton_iterations = 0;
  double seconds = 0;  // the steps' own wall time: what `observe` does is not counted
  std::optional<std::string> failure;  // "failed at step j (t = …): why"
  bool ok() const { return !failure; }
};

/// N steps of h from y0; `observe(j, step)` after every step j = 1..N. Stops at the first step that
/// throws (Newton did not converge: the core never returns such a step) or leaves a non-finite state.
template <class Lag, class Observe>
ins_run run_method(ins_method m, const Lag& L, const ndof_state<double>& y0, double h, long long N, Observe&& observe) {
  ins_run out;
  out.state = y0;
  std::chrono::steady_clock::duration stepping{};
  for (long long j = 1; j <= N; ++j) {
    try {
      const auto start = std::chrono::steady_clock::now();
      const ins_step step = take_step(m, L, h, out.state);
      stepping += std::chrono::steady_clock::now() - start;
      if (!step.state.q.allFinite() || !step.state.p.allFinite()) {
        out.failure = fmt::format("failed at step {} (t = {:.6g}): a non-finite state", j, static_cast<double>(j) * h);
        break;
      }
      out.state = step.state;
      out.newton_iterations += step.newton_iterations;
      out.steps = j;
      observe(j, step);
    } catch (const std::domain_error& e) {
      out.failure = fmt::format("failed at step {} (t = {:.6g}): {}", j, static_cast<double>(j) * h, e.what());
      break;
    }
  }
  out.seconds = std::chrono::duration<double>(stepping).count();
  return out;
}

/// One method's run at one N, as the tables show it.
struct convergence_point {
  long long N = 0;
  double error = 0;   // the error used for orders and costs (the top: |θ − θ(T)|'s midpoint)
  figure shown;       // the same as reported (an enclosure for the top)
  double seconds = 0;
  ins_run run;
};

/// The N (and seconds) at which a method's error first reaches `target`, interpolated linearly in
/// log N against log error between the two measured points that bracket it.
struct reached {
  std::optional<double> N, seconds;
  std::string why_not;  // "not reached by N = …", "below at N = …"
};
reached interpolate_reach(const std::vector<convergence_point>& points, double target);

/// The local orders between consecutive N, enclosed, and what they decide against `order`: proved
/// when at least two pairs are above the rounding allowance and each pair's enclosure lies within
/// 1/2 of the order; refuted when a used pair's lies wholly outside; else undecided.
struct order_decision {
  std::vector<interval> local;  // per pair (N_k, N_{k+1}); 0 when the pair is not used
  std::vector<bool> used;
  int pairs_used = 0;
  enum class verdict { proved, refuted, undecided } outcome = verdict::undecided;
  std::string text;
};
/// The rounding allowance of a run of N steps: 1000 N eps.
double rounding_allowance(long long N);
order_decision decide_order(const std::vector<long long>& N, const std::vector<interval>& errors, int order);

/// The section's parts: each adds its blocks and expectations to `out` and returns its
/// convergence runs per method, for the cost of an accuracy.
struct part_runs {
  std::vector<std::vector<convergence_point>> by_method;  // in ins_methods' order
  std::string system;
};
part_runs run_top_part(const inseparable_settings& s, section_result& out);

/// The top's exact motion (enclosed) against an independent MPFR integration of its Hamiltonian
/// equations at T: the text and the expectation (inseparable_top_reference.cpp).
void add_top_reference_check(const inseparable_settings& s, const lagrange_top_exact& exact, section_result& out);
part_runs run_pendulum_part(const inseparable_settings& s, section_result& out);

}  // namespace simpson::verify::detail

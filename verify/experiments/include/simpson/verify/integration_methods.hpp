#pragma once
// The methods the experiment sections run on problems of n degrees of freedom, as data: one list
// (integration_methods) gives each its name in the reports, its algorithm, the scheme of core's
// scheme_list it is on the oscillator (its 2 × 2 matrix and its plot style), whether it is implicit
// (Newton on its stages) and whether it keeps the force a step ends with for the next (first same as
// last: one force evaluation at the run's start). A section chooses methods from this list by name or
// id; `ndof_stepper` runs any of them on a separable system, and integrate_n_steps
// (integration_driver.hpp) runs the stepper.

#include <simpson/verify/scheme_style.hpp>

#include <simpson/nonlinear_ndof_step.hpp>
#include <simpson/runge_kutta_tableaux.hpp>
#include <simpson/scheme.hpp>
#include <simpson/separable_system.hpp>
#include <simpson/stormer_verlet.hpp>
#include <simpson/trigonometric_step.hpp>

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

namespace simpson::verify {

enum class method_id { simpson, gauss_legendre_2, implicit_midpoint, stormer_verlet, yoshida, rk4, trigonometric };

struct integration_method {
  method_id id;
  std::string_view name;
  std::optional<scheme_id> on_oscillator;  // the scheme it is on the oscillator (none: the trigonometric method, exact there)
  bool implicit;                           // its stages solved by Newton's method (16 eps of the terms)
  bool keeps_last_force;                   // first same as last: the force at the run's start evaluated once
};

/// Every method of the sections, in the order their reports list them. The implicit midpoint rule is
/// Newmark's average acceleration on the oscillator (the same matrix); the trigonometric method is
/// Hairer, Lubich and Wanner's method (C), exact on the stiff part of a split potential.
inline constexpr std::array<integration_method, 7> integration_methods{{
    {method_id::simpson, "simpson", scheme_id::simpson, true, true},
    {method_id::gauss_legendre_2, "gauss-legendre-2", scheme_id::gauss_legendre_2, true, false},
    {method_id::implicit_midpoint, "implicit-midpoint", scheme_id::newmark, true, false},
    {method_id::stormer_verlet, "stormer-verlet", scheme_id::stormer_verlet, false, true},
    {method_id::yoshida, "yoshida", scheme_id::yoshida, false, true},
    {method_id::rk4, "rk4", scheme_id::rk4, false, false},
    {method_id::trigonometric, "trigonometric", std::nullopt, false, true},
}};

constexpr const integration_method& method_of(method_id id) {
  for (const integration_method& m : integration_methods) {
    if (m.id == id) return m;
  }
  throw std::logic_error("method_of: method missing from integration_methods");
}

/// The method named `name`; std::invalid_argument naming it and the known names otherwise.
inline const integration_method& find_method(std::string_view name) {
  for (const integration_method& m : integration_methods) {
    if (m.name == name) return m;
  }
  std::string known;
  for (const integration_method& m : integration_methods) known += (known.empty() ? "" : ", ") + std::string(m.name);
  throw std::invalid_argument("unknown method '" + std::string(name) + "' (expected " + known + ")");
}

/// A method drawn as the scheme it is on the oscillator; the trigonometric method, no scheme of ours
/// there, in black with open diamonds.
inline scheme_style style_of(const integration_method& m) {
  if (m.on_oscillator) return style_of(*m.on_oscillator);
  return {9, 12, line_style::lines_points, 1};
}

/// Whether a potential is split into a stiff linear part and a slow one (stiff_frequency(),
/// stiff_projection(v), slow_gradient(q)), what the trigonometric method needs. A wrapper of a
/// potential (a counting one) declares itself split when what it wraps is.
template <class Potential, class = void>
struct has_stiff_split : std::false_type {};
template <class Potential>
struct has_stiff_split<Potential, std::void_t<decltype(std::declval<const Potential&>().stiff_frequency())>> : std::true_type {};

/// A method's step on one separable system, in Real: Newton's iterations of the implicit steps added
/// to a count; the force a step ends with kept for the next where the method keeps it. One stepper a
/// run (the kept force is the run's state); the system is held by reference.
template <class Real, class Potential>
class ndof_stepper {
 public:
  ndof_stepper(const integration_method& m, const separable_system<Real, Potential>& s)
      : method_(m.id), system_(s),
        tableau_(m.id == method_id::implicit_midpoint ? implicit_midpoint_tableau<Real>() : gauss_legendre2_tableau<Real>()),
        coupling_(couple(tableau_, tableau_)), weights_(yoshida_weights<Real>()) {}

  ndof_state<Real> step(const Real& h, const ndof_state<Real>& y, long long& iterations) {
    switch (method_) {
      case method_id::simpson: return counted(simpson_ndof_step(system_, h, y, kept_), iterations);
      case method_id::gauss_legendre_2:
      case method_id::implicit_midpoint: return counted(prk_ndof_step(tableau_, tableau_, coupling_, system_, h, y), iterations);
      case method_id::stormer_verlet: return stormer_verlet_ndof_step(system_, h, y, kept_);
      case method_id::yoshida: return yoshida_ndof_step(system_, weights_, h, y, kept_);
      case method_id::rk4: return rk4_ndof_step(system_, h, y);
      case method_id::trigonometric:
        if constexpr (has_stiff_split<Potential>::value) return trigonometric_step(system_.potential(), h, y, kept_);
        throw std::invalid_argument("ndof_stepper: the trigonometric method needs a split potential");
    }
    return y;
  }

 private:
  static ndof_state<Real> counted(const ndof_step_result<Real>& r, long long& iterations) {
    iterations += r.newton_iterations;
    return r.state;
  }
  method_id method_;
  const separable_system<Real, Potential>& system_;
  butcher_tableau<Real> tableau_;
  stage_coupling<Real> coupling_;
  std::array<Real, 3> weights_;
  last_force<Real> kept_;  // the force at the step's end (Simpson's impulse, the explicit kicks): the next step's start
};

}  // namespace simpson::verify

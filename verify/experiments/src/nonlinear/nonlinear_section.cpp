// The nonlinear section (beyond the paper): its four parts in order, with the settings they
// depend on.

#include "nonlinear_parts.hpp"

#include <simpson/verify/nonlinear_section.hpp>

#include <algorithm>

namespace simpson::verify {

section_result run_nonlinear(const nonlinear_settings& s) {
  section_result out;
  out.name = "nonlinear";
  const auto runs = [&s](const char* part) { return std::find(s.parts.begin(), s.parts.end(), part) != s.parts.end(); };
  const bool problems_alone = s.parts == std::vector<std::string>{"problems"};
  out.title = problems_alone ? "Error against work on nonlinear problems (beyond the paper): Simpson and its peers"
                             : "Beyond the paper: any potential, several degrees of freedom";
  out.conventions = {{"parts", s.parts},
                     {"pendulum_q0", s.pendulum_q0},
                     {"pendulum_T", s.pendulum_T},
                     {"pendulum_N", s.pendulum_N},
                     {"mpfr_digits", s.mpfr_digits},
                     {"energy_steps", s.energy_steps},
                     {"brouwer_h", s.brouwer_h},
                     {"brouwer_steps", s.brouwer_steps},
                     {"problems", s.problems},
                     {"N", s.N},
                     {"eccentricity", s.eccentricity},
                     {"kepler_periods", s.kepler_periods},
                     {"reference_digits", s.reference_digits},
                     {"double_pendulum_N", s.double_pendulum_N}};
  out.timing_conventions = {{"warm_up_runs", 1}, {"max_runs", s.timing.max_runs}, {"max_seconds", s.timing.max_seconds}};
  out.text(
      "The Simpson variational integrator for any smooth V (nonlinear_simpson_step.hpp, nonlinear_ndof_step.hpp): "
      "each step solves the discrete Euler–Lagrange equations of L_h for the internal node by Newton's method in the "
      "working precision, then takes Simpson's rule for the impulse. The paper's §9 leaves this case open; the claims "
      "of the ledger part \"beyond\" prove that the step is the 3-stage Lobatto IIIA–IIIB step and symplectic for every V.");
  if (problems_alone) {
    out.text("The oscillator's comparison of the schemes in every precision is the work_precision section's; here the same peers, "
             "each in the form its users write it for any force, on the paper's oscillator and the nonlinear problems the field uses, "
             "against N, force evaluations (∇V) and run time.");
  }
  if (runs("pendulum")) detail::add_nonlinear_pendulum(s, out);
  if (runs("brouwer")) detail::add_nonlinear_brouwer(s, out);
  if (runs("problems")) detail::add_nonlinear_problems(s, out);
  if (runs("double-pendulum")) detail::add_double_pendulum(s, out);
  return out;
}

}  // namespace simpson::verify

#pragma once
// The three parts of the nonlinear section (nonlinear_section.cpp assembles them).

#include <simpson/verify/nonlinear_section.hpp>

#include <string>
#include <vector>

namespace simpson::verify::detail {

/// The pendulum's convergence table in mpfr, with its energy over long runs in double.
void add_nonlinear_pendulum(const nonlinear_settings& s, section_result& out);
/// Brouwer's law: the pendulum's energy round-off in the step's three forms over a long run in double.
void add_nonlinear_brouwer(const nonlinear_settings& s, section_result& out);
/// Error against N and run time on the pendulum, Kepler and Hénon–Heiles, in double.
void add_nonlinear_problems(const nonlinear_settings& s, section_result& out);
/// The linearized double pendulum: errors and the discrete energy.
void add_double_pendulum(const nonlinear_settings& s, section_result& out);

/// Orders between consecutive rows: log(e_k−1/e_k)/log(N_k/N_k−1), in Real.
template <class Real>
std::vector<Real> observed_orders(const std::vector<long long>& N, const std::vector<Real>& errors) {
  using std::log;
  std::vector<Real> out;
  for (std::size_t k = 1; k < errors.size(); ++k) {
    out.push_back(log(Real(errors[k - 1] / errors[k])) / log(Real(Real(N[k]) / Real(N[k - 1]))));
  }
  return out;
}

}  // namespace simpson::verify::detail

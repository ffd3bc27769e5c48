// Sections 3 and 4: the range of the Simpson action's sum (the interpolant, the rule's exactness
// and the Simpson Lagrangian are proof shapes' records in claims/paper.toml).

#include "claim_support.hpp"
#include "claims_section3_4.hpp"

#include <simpson/reduced_lagrangian.hpp>
#include <simpson/three_term_scheme.hpp>

namespace simpson::verify::detail {
namespace {

/// dS/dq_1 + (factor) × scheme at j = 1 for N = 3, summing L over j = first..N−1.
claim_result check_simpson_action_range(const run_context&) {
  const auto gap = [&](int first) {
    return [first](const auto& q) {
      using S = std::decay_t<decltype(q[0])>;
      const auto par = theta_oscillator<S>();
      const auto action = [&](const S& q1) {
        std::vector<S> nodes = q;
        nodes[1] = q1;
        S sum(0);
        for (int j = first; j <= 2; ++j) {
          sum += reduced_lagrangian(par, nodes[static_cast<std::size_t>(j)], nodes[static_cast<std::size_t>(j) + 1]);
        }
        return sum;
      };
      // On the discrete Euler-Lagrange equation dSigma/dq_1 = -(m h/(1 - x/8)) (schema-ordre-3).
      return exact_derivative(action, q[1]) +
             par.m() * par.h() / (1 - par.omega2_h2() / 8) * three_term_residual(par, q[0], q[1], q[2]);
    };
  };
  const std::vector<std::string> vars{"q0", "q1", "q2", "q3"};
  const std::string reduction =
      "m = omega = 1, h = theta; q_m eliminated (Lagrangien-reduit); N = 3; dSigma_d/dq_1 + (m h/(1 - x/8)) (schema-ordre-3) "
      "at j = 1";
  const proof printed = prove_zero_on_grid(reduction + "; summed over j = 1..N-1 as printed", vars, 1, gap(1));
  const proof corrected = prove_zero_on_grid(reduction + "; summed over j = 0..N-1", vars, 1, gap(0));
  return erratum(printed, corrected, "Sigma_d = sum_{j=0}^{N-1} L_h(q_j, q_{j+1/2}, q_{j+1}): N intervals give N terms",
                 "Same range slip as S_d in Section 2: the first interval [t_0, t_1] is left out.");
}

}  // namespace

void add_section3_4_checks(check_registry& checks) {
  checks.add("simpson-action-range", check_simpson_action_range);
}

}  // namespace simpson::verify::detail

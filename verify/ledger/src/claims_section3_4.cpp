// Sections 3 and 4: quadratic interpolation, Simpson's rule, the Simpson Lagrangian and action.

#include "claim_support.hpp"
#include "claims_section3_4.hpp"

#include <simpson/verify/quoted_words.hpp>

#include <simpson/internal_node.hpp>
#include <simpson/quadratic_interpolation.hpp>
#include <simpson/reduced_lagrangian.hpp>
#include <simpson/simpson_lagrangian.hpp>
#include <simpson/simpson_rule.hpp>
#include <simpson/three_term_scheme.hpp>

namespace simpson::verify::detail {
namespace {

claim_result check_basis_nodal(const run_context&) {
  const proof p = prove_zero_on_grid("q(t) of (q2t) at t = 0, h/2, h minus q_l, q_m, q_r", {"q_l", "q_m", "q_r"}, 1,
                                     [&](const auto& v) {
                                       using S = std::decay_t<decltype(v[0])>;
                                       const S ql(v[0]), qm(v[1]), qr(v[2]);
                                       return std::vector<S>{quadratic_interpolant(ql, qm, qr, S(0)) - ql,
                                                             quadratic_interpolant(ql, qm, qr, S(1) / 2) - qm,
                                                             quadratic_interpolant(ql, qm, qr, S(1)) - qr};
                                     });
  return identity(p);
}

claim_result check_interpolant_derivative(const run_context&) {
  // h symbolic and s = t/h on a grid: every side is of degree <= 1 in s, so three values of s prove
  // the identity for every s and every h (no homogeneity argument needed).
  const proof p = prove_zero_on_grid(
      "h symbolic, s = t/h on a grid (degree <= 1 in s); dq/dt by exact differences of (q2t) in s, divided by h, against "
      "the printed (1/h)[q_l (4s - 3) + 4 q_m (1 - 2s) + q_r (4s - 1)] and against g_l (1 - s) + g_r s",
      {"q_l", "q_m", "q_r", "s"}, {1, 1, 1, 2}, [&](const auto& v) {
        using S = std::decay_t<decltype(v[0])>;
        const S h = theta_variable<S>();
        const S ql(v[0]), qm(v[1]), qr(v[2]), s(v[3]);
        const S by_difference = exact_derivative([&](const S& u) { return quadratic_interpolant(ql, qm, qr, u); }, s) / h;
        const S printed = quadratic_interpolant_derivative(ql, qm, qr, h, s);
        const S affine = gear_left(ql, qm, qr, h) * (1 - s) + gear_right(ql, qm, qr, h) * s;
        return std::vector<S>{by_difference - printed, printed - affine};
      });
  return identity(p);
}

claim_result check_gear(const run_context&) {
  const proof p = prove_zero_on_grid("h = theta symbolic; g_l - q'(0), g_r - q'(h) with q' by exact differences of (q2t)",
                                     {"q_l", "q_m", "q_r"}, 1, [&](const auto& v) {
                                       using S = std::decay_t<decltype(v[0])>;
                                       const S h = theta_variable<S>();
                                       const S ql(v[0]), qm(v[1]), qr(v[2]);
                                       const auto q_of_s = [&](const S& u) { return quadratic_interpolant(ql, qm, qr, u); };
                                       return std::vector<S>{gear_left(ql, qm, qr, h) - exact_derivative(q_of_s, S(0)) / h,
                                                             gear_right(ql, qm, qr, h) - exact_derivative(q_of_s, S(1)) / h};
                                     });
  return identity(p);
}

claim_result check_centred(const run_context&) {
  const proof p = prove_zero_on_grid(
      "h = theta symbolic; g_m - q'(h/2), g_m - (g_l + g_r)/2 with q' by exact differences of (q2t)", {"q_l", "q_m", "q_r"}, 1,
      [&](const auto& v) {
        using S = std::decay_t<decltype(v[0])>;
        const S h = theta_variable<S>();
        const S ql(v[0]), qm(v[1]), qr(v[2]);
        const auto q_of_s = [&](const S& u) { return quadratic_interpolant(ql, qm, qr, u); };
        const S gm = centred_derivative(ql, qr, h);
        return std::vector<S>{gm - exact_derivative(q_of_s, S(S(1) / 2)) / h, gm - (gear_left(ql, qm, qr, h) + gear_right(ql, qm, qr, h)) / 2};
      });
  return identity(p);
}

/// ∫_0^1 s^k ds against a rule, for k = 0..top: the degrees it integrates exactly.
template <class Rule>
json exactness_by_degree(Rule&& rule, int top, int& exact_up_to) {
  json rows = json::array();
  exact_up_to = -1;
  bool still_exact = true;
  for (int k = 0; k <= top; ++k) {
    const auto monomial = [k](const rational& s) -> rational {
      rational v = 1;
      for (int i = 0; i < k; ++i) v *= s;
      return v;
    };
    const rational rule_value = rule(monomial);
    const rational integral = rational(1, k + 1);
    const bool exact = rule_value == integral;
    if (exact && still_exact) exact_up_to = k;
    still_exact = still_exact && exact;
    rows.push_back({{"degree", k}, {"rule", simpson::to_string(rule_value)}, {"integral", simpson::to_string(integral)}, {"exact", exact}});
  }
  return rows;
}

/// The degree of exactness a sentence states, against the one computed: holds when they agree,
/// else an erratum whose correction is the computed degree (the monomial table proves it).
claim_result exactness_as_stated(const std::string& rule, const json& rows, int exact_up_to, int stated_up_to,
                                 const std::string& stated) {
  json evidence;
  evidence["exact"] = {{"method", "exact"}, {"rule", rule}, {"monomials", rows}, {"exact_up_to_degree", exact_up_to},
                       {"stated", stated}, {"stated_up_to_degree", stated_up_to}};
  claim_result r;
  r.evidence = evidence;
  const std::string computed = "exact for every polynomial of degree <= " + std::to_string(exact_up_to) + " and not for degree " +
                               std::to_string(exact_up_to + 1);
  if (stated_up_to == exact_up_to) {
    r.outcome = verdict::holds;
    r.note = "As stated ('" + stated + "'): " + computed + ".";
  } else {
    r.outcome = verdict::erratum;
    r.correction = "The rule is " + computed + " (the printed words say '" + stated + "')";
  }
  return r;
}

/// The highest degree a stated bound admits ("smaller or equal to 1": 1; "smaller than 2": 1).
int highest_admitted(const stated_bound& b) {
  int top = -1;
  for (int k = 0; k <= 12; ++k) {
    if (b.admits(k)) top = k;
  }
  return b.admits(13) ? 13 : top;  // an open-ended bound ("at least") admits every degree: never sharp
}

claim_result check_midpoint_exactness(const run_context& ctx) {
  const quoted_sentence said =
      quote(ctx, "the midpoint method studied previously $ \\, \\int_0^1 \\psi(\\theta) \\, \\dd \\theta \\simeq \\psi \\big( {1\\over2} "
                 "\\big) \\, $ is exact for a polynomial $ \\, \\psi \\, $ of degree {degree}.");
  const stated_bound stated = said.bound("degree");
  int exact_up_to = -1;
  const json rows = exactness_by_degree([](auto&& psi) { return psi(rational(1, 2)); }, 3, exact_up_to);
  return exactness_as_stated("psi(1/2)", rows, exact_up_to, highest_admitted(stated), said.words("degree"));
}

claim_result check_simpson_exactness(const run_context& ctx) {
  const quoted_sentence said =
      quote(ctx, "The quadrature formula (\\ref{simpson}) is accurate up to polynomials of degree {degree}.");
  const int stated = said.number("degree");
  int exact_up_to = -1;
  const json rows = exactness_by_degree([](auto&& psi) { return simpson_rule<rational>(psi); }, std::max(5, stated + 1), exact_up_to);
  return exactness_as_stated("(simpson) of the core", rows, exact_up_to, stated, said.words("degree"));
}

claim_result check_simpson_lagrangian(const run_context&) {
  // (LLhh) against h * simpson(m/2 q'^2 - V(q)) along (q2t): degree <= 4 in each q, 1 in m.
  return identity_for_quartic_potentials(
      "h = theta; (LLhh) - h (simpson)[m/2 (dq/dt)^2 - V(q)] along (q2t)", {"m", "q_l", "q_m", "q_r"}, {1, 4, 4, 4},
      [&](const monomial_potential& V, const auto& v) {
        using S = std::decay_t<decltype(v[0])>;
        const S h = theta_variable<S>();
        const S m(v[0]), ql(v[1]), qm(v[2]), qr(v[3]);
        const auto potential = [&](const S& x) { return V(x); };
        const auto integrand = [&](const S& s) {
          const S velocity = quadratic_interpolant_derivative(ql, qm, qr, h, s);
          return S(m / 2 * velocity * velocity - V(quadratic_interpolant(ql, qm, qr, s)));
        };
        return S(simpson_lagrangian(m, h, potential, ql, qm, qr) - h * simpson_rule<S>(integrand));
      },
      "Proved for every polynomial V of degree <= 4 (the identity is linear in V).");
}

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
  checks.add("basis-nodal", check_basis_nodal);
  checks.add("interpolant-derivative", check_interpolant_derivative);
  checks.add("gear", check_gear);
  checks.add("centred", check_centred);
  checks.add("midpoint-exactness", check_midpoint_exactness);
  checks.add("simpson-exactness", check_simpson_exactness);
  checks.add("simpson-lagrangian", check_simpson_lagrangian);
  checks.add("simpson-action-range", check_simpson_action_range);
}

}  // namespace simpson::verify::detail

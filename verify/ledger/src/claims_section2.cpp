// Section 2: the classical variational scheme and the Newmark map.

#include "claim_support.hpp"
#include "claims_section2.hpp"

#include <simpson/verify/quoted_words.hpp>
#include <simpson/verify/stability_analysis.hpp>

#include <simpson/verify/tex_math.hpp>  // canonical_text

#include <ginac/ginac.h>

#include <sstream>

#include <simpson/classical_lagrangian.hpp>
#include <simpson/energy.hpp>
#include <simpson/newmark_map.hpp>

namespace simpson::verify::detail {
namespace {

/// ∂/∂q_1 of Σ_{j=first}^{N−1} L(q_j, q_{j+1}) for N = 3, by exact differences.
template <class Lagrangian, class S>
S action_derivative_at_q1(Lagrangian&& L, int first, const std::vector<S>& q) {
  const auto action = [&](const S& q1) {
    std::vector<S> nodes = q;
    nodes[1] = q1;
    S sum(0);
    for (int j = first; j <= 2; ++j) sum += L(nodes[static_cast<std::size_t>(j)], nodes[static_cast<std::size_t>(j) + 1]);
    return sum;
  };
  return exact_derivative(action, q[1]);
}

claim_result check_action_range(const run_context&) {
  const auto euler_lagrange_gap = [&](int first) {
    return [first](const auto& q) {
      using S = std::decay_t<decltype(q[0])>;
      const auto par = theta_oscillator<S>();
      const auto L = [&](const S& l, const S& r) {
        return classical_lagrangian(par.m(), par.h(), [&](const S& v) { return par.potential(v); }, l, r);
      };
      const auto gradient = [&](const S& v) { return par.force_gradient(v); };
      return action_derivative_at_q1(L, first, q) + par.h() * classical_scheme_residual(par.m(), par.h(), gradient, q[0], q[1], q[2]);
    };
  };
  const std::vector<std::string> vars{"q0", "q1", "q2", "q3"};
  const std::string reduction = std::string(unit_reduction) +
                                "; N = 3; dS_d/dq_1 + h (schema-ordre-deux) at j = 1, which must vanish for the discrete "
                                "Euler-Lagrange equation to hold at the first interior node";
  const proof printed = prove_zero_on_grid(reduction + "; S_d summed over j = 1..N-1 as printed", vars, 1, euler_lagrange_gap(1));
  const proof corrected = prove_zero_on_grid(reduction + "; S_d summed over j = 0..N-1", vars, 1, euler_lagrange_gap(0));
  return erratum(printed, corrected, "S_d = sum_{j=0}^{N-1} L_d(q_j, q_{j+1}): N elements give N terms",
                 "The printed range has N-1 terms and leaves out the first element [t_0, t_1]; the scheme "
                 "(schema-ordre-deux) then fails at j = 1. Typographical; the later sections do not depend on it.");
}

claim_result check_classical_euler_lagrange(const run_context&) {
  // dL_d/dq_r(q_{j-1}, q_j) + dL_d/dq_l(q_j, q_{j+1}) + h (schema-ordre-deux) = 0: a polynomial of
  // degree <= 4 in each q and of degree 1 in m.
  return identity_for_quartic_potentials(
      "h = theta; dL_d/dq_r(q_{j-1},q_j) + dL_d/dq_l(q_j,q_{j+1}) (exact differences) + h (schema-ordre-deux)",
      {"m", "q_{j-1}", "q_j", "q_{j+1}"}, {1, 4, 4, 4},
      [&](const monomial_potential& V, const auto& v) {
        using S = std::decay_t<decltype(v[0])>;
        const S h = theta_variable<S>();
        const S m(v[0]), qp(v[1]), q(v[2]), qn(v[3]);
        const auto potential = [&](const S& x) { return V(x); };
        const auto dV = [&](const S& x) { return V.derivative(x); };
        return exact_derivative([&](const S& x) { return classical_lagrangian(m, h, potential, qp, x); }, q) +
               exact_derivative([&](const S& x) { return classical_lagrangian(m, h, potential, x, qn); }, q) +
               h * classical_scheme_residual(m, h, dV, qp, q, qn);
      },
      "Proved for every polynomial V of degree <= 4 (the identity is linear in V); for a general smooth V it is the "
      "chain rule on V((q_l + q_r)/2).");
}

/// y_{j+1} from Φ, with p_j = −∂L_d/∂q_l(q_j, q_{j+1}) and p_{j+1} = ∂L_d/∂q_r(q_j, q_{j+1}).
claim_result check_newmark_discrete_system(const run_context&) {
  const proof p = prove_zero_on_grid(
      std::string(unit_reduction) +
          "; p_j = -dL_d/dq_l(q_j,q_{j+1}), p_{j+1} = dL_d/dq_r(q_j,q_{j+1}) (exact differences) put into both relations",
      {"q_j", "q_{j+1}"}, 1, [&](const auto& v) {
        using S = std::decay_t<decltype(v[0])>;
        const auto par = theta_oscillator<S>();
        const auto V = [&](const S& x) { return par.potential(x); };
        const S q(v[0]), qn(v[1]);
        const S p_next = exact_derivative([&](const S& x) { return classical_lagrangian(par.m(), par.h(), V, q, x); }, qn);
        const S p_now = -exact_derivative([&](const S& x) { return classical_lagrangian(par.m(), par.h(), V, x, qn); }, q);
        const phase_point<S> r = newmark_system_residual(par, phase_point<S>{p_now, q}, phase_point<S>{p_next, qn});
        return std::vector<S>{r.p, r.q};
      });
  return identity(p, "On a solution, p_j = dL_d/dq_r(q_{j-1}, q_j) equals -dL_d/dq_l(q_j, q_{j+1}) by (Euler-Lagrange-discret).");
}

claim_result check_newmark_matrix(const run_context&) {
  const proof p = prove_zero_on_grid(std::string(unit_reduction) + "; (systeme-dynamique-discret-ordre-2) at (p_{j+1}, q_{j+1}) = Phi (p_j, q_j)",
                                     {"p_j", "q_j"}, 1, [&](const auto& v) {
                                       using S = std::decay_t<decltype(v[0])>;
                                       const auto par = theta_oscillator<S>();
                                       const phase_point<S> y{v[0], v[1]};
                                       const phase_point<S> r = newmark_system_residual(par, y, newmark_map(par) * y);
                                       return std::vector<S>{r.p, r.q};
                                     });
  return identity(p);
}

claim_result check_newmark_stability(const run_context& ctx) {
  const quoted_sentence linearly = quote(ctx, "the scheme (\\ref{schema-ordre-deux}) is {stability}.");
  const std::string stated = linearly.choice("stability", {{"linearly stable", "stable"}, {"stable", "stable"},
                                                           {"linearly unstable", "unstable"}, {"unstable", "unstable"}});
  const quoted_sentence kane = quote(ctx, "is one particular {qualifier} stable version of the Newmark scheme");
  // "inconditionally" is the French spelling the paper uses for "unconditionally".
  const std::string qualifier = kane.choice("qualifier", {{"inconditionally", "unconditional"}, {"unconditionally", "unconditional"},
                                                          {"conditionally", "conditional"}, {"conditionnally", "conditional"}});
  const auto par = unit_oscillator_in_theta();
  const auto gradient = [&](const symbolic& v) { return par.force_gradient(v); };
  const stability_report report = analyse_three_term_scheme([&](const symbolic& qp, const symbolic& q, const symbolic& qn) {
    return classical_scheme_residual(par.m(), par.h(), gradient, qp, q, qn);
  });
  json evidence;
  evidence["exact"] = report.evidence;
  // Unconditionally stable: one band, stable from 0 to infinity (no positive root of Δ).
  const bool unconditional = report.bands.size() == 1 && report.bands[0].stable && !report.bands[0].to;
  evidence["stated"] = {{"scheme", stated}, {"qualifier", qualifier}};
  if (!unconditional) return confirmed_if(false, evidence);
  if (stated == "stable" && qualifier == "unconditional") return confirmed_if(true, evidence);
  return words_erratum(evidence,
                       "The scheme (schema-ordre-deux) is stable for every omega h > 0 (unconditionally): Delta < 0 on the whole half-line");
}

/// Newmark's scheme for m q'' + m ω² q = 0 with parameters (β, γ), v = p/m, a = −ω² q:
///   q₁ = q + h v + h² ((1/2 − β) a + β a₁),  v₁ = v + h ((1 − γ) a + γ a₁).
/// Solved for (q₁, v₁) in GiNaC with every symbol free; at β = 1/4, γ = 1/2 the map must be Φ.
claim_result check_newmark_identification(const run_context& ctx) {
  const quoted_sentence said =
      quote(ctx, "the numerical scheme (\\ref{systeme-symplectique-ordre-2}) is one particular inconditionally stable version of the {family} scheme");
  said.choice("family", {{"Newmark", "Newmark (beta, gamma) family"}});
  const GiNaC::symbol m("m"), w("omega"), h("h"), p("p"), q("q"), q1("q1"), v1("v1"), beta("beta"), gamma("gamma");
  const GiNaC::ex v = p / m, a = -w * w * q, a1 = -w * w * q1;
  const GiNaC::ex solution = GiNaC::lsolve(
      GiNaC::lst{q1 == q + h * v + h * h * ((GiNaC::numeric(1, 2) - beta) * a + beta * a1), v1 == v + h * ((1 - gamma) * a + gamma * a1)},
      GiNaC::lst{q1, v1});
  const GiNaC::ex q_next = GiNaC::ex(q1).subs(solution), p_next = m * GiNaC::ex(v1).subs(solution);
  const GiNaC::lst average_acceleration{beta == GiNaC::numeric(1, 4), gamma == GiNaC::numeric(1, 2)};
  const one_step_matrix<GiNaC::ex> phi = newmark_map(oscillator_parameters<GiNaC::ex>{m, w, h});
  const GiNaC::ex dp = GiNaC::normal(p_next.subs(average_acceleration) - (phi.alpha * p + phi.beta * q));
  const GiNaC::ex dq = GiNaC::normal(q_next.subs(average_acceleration) - (phi.gamma * p + phi.delta * q));
  // And the family: det of the Newmark map is 1 exactly when γ = 1/2 (symplectic), for any β.
  const GiNaC::ex a11 = GiNaC::normal(p_next.diff(p)), a12 = GiNaC::normal(p_next.diff(q)), a21 = GiNaC::normal(q_next.diff(p)),
                  a22 = GiNaC::normal(q_next.diff(q));
  const GiNaC::ex det_minus_one = GiNaC::factor(GiNaC::normal(a11 * a22 - a12 * a21 - 1));
  // Canonical text: GiNaC's own printing order depends on symbol serial numbers.
  const std::string det_string = canonical_text(det_minus_one);
  json evidence;
  evidence["exact"] = {{"kernel", "GiNaC"},
                       {"method", "Newmark's two update equations solved for (q_{j+1}, v_{j+1}) with m, omega, h, p, q, beta, "
                                  "gamma symbolic (lsolve), then beta = 1/4, gamma = 1/2 substituted and compared with "
                                  "(matrice-symplectique-ordre-2)"},
                       {"p_next_minus_phi", dp.is_zero() ? "0" : "nonzero"},
                       {"q_next_minus_phi", dq.is_zero() ? "0" : "nonzero"},
                       {"det_minus_one_for_any_beta_gamma", det_string}};
  return confirmed_if(dp.is_zero() && dq.is_zero(), evidence,
                      "Kane et al.'s identification holds: Phi is Newmark's average-acceleration scheme (beta = 1/4, gamma = 1/2). "
                      "Over the whole family det - 1 = " + det_string + ", which vanishes for gamma = 1/2 and any beta.");
}

}  // namespace

void add_section2_checks(check_registry& checks) {
  checks.add("action-range", check_action_range);
  checks.add("classical-euler-lagrange", check_classical_euler_lagrange);
  checks.add("newmark-discrete-system", check_newmark_discrete_system);
  checks.add("newmark-matrix", check_newmark_matrix);
  checks.add("newmark-identification", check_newmark_identification);
  checks.add("newmark-stability", check_newmark_stability);
}

}  // namespace simpson::verify::detail

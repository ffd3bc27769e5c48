// §2–4 as printed: the discrete action's range, L_d and its scheme, Newmark's momentum, system,
// matrix and energy; the Gear derivatives and the interpolant's velocity; Simpson's L_h.

#include "check_registry.hpp"
#include "printed_check_support.hpp"

#include <simpson/classical_lagrangian.hpp>
#include <simpson/energy.hpp>
#include <simpson/newmark_map.hpp>
#include <simpson/quadratic_interpolation.hpp>
#include <simpson/simpson_lagrangian.hpp>

namespace simpson::verify::detail {
namespace {

using GiNaC::ex;

/// S_d and Σ_d: N elements [t_j, t_{j+1}] of [0, T] are j = 0 … N − 1, so the sum runs over them.
printed_outcome action_range(const paper_reading& r, const std::string& name, const std::string& what) {
  const ex& sum = printed_side(r, name);
  printed_outcome o;
  o.derived = "the elements [t_j, t_{j+1}] inside [0, T = N h] are j = 0, ..., N-1: N terms";
  if (!is_sum(sum)) {
    o.proved = "the printed " + what + " is not a sum: " + text_of(sum);
    return o;
  }
  const ex lower = sum.op(2), upper = sum.op(3), N = sym("N");
  const ex terms = GiNaC::normal(upper - lower + 1);
  o.holds = GiNaC::normal(lower).is_zero() && GiNaC::normal(upper - (N - 1)).is_zero();
  o.proved = "printed " + what + " sums j = " + text_of(lower) + ", ..., " + text_of(upper) + ": " + text_of(terms) +
             " terms for N elements";
  if (!o.holds) o.correction = what + " = sum_{j=0}^{N-1} " + text_of(sum.op(0)) + ": N elements give N terms";
  return o;
}

printed_outcome classical_euler_lagrange(const paper_reading& r) {
  const symbolic_derivation& d = derivation();
  const potential_function V = [&d](const ex& x) { return d.general_V(x); };
  // L_d as printed against L_d derived (affine interpolant, midpoint rule), V uninterpreted.
  const ex derived_L = d.classical_lagrangian(V, d.q_l, d.q_r);
  printed_outcome o = compare("L_d", printed_side(r, "lagrangien-discret"), derived_L,
                              classical_lagrangian(d.m, d.h, V, d.q_l, d.q_r));
  // The printed scheme against the Euler-Lagrange equation of the printed L_d.
  const GiNaC::symbol& l = GiNaC::ex_to<GiNaC::symbol>(d.q_l);
  const GiNaC::symbol& rr = GiNaC::ex_to<GiNaC::symbol>(d.q_r);
  const auto euler_lagrange_of = [&](const ex& L) {
    return L.diff(rr).subs(GiNaC::lst{d.q_l == d.q_prev, d.q_r == d.q_j}) + L.diff(l).subs(GiNaC::lst{d.q_l == d.q_j, d.q_r == d.q_next});
  };
  const ex euler_lagrange = euler_lagrange_of(printed_side(r, "lagrangien-discret"));
  const auto factor = equation_factor(printed_side(r, "schema-ordre-deux"), euler_lagrange, {d.q_prev, d.q_j, d.q_next});
  printed_outcome scheme;
  scheme.holds = factor.has_value();
  scheme.proved = factor ? "dL_d/dq_r(q_{j-1}, q_j) + dL_d/dq_l(q_j, q_{j+1}) of the printed L_d = (" + text_of(*factor) +
                               ") x printed (schema-ordre-deux), V uninterpreted"
                         : "the Euler-Lagrange equation of the printed L_d is not a multiple of the printed (schema-ordre-deux)";
  if (!scheme.holds) scheme.correction = "as derived: " + text_of(euler_lagrange) + " = 0";
  const auto core = equation_factor(classical_scheme_residual(d.m, d.h, general_force, d.q_prev, d.q_j, d.q_next),
                                    euler_lagrange_of(derived_L), {d.q_prev, d.q_j, d.q_next});
  scheme.derived_holds = core.has_value();
  scheme.derived = core ? "core classical_scheme_residual = derived Euler-Lagrange equation / (" + text_of(*core) + ")"
                        : "core classical_scheme_residual is not the derived Euler-Lagrange equation";
  return both(o, scheme);
}

/// (systeme-dynamique-discret-ordre-2) on smooth p(t), q(t): its leading terms are the printed
/// first-order Hamilton equations.
printed_outcome hamilton_consistency(const paper_reading& r) {
  const symbolic_derivation& d = derivation();
  const std::vector<smooth_state> states{{d.p_j, "p", 0}, {d.p_next, "p", d.h}, {d.q_j, "q", 0}, {d.q_next, "q", d.h}};
  const auto relation = [&r](const char* name) { return printed_side(r, name, 0) - printed_side(r, name, 1); };
  const phase_point<ex> core = newmark_system_residual(parameters(d), phase_point<ex>{d.p_j, d.q_j}, phase_point<ex>{d.p_next, d.q_next});
  return both(consistent_with("first relation", relation("systeme-dynamique-discret-ordre-2#0"), core.p, relation("Hamilton dp/dt"), states, d.h),
              consistent_with("second relation", relation("systeme-dynamique-discret-ordre-2#1"), core.q, relation("Hamilton dq/dt"), states, d.h));
}

/// (schema-ordre-deux) on a smooth q(t), V uninterpreted: its leading term is (oscillateur-nonlineaire).
printed_outcome classical_consistency(const paper_reading& r) {
  const symbolic_derivation& d = derivation();
  const std::vector<smooth_state> states{{d.q_prev, "q", -d.h}, {d.q_j, "q", 0}, {d.q_next, "q", d.h}};
  return consistent_with("(schema-ordre-deux)", printed_side(r, "schema-ordre-deux"),
                         classical_scheme_residual(d.m, d.h, general_force, d.q_prev, d.q_j, d.q_next),
                         printed_side(r, "oscillateur-nonlineaire", 0) - printed_side(r, "oscillateur-nonlineaire", 1), states, d.h);
}

printed_outcome newmark_system(const paper_reading& r) {
  const symbolic_derivation& d = derivation();
  // p_{j+1} = dL_d/dq_r (q_j, q_{j+1}) and p_j = -dL_d/dq_l (q_j, q_{j+1}), as derived.
  const GiNaC::lst momenta{d.p_next == newmark_derivation().momentum_right, d.p_j == newmark_derivation().momentum_left};
  printed_outcome o;
  o.holds = true;
  for (const char* name : {"systeme-dynamique-discret-ordre-2#0", "systeme-dynamique-discret-ordre-2#1"}) {
    const ex gap = GiNaC::normal((printed_side(r, name, 0) - printed_side(r, name, 1)).subs(momenta));
    o.holds = o.holds && gap.is_zero();
    o.goals.push_back({"printed", printed_side(r, name, 0).subs(momenta), printed_side(r, name, 1).subs(momenta), gap.is_zero()});
    o.proved += std::string(o.proved.empty() ? "" : "; ") + "printed " + name + ", left − right with the derived momenta = " + text_of(gap);
  }
  if (!o.holds) o.correction = "as derived: p_{j+1} = " + text_of(newmark_derivation().momentum_right) + ", p_j = " + text_of(newmark_derivation().momentum_left);
  const phase_point<ex> core = newmark_system_residual(parameters(d), phase_point<ex>{d.p_j, d.q_j}, phase_point<ex>{d.p_next, d.q_next});
  const ex first = GiNaC::normal(core.p.subs(momenta)), second = GiNaC::normal(core.q.subs(momenta));
  o.derived_holds = first.is_zero() && second.is_zero();
  o.derived = "core newmark_system_residual with the momenta derived from L_d: " + text_of(first) + ", " + text_of(second);
  return o;
}

/// Φ's defining property, what a certificate states (Φ = derived is one normal form for GiNaC):
/// with q_{j+1} from Φ's second row, the momenta of L_d are p_j and Φ's first row.
void add_momenta_goals(printed_outcome& o, const std::string& who, const ex& phi, bool printed) {
  if (!GiNaC::is_a<GiNaC::matrix>(phi) || GiNaC::ex_to<GiNaC::matrix>(phi).rows() != 2 || GiNaC::ex_to<GiNaC::matrix>(phi).cols() != 2) return;
  const symbolic_derivation& d = derivation();
  const GiNaC::matrix& M = GiNaC::ex_to<GiNaC::matrix>(phi);
  const ex p_next = M(0, 0) * d.p_j + M(0, 1) * d.q_j, q_next = M(1, 0) * d.p_j + M(1, 1) * d.q_j;
  add_goal(o, decided(who + "_momentum_left", newmark_derivation().momentum_left.subs(d.q_next == q_next), d.p_j), printed);
  add_goal(o, decided(who + "_momentum_right", newmark_derivation().momentum_right.subs(d.q_next == q_next), p_next), printed);
}

printed_outcome newmark_matrix(const paper_reading& r) {
  const symbolic_derivation& d = derivation();
  const GiNaC::matrix core = as_matrix(newmark_map(parameters(d)));
  printed_outcome o = compare("Phi", printed_side(r, "matrice-symplectique-ordre-2"), newmark_derivation().newmark_phi, core);
  add_momenta_goals(o, "printed", printed_side(r, "matrice-symplectique-ordre-2"), true);
  add_momenta_goals(o, "core", core, false);
  return o;
}

/// (q2t) with the printed basis functions (fonctions-de-base), t = h theta: at the printed points it
/// takes the printed values. The core's interpolant is the derived one (solved through the nodes).
printed_outcome interpolant_nodal(const paper_reading& r) {
  const symbolic_derivation& d = derivation();
  const char* basis[] = {"varphi_0", "varphi_1/2", "varphi_1"};
  ex q_of_theta = printed_side(r, "q2t");
  for (int k = 0; k < 3; ++k) {
    q_of_theta = q_of_theta.subs(apply_function(basis[k], {d.theta}) == printed_side(r, "fonctions-de-base#" + std::to_string(k)));
  }
  printed_outcome o;
  o.property = true;
  o.holds = true;
  for (const char* name : {"q(0)", "q(h/2)", "q(h)"}) {
    const ex& at = printed_side(r, name, 0);  // q(t_0), as read
    const ex t0 = GiNaC::is_a<GiNaC::function>(at) && at.nops() == 1 ? at.op(0) : ex(GiNaC::symbol("not_q_of_t"));
    const ex gap = GiNaC::normal(q_of_theta.subs(d.theta == t0 / d.h) - printed_side(r, name, 1));
    o.holds = o.holds && gap.is_zero();
    o.proved += std::string(o.proved.empty() ? "" : "; ") + "printed (q2t) at t = " + text_of(t0) + " minus the printed value = " + text_of(gap);
  }
  const ex core = quadratic_interpolant(d.q_l, d.q_m, d.q_r, d.theta);
  compare_core(o, "q(h theta)", GiNaC::normal(d.interpolant.subs(d.t == d.h * d.theta)), core);
  const ex printed_gap = GiNaC::normal(q_of_theta - core);
  o.derived += "; printed (q2t) with (fonctions-de-base) − core = " + text_of(printed_gap);
  o.holds = o.holds && printed_gap.is_zero();
  return o;
}

/// A derivative formula of q_l, q_m, q_r (the values at t = 0, h/2, h) is exact on quadratics: on
/// the values of c0 + c1 t + c2 t², as written, it is the derivative c1 + 2 c2 t at `at`. That is
/// what a certificate states (formula = derived is one normal form for GiNaC).
proof_goal exact_on_quadratics(const std::string& name, const ex& formula, const ex& at) {
  const symbolic_derivation& d = derivation();
  const GiNaC::symbol c0("c0"), c1("c1"), c2("c2");
  const auto P = [&](const ex& t) { return c0 + c1 * t + c2 * t * t; };
  return decided(name, formula.subs(GiNaC::lst{d.q_l == P(0), d.q_m == P(d.h / 2), d.q_r == P(d.h)}), c1 + 2 * c2 * at);
}

printed_outcome gear_derivatives(const paper_reading& r) {
  const symbolic_derivation& d = derivation();
  printed_outcome o = both(compare("g_l", printed_side(r, "derivees-gear#0"), d.g_l, gear_left(d.q_l, d.q_m, d.q_r, d.h)),
                           compare("g_r", printed_side(r, "derivees-gear#1"), d.g_r, gear_right(d.q_l, d.q_m, d.q_r, d.h)));
  add_goal(o, exact_on_quadratics("printed_exact", printed_side(r, "derivees-gear#0"), 0), true);
  add_goal(o, exact_on_quadratics("printed_exact", printed_side(r, "derivees-gear#1"), d.h), true);
  add_goal(o, exact_on_quadratics("core_exact", gear_left(d.q_l, d.q_m, d.q_r, d.h), 0), false);
  add_goal(o, exact_on_quadratics("core_exact", gear_right(d.q_l, d.q_m, d.q_r, d.h), d.h), false);
  return o;
}

printed_outcome centred_derivative_check(const paper_reading& r) {
  const symbolic_derivation& d = derivation();
  const ex core = centred_derivative(d.q_l, d.q_r, d.h);
  printed_outcome o = both(compare("(g_l + g_r)/2", with_gear(printed_side(r, "derivee-centree", 0), d), d.g_m, core),
                           compare("g_m", printed_side(r, "derivee-centree", 1), d.g_m, core));
  add_goal(o, exact_on_quadratics("printed_exact", printed_side(r, "derivee-centree", 1), d.h / 2), true);
  add_goal(o, exact_on_quadratics("core_exact", core, d.h / 2), false);
  return o;
}

printed_outcome interpolant_derivative(const paper_reading& r) {
  const symbolic_derivation& d = derivation();
  // dq/dt at t = h theta, for symbolic h.
  const ex derived = GiNaC::normal(d.velocity.subs(d.t == d.h * d.theta));
  const ex core = quadratic_interpolant_derivative(d.q_l, d.q_m, d.q_r, d.h, d.theta);
  return both(compare("dq/dt", printed_side(r, "dq/dt", 0), derived, core),
              compare("g_l (1 - theta) + g_r theta", with_gear(printed_side(r, "dq/dt", 1), d), derived, core));
}

printed_outcome simpson_lagrangian_check(const paper_reading& r) {
  const symbolic_derivation& d = derivation();
  const potential_function V = [&d](const ex& x) { return d.general_V(x); };
  return compare("L_h", with_gear(printed_side(r, "LLhh"), d), d.simpson_lagrangian(V),
                 simpson_lagrangian(d.m, d.h, V, d.q_l, d.q_m, d.q_r));
}

}  // namespace

void add_printed_checks_section2_4(check_registry& checks) {
  checks.add_printed("action-range", {"S_d"}, [](const paper_reading& r) { return action_range(r, "S_d", "S_d"); });
  checks.add_printed("classical-euler-lagrange", {"lagrangien-discret", "schema-ordre-deux"}, classical_euler_lagrange);
  checks.add_printed("classical-consistency", {"schema-ordre-deux", "oscillateur-nonlineaire"}, classical_consistency);
  checks.add_printed("hamilton-consistency", {"systeme-dynamique-discret-ordre-2#0", "systeme-dynamique-discret-ordre-2#1", "Hamilton dp/dt",
                                     "Hamilton dq/dt"}, hamilton_consistency);
  checks.add_printed("newmark-discrete-system", {"systeme-dynamique-discret-ordre-2#0", "systeme-dynamique-discret-ordre-2#1"}, newmark_system);
  checks.add_printed("newmark-matrix", {"matrice-symplectique-ordre-2"}, newmark_matrix);
  checks.add_printed("basis-nodal", {"fonctions-de-base#0", "fonctions-de-base#1", "fonctions-de-base#2", "q2t", "q(0)", "q(h/2)", "q(h)"}, interpolant_nodal);
  checks.add_printed("gear", {"derivees-gear#0", "derivees-gear#1"}, gear_derivatives);
  checks.add_printed("centred", {"derivee-centree"}, centred_derivative_check);
  checks.add_printed("interpolant-derivative", {"dq/dt"}, interpolant_derivative);
  checks.add_printed("simpson-lagrangian", {"LLhh"}, simpson_lagrangian_check);
  checks.add_printed("simpson-action-range", {"SSdd"}, [](const paper_reading& r) { return action_range(r, "SSdd", "Sigma_d"); });
}

}  // namespace simpson::verify::detail

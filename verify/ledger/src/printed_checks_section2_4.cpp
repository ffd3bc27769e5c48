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

}  // namespace

void add_printed_checks_section2_4(check_registry& checks) {
  checks.add_printed("action-range", {"S_d"}, [](const paper_reading& r) { return action_range(r, "S_d", "S_d"); });
  checks.add_printed("classical-euler-lagrange", {"lagrangien-discret", "schema-ordre-deux"}, classical_euler_lagrange);
  checks.add_printed("newmark-discrete-system", {"systeme-dynamique-discret-ordre-2#0", "systeme-dynamique-discret-ordre-2#1"}, newmark_system);
  checks.add_printed("newmark-matrix", {"matrice-symplectique-ordre-2"}, newmark_matrix);
  checks.add_printed("simpson-action-range", {"SSdd"}, [](const paper_reading& r) { return action_range(r, "SSdd", "Sigma_d"); });
}

}  // namespace simpson::verify::detail

// §2 as printed: L_d and its scheme, Newmark's discrete system and matrix (the other claims of
// §2–4 are proof shapes' records in claims/paper.toml).

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

}  // namespace

void add_printed_checks_section2_4(check_registry& checks) {
  checks.add_printed("classical-euler-lagrange", {"lagrangien-discret", "schema-ordre-deux"}, classical_euler_lagrange);
  checks.add_printed("newmark-discrete-system", {"systeme-dynamique-discret-ordre-2#0", "systeme-dynamique-discret-ordre-2#1"}, newmark_system);
}

}  // namespace simpson::verify::detail

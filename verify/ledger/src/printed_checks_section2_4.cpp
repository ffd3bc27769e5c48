// §2 as printed: Newmark's discrete system (the other claims of
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
  checks.add_printed("newmark-discrete-system", {"systeme-dynamique-discret-ordre-2#0", "systeme-dynamique-discret-ordre-2#1"}, newmark_system);
}

}  // namespace simpson::verify::detail

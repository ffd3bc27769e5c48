// Sections 4 to 6, where no proof shape decides yet: the derivation of Φ₃ from first principles in
// our kernel.

#include "claim_support.hpp"
#include "bespoke_checks.hpp"
#include "derivation_support.hpp"

#include <simpson/internal_node.hpp>
#include <simpson/reduced_lagrangian.hpp>
#include <simpson/simpson_elimination.hpp>
#include <simpson/simpson_lagrangian.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/three_term_scheme.hpp>

namespace simpson::verify::detail {
namespace {

/// Our kernel's route through the same derivation, in θ: L_h (simpson_lagrangian, Simpson's rule on
/// the quadratic interpolant) at the harmonic q_m is L_hʳ; q_m makes ∂L_h/∂q_m vanish; eliminating
/// q_{j-1} with p_r and the scheme gives Φ₃.
decider_evidence check_derivation_phi3(const run_context& ctx) {
  const proof steps = prove_zero_on_grid(
      std::string(unit_reduction) +
          "; dL_h/dq_m at q_m of (qm-oscillateur-harmonique), L_h^r - L_h at that q_m, and (Phi3) y - the state by "
          "eliminating q_{j-1}",
      {"q_l", "q_r"}, 2, [&](const auto& v) {
        using S = std::decay_t<decltype(v[0])>;
        const auto par = theta_oscillator<S>();
        const auto V = [&](const S& x) { return par.potential(x); };
        const auto force = [&](const S& x) { return par.force_gradient(x); };
        const S ql(v[0]), qr(v[1]);
        const S qm = harmonic_internal_node(par, ql, qr);
        const phase_point<S> y{ql, qr};  // a state (p_j, q_j) on the same grid
        const phase_point<S> by_formula = simpson_map(par) * y, by_elimination = simpson_step_by_elimination(par, y);
        return std::vector<S>{simpson_lagrangian_dq_mid(par.m(), par.h(), force, ql, qm, qr),
                                     reduced_lagrangian(par, ql, qr) - simpson_lagrangian(par.m(), par.h(), V, ql, qm, qr),
                                     by_formula.p - by_elimination.p, by_formula.q - by_elimination.q};
      }, ctx.memo);
  return identity(steps, "Our kernel checks the chain through the core's formulas; GiNaC performs each step itself (below).");
}

/// GiNaC's route, from first principles: Φ₃ as derived (each step in GiNaC) against the printed and the core's,
/// and T_h(q_j) of the derived scheme to O(h¹⁰).
printed_outcome derivation_phi3_printed(const paper_reading& r) {
  using GiNaC::ex;
  const symbolic_derivation& d = derivation();
  printed_outcome o = compare("Phi_3", printed_side(r, "Phi3"), d.phi3, as_matrix(simpson_map(parameters(d))));
  std::string steps;
  for (std::size_t k = 0; k < d.steps.size(); ++k) steps += (k ? "; " : "") + std::to_string(k + 1) + ") " + d.steps[k];
  const ex series = truncation_series(d, three_term_residual(parameters(d), d.q_prev, d.q_j, d.q_next), 10);
  o.derived += ". Steps: " + steps + ". T_h(q_j) of the derived scheme, normalised as (schema-ordre-3): " + text_of(series) + " + O(h^10)";
  return o;
}

}  // namespace

void add_section6_7_checks(check_registry& checks) {
  checks.add("derivation-phi3", check_derivation_phi3);
  checks.add_printed("derivation-phi3", {"Phi3"}, derivation_phi3_printed);
}

}  // namespace simpson::verify::detail

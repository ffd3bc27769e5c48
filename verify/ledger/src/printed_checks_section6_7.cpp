// §4–6 as printed, where no proof shape decides yet: Φ₃ against the end-to-end derivation.

#include "check_registry.hpp"
#include "printed_check_support.hpp"

#include <simpson/simpson_map.hpp>
#include <simpson/simpson_momentum.hpp>
#include <simpson/three_term_scheme.hpp>

namespace simpson::verify::detail {
namespace {

using GiNaC::ex;

/// The end-to-end derivation: Φ₃ as derived (each step in GiNaC) against the printed and the core's,
/// and T_h(q_j) of the derived scheme to O(h¹⁰).
printed_outcome derivation_phi3(const paper_reading& r) {
  const symbolic_derivation& d = derivation();
  printed_outcome o = compare("Phi_3", printed_side(r, "Phi3"), d.phi3, as_matrix(simpson_map(parameters(d))));
  std::string steps;
  for (std::size_t k = 0; k < d.steps.size(); ++k) steps += (k ? "; " : "") + std::to_string(k + 1) + ") " + d.steps[k];
  const ex series = truncation_series(d, three_term_residual(parameters(d), d.q_prev, d.q_j, d.q_next), 10);
  o.derived += ". Steps: " + steps + ". T_h(q_j) of the derived scheme, normalised as (schema-ordre-3): " + text_of(series) + " + O(h^10)";
  return o;
}

}  // namespace

void add_printed_checks_section6_7(check_registry& checks) {
  checks.add_printed("derivation-phi3", {"Phi3"}, derivation_phi3);
}

}  // namespace simpson::verify::detail

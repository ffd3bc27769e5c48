// §6–7 as printed, where no proof shape decides yet: Φ₃ against the end-to-end derivation, the singular
// case of Γ and the conserved form Q_c.

#include "check_registry.hpp"
#include "printed_check_support.hpp"

#include <simpson/quadratic_invariant.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/simpson_momentum.hpp>
#include <simpson/three_term_scheme.hpp>

namespace simpson::verify::detail {
namespace {

using GiNaC::ex;

/// H(Φ y) − H(y), normalised.
ex change_under(const ex& H, const ex& phi, const ex& p, const ex& q) { return GiNaC::normal(after_step(H, phi, p, q) - H); }


/// Γ derived: the coefficients of p², pq, q² in Q(Φy) − Q(y), Φ = ((α, β), (γ, δ)), as a matrix acting on (ξ, η, ζ).
GiNaC::matrix derived_gamma() {
  const ex a = sym("alpha"), b = sym("beta"), c = sym("gamma"), dd = sym("delta"), p = sym("p"), q = sym("q");
  const ex xi = sym("xi"), eta = sym("eta"), zeta = sym("zeta");
  const auto Q = [&](const ex& pp, const ex& qq) { return xi * pp * pp / 2 + eta * pp * qq + zeta * qq * qq / 2; };
  const ex change = GiNaC::expand(Q(a * p + b * q, c * p + dd * q) - Q(p, q));
  const ex rows[] = {change.coeff(p, 2).coeff(q, 0), change.coeff(p, 1).coeff(q, 1), change.coeff(p, 0).coeff(q, 2)};
  const ex unknowns[] = {xi, eta, zeta};
  GiNaC::matrix g(3, 3);
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) g(i, j) = GiNaC::expand(rows[i]).coeff(unknowns[j], 1);
  }
  return g;
}

/// The determinant of a 3 × 3 matrix by its first row's cofactors, as written.
ex determinant_3x3(const GiNaC::matrix& M) {
  return M(0, 0) * (M(1, 1) * M(2, 2) - M(1, 2) * M(2, 1)) - M(0, 1) * (M(1, 0) * M(2, 2) - M(1, 2) * M(2, 0)) +
         M(0, 2) * (M(1, 0) * M(2, 1) - M(1, 1) * M(2, 0));
}

/// The printed Γ as a matrix: the coefficients of ξ, η, ζ in the printed Γ (ξ, η, ζ)ᵀ.
GiNaC::matrix printed_gamma(const paper_reading& r) {
  const ex product = printed_side(r, "Gamma").evalm();
  GiNaC::matrix g(3, 3);
  if (!GiNaC::is_a<GiNaC::matrix>(product) || GiNaC::ex_to<GiNaC::matrix>(product).rows() != 3) return g;
  const GiNaC::matrix& column = GiNaC::ex_to<GiNaC::matrix>(product);
  const GiNaC::symbol* unknowns[] = {&GiNaC::ex_to<GiNaC::symbol>(sym("xi")), &GiNaC::ex_to<GiNaC::symbol>(sym("eta")),
                                     &GiNaC::ex_to<GiNaC::symbol>(sym("zeta"))};
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) g(i, j) = GiNaC::normal(column(i, 0).diff(*unknowns[j]));
  }
  return g;
}

/// The paper's own example of its hypotheses (α = δ, det Φ = 1): α = δ = 1/2, β = −1, γ = 3/4.
GiNaC::exmap hypotheses_substitution() {
  return {{sym("alpha"), GiNaC::numeric(1, 2)}, {sym("beta"), -1}, {sym("gamma"), GiNaC::numeric(3, 4)}, {sym("delta"), GiNaC::numeric(1, 2)}};
}

/// "det Γ vanishes when αδ − βγ = 1", judged for the Γ the paper prints: its determinant on
/// δ = (1 + βγ)/α, against the derived (corrected) Γ's.
printed_outcome gamma_singular(const paper_reading& r) {
  const ex on_unit = sym("delta") == (1 + sym("beta") * sym("gamma")) / sym("alpha");
  const GiNaC::matrix gamma = printed_gamma(r);
  const ex printed = GiNaC::normal(gamma.determinant().subs(on_unit));
  const ex derived = GiNaC::normal(derived_gamma().determinant().subs(on_unit));
  const ex product = GiNaC::normal(printed_side(r, "det Gamma").subs(on_unit));
  printed_outcome o;
  o.holds = printed.is_zero();
  o.goals.push_back({"printed", determinant_3x3(gamma).subs(on_unit), 0, o.holds});
  o.proved = "det of the printed Gamma at delta = (1 + beta gamma)/alpha: " + text_of(printed) + " (at alpha = delta = 1/2, beta = -1, "
             "gamma = 3/4: " + text_of(GiNaC::normal(gamma.determinant().subs(hypotheses_substitution()))) + "); the printed product there: " +
             text_of(product);
  if (!o.holds) {
    o.correction = "det Gamma vanishes on alpha delta - beta gamma = 1 for the corrected Gamma (last entry (delta^2 - 1)/2, "
                   "gamma-system); the printed Gamma's determinant does not (" + text_of(GiNaC::normal(gamma.determinant().subs(hypotheses_substitution()))) +
                   " at alpha = delta = 1/2, beta = -1, gamma = 3/4), although the printed product, which is not its determinant, does";
  }
  o.derived_holds = derived.is_zero();
  o.goals.push_back({"derived", determinant_3x3(derived_gamma()).subs(on_unit), 0, o.derived_holds});
  o.derived = "derived det Gamma at delta = (1 + beta gamma)/alpha: " + text_of(derived);
  return o;
}

/// "When α = δ, we obtain η = 0 and Q_c = γp²/2 − βq²/2", judged as printed: the printed Q_c's
/// coefficients (ξ, η, ζ) must solve the printed Γ's system (α = δ, γ = (α² − 1)/β), and Q_c must be
/// conserved. The derived side: the corrected Γ's kernel holds (γ, 0, −β), and Q_c is conserved.
printed_outcome conserved_form(const paper_reading& r) {
  const ex a = sym("alpha"), b = sym("beta"), p = sym("p"), q = sym("q");
  const GiNaC::lst hypotheses{sym("gamma") == (a * a - 1) / b, sym("delta") == a};
  const GiNaC::matrix phi{{a, b}, {(a * a - 1) / b, a}};
  const ex printed_qc = printed_side(r, "Q_c").subs(hypotheses);
  const ex change = change_under(printed_qc, phi, p, q);
  // The printed Q_c as (ξ, η, ζ): Q = ξ p²/2 + η p q + ζ q²/2.
  const ex expanded = GiNaC::expand(printed_qc);
  const GiNaC::matrix coefficients{
      {2 * expanded.coeff(p, 2).coeff(q, 0)}, {expanded.coeff(p, 1).coeff(q, 1)}, {2 * expanded.coeff(q, 2).coeff(p, 0)}};
  const ex printed_system = normal_difference(ex(printed_gamma(r)).subs(hypotheses).evalm() * coefficients, GiNaC::matrix(3, 1));
  const ex printed_det = GiNaC::normal(printed_gamma(r).determinant().subs(hypotheses));
  printed_outcome o;
  o.holds = is_zero_expression(printed_system) && change.is_zero();
  o.goals.push_back({"printed", after_step(printed_qc, phi, p, q), printed_qc, change.is_zero()});
  o.goals.push_back({"printed", (ex(printed_gamma(r)).subs(hypotheses).evalm() * coefficients).evalm(), GiNaC::matrix(3, 1),
                     is_zero_expression(printed_system)});
  o.proved = "printed Gamma (xi, eta, zeta)^T of the printed Q_c, with delta = alpha, gamma = (alpha^2 - 1)/beta: " + text_of(printed_system) +
             "; det of the printed Gamma there: " + text_of(printed_det) +
             (printed_det.is_zero() ? "" : " (nonzero: only xi = eta = zeta = 0 solves it)") + "; printed Q_c(Phi y) - Q_c(y): " + text_of(change);
  if (!o.holds) {
    o.correction = "eta = 0 and Q_c = gamma p^2/2 - beta q^2/2 follow from the corrected Gamma (last entry (delta^2 - 1)/2, "
                   "gamma-system), whose kernel is spanned by (gamma, 0, -beta); Q_c is conserved (Q_c(Phi y) - Q_c(y) = " + text_of(change) + ")";
  }
  const auto c = conserved_form_coefficients(one_step_matrix<ex>{a, b, (a * a - 1) / b, a});
  const GiNaC::matrix core_coefficients{{c[0]}, {c[1]}, {c[2]}};
  const ex in_kernel = normal_difference(ex(derived_gamma()).subs(hypotheses).evalm() * core_coefficients, GiNaC::matrix(3, 1));
  o.derived_holds = is_zero_expression(in_kernel);
  o.derived = "derived Gamma x core (gamma, 0, -beta)^T = " + text_of(in_kernel);
  return o;
}

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
  checks.add_printed("gamma-singular", {"Gamma", "det Gamma"}, gamma_singular);
  checks.add_printed("conserved-form", {"Gamma", "Q_c"}, conserved_form);
}

}  // namespace simpson::verify::detail

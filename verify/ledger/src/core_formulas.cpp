// The core's formulas that the paper prints (core_formulas.hpp): the core's templates instantiated
// with GiNaC expressions, the paper's symbols standing for m, ω, h and the variables. Each line
// names the template, the label its comment gives, and its variables in order.

#include "core_formulas.hpp"

#include <simpson/classical_lagrangian.hpp>
#include <simpson/energy.hpp>
#include <simpson/internal_node.hpp>
#include <simpson/newmark_map.hpp>
#include <simpson/quadratic_interpolation.hpp>
#include <simpson/quadratic_invariant.hpp>
#include <simpson/reduced_lagrangian.hpp>
#include <simpson/simpson_lagrangian.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/simpson_momentum.hpp>
#include <simpson/three_term_scheme.hpp>

#include "derivation_support.hpp"

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

oscillator_parameters<ex> oscillator_of(const core_arguments& a) { return {a.m, a.omega, a.h}; }

const ex& argument_at(const core_arguments& a, std::size_t k) { return a.variables.at(k); }

/// The map ((α, β), (γ, δ)) of Section 7 from the first four variables.
one_step_matrix<ex> generic_map(const core_arguments& a) { return {argument_at(a, 0), argument_at(a, 1), argument_at(a, 2), argument_at(a, 3)}; }

}  // namespace

const std::vector<core_formula>& core_formulas() {
  // Each line: the core's template, the label its comment names, its variables, and the call.
  static const std::vector<core_formula> all{
      {"classical_lagrangian", "lagrangien-discret", {"q_l", "q_r"}, "L_d(q_l, q_r), the midpoint rule's discrete Lagrangian",
       [](const core_arguments& a) { return classical_lagrangian(a.m, a.h, a.potential, argument_at(a, 0), argument_at(a, 1)); }},
      {"classical_scheme_residual", "schema-ordre-deux", {"q_{j-1}", "q_j", "q_{j+1}"}, "the second-order scheme's left side",
       [](const core_arguments& a) { return classical_scheme_residual(a.m, a.h, a.force_gradient, argument_at(a, 0), argument_at(a, 1), argument_at(a, 2)); }},
      {"classical_momentum", "moment", {"q_l", "q_r"}, "p_r = dL_d/dq_r",
       [](const core_arguments& a) { return classical_momentum(a.m, a.h, a.force_gradient, argument_at(a, 0), argument_at(a, 1)); }},
      {"newmark_map", "matrice-symplectique-ordre-2", {}, "Newmark's (implicit midpoint) one-step map on (p, q)",
       [](const core_arguments& a) { return ex(as_matrix(newmark_map(oscillator_of(a)))); }},
      {"energy", "HH-exact", {"p", "q"}, "H = p^2/(2m) + m omega^2 q^2/2",
       [](const core_arguments& a) { return energy(oscillator_of(a), phase_point<ex>{argument_at(a, 0), argument_at(a, 1)}); }},
      {"basis_phi0", "fonctions-de-base", {"s"}, "phi_0(s)", [](const core_arguments& a) { return basis_phi0(argument_at(a, 0)); }},
      {"basis_phi_half", "fonctions-de-base", {"s"}, "phi_{1/2}(s)", [](const core_arguments& a) { return basis_phi_half(argument_at(a, 0)); }},
      {"basis_phi1", "fonctions-de-base", {"s"}, "phi_1(s)", [](const core_arguments& a) { return basis_phi1(argument_at(a, 0)); }},
      {"quadratic_interpolant", "q2t", {"q_l", "q_m", "q_r", "s"}, "q at t = h s",
       [](const core_arguments& a) { return quadratic_interpolant(argument_at(a, 0), argument_at(a, 1), argument_at(a, 2), argument_at(a, 3)); }},
      {"gear_left", "derivees-gear", {"q_l", "q_m", "q_r"}, "g_l = dq/dt(0)",
       [](const core_arguments& a) { return gear_left(argument_at(a, 0), argument_at(a, 1), argument_at(a, 2), a.h); }},
      {"gear_right", "derivees-gear", {"q_l", "q_m", "q_r"}, "g_r = dq/dt(h)",
       [](const core_arguments& a) { return gear_right(argument_at(a, 0), argument_at(a, 1), argument_at(a, 2), a.h); }},
      {"centred_derivative", "derivee-centree", {"q_l", "q_r"}, "g_m = dq/dt(h/2)",
       [](const core_arguments& a) { return centred_derivative(argument_at(a, 0), argument_at(a, 1), a.h); }},
      {"simpson_lagrangian", "LLhh", {"q_l", "q_m", "q_r"}, "L_h(q_l, q_m, q_r), Simpson's rule on the quadratic interpolant",
       [](const core_arguments& a) { return simpson_lagrangian(a.m, a.h, a.potential, argument_at(a, 0), argument_at(a, 1), argument_at(a, 2)); }},
      {"simpson_lagrangian_dq_mid", "the inline dL_h/dq_m = ... (Section 5)", {"q_l", "q_m", "q_r"}, "dL_h/dq_m, before the internal node's equation",
       [](const core_arguments& a) { return simpson_lagrangian_dq_mid(a.m, a.h, a.force_gradient, argument_at(a, 0), argument_at(a, 1), argument_at(a, 2)); }},
      {"internal_equation_residual", "equation-milieu-intervalle", {"q_l", "q_m", "q_r"}, "the internal node's equation, its left side",
       [](const core_arguments& a) { return internal_equation_residual(a.m, a.h, a.force_gradient, argument_at(a, 0), argument_at(a, 1), argument_at(a, 2)); }},
      {"harmonic_internal_node", "qm-oscillateur-harmonique", {"q_l", "q_r"}, "q_m for the harmonic oscillator",
       [](const core_arguments& a) { return harmonic_internal_node(oscillator_of(a), argument_at(a, 0), argument_at(a, 1)); }},
      {"reduced_lagrangian", "Lagrangien-reduit", {"q_l", "q_r"}, "L_h^r(q_l, q_r)",
       [](const core_arguments& a) { return reduced_lagrangian(oscillator_of(a), argument_at(a, 0), argument_at(a, 1)); }},
      {"three_term_residual", "schema-ordre-3", {"q_{j-1}", "q_j", "q_{j+1}"}, "the three-term scheme's left side",
       [](const core_arguments& a) { return three_term_residual(oscillator_of(a), argument_at(a, 0), argument_at(a, 1), argument_at(a, 2)); }},
      {"characteristic_polynomial.a", "the inline a = ... (Section 5)", {}, "a of a r^2 + b r + c, x = omega^2 h^2",
       [](const core_arguments& a) { return characteristic_polynomial(ex(a.omega * a.omega * a.h * a.h)).a; }},
      {"characteristic_polynomial.b", "the inline b = ... (Section 5)", {}, "b of a r^2 + b r + c, as printed",
       [](const core_arguments& a) { return characteristic_polynomial(ex(a.omega * a.omega * a.h * a.h)).b; }},
      {"discriminant_factorized", "the display after 'can be factorized' (Section 5)", {}, "Delta as printed factored, x = omega^2 h^2",
       [](const core_arguments& a) { return discriminant_factorized(ex(a.omega * a.omega * a.h * a.h)); }},
      {"simpson_momentum", "moment-ordre-3", {"q_l", "q_r"}, "p_r = dL_h^r/dq_r",
       [](const core_arguments& a) { return simpson_momentum(oscillator_of(a), argument_at(a, 0), argument_at(a, 1)); }},
      {"quadratic_form", "forme-quadratique", {"xi", "eta", "zeta", "p", "q"}, "Q(p, q) = xi p^2/2 + eta p q + zeta q^2/2",
       [](const core_arguments& a) { return quadratic_form(argument_at(a, 0), argument_at(a, 1), argument_at(a, 2), phase_point<ex>{argument_at(a, 3), argument_at(a, 4)}); }},
      {"invariance_system", "the display of Gamma (xi, eta, zeta)^T (Section 7)", {"alpha", "beta", "gamma", "delta", "xi", "eta", "zeta"},
       "Gamma (xi, eta, zeta)^T: Q(Phi y) = Q(y) for all y exactly when it is 0",
       [](const core_arguments& a) {
         const auto g = invariance_system(generic_map(a));
         GiNaC::matrix out(3, 1);
         for (unsigned r = 0; r < 3; ++r) out(r, 0) = g[r][0] * argument_at(a, 4) + g[r][1] * argument_at(a, 5) + g[r][2] * argument_at(a, 6);
         return ex(out);
       }},
      {"invariance_system_determinant", "the inline det Gamma = ... (Section 7)", {"alpha", "beta", "gamma", "delta"}, "det Gamma",
       [](const core_arguments& a) { return invariance_system_determinant(generic_map(a)); }},
      {"conserved_form_coefficients", "the inline Q_c(p, q) = ... (Section 7)", {"alpha", "beta", "gamma", "delta", "p", "q"},
       "Q_c = gamma p^2/2 - beta q^2/2, as the form of its coefficients",
       [](const core_arguments& a) {
         const auto c = conserved_form_coefficients(generic_map(a));
         return quadratic_form(c[0], c[1], c[2], phase_point<ex>{argument_at(a, 4), argument_at(a, 5)});
       }},
      {"simpson_map", "Phi3", {}, "Phi_3, the scheme's one-step map on (p, q)",
       [](const core_arguments& a) { return ex(as_matrix(simpson_map(oscillator_of(a)))); }},
      {"discrete_energy", "hamiltonien-discret", {"p", "q"}, "H_d, the conserved discrete energy",
       [](const core_arguments& a) { return discrete_energy(oscillator_of(a), phase_point<ex>{argument_at(a, 0), argument_at(a, 1)}); }},
  };
  return all;
}

const core_formula* find_core_formula(const std::string& name) {
  for (const core_formula& f : core_formulas()) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

}  // namespace simpson::verify::detail

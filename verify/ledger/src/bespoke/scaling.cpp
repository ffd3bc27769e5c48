// The scaling lemma the exact proofs rest on: with p scaled by m ω and t by ω every result depends
// on θ = ωh alone, so the exact proofs take m = ω = 1, h = θ.

#include "bespoke_checks.hpp"
#include "claim_support.hpp"
#include "derivation_support.hpp"

#include <simpson/classical_lagrangian.hpp>
#include <simpson/energy.hpp>
#include <simpson/internal_node.hpp>
#include <simpson/newmark_map.hpp>
#include <simpson/reduced_lagrangian.hpp>
#include <simpson/simpson_lagrangian.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/simpson_momentum.hpp>
#include <simpson/three_term_scheme.hpp>

#include <ginac/ginac.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace simpson::verify::detail {
namespace {

decider_evidence check_scaling(const run_context& ctx) {
  // h = θ/ω with θ symbolic and m, ω, p, q on a grid. Each quantity is m^a ω^b h^c F(ω²h²) with
  // |a|, |b|, |c| <= 2, so (mω)² × gap is a polynomial of degree <= 4 in m and in ω, and of degree
  // <= 2 in p and q.
  const proof p = prove_zero_on_grid(
      "h = theta/omega; (m omega)^2 times: Phi_3 and Phi entries minus S Phi(1, 1, theta) S^-1 with S = diag(m omega, 1); "
      "H_d and H minus m omega^2 times their unit values at (p/(m omega), q); (schema-ordre-3) minus omega^2 times its "
      "unit value",
      {"m", "omega", "p", "q"}, std::vector<int>{4, 4, 2, 2}, [&](const auto& v) {
        using S = std::decay_t<decltype(v[0])>;
        const S theta = theta_variable<S>();
        const oscillator_parameters<S> unit = theta_oscillator<S>();
        const S m(v[0]), w(v[1]), p(v[2]), q(v[3]);
        const oscillator_parameters<S> par{m, w, S(theta / w)};
        const S mw = m * w, clear = mw * mw;
        std::vector<S> gaps;
        for (const bool simpson_scheme : {true, false}) {
          const one_step_matrix<S> full = simpson_scheme ? simpson_map(par) : newmark_map(par);
          const one_step_matrix<S> reduced = simpson_scheme ? simpson_map(unit) : newmark_map(unit);
          gaps.push_back(clear * (full.alpha - reduced.alpha));
          gaps.push_back(clear * (full.beta - mw * reduced.beta));
          gaps.push_back(clear * (full.gamma - reduced.gamma / mw));
          gaps.push_back(clear * (full.delta - reduced.delta));
        }
        const phase_point<S> y{p, q}, scaled{S(p / mw), q};
        gaps.push_back(clear * (discrete_energy(par, y) - m * w * w * discrete_energy(unit, scaled)));
        gaps.push_back(clear * (energy(par, y) - m * w * w * energy(unit, scaled)));
        gaps.push_back(clear * (three_term_residual(par, p, q, p + q) - w * w * three_term_residual(unit, p, q, p + q)));
        return gaps;
      }, ctx.memo);
  // The formulas the other proofs evaluate at m = omega = 1 as well, with (q_l, q_r) = (p, q): q_m is
  // invariant, p_r and the Lagrangians scale by m omega. The elimination route of Section 6 solves
  // p_j = p_r(q_{j-1}, q_j) and (schema-ordre-3) and evaluates p_r: built from p_r and the scheme
  // alone, both covered, it scales as Phi_3 does (and phi3-elimination proves it equal to Phi_3
  // in GiNaC with every symbol free). Each is (m omega)^a F(theta) with |a| <= 1, so
  // m omega × gap has degree <= 2 in m and in omega, and <= 2 in p and q. The unit values depend on
  // (p, q) only and are computed once per pair.
  const auto unit_values_at = [](const auto& p, const auto& q) {
    using S = std::decay_t<decltype(p)>;
    const S theta = theta_variable<S>();
    const oscillator_parameters<S> unit = theta_oscillator<S>();
    const auto V = [&](const S& x) { return unit.potential(x); };
    const auto force = [&](const S& x) { return unit.force_gradient(x); };
    return std::vector<S>{harmonic_internal_node(unit, p, q), simpson_momentum(unit, p, q), reduced_lagrangian(unit, p, q),
                          simpson_lagrangian(S(1), theta, V, p, S(p + q), q), classical_lagrangian(S(1), theta, V, p, q),
                          classical_momentum(S(1), theta, force, p, q)};
  };
  std::map<std::pair<std::string, std::string>, std::vector<symbolic>> unit_values;
  const auto unit_at = [&](const auto& p, const auto& q) {
    using S = std::decay_t<decltype(p)>;
    if constexpr (is_ginac_v<S>) {
      return unit_values_at(p, q);
    } else {
      const auto key = std::make_pair(to_string(p.numerator(), "θ"), to_string(q.numerator(), "θ"));
      auto it = unit_values.find(key);
      if (it == unit_values.end()) it = unit_values.emplace(key, unit_values_at(p, q)).first;
      return it->second;
    }
  };
  const proof extended = prove_zero_on_grid(
      "h = theta/omega; m omega times: q_m (qm-oscillateur-harmonique) minus its unit value; p_r (moment-ordre-3), L_h^r "
      "(Lagrangien-reduit), L_h (LLhh, harmonic V), L_d (lagrangien-discret) and its momentum minus m omega times their unit "
      "values, at (q_l, q_r) = (p, q)",
      {"m", "omega", "p", "q"}, std::vector<int>{2, 2, 2, 2}, [&](const auto& v) {
        using S = std::decay_t<decltype(v[0])>;
        const S m(v[0]), w(v[1]), p(v[2]), q(v[3]);
        const oscillator_parameters<S> par{m, w, S(theta_variable<S>() / w)};
        const S mw = m * w;
        const auto V = [&](const S& x) { return par.potential(x); };
        const auto force = [&](const S& x) { return par.force_gradient(x); };
        const std::vector<S> u = unit_at(p, q);
        return std::vector<S>{mw * (harmonic_internal_node(par, p, q) - u[0]), mw * (simpson_momentum(par, p, q) - mw * u[1]),
                                     mw * (reduced_lagrangian(par, p, q) - mw * u[2]),
                                     mw * (simpson_lagrangian(m, par.h(), V, p, S(p + q), q) - mw * u[3]),
                                     mw * (classical_lagrangian(m, par.h(), V, p, q) - mw * u[4]),
                                     mw * (classical_momentum(m, par.h(), force, p, q) - mw * u[5])};
      }, ctx.memo);
  json evidence = json::object();
  evidence["exact"] = json::array({p.evidence, extended.evidence});
  return confirmed_if(p.proved && extended.proved, evidence,
                      "With p scaled by m omega and t by omega every result depends on theta = omega h alone; the exact "
                      "proofs therefore take m = omega = 1, h = theta.");
}

/// The reduction every exact proof of our kernel uses: with S = diag(mω, 1), Φ(m, ω, h) =
/// S Φ(1, 1, ωh) S⁻¹ for Φ₃ and Newmark's Φ, and H_d(m, ω, h; p, q) = mω² H_d(1, 1, ωh; p/(mω), q).
std::vector<proof_goal> dimensional_scaling() {
  using GiNaC::ex;
  const symbolic_derivation& d = derivation();
  const oscillator_parameters<ex> unit{1, 1, d.omega * d.h};
  const GiNaC::matrix S{{d.m * d.omega, 0}, {0, 1}}, S_inverse{{1 / (d.m * d.omega), 0}, {0, 1}};
  const auto scaled = [&](const one_step_matrix<ex>& at_unit) { return S.mul(as_matrix(at_unit)).mul(S_inverse); };
  return {decided("phi3", scaled(simpson_map(unit)), as_matrix(simpson_map(parameters(d)))),
          decided("newmark", scaled(newmark_map(unit)), as_matrix(newmark_map(parameters(d)))),
          decided("discrete_energy", discrete_energy(parameters(d), phase_point<ex>{d.p, d.q}),
                  d.m * d.omega * d.omega * discrete_energy(unit, phase_point<ex>{d.p / (d.m * d.omega), d.q}))};
}

}  // namespace

void add_scaling_lemma_check(check_registry& checks) {
  checks.add("scaling", check_scaling);
  checks.add_coq_goals("scaling", dimensional_scaling);
}

}  // namespace simpson::verify::detail

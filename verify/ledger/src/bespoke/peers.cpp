// A finding the paper does not print: how Φ₃ relates to the schemes a user would pick instead.
// Each peer's one-step matrix on the oscillator is compared with Φ₃ exactly: in rational
// functions of θ = ωh where its coefficients are rational, in power series of θ over Q(√3) or
// Q(∛2) where they are not.

#include <simpson/verify/algebraic_series.hpp>
#include "claim_support.hpp"
#include "bespoke_checks.hpp"

#include <simpson/newmark_map.hpp>
#include <simpson/runge_kutta_tableaux.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/stormer_verlet.hpp>

#include <cmath>
#include <map>

namespace simpson::verify::detail {
namespace {

constexpr int series_order = 12;

/// The exact flow's matrix at m = ω = 1 as series: ((cos θ, −sin θ), (sin θ, cos θ)).
template <class Series>
one_step_matrix<Series> exact_flow_series() {
  Series c(0), s(0), power(1);
  const Series theta = Series::variable();
  for (int k = 0; k <= series_order; ++k) {
    rational inverse_factorial(1);
    for (int j = 2; j <= k; ++j) inverse_factorial /= j;
    const int sign = (k / 2) % 2 == 0 ? 1 : -1;
    if (k % 2 == 0) {
      c += Series(rational(sign) * inverse_factorial) * power;
    } else {
      s += Series(rational(sign) * inverse_factorial) * power;
    }
    power *= theta;
  }
  return {c, -s, s, c};
}

/// The lowest power of θ with a non-zero coefficient in any entry, or -1 when all vanish through
/// series_order; with each entry's coefficient at that power.
template <class Series>
json leading_term(const one_step_matrix<Series>& d, const std::string& root_name) {
  for (int k = 0; k <= series_order; ++k) {
    const std::array<const Series*, 4> entries{&d.alpha, &d.beta, &d.gamma, &d.delta};
    bool any = false;
    for (const Series* e : entries) any = any || !(*e)[k].is_zero();
    if (!any) continue;
    return json{{"order", k},
                {"alpha", d.alpha[k].to_string(root_name)},
                {"beta", d.beta[k].to_string(root_name)},
                {"gamma", d.gamma[k].to_string(root_name)},
                {"delta", d.delta[k].to_string(root_name)}};
  }
  return json{{"order", "none through theta^" + std::to_string(series_order)}};
}

template <class Series>
one_step_matrix<Series> difference(const one_step_matrix<Series>& a, const one_step_matrix<Series>& b) {
  return {a.alpha - b.alpha, a.beta - b.beta, a.gamma - b.gamma, a.delta - b.delta};
}

/// Compares one peer's matrix with Φ₃ and with the exact flow, at m = ω = 1 (every one-step map of
/// a Runge–Kutta or composition method commutes with the scaling of the scaling lemma).
template <class Series>
json compare_with_phi3(const std::string& peer, const std::string& field, const std::string& root_name,
                       const one_step_matrix<Series>& peer_map, int& order_of_difference) {
  const oscillator_parameters<Series> unit{Series(1), Series(1), Series::variable()};
  const one_step_matrix<Series> phi3 = simpson_map(unit);
  const json to_phi3 = leading_term(difference(peer_map, phi3), root_name);
  const json to_flow = leading_term(difference(peer_map, exact_flow_series<Series>()), root_name);
  const Series det_minus_one = determinant(peer_map) - Series(1);
  int det_order = -1;
  for (int k = 0; k <= series_order && det_order < 0; ++k) {
    if (!det_minus_one[k].is_zero()) det_order = k;
  }
  order_of_difference = to_phi3["order"].is_number() ? to_phi3["order"].get<int>() : -1;
  return json{{"peer", peer},
              {"coefficients_in", field},
              {"peer_minus_phi3_leading_term", to_phi3},
              {"peer_minus_exact_flow_leading_term", to_flow},
              {"method_order", to_flow["order"].is_number() ? json(to_flow["order"].get<int>() - 1) : json("exact")},
              {"det_minus_one", det_order < 0 ? json("0 through theta^" + std::to_string(series_order))
                                              : json("theta^" + std::to_string(det_order) + " coefficient " +
                                                     det_minus_one[det_order].to_string(root_name))}};
}

decider_evidence check_peer_schemes(const run_context& ctx) {
  using rational_series = truncated_series<number_field_element<1, 1>, series_order>;
  using sqrt3_series = truncated_series<number_field_element<2, 3>, series_order>;
  using cbrt2_series = truncated_series<number_field_element<3, 2>, series_order>;
  json peers = json::array();
  std::map<std::string, int> orders;
  int order = 0;
  {
    const oscillator_parameters<rational_series> unit{rational_series(1), rational_series(1), rational_series::variable()};
    peers.push_back(compare_with_phi3("Newmark (implicit midpoint)", "Q", "", newmark_map(unit), order));
    orders["newmark"] = order;
    peers.push_back(compare_with_phi3("Stormer-Verlet", "Q", "", stormer_verlet_map(unit), order));
    orders["stormer-verlet"] = order;
    peers.push_back(compare_with_phi3("classic RK4", "Q", "",
                                      partitioned_runge_kutta_map(unit, classic_rk4_tableau<rational_series>(),
                                                                  classic_rk4_tableau<rational_series>()),
                                      order));
    orders["rk4"] = order;
    peers.push_back(compare_with_phi3("Lobatto IIIA-IIIB, 3 stages (IIIA for q, IIIB for p)", "Q", "",
                                      partitioned_runge_kutta_map(unit, lobatto_iiia3_tableau<rational_series>(),
                                                                  lobatto_iiib3_tableau<rational_series>()),
                                      order));
    orders["lobatto"] = order;
    peers.push_back(compare_with_phi3("Lobatto IIIB-IIIA, 3 stages (IIIB for q, IIIA for p)", "Q", "",
                                      partitioned_runge_kutta_map(unit, lobatto_iiib3_tableau<rational_series>(),
                                                                  lobatto_iiia3_tableau<rational_series>()),
                                      order));
    orders["lobatto-swapped"] = order;
  }
  {
    const oscillator_parameters<sqrt3_series> unit{sqrt3_series(1), sqrt3_series(1), sqrt3_series::variable()};
    const auto tableau = gauss_legendre2_tableau(sqrt3_series(number_field_element<2, 3>::root()));
    peers.push_back(compare_with_phi3("Gauss-Legendre, 2 stages", "Q(sqrt 3)", "sqrt3",
                                      partitioned_runge_kutta_map(unit, tableau, tableau), order));
    orders["gauss-legendre"] = order;
  }
  {
    const oscillator_parameters<cbrt2_series> unit{cbrt2_series(1), cbrt2_series(1), cbrt2_series::variable()};
    peers.push_back(compare_with_phi3("Yoshida / Forest-Ruth composition of Stormer-Verlet", "Q(cbrt 2)", "cbrt2",
                                      yoshida_map(unit, yoshida_weights(cbrt2_series(number_field_element<3, 2>::root()))),
                                      order));
    orders["yoshida"] = order;
  }

  // The identity with Lobatto IIIA–IIIB, beyond any order: rational functions of θ, with m and ω
  // on a grid ((mω)² times each gap is a polynomial of degree <= 4 in m and in ω).
  const proof lobatto = prove_zero_on_grid(
      "h = theta/omega; (m omega)^2 times each entry of Phi_Lobatto(IIIA for q, IIIB for p, 3 stages) minus Phi_3",
      {"m", "omega"}, 4, [&](const auto& v) {
        using S = std::decay_t<decltype(v[0])>;
        const S m(v[0]), w(v[1]), clear = m * w * m * w;
        const oscillator_parameters<S> par{m, w, S(theta_variable<S>() / w)};
        const one_step_matrix<S> a = partitioned_runge_kutta_map(par, lobatto_iiia3_tableau<S>(), lobatto_iiib3_tableau<S>());
        const one_step_matrix<S> b = simpson_map(par);
        return std::vector<S>{clear * (a.alpha - b.alpha), clear * (a.beta - b.beta), clear * (a.gamma - b.gamma),
                              clear * (a.delta - b.delta)};
      }, ctx.memo);

  // Numeric: the Lobatto stage algorithm against Φ₃ y at random (m, ω, h, p, q). Both sum terms of
  // size (|q| + h|p|/m)(1 + x/|1 − x/8|) (the stage system is singular at x = ω²h² = 8, where Φ₃'s
  // intermediate quantities are) over ~60 roundings: 256 eps times that scale.
  bool within = false;
  const json numeric = recheck_with(ctx, "peer-lobatto", [](const auto& par, const auto& y) {
    using Real = std::decay_t<decltype(y.p)>;
    using std::abs;
    const phase_point<Real> a = simpson_map(par) * y;
    const phase_point<Real> b =
        partitioned_runge_kutta_step(par, lobatto_iiia3_tableau<Real>(), lobatto_iiib3_tableau<Real>(), y);
    const Real x = par.omega2_h2();
    const Real scale = (abs(y.q) + abs(a.q) + par.h() * abs(y.p) / par.m()) * (1 + x / abs(Real(1 - x / 8)));
    return residual_and_bound<Real>{Real(abs(Real(a.q - b.q)) + par.h() / par.m() * abs(Real(a.p - b.p))),
                                    Real(256 * eps<Real>() * scale)};
  }, within);

  json evidence;
  evidence["exact"] = lobatto.evidence;
  evidence["exact"]["peers"] = peers;
  evidence["numeric"] = numeric;
  const bool others_differ = orders["newmark"] == 3 && orders["stormer-verlet"] == 3 && orders["rk4"] == 5 &&
                             orders["gauss-legendre"] == 5 && orders["yoshida"] == 5 && orders["lobatto-swapped"] == 5 &&
                             orders["lobatto"] == -1;
  return confirmed_if(lobatto.proved && others_differ && within, evidence,
                      "Phi_3 is the 3-stage Lobatto IIIA-IIIB method (Jay 1996; Marsden and West 2001 show that Galerkin "
                      "variational integrators with Lobatto quadrature are exactly these pairs). That pair is defined for "
                      "any force, so the nonlinear extension that Section 9 leaves open exists: an implicit stage system "
                      "replaces the explicit elimination.");
}

}  // namespace

void add_peer_checks(check_registry& checks) {
  checks.add("peer-schemes", check_peer_schemes);
}

}  // namespace simpson::verify::detail

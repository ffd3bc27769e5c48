// One member of the Galerkin family, derived and analysed (galerkin_member.hpp).

#include <simpson/verify/galerkin_member.hpp>

#include "family_algebra.hpp"
#include <simpson/verify/partitioned_pair.hpp>

#include <simpson/verify/exact_proof.hpp>
#include <simpson/verify/stability_analysis.hpp>

#include <simpson/newmark_map.hpp>
#include <simpson/partitioned_runge_kutta.hpp>
#include <simpson/runge_kutta_tableaux.hpp>
#include <simpson/simpson_map.hpp>

#include <boost/multiprecision/mpfr.hpp>

#include <chrono>
#include <map>
#include <stdexcept>

namespace simpson::verify {
namespace {

using family_detail::derivative;
using family_detail::gcd_of;
using family_detail::lcm_of;
using family_detail::product;
using family_detail::reduced;
using tau_polynomial = std::vector<rational>;  // in τ ∈ [0, 1], constant term first

/// The interpolant's basis: 1 − τ (q_j), τ (q_{j+1}), τᵏ(1 − τ) for k = 1 … s − 1 (internal).
std::vector<tau_polynomial> basis(int s) {
  std::vector<tau_polynomial> out{{rational(1), rational(-1)}, {rational(0), rational(1)}};
  for (int k = 1; k < s; ++k) {
    tau_polynomial b(static_cast<std::size_t>(k) + 2, rational(0));
    b[static_cast<std::size_t>(k)] = 1;
    b[static_cast<std::size_t>(k) + 1] = -1;
    out.push_back(b);
  }
  return out;
}

/// The rule applied to a polynomial: Σ_n f_n μ_n.
rational apply_rule(const tau_polynomial& f, const std::vector<rational>& moments) {
  rational sum(0);
  for (std::size_t n = 0; n < f.size(); ++n) sum += f[n] * moments[n];
  return sum;
}

long size_of(const symbolic& f) { return std::max(degree(f.numerator()), degree(f.denominator())); }

std::string text(const symbolic& f) {
  const std::string n = to_string(f.numerator(), "θ"), d = to_string(f.denominator(), "θ");
  return d == "1" ? n : "(" + n + ") / (" + d + ")";
}

/// Gauss–Legendre with s stages on ẏ = Ay (m = ω = 1, A² = −1): R(hA) for the diagonal Padé
/// approximant P(z)/P(−z) of eᶻ, P(z) = Σ_j (2s − j)! s! / ((2s)! j! (s − j)!) zʲ. With
/// P(θA) = a + bθA: R = ((a² − b²θ²) + 2abθA)/(a² + b²θ²).
one_step_matrix<symbolic> gauss_legendre_map(int s) {
  const auto factorial = [](int k) {
    boost::multiprecision::cpp_int f = 1;
    for (int i = 2; i <= k; ++i) f *= i;
    return rational(f);
  };
  const symbolic theta = symbolic::variable(), x = theta * theta;
  symbolic a(0), b(0), power(1);  // power = (−θ²)^⌊j/2⌋
  for (int j = 0; j <= s; ++j) {
    const rational c = factorial(2 * s - j) * factorial(s) / (factorial(2 * s) * factorial(j) * factorial(s - j));
    if (j % 2 == 0) {
      a += symbolic(c) * power;
    } else {
      b += symbolic(c) * power;
      power = power * (symbolic(0) - x);
    }
  }
  const symbolic den = a * a + b * b * x, diagonal = (a * a - b * b * x) / den, off = symbolic(2) * a * b * theta / den;
  // A = [[0, −1], [1, 0]] on (p, q): p' = −q, q' = p.
  return {diagonal, symbolic(0) - off, off, diagonal};
}

bool same_map(const one_step_matrix<symbolic>& a, const one_step_matrix<symbolic>& b) {
  return (a.alpha - b.alpha).is_zero() && (a.beta - b.beta).is_zero() && (a.gamma - b.gamma).is_zero() &&
         (a.delta - b.delta).is_zero();
}

/// The known schemes, with m = ω = 1 and h = θ, in the core's own formulas where it has them.
std::vector<std::pair<std::string, one_step_matrix<symbolic>>> known_schemes() {
  const oscillator_parameters<symbolic> unit = unit_oscillator_in_theta();
  std::vector<std::pair<std::string, one_step_matrix<symbolic>>> out{
      {"Φ₃ (the paper's Simpson scheme)", simpson_map(unit)},
      {"Newmark (the paper's Section 2)", newmark_map(unit)},
      {"Störmer–Verlet (Lobatto IIIA–IIIB, 2 stages)",
       partitioned_runge_kutta_map(unit, lobatto_iiia2_tableau<symbolic>(), lobatto_iiib2_tableau<symbolic>())},
      {"Lobatto IIIA–IIIB, 3 stages",
       partitioned_runge_kutta_map(unit, lobatto_iiia3_tableau<symbolic>(), lobatto_iiib3_tableau<symbolic>())}};
  return out;
}

std::pair<std::string, one_step_matrix<symbolic>> gauss_legendre_entry(int s) {
  return {"Gauss–Legendre, " + std::to_string(s) + " stage" + (s == 1 ? " (implicit midpoint)" : "s"), gauss_legendre_map(s)};
}

/// 1. L_h = (1/2θ) xᵀ K x with K = T − θ² M (m = ω = 1, h = θ): Σ_k w_k h [½ (q'/h)² − ½ q²]; K, and
/// the evidence of the basis, K and the rule's moments.
std::vector<std::vector<symbolic>> discrete_lagrangian(const std::vector<tau_polynomial>& phi, const std::vector<rational>& mu,
                                                       member_analysis& out) {
  const std::size_t n = phi.size();
  const symbolic theta = symbolic::variable(), x = theta * theta;
  std::vector<std::vector<symbolic>> K(n, std::vector<symbolic>(n));
  json lagrangian = json::array();
  for (std::size_t i = 0; i < n; ++i) {
    json row = json::array();
    for (std::size_t j = 0; j < n; ++j) {
      const rational t = apply_rule(product(derivative(phi[i]), derivative(phi[j])), mu), m = apply_rule(product(phi[i], phi[j]), mu);
      K[i][j] = symbolic(t) - symbolic(m) * x;
      row.push_back(text(K[i][j]));
    }
    lagrangian.push_back(row);
  }
  out.evidence["basis"] = "1 - tau (q_j), tau (q_{j+1}), tau^k (1 - tau) for k = 1 .. s - 1 (internal), tau = (t - t_j)/h";
  out.evidence["discrete_lagrangian"] = {{"form", "L_h = (1/(2 theta)) x^T K x, x = (q_j, q_{j+1}, internal), m = omega = 1, h = theta"},
                                         {"K", lagrangian},
                                         {"moments", [&] {
                                            json m = json::array();
                                            for (const rational& v : mu) m.push_back(simpson::to_string(v));
                                            return m;
                                          }()}};
  return K;
}

/// 2–3. dL_h/d(internal) = 0, eliminated one internal unknown at a time (a Schur complement): K
/// reduced in place to its (q_j, q_{j+1}) block; false, with out.failure, where the rule cannot fix an
/// internal unknown or the elimination passes the budget.
bool eliminate_internal(std::vector<std::vector<symbolic>>& K, long budget_degree, member_analysis& out) {
  const std::size_t n = K.size();
  for (std::size_t k = n; k-- > 2;) {
    if (K[k][k].is_zero()) {
      out.failure = "internal system singular: the rule cannot fix internal degree of freedom " + std::to_string(k - 1) +
                    " (too few quadrature points for the degree)";
      return false;
    }
    for (std::size_t i = 0; i < k; ++i) {
      if (K[i][k].is_zero()) continue;
      const symbolic factor = reduced(K[i][k] / K[k][k]);
      for (std::size_t j = 0; j < k; ++j) K[i][j] = reduced(K[i][j] - factor * K[k][j]);
    }
    long largest = 0;
    for (std::size_t i = 0; i < k; ++i) {
      for (std::size_t j = 0; j < k; ++j) largest = std::max(largest, size_of(K[i][j]));
    }
    if (largest > budget_degree) {
      out.failure = "stopped at the budget: the elimination reached degree " + std::to_string(largest) + " in θ (budget " +
                    std::to_string(budget_degree) + ")";
      return false;
    }
  }
  return true;
}

/// 4. p_j = −∂L_h/∂q_j = −(S00 q_j + S01 q_{j+1})/θ solved for q_{j+1}; p_{j+1} = ∂L_h/∂q_{j+1}: Φ, with
/// its entries as text and as coefficients.
one_step_matrix<symbolic> one_step_map_of(const symbolic& S00, const symbolic& S01, const symbolic& S11, member_analysis& out) {
  const symbolic theta = symbolic::variable();
  one_step_matrix<symbolic> map{reduced((symbolic(0) - S11) / S01), reduced((S01 * S01 - S00 * S11) / (theta * S01)),
                                reduced((symbolic(0) - theta) / S01), reduced((symbolic(0) - S00) / S01)};
  out.alpha = text(map.alpha);
  out.beta = text(map.beta);
  out.gamma = text(map.gamma);
  out.delta = text(map.delta);
  const auto coefficients = [](const polynomial& p) {
    std::vector<std::string> c;
    for (long k = 0; k <= degree(p); ++k) c.push_back(simpson::to_string(p[static_cast<std::size_t>(k)]));
    return c;
  };
  const std::array<const symbolic*, 4> entries{&map.alpha, &map.beta, &map.gamma, &map.delta};
  for (std::size_t k = 0; k < 4; ++k) out.map_coefficients[k] = {coefficients(entries[k]->numerator()), coefficients(entries[k]->denominator())};
  out.size = std::max({size_of(map.alpha), size_of(map.beta), size_of(map.gamma), size_of(map.delta)});
  out.derived = true;
  return map;
}

/// det Φ = 1 and the conserved form W, as polynomial identities over Φ's common denominator d:
/// Φ = P/d, det Φ = 1 ⇔ det P = d², and with W = V/d, ΦᵀWΦ = W ⇔ PᵀVP = d² V.
void check_invariants(const one_step_matrix<symbolic>& map, member_analysis& out) {
  const polynomial d = lcm_of(lcm_of(map.alpha.denominator(), map.beta.denominator()),
                              lcm_of(map.gamma.denominator(), map.delta.denominator()));
  const auto over_d = [&](const symbolic& f) { return f.numerator() * (d / f.denominator()); };
  const polynomial Pa = over_d(map.alpha), Pb = over_d(map.beta), Pc = over_d(map.gamma), Pd = over_d(map.delta);
  const polynomial d2 = d * d, half = make_polynomial({rational(1, 2)});
  out.det_one = is_zero(Pa * Pd - Pb * Pc - d2);
  const polynomial v_pp = polynomial() - Pc, v_pq = (Pa - Pd) * half, v_qq = Pb;
  // (PᵀVP)_{ij} for columns (a1, b1) and (a2, b2) of P.
  const auto quad = [&](const polynomial& a1, const polynomial& b1, const polynomial& a2, const polynomial& b2) {
    return a1 * v_pp * a2 + a1 * v_pq * b2 + b1 * v_pq * a2 + b1 * v_qq * b2;
  };
  out.form_conserved = is_zero(quad(Pa, Pc, Pa, Pc) - d2 * v_pp) && is_zero(quad(Pa, Pc, Pb, Pd) - d2 * v_pq) &&
                       is_zero(quad(Pb, Pd, Pb, Pd) - d2 * v_qq);
  out.evidence["conserved_form"] = {{"W", "[[-gamma, (alpha - delta)/2], [(alpha - delta)/2, beta]]"},
                                    {"Phi^T W Phi = W", out.form_conserved}};
}

/// Stability: the three-term scheme S01 q_{j−1} + (S00 + S11) q_j + S01 q_{j+1} = 0, scaled by the
/// entries' common denominator (the same characteristic roots), so that the analysis works on
/// polynomials; its discriminant, each root's endpoint decided, and the stable set of ωh.
void analyse_stability(const symbolic& S00, const symbolic& S01, const symbolic& S11, const one_step_matrix<symbolic>& map,
                       member_analysis& out) {
  const symbolic theta = symbolic::variable();
  const polynomial common = lcm_of(lcm_of(S00.denominator(), S01.denominator()), S11.denominator());
  const symbolic a_poly(S01.numerator() * (common / S01.denominator()), make_polynomial({rational(1)}));
  const symbolic b_poly(S00.numerator() * (common / S00.denominator()) + S11.numerator() * (common / S11.denominator()),
                        make_polynomial({rational(1)}));
  const stability_report stability = analyse_three_term_scheme([&](const symbolic& qp, const symbolic& q, const symbolic& qn) {
    return a_poly * qp + b_poly * q + a_poly * qn;
  });
  out.evidence["stability"] = stability.evidence;
  out.discriminant = stability.evidence["discriminant_over_a2_numerator"].get<std::string>() + " / (" +
                     stability.evidence["discriminant_over_a2_denominator"].get<std::string>() + ")";
  // ωh at a root of Δ: exact ("2 sqrt(2)") or, for an irrational root, √ of its isolating interval to 10 digits.
  const auto omega_h = [](const positive_root& r) {
    if (r.exact()) return omega_h_text(r);
    using real = boost::multiprecision::mpfr_float_50;
    const real low = sqrt(real(numerator(r.low)) / real(denominator(r.low)));
    return "≈" + low.str(10, std::ios_base::fmtflags(0));
  };
  const auto omega_h_value = [](const rational& x) {
    using real = boost::multiprecision::mpfr_float_50;
    return static_cast<double>(sqrt(real(numerator(x)) / real(denominator(x))));
  };
  // At a root of Δ, tr Φ = ±2: Φ is power-bounded there exactly when Φ = ±I (β = γ = 0), else a
  // Jordan block grows linearly. β = γ = 0 at the root ⇔ the root is one of
  // g = gcd(num(γ/θ), num(βθ), num(Δ)), all polynomials in x = θ².
  const symbolic trace_x = reduced(map.alpha + map.delta);
  const polynomial disc = even_in_theta_to_x(trace_x.numerator() * trace_x.numerator() -
                                             make_polynomial({rational(4)}) * trace_x.denominator() * trace_x.denominator());
  const polynomial identity_points =
      gcd_of(gcd_of(even_in_theta_to_x(reduced(map.gamma / theta).numerator()), even_in_theta_to_x(reduced(map.beta * theta).numerator())),
             disc);
  const auto scalar_at_root = [&](const positive_root& r) {
    if (degree(identity_points) < 1) return false;
    if (r.exact()) return identity_points.evaluate(r.low) == 0;
    return count_real_roots(identity_points, r.low, r.high) > 0;
  };
  // The stable set: bands and roots in increasing order, consecutive stable ones merged.
  struct element {
    bool stable;
    bool point;
    std::size_t index;
  };
  std::vector<element> line;
  json endpoint_decisions = json::array();
  for (std::size_t k = 0; k < stability.bands.size(); ++k) {
    line.push_back({stability.bands[k].stable, false, k});
    if (k < stability.roots.size()) {
      const bool scalar = stability.product_of_roots_is_one && scalar_at_root(stability.roots[k]);
      line.push_back({scalar, true, k});
      endpoint_decisions.push_back({{"omega_h", omega_h(stability.roots[k])},
                                    {"Phi", scalar ? "+-I: stable (power-bounded)" : "a Jordan block: unstable (linear growth)"}});
    }
  }
  out.evidence["endpoints"] = endpoint_decisions;
  for (std::size_t i = 0; i < line.size();) {
    if (!line[i].stable) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < line.size() && line[j + 1].stable) ++j;
    stable_piece piece;
    if (line[i].point) {
      piece.from = omega_h(stability.roots[line[i].index]);
      piece.from_closed = true;
      piece.from_value = omega_h_value(stability.roots[line[i].index].low);
    } else if (line[i].index > 0) {
      piece.from = omega_h(stability.roots[line[i].index - 1]);
      piece.from_value = omega_h_value(stability.roots[line[i].index - 1].low);
    }
    if (line[j].point) {
      piece.to = omega_h(stability.roots[line[j].index]);
      piece.to_closed = true;
      piece.to_value = omega_h_value(stability.roots[line[j].index].low);
    } else if (line[j].index < stability.roots.size()) {
      piece.to = omega_h(stability.roots[line[j].index]);
      piece.to_value = omega_h_value(stability.roots[line[j].index].low);
    }
    out.stable_set.push_back(piece);
    i = j + 1;
  }
}

/// Order: (2 cos θ − tr Φ)/h² = c θ^r / θ² + ..., the three-term scheme's truncation error on e^{iωt}.
void truncation_order(const one_step_matrix<symbolic>& map, member_analysis& out) {
  const symbolic trace = reduced(map.alpha + map.delta);
  const polynomial& N = trace.numerator();
  const polynomial& D = trace.denominator();
  const int bound = static_cast<int>(degree(N) + degree(D)) + 24;
  polynomial series = make_polynomial({rational(2)}) * cos_taylor(bound) * D - N;
  int r = -1;
  for (int k = 0; k <= bound && k <= degree(series); ++k) {
    if (series[static_cast<std::size_t>(k)] != 0) {
      r = k;
      break;
    }
  }
  if (r < 0 || D[0] == 0) {
    out.evidence["truncation"] = "no leading term within the series' exact part";
  } else {
    const rational c = series[static_cast<std::size_t>(r)] / D[0];
    out.order = r - 2;
    out.error_constant = simpson::to_string(c);
    out.evidence["truncation"] = {{"leading", simpson::to_string(c) + " omega^" + std::to_string(r) + " h^" + std::to_string(r - 2)},
                                  {"definition", "(q(t+h) - tr(Phi) q(t) + q(t-h))/h^2 on q = exp(i omega t), divided by q"}};
  }
}

/// The known schemes whose Φ is this one.
void known_equalities(const one_step_matrix<symbolic>& map, int s, run_memo* memo, member_analysis& out) {
  static const std::vector<std::pair<std::string, one_step_matrix<symbolic>>> fixed = known_schemes();
  for (const auto& [name, known] : fixed) {
    if (same_map(map, known)) out.equals.push_back(name);
  }
  std::vector<std::pair<std::string, one_step_matrix<symbolic>>> by_degree{gauss_legendre_entry(s)};
  // Lobatto IIIA–IIIB with 4 … s + 2 stages (irrational tableaux), exactly through the nodal
  // quotient ring (partitioned_pair.hpp); 2 and 3 stages are the core's own, above. Each is made
  // once per run (the run's memo), not once per member.
  for (int k = 4; k <= s + 2; ++k) {
    by_degree.emplace_back("Lobatto IIIA–IIIB, " + std::to_string(k) + " stages",
                           remembered<one_step_matrix<symbolic>>(memo, "Lobatto IIIA-IIIB map, stages " + std::to_string(k),
                                                                 [&] { return family_detail::partitioned_pair_map({quadrature_family::lobatto, k}); }));
  }
  for (const auto& [name, known] : by_degree) {
    if (same_map(map, known)) out.equals.push_back(name);
  }
}

}  // namespace

std::string piece_text(const stable_piece& p) {
  if (p.from_closed && p.to_closed && p.from == p.to) return "{" + p.from + "}";
  return std::string(p.from_closed ? "[" : "(") + p.from + ", " + (p.to.empty() ? "∞" : p.to) + (p.to_closed ? "]" : ")");
}

std::vector<quadrature_rule> family_rules(int s) {
  std::vector<quadrature_rule> out;
  for (int k = 2; k <= s + 2; ++k) out.push_back({quadrature_family::newton_cotes, k});
  for (int k = 2; k <= s + 2; ++k) out.push_back({quadrature_family::lobatto, k});
  for (int k = 1; k <= s + 1; ++k) out.push_back({quadrature_family::gauss, k});
  return out;
}

std::string member_name(const galerkin_member& m) { return "s = " + std::to_string(m.degree) + ", " + rule_name(m.rule); }

member_analysis analyse_member(const galerkin_member& member, long budget_degree, run_memo* memo) {
  const auto start = std::chrono::steady_clock::now();
  member_analysis out;
  out.member = member;
  const int s = member.degree;
  if (s < 1) throw std::invalid_argument("the interpolant's degree must be at least 1");
  const std::vector<rational> mu = quadrature_moments(member.rule, 2 * s);
  const std::vector<tau_polynomial> phi = basis(s);
  std::vector<std::vector<symbolic>> K = discrete_lagrangian(phi, mu, out);
  if (!eliminate_internal(K, budget_degree, out)) {
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
  }
  const symbolic S00 = K[0][0], S01 = K[0][1], S10 = K[1][0], S11 = K[1][1];
  if (S01.is_zero()) {
    out.failure = "the reduced Lagrangian does not couple q_j and q_{j+1}: no one-step map";
    return out;
  }
  out.evidence["reduced_lagrangian"] = {{"form", "L_h(q_j, q_{j+1}) = (1/(2 theta)) (S00 q_j^2 + 2 S01 q_j q_{j+1} + S11 q_{j+1}^2)"},
                                        {"S00", text(S00)}, {"S01", text(S01)}, {"S11", text(S11)},
                                        {"symmetric", (S01 - S10).is_zero()}};
  const one_step_matrix<symbolic> map = one_step_map_of(S00, S01, S11, out);
  check_invariants(map, out);
  analyse_stability(S00, S01, S11, map, out);
  truncation_order(map, out);
  known_equalities(map, s, memo, out);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace simpson::verify
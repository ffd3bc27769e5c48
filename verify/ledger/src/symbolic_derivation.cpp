#include "symbolic_derivation.hpp"

#include <chrono>

namespace simpson::verify::detail {
namespace {

using GiNaC::ex;

/// The polynomial of degree nodes − 1 in t through (t_k, q_k), by solving for its coefficients.
ex interpolating_polynomial(const ex& t, const std::vector<std::pair<ex, ex>>& nodes) {
  GiNaC::lst unknowns, equations;
  ex poly = 0;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const GiNaC::symbol c("c" + std::to_string(k));
    unknowns.append(c);
    poly += c * GiNaC::pow(t, static_cast<int>(k));
  }
  for (const auto& [at, value] : nodes) equations.append(poly.subs(t == at) == value);
  return GiNaC::normal(poly.subs(GiNaC::ex_to<GiNaC::lst>(GiNaC::lsolve(equations, unknowns))));
}

/// Eliminates q_{j-1}: given p_j = p_r(q_{j-1}, q_j) and the scheme E(q_{j-1}, q_j, q_{j+1}) = 0,
/// solves for q_{j-1} and q_{j+1}, then p_{j+1} = p_r(q_j, q_{j+1}); returns the one-step matrix.
GiNaC::matrix eliminate(const symbolic_derivation& d, const std::function<ex(const ex&, const ex&)>& momentum,
                        const ex& scheme) {
  const GiNaC::lst unknowns{d.q_prev, d.q_next};
  const GiNaC::lst equations{momentum(d.q_prev, d.q_j) == d.p_j, scheme == 0};
  const ex solution = GiNaC::lsolve(equations, unknowns);
  const ex q_next = solution.op(1).rhs();
  const ex p_next = GiNaC::normal(momentum(d.q_j, q_next));
  return one_step_matrix_of(p_next, q_next, d.p_j, d.q_j);
}

}  // namespace

GiNaC::matrix one_step_matrix_of(const ex& p_next, const ex& q_next, const ex& p, const ex& q) {
  GiNaC::matrix phi(2, 2);
  phi(0, 0) = GiNaC::normal(p_next.diff(GiNaC::ex_to<GiNaC::symbol>(p)));
  phi(0, 1) = GiNaC::normal(p_next.diff(GiNaC::ex_to<GiNaC::symbol>(q)));
  phi(1, 0) = GiNaC::normal(q_next.diff(GiNaC::ex_to<GiNaC::symbol>(p)));
  phi(1, 1) = GiNaC::normal(q_next.diff(GiNaC::ex_to<GiNaC::symbol>(q)));
  return phi;
}

ex symbolic_derivation::general_V(const ex& x) const { return apply_function("V", {x}); }
ex symbolic_derivation::harmonic_V(const ex& x) const { return m * omega * omega * x * x / 2; }

ex symbolic_derivation::classical_lagrangian(const potential_function& V, const ex& l, const ex& r) const {
  // The affine interpolant between (0, l) and (h, r); the midpoint rule h f(h/2) on m/2 q'² − V(q).
  const ex affine = interpolating_polynomial(t, {{0, l}, {h, r}});
  const ex slope = affine.diff(GiNaC::ex_to<GiNaC::symbol>(t));
  return h * (m / 2 * slope * slope - V(affine.subs(t == h / 2)));
}

ex symbolic_derivation::simpson_lagrangian(const potential_function& V) const {
  // (simpson) on [0, h]: h/6 [f(0) + 4 f(h/2) + f(h)] with f = m/2 q'² − V(q) along the interpolant.
  const auto integrand = [&](const ex& at) {
    const ex v = velocity.subs(t == at);
    return m / 2 * v * v - V(interpolant.subs(t == at));
  };
  return h / 6 * (integrand(0) + 4 * integrand(h / 2) + integrand(h));
}

ex symbolic_derivation::scheme(const ex& prev, const ex& at, const ex& next) const {
  const GiNaC::symbol& l = GiNaC::ex_to<GiNaC::symbol>(q_l);
  const GiNaC::symbol& r = GiNaC::ex_to<GiNaC::symbol>(q_r);
  // (Euler-Lagrange-discret) for L_hʳ: ∂L/∂q_r (q_{j-1}, q_j) + ∂L/∂q_l (q_j, q_{j+1}).
  return GiNaC::normal(reduced_lagrangian.diff(r).subs(GiNaC::lst{q_l == prev, q_r == at}) +
                       reduced_lagrangian.diff(l).subs(GiNaC::lst{q_l == at, q_r == next}));
}

const symbolic_derivation& derivation() {
  static const symbolic_derivation d = [] {
    const auto start = std::chrono::steady_clock::now();
    tex_symbols& s = paper_symbols();
    symbolic_derivation r;
    r.m = s["m"], r.omega = s["omega"], r.h = s["h"], r.t = s["t"], r.theta = s["theta"];
    r.q_l = s["q_l"], r.q_m = s["q_m"], r.q_r = s["q_r"], r.p = s["p"], r.q = s["q"];
    r.q_prev = s["q_j-1"], r.q_j = s["q_j"], r.q_next = s["q_j+1"], r.p_j = s["p_j"], r.p_next = s["p_j+1"];
    const GiNaC::symbol& t = GiNaC::ex_to<GiNaC::symbol>(r.t);
    const GiNaC::symbol& mid = GiNaC::ex_to<GiNaC::symbol>(r.q_m);
    const GiNaC::symbol& right = GiNaC::ex_to<GiNaC::symbol>(r.q_r);
    const potential_function harmonic = [&r](const ex& x) { return r.harmonic_V(x); };
    const potential_function general = [&r](const ex& x) { return r.general_V(x); };

    // §3: the quadratic interpolant and its velocity at 0, h/2, h.
    r.interpolant = interpolating_polynomial(r.t, {{0, r.q_l}, {r.h / 2, r.q_m}, {r.h, r.q_r}});
    r.velocity = GiNaC::normal(r.interpolant.diff(t));
    r.g_l = GiNaC::normal(r.velocity.subs(r.t == 0));
    r.g_m = GiNaC::normal(r.velocity.subs(r.t == r.h / 2));
    r.g_r = GiNaC::normal(r.velocity.subs(r.t == r.h));

    // §4–5: L_h, V general, and ∂L_h/∂q_m.
    r.lh_dqm = GiNaC::expand(r.simpson_lagrangian(general).diff(mid));

    // §5, V harmonic: q_m from ∂L_h/∂q_m = 0, then L_hʳ = L_h at that q_m.
    const ex L_h = r.simpson_lagrangian(harmonic);
    r.harmonic_qm = GiNaC::normal(GiNaC::lsolve(L_h.diff(mid) == 0, mid));
    r.reduced_lagrangian = GiNaC::normal(L_h.subs(r.q_m == r.harmonic_qm));
    r.momentum = GiNaC::normal(r.reduced_lagrangian.diff(right));

    // §6: eliminating q_{j-1} between p_j = p_r(q_{j-1}, q_j) and the scheme gives Φ₃.
    const auto simpson_p = [&](const ex& a, const ex& b) { return r.momentum.subs(GiNaC::lst{r.q_l == a, r.q_r == b}); };
    r.phi3 = eliminate(r, simpson_p, r.scheme(r.q_prev, r.q_j, r.q_next));

    r.steps = {"the quadratic q(t) through (0, q_l), (h/2, q_m), (h, q_r), solved for its coefficients (lsolve)",
               "its velocity dq/dt and the Gear values g_l = q'(0), g_m = q'(h/2), g_r = q'(h) (diff, subs)",
               "L_h = h/6 [f(0) + 4 f(h/2) + f(h)], f = m/2 q'^2 - V(q), Simpson's rule (simpson) along it",
               "dL_h/dq_m (diff), V uninterpreted; with V = m omega^2 q^2/2, q_m solved from dL_h/dq_m = 0 (lsolve)",
               "L_h^r = L_h at that q_m (subs, normal); p_r = dL_h^r/dq_r (diff)",
               "the scheme dL_h^r/dq_r (q_{j-1}, q_j) + dL_h^r/dq_l (q_j, q_{j+1}) = 0 (Euler-Lagrange-discret)",
               "q_{j-1} and q_{j+1} solved from p_j = p_r(q_{j-1}, q_j) and the scheme (lsolve); p_{j+1} = p_r(q_j, q_{j+1})",
               "Phi_3 = the coefficients of p_j and q_j in (p_{j+1}, q_{j+1}) (diff, normal)"};
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  }();
  return d;
}

const classical_derivation& newmark_derivation() {
  static const classical_derivation n = [] {
    const symbolic_derivation& d = derivation();
    const GiNaC::symbol& l = GiNaC::ex_to<GiNaC::symbol>(d.q_l);
    const GiNaC::symbol& right = GiNaC::ex_to<GiNaC::symbol>(d.q_r);
    const ex L_d = d.classical_lagrangian([&d](const ex& x) { return d.harmonic_V(x); }, d.q_l, d.q_r);
    const auto momentum = [&](const ex& a, const ex& b) { return L_d.diff(right).subs(GiNaC::lst{d.q_l == a, d.q_r == b}); };
    const ex scheme = L_d.diff(right).subs(GiNaC::lst{d.q_l == d.q_prev, d.q_r == d.q_j}) +
                      L_d.diff(l).subs(GiNaC::lst{d.q_l == d.q_j, d.q_r == d.q_next});
    classical_derivation c;
    c.momentum_right = GiNaC::normal(momentum(d.q_j, d.q_next));
    c.momentum_left = GiNaC::normal(-L_d.diff(l).subs(GiNaC::lst{d.q_l == d.q_j, d.q_r == d.q_next}));
    c.newmark_phi = eliminate(d, momentum, scheme);
    return c;
  }();
  return n;
}

}  // namespace simpson::verify::detail

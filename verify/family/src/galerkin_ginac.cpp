// One member of the Galerkin family derived again in GiNaC, m, ω, h symbolic (galerkin_ginac.hpp).

#include <simpson/verify/galerkin_ginac.hpp>
#include <simpson/verify/galerkin_ginac_map.hpp>

#include <ginac/ginac.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace simpson::verify {
namespace {

using GiNaC::ex;
using GiNaC::symbol;

/// The rule's nodal polynomial ω_k(τ) on [0, 1], up to a constant factor: the product over
/// equispaced nodes (Newton–Cotes), the shifted Legendre polynomial dᵏ/dτᵏ (τ² − τ)ᵏ (Gauss), and
/// τ(τ − 1) dᵏ/dτᵏ (τ² − τ)ᵏ⁻¹ (Lobatto: the ends and the roots of P′_{k−1}).
ex nodal_polynomial(const quadrature_rule& rule, const symbol& tau) {
  const int k = rule.points;
  switch (rule.family) {
    case quadrature_family::newton_cotes: {
      ex out = 1;
      for (int i = 0; i < k; ++i) out *= tau - GiNaC::numeric(i, k - 1);
      return out.expand();
    }
    case quadrature_family::gauss:
      return GiNaC::pow(tau * tau - tau, k).diff(tau, static_cast<unsigned>(k)).expand();
    case quadrature_family::lobatto:
      return (tau * (tau - 1) * GiNaC::pow(tau * tau - tau, k - 1).diff(tau, static_cast<unsigned>(k))).expand();
  }
  throw std::logic_error("nodal_polynomial: unknown rule");
}

/// The rule applied to a polynomial f in τ (any coefficients): an interpolatory k-point rule is
/// exact below degree k and vanishes on ω_k, so Q[τⁿ] = ∫₀¹ rem(τⁿ, ω_k), and Q[f] = Σ f_n Q[τⁿ].
ex apply_rule(const ex& f, const ex& nodal, const symbol& tau) {
  const ex expanded = f.expand();
  ex out = 0;
  for (int n = 0; n <= expanded.degree(tau); ++n) {
    const ex r = GiNaC::rem(GiNaC::pow(tau, n), nodal, tau).expand();
    ex moment = 0;
    for (int j = 0; j <= r.degree(tau); ++j) moment += r.coeff(tau, j) / (j + 1);
    out += expanded.coeff(tau, n) * moment;
  }
  return out;
}

struct derived_map {
  ex alpha, beta, gamma, delta;
  ex reduced_lagrangian;
};

/// The derivation with the interpolant q(τ) = Σ basis_k(τ) x_k, x = (q_j, q_{j+1}, Q_1 … Q_{s−1}).
std::optional<derived_map> derive(const std::vector<ex>& basis, const std::vector<symbol>& unknowns, const ex& nodal,
                                  const symbol& tau, const symbol& m, const symbol& omega, const symbol& h, std::string& failure) {
  ex q = 0;
  for (std::size_t k = 0; k < basis.size(); ++k) q += basis[k] * unknowns[k];
  const ex velocity = q.diff(tau) / h;
  const ex lagrangian = (h * apply_rule(m / 2 * velocity * velocity - m * omega * omega / 2 * q * q, nodal, tau)).expand();
  const symbol &qa = unknowns[0], &qb = unknowns[1];
  // ∂L_h/∂Q_k = 0 for the internal unknowns.
  ex reduced = lagrangian;
  if (unknowns.size() > 2) {
    GiNaC::lst equations, internal;
    for (std::size_t k = 2; k < unknowns.size(); ++k) {
      equations.append(lagrangian.diff(unknowns[k]) == 0);
      internal.append(unknowns[k]);
    }
    const ex solution = GiNaC::lsolve(equations, internal);
    if (solution.nops() != internal.nops()) {
      failure = "the internal equations have no solution";
      return std::nullopt;
    }
    for (const ex& eq : solution) {
      for (const ex& unknown : internal) {
        if (eq.rhs().has(unknown)) {
          failure = "internal system singular: the internal equations do not fix every internal degree of freedom";
          return std::nullopt;
        }
      }
    }
    reduced = GiNaC::normal(lagrangian.subs(solution));
  }
  // p_j = −∂L_h/∂q_j solved for q_{j+1}; p_{j+1} = ∂L_h/∂q_{j+1}.
  const symbol p("p");
  const ex momentum_equation = -reduced.diff(qa) - p;
  const ex coefficient = GiNaC::normal(momentum_equation.diff(qb));
  if (coefficient.is_zero()) {
    failure = "the reduced Lagrangian does not couple q_j and q_{j+1}: no one-step map";
    return std::nullopt;
  }
  const ex q_next = GiNaC::normal(qb - momentum_equation / coefficient);  // linear in q_{j+1}
  const ex p_next = GiNaC::normal(reduced.diff(qb).subs(qb == q_next));
  derived_map out;
  out.alpha = GiNaC::normal(p_next.diff(p));
  out.beta = GiNaC::normal(p_next.diff(qa));
  out.gamma = GiNaC::normal(q_next.diff(p));
  out.delta = GiNaC::normal(q_next.diff(qa));
  out.reduced_lagrangian = GiNaC::collect_common_factors(reduced);
  return out;
}

/// Our kernel's entry: Σ a_k θᵏ / Σ b_k θᵏ from its exact coefficients.
ex from_coefficients(const std::array<std::vector<std::string>, 2>& c, const symbol& theta) {
  const auto polynomial = [&](const std::vector<std::string>& coefficients) {
    ex out = 0;
    for (std::size_t k = 0; k < coefficients.size(); ++k) {
      const std::string& text = coefficients[k];
      const std::size_t slash = text.find('/');
      const GiNaC::numeric value = slash == std::string::npos
                                       ? GiNaC::numeric(text.c_str())
                                       : GiNaC::numeric(text.substr(0, slash).c_str()) / GiNaC::numeric(text.substr(slash + 1).c_str());
      out += value * GiNaC::pow(theta, static_cast<int>(k));
    }
    return out;
  };
  return polynomial(c[0]) / polynomial(c[1]);
}

std::string text_of(const ex& e) {
  std::ostringstream os;
  os << e;
  return os.str();
}

bool zero(const ex& e) { return GiNaC::normal(e).is_zero(); }

/// A univariate polynomial with rational coefficients, highest power first ("x^2 - 24 x + 1"):
/// printed from its coefficients, so the text never depends on GiNaC's term order.
std::string polynomial_text(const ex& p, const symbol& x) {
  const ex e = p.expand();
  std::string out;
  for (int k = e.degree(x); k >= 0; --k) {
    const GiNaC::numeric c = GiNaC::ex_to<GiNaC::numeric>(e.coeff(x, k));
    if (c.is_zero()) continue;
    const GiNaC::numeric magnitude = GiNaC::abs(c);
    out += out.empty() ? (c < 0 ? "-" : "") : (c < 0 ? " - " : " + ");
    const bool unit = magnitude == 1 && k > 0;
    if (!unit) out += text_of(magnitude);
    if (k > 0) out += (unit ? "" : " ") + x.get_name() + (k > 1 ? "^" + std::to_string(k) : "");
  }
  return out.empty() ? "0" : out;
}

/// GiNaC's factor() of a univariate polynomial, printed canonically: the constant first, then each
/// irreducible factor, leading coefficient positive, and its power, shortest first.
std::string factored_text(const ex& f, const symbol& x) {
  GiNaC::numeric constant = 1;
  std::vector<std::string> factors;
  const auto add = [&](const ex& factor) {
    if (GiNaC::is_a<GiNaC::numeric>(factor)) {
      constant *= GiNaC::ex_to<GiNaC::numeric>(factor);
      return;
    }
    const bool raised = GiNaC::is_a<GiNaC::power>(factor) && GiNaC::is_a<GiNaC::numeric>(factor.op(1));
    ex base = (raised ? factor.op(0) : factor).expand();
    const int power = raised ? GiNaC::ex_to<GiNaC::numeric>(factor.op(1)).to_int() : 1;
    // GiNaC picks a factor's sign differently from run to run: each is made positive-leading, its
    // sign moved to the constant.
    if (GiNaC::ex_to<GiNaC::numeric>(base.lcoeff(x)) < 0) {
      base = (-base).expand();
      if (power % 2 != 0) constant = -constant;
    }
    const std::string text = polynomial_text(base, x);
    factors.push_back((text.find(' ') == std::string::npos ? text : "(" + text + ")") + (power == 1 ? "" : "^" + std::to_string(power)));
  };
  if (GiNaC::is_a<GiNaC::mul>(f)) {
    for (std::size_t k = 0; k < f.nops(); ++k) add(f.op(k));
  } else {
    add(f);
  }
  // Shorter factors first (x, then linear ones by their constant's length, then higher degrees).
  std::sort(factors.begin(), factors.end(), [](const std::string& a, const std::string& b) {
    return a.size() != b.size() ? a.size() < b.size() : a < b;
  });
  std::string out = constant == 1 && !factors.empty() ? "" : text_of(constant);
  for (const std::string& factor : factors) out += (out.empty() ? "" : " ") + factor;
  return out;
}

/// The unknowns (q_j, q_{j+1}, Q_1 … Q_{s−1}) and the basis 1 − τ, τ, τᵏ(1 − τ), as our kernel's.
std::pair<std::vector<symbol>, std::vector<ex>> monomial_basis(int s, const symbol& tau) {
  std::vector<symbol> unknowns{symbol("q_j"), symbol("q_j1")};
  std::vector<ex> basis{1 - tau, tau};
  for (int k = 1; k < s; ++k) {
    unknowns.emplace_back("Q" + std::to_string(k));
    basis.push_back(GiNaC::pow(tau, k) * (1 - tau));
  }
  return {unknowns, basis};
}

}  // namespace

std::optional<GiNaC::matrix> ginac_one_step_map(const galerkin_member& member, const symbol& m, const symbol& omega, const symbol& h) {
  const symbol tau("tau");
  const auto [unknowns, basis] = monomial_basis(member.degree, tau);
  std::string failure;
  const auto map = derive(basis, unknowns, nodal_polynomial(member.rule, tau), tau, m, omega, h, failure);
  if (!map) return std::nullopt;
  return GiNaC::matrix{{map->alpha, map->beta}, {map->gamma, map->delta}};
}

ginac_member_check check_member_in_ginac(const member_analysis& ours, int node_check_degree) {
  const auto start = std::chrono::steady_clock::now();
  ginac_member_check out;
  const int s = ours.member.degree;
  const symbol m("m"), omega("omega"), h("h"), tau("tau"), theta("theta");
  const ex nodal = nodal_polynomial(ours.member.rule, tau);
  const auto [unknowns, basis] = monomial_basis(s, tau);
  const auto map = derive(basis, unknowns, nodal, tau, m, omega, h, out.failure);
  const auto finish = [&] {
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
  };
  if (!map) return finish();
  out.derived = true;
  out.alpha = text_of(map->alpha);
  out.beta = text_of(map->beta);
  out.gamma = text_of(map->gamma);
  out.delta = text_of(map->delta);
  if (s <= 2) out.reduced_lagrangian = text_of(map->reduced_lagrangian);

  const ex a = map->alpha, b = map->beta, c = map->gamma, d = map->delta;
  out.det_one = zero(a * d - b * c - 1);
  // W = [[−γ, (α−δ)/2], [(α−δ)/2, β]]; ΦᵀWΦ − W entry by entry.
  const ex w_pp = -c, w_pq = (a - d) / 2, w_qq = b;
  const auto quad = [&](const ex& a1, const ex& b1, const ex& a2, const ex& b2) {
    return a1 * w_pp * a2 + a1 * w_pq * b2 + b1 * w_pq * a2 + b1 * w_qq * b2;
  };
  out.form_conserved = zero(quad(a, c, a, c) - w_pp) && zero(quad(a, c, b, d) - w_pq) && zero(quad(b, d, b, d) - w_qq);

  // Against our kernel, and the scaling law.
  const GiNaC::lst unit{m == 1, omega == 1, h == theta};
  const std::array<ex, 4> mine{a, b, c, d};
  bool same = true, scaling = true;
  const std::array<ex, 4> factor{1, m * omega, 1 / (m * omega), 1};
  for (std::size_t k = 0; k < 4; ++k) {
    const ex theirs = from_coefficients(ours.map_coefficients[k], theta);
    same = same && zero(mine[k].subs(unit) - theirs);
    scaling = scaling && zero(mine[k] - factor[k] * theirs.subs(theta == omega * h));
  }
  out.same_as_exact_kernel = same;
  out.scaling = scaling;

  // tr Φ in x = θ² (even in θ), and (tr Φ)² − 4 factored, numerator and denominator apart.
  const symbol x("x");
  const auto in_x = [&](const ex& even) {
    const ex expanded = even.expand();
    ex out_x = 0;
    for (int k = 0; k <= expanded.degree(theta); k += 2) out_x += expanded.coeff(theta, k) * GiNaC::pow(x, k / 2);
    return out_x;
  };
  const ex trace = GiNaC::normal((a + d).subs(unit));
  const ex trace_x = GiNaC::normal(in_x(GiNaC::numer(trace)) / in_x(GiNaC::denom(trace)));
  const ex disc = GiNaC::normal(trace_x * trace_x - 4);
  // Numerator and denominator with the denominator's leading coefficient positive (normal() may
  // give either sign to both).
  const auto parts = [&](const ex& f) {
    ex n = GiNaC::numer(f).expand(), d = GiNaC::denom(f).expand();
    if (GiNaC::ex_to<GiNaC::numeric>(d.lcoeff(x)) < 0) n = (-n).expand(), d = (-d).expand();
    return std::pair{n, d};
  };
  const auto [trace_num, trace_den] = parts(trace_x);
  const auto [disc_num, disc_den] = parts(disc);
  out.trace = "(" + polynomial_text(trace_num, x) + ")" + (trace_den == 1 ? "" : " / (" + polynomial_text(trace_den, x) + ")");
  out.discriminant_factored =
      factored_text(GiNaC::factor(disc_num), x) + (disc_den == 1 ? "" : " / " + factored_text(GiNaC::factor(disc_den), x));

  // The internal nodes as symbols ν_k: the Lagrange basis through (0, q_j), (ν_k, Q_k), (1, q_{j+1}).
  if (s <= node_check_degree) {
    std::vector<ex> nodes{0, 1};
    for (int k = 1; k < s; ++k) nodes.push_back(symbol("nu" + std::to_string(k)));
    std::vector<ex> lagrange;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      ex l = 1;
      for (std::size_t j = 0; j < nodes.size(); ++j) {
        if (j != i) l *= (tau - nodes[j]) / (nodes[i] - nodes[j]);
      }
      lagrange.push_back(GiNaC::normal(l));
    }
    std::string ignored;
    const auto placed = derive(lagrange, unknowns, nodal, tau, m, omega, h, ignored);
    out.node_independent = placed && zero(placed->alpha - a) && zero(placed->beta - b) && zero(placed->gamma - c) &&
                           zero(placed->delta - d);
  }
  return finish();
}

}  // namespace simpson::verify

// Beyond the paper, several degrees of freedom with a quadratic Lagrangian ½ q̇ᵀMq̇ − ½ qᵀKq: Φ₃'s
// block analogue (core/ndof_linear.hpp) proved symplectic and energy-conserving in exact rational
// arithmetic by GiNaC (a second construction of the map from the step's equations, compared with
// the core's in mpfr:100), and its stability decided exactly from Φ's characteristic polynomial
// against the generalized eigenvalues of (K, M).

#include "bespoke_checks.hpp"

#include "claim_support.hpp"

#include <simpson/ndof_linear.hpp>
#include <simpson/three_term_scheme.hpp>
#include <simpson/verify/exact_proof.hpp>

#include <Eigen/Eigenvalues>
#include <ginac/ginac.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace simpson::verify::detail {
namespace {

using GiNaC::ex;

/// A system of the claims: its name, M and K (rational entries as numerator/denominator pairs).
struct linear_system {
  std::string name;
  std::vector<std::vector<std::pair<int, int>>> mass, stiffness;
};

const std::vector<linear_system>& systems() {
  static const std::vector<linear_system> list{
      {"linearized double pendulum, m1 = m2 = l1 = l2 = g = 1: M = [[2, 1], [1, 1]], K = diag(2, 1)",
       {{{2, 1}, {1, 1}}, {{1, 1}, {1, 1}}},
       {{{2, 1}, {0, 1}}, {{0, 1}, {1, 1}}}},
      {"3-DOF spring chain: M = diag(3, 1/2, 2), K = tridiag(-1, 2, -1)",
       {{{3, 1}, {0, 1}, {0, 1}}, {{0, 1}, {1, 2}, {0, 1}}, {{0, 1}, {0, 1}, {2, 1}}},
       {{{2, 1}, {-1, 1}, {0, 1}}, {{-1, 1}, {2, 1}, {-1, 1}}, {{0, 1}, {-1, 1}, {2, 1}}}}};
  return list;
}

const std::vector<std::pair<int, int>>& steps() {
  static const std::vector<std::pair<int, int>> h{{1, 10}, {1, 2}, {7, 5}};
  return h;
}

GiNaC::matrix exact_matrix(const std::vector<std::vector<std::pair<int, int>>>& entries) {
  const unsigned n = static_cast<unsigned>(entries.size());
  GiNaC::matrix out(n, n);
  for (unsigned i = 0; i < n; ++i) {
    for (unsigned j = 0; j < n; ++j) out(i, j) = GiNaC::numeric(entries[i][j].first, entries[i][j].second);
  }
  return out;
}

/// Φ from the step's equations in GiNaC, exactly: x = (M + h²K/24)⁻¹ (M q + (h/2) p − (h²/12) K q),
/// q' = q + h M⁻¹ p − (h²/6) M⁻¹ K (q + 2x), p' = p − (h/6) K (q + 4x + q'), applied to symbolic p, q.
GiNaC::matrix exact_phi(const GiNaC::matrix& M, const GiNaC::matrix& K, const ex& h) {
  const unsigned n = M.rows();
  GiNaC::matrix p(n, 1), q(n, 1);
  GiNaC::lst unknowns;
  for (unsigned i = 0; i < n; ++i) {
    p(i, 0) = GiNaC::symbol("p" + std::to_string(i));
    q(i, 0) = GiNaC::symbol("q" + std::to_string(i));
  }
  const GiNaC::matrix M_inv = M.inverse();
  const GiNaC::matrix internal = M.add(K.mul_scalar(h * h / 24));
  const GiNaC::matrix x = internal.inverse().mul(M.mul(q).add(p.mul_scalar(h / 2)).sub(K.mul(q).mul_scalar(h * h / 12)));
  const GiNaC::matrix q_next = q.add(M_inv.mul(p).mul_scalar(h)).sub(M_inv.mul(K).mul(q.add(x.mul_scalar(2))).mul_scalar(h * h / 6));
  const GiNaC::matrix p_next = p.sub(K.mul(q.add(x.mul_scalar(4)).add(q_next)).mul_scalar(h / 6));
  GiNaC::matrix phi(2 * n, 2 * n);
  for (unsigned i = 0; i < n; ++i) {
    for (unsigned j = 0; j < n; ++j) {
      const GiNaC::symbol& pj = GiNaC::ex_to<GiNaC::symbol>(p(j, 0));
      const GiNaC::symbol& qj = GiNaC::ex_to<GiNaC::symbol>(q(j, 0));
      phi(i, j) = GiNaC::expand(p_next(i, 0)).coeff(pj);
      phi(i, n + j) = GiNaC::expand(p_next(i, 0)).coeff(qj);
      phi(n + i, j) = GiNaC::expand(q_next(i, 0)).coeff(pj);
      phi(n + i, n + j) = GiNaC::expand(q_next(i, 0)).coeff(qj);
    }
  }
  return phi;
}

/// The block H_d form diag(M⁻¹, K (I − S/12)(I − S/24)(I − S/8)⁻¹), S = h² M⁻¹ K, in GiNaC.
GiNaC::matrix exact_energy_form(const GiNaC::matrix& M, const GiNaC::matrix& K, const ex& h) {
  const unsigned n = M.rows();
  GiNaC::matrix I(n, n);
  for (unsigned i = 0; i < n; ++i) I(i, i) = 1;
  const GiNaC::matrix S = M.inverse().mul(K).mul_scalar(h * h);
  const GiNaC::matrix block =
      K.mul(I.sub(S.mul_scalar(ex(1) / 12))).mul(I.sub(S.mul_scalar(ex(1) / 24))).mul(I.sub(S.mul_scalar(ex(1) / 8)).inverse());
  GiNaC::matrix form(2 * n, 2 * n);
  const GiNaC::matrix M_inv = M.inverse();
  for (unsigned i = 0; i < n; ++i) {
    for (unsigned j = 0; j < n; ++j) {
      form(i, j) = M_inv(i, j);
      form(n + i, n + j) = block(i, j);
    }
  }
  return form;
}

bool is_zero_matrix(const GiNaC::matrix& m) {
  for (unsigned i = 0; i < m.rows(); ++i) {
    for (unsigned j = 0; j < m.cols(); ++j) {
      if (!GiNaC::normal(m(i, j)).is_zero()) return false;
    }
  }
  return true;
}

/// The core's Φ (Eigen, mpfr:100) against GiNaC's exact one: the largest entry gap relative to the
/// largest entry, as text in mpfr:100, and whether it is within 64 n² eps (each entry of the core's
/// Φ comes from two LU solves and products of n terms, ~n² roundings of terms of size max|Φ|).
std::pair<std::string, bool> core_gap(const linear_system& s, const GiNaC::matrix& exact, int h_num, int h_den) {
  const scoped_mpfr_digits digits(100);
  using Real = mpfr;
  const auto to_dense = [](const std::vector<std::vector<std::pair<int, int>>>& entries) {
    dense_matrix<Real> out(static_cast<Eigen::Index>(entries.size()), static_cast<Eigen::Index>(entries.size()));
    for (std::size_t i = 0; i < entries.size(); ++i) {
      for (std::size_t j = 0; j < entries.size(); ++j) {
        out(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = Real(entries[i][j].first) / entries[i][j].second;
      }
    }
    return out;
  };
  const dense_matrix<Real> phi = ndof_simpson_map(to_dense(s.mass), to_dense(s.stiffness), Real(Real(h_num) / h_den));
  Real worst(0), size(0);
  for (unsigned i = 0; i < exact.rows(); ++i) {
    for (unsigned j = 0; j < exact.cols(); ++j) {
      const GiNaC::numeric value = GiNaC::ex_to<GiNaC::numeric>(GiNaC::normal(exact(i, j)));
      const auto decimal = [](const GiNaC::numeric& integer) {  // exact, whatever its size
        std::ostringstream text;
        text << integer;
        return Real(text.str());
      };
      const Real want = decimal(value.numer()) / decimal(value.denom());
      using std::abs;
      worst = std::max(worst, Real(abs(Real(phi(i, j) - want))));
      size = std::max(size, Real(abs(want)));
    }
  }
  const Real relative = worst / size, n = Real(static_cast<long>(s.mass.size()));
  return {simpson::to_string(relative, 3), relative <= 64 * n * n * eps<Real>()};
}

decider_evidence check_ndof_exact(bool energy) {
  decider_evidence judged;
  claim_result& r = judged.found;
  json rows = json::array();
  bool all = true;
  bool same_map = true;
  for (const linear_system& s : systems()) {
    const GiNaC::matrix M = exact_matrix(s.mass), K = exact_matrix(s.stiffness);
    const unsigned n = M.rows();
    for (const auto& [num, den] : steps()) {
      const ex h = GiNaC::numeric(num, den);
      const GiNaC::matrix phi = exact_phi(M, K, h);
      GiNaC::matrix target(2 * n, 2 * n);
      if (energy) {
        target = exact_energy_form(M, K, h);
      } else {
        for (unsigned i = 0; i < n; ++i) {
          target(i, n + i) = -1;
          target(n + i, i) = 1;
        }
      }
      const bool holds = is_zero_matrix(phi.transpose().mul(target).mul(phi).sub(target)) &&
                         (!energy || is_zero_matrix(target.transpose().sub(target)));
      const auto [gap, gap_within] = core_gap(s, phi, num, den);
      same_map = same_map && gap_within;
      all = all && holds;
      rows.push_back({{"system", s.name}, {"h", std::to_string(num) + "/" + std::to_string(den)}, {"holds_exactly", holds},
                      {"core_phi_mpfr100_relative_gap", gap}});
    }
  }
  judged.own = answer_of(all && same_map);
  judged.if_false = verdict::fails;
  r.evidence["exact"] = {{"kernel", "GiNaC (exact rationals)"},
                         {"method", energy ? "Phi^T Q Phi - Q = 0 and Q symmetric, Q = diag(M^-1, K (I - S/12)(I - S/24)(I - S/8)^-1), "
                                             "S = h^2 M^-1 K; Phi built from the step's equations in GiNaC"
                                           : "Phi^T J Phi - J = 0, J = [[0, -I], [I, 0]] on (p, q); Phi built from the step's "
                                             "equations in GiNaC"},
                         {"cases", rows},
                         {"core", "the core's ndof_simpson_map (Eigen, mpfr:100) is GiNaC's Phi within 64 n^2 eps relative in every case"}};
  return judged;
}

decider_evidence check_ndof_symplectic(const run_context&) { return check_ndof_exact(false); }

decider_evidence check_ndof_energy(const run_context&) {
  decider_evidence judged = check_ndof_exact(true);
  judged.found.note = "The discrete energy for n degrees of freedom is H_d = p^T M^-1 p/2 + q^T K (I - S/12)(I - S/24)(I - S/8)^-1 q/2 with "
           "S = h^2 M^-1 K: the block analogue of (hamiltonien-discret), to which it reduces for n = 1.";
  return judged;
}

/// A GiNaC rational as an exact rational.
rational exact_rational(const GiNaC::numeric& v) {
  std::ostringstream numerator, denominator;
  numerator << v.numer();
  denominator << v.denom();
  return rational(boost::multiprecision::cpp_int(numerator.str()), boost::multiprecision::cpp_int(denominator.str()));
}

/// The coefficients of a polynomial in `x` with rational GiNaC coefficients.
polynomial exact_polynomial(const ex& p, const GiNaC::symbol& x) {
  const ex expanded = GiNaC::expand(p);
  std::vector<rational> c;
  for (int k = 0; k <= expanded.degree(x); ++k) c.push_back(exact_rational(GiNaC::ex_to<GiNaC::numeric>(expanded.coeff(x, k))));
  return polynomial(c.begin(), c.end());
}

/// Φ's stability, decided from its exact characteristic polynomial P(λ) (degree 2n, palindromic as
/// Φ is symplectic): λ⁻ⁿ P(λ) = Q(μ), μ = λ + 1/λ, with λʲ + λ⁻ʲ = T_j(μ) (T_0 = 2, T_1 = μ,
/// T_{j+1} = μ T_j − T_{j−1}). Every eigenvalue is on the unit circle and simple iff Q has n distinct
/// real roots in (−2, 2) (Sturm); a squarefree Q without roots at ±2 and fewer roots there has an
/// eigenvalue off the circle. Else (a repeated μ, or μ = ±2: an eigenvalue ±1) it is not decided here.
enum class exact_stability { stable, unstable, undecided };

exact_stability decide_from_charpoly(const polynomial& P, std::string& why) {
  const long degree_2n = degree(P);
  const std::size_t n = static_cast<std::size_t>(degree_2n / 2);
  for (std::size_t i = 0; i <= 2 * n; ++i) {
    if (P[i] != P[2 * n - i]) {
      why = "the characteristic polynomial is not palindromic: Phi is not symplectic";
      return exact_stability::unstable;
    }
  }
  std::vector<polynomial> T{polynomial({rational(2)}), polynomial({rational(0), rational(1)})};
  for (std::size_t j = 1; j < n; ++j) T.push_back(polynomial({rational(0), rational(1)}) * T[j] - T[j - 1]);
  polynomial Q({P[n]});
  for (std::size_t j = 1; j <= n; ++j) Q += P[n + j] * T[j];
  const std::vector<polynomial> sturm = sturm_sequence(Q);
  const bool squarefree = degree(sturm.back()) == 0;
  const bool at_ends = Q.evaluate(rational(-2)) == 0 || Q.evaluate(rational(2)) == 0;
  const std::size_t inside = at_ends ? 0 : count_real_roots(Q, rational(-2), rational(2));
  why = "Q(mu) = " + std::to_string(inside) + " distinct roots in (-2, 2) of " + std::to_string(n);
  if (!squarefree || at_ends) {
    why += squarefree ? "; a root at mu = +-2 (eigenvalue +-1)" : "; a repeated root";
    return exact_stability::undecided;
  }
  return inside == n ? exact_stability::stable : exact_stability::unstable;
}

/// The modal prediction at x = ω_k² h²: every root of c(x) = det(h² K − x M) in (0, 8) ∪ (12, 24), the
/// scalar stable set (three_term_scheme.hpp's discriminant), endpoints included in the decision: a
/// root at 8, 12 or 24 is not stable (there the scalar map is singular or has a double root ±1).
bool predicted_stable(const polynomial& c, std::string& why) {
  const std::size_t n = static_cast<std::size_t>(degree(c));
  for (const int end : {0, 8, 12, 24}) {
    if (c.evaluate(rational(end)) == 0) {
      why = "a mode at omega_k^2 h^2 = " + std::to_string(end);
      return false;
    }
  }
  const std::size_t first = count_real_roots(c, rational(0), rational(8)), second = count_real_roots(c, rational(12), rational(24));
  why = std::to_string(first) + " modes in (0, 8), " + std::to_string(second) + " in (12, 24), of " + std::to_string(n);
  return first + second == n;
}

/// Stability: Φ's exact characteristic polynomial against the scalar stable set at each ω_k² h², both
/// decided exactly (Sturm) at h = k/20, k = 1..60, for each system.
decider_evidence check_ndof_stability(const run_context&) {
  const GiNaC::symbol lambda("lambda"), x("x");
  json rows = json::array();
  bool all = true;
  std::size_t cases = 0, stable_cases = 0;
  std::string undecided;
  for (const linear_system& system : systems()) {
    const GiNaC::matrix M = exact_matrix(system.mass), K = exact_matrix(system.stiffness);
    for (int k = 1; k <= 60; ++k) {
      throw_if_interrupted();
      const GiNaC::numeric h(k, 20);
      std::string why_phi, why_modes;
      const exact_stability actual = decide_from_charpoly(exact_polynomial(exact_phi(M, K, h).charpoly(lambda), lambda), why_phi);
      const bool predicted = predicted_stable(exact_polynomial(K.mul_scalar(h * h).sub(M.mul_scalar(x)).determinant(), x), why_modes);
      ++cases;
      if (actual == exact_stability::undecided) {
        undecided = system.name + ", h = " + std::to_string(k) + "/20: " + why_phi;
        continue;
      }
      const bool stable = actual == exact_stability::stable;
      stable_cases += stable;
      all = all && stable == predicted;
      if (k % 10 == 0 || stable != predicted) {
        rows.push_back({{"system", system.name}, {"h", std::to_string(k) + "/20"}, {"modes", why_modes}, {"predicted_stable", predicted},
                        {"phi", why_phi}, {"phi_stable", stable}});
      }
    }
  }
  if (!undecided.empty() && all) throw enclosure_undecided("ndof-stability: " + undecided);
  decider_evidence judged;
  claim_result& r = judged.found;
  judged.own = answer_of(all);
  judged.if_false = verdict::fails;
  r.evidence["exact"] = {
      {"method", "exact (rational arithmetic, Sturm sequences), no tolerance: Phi from the step's equations in GiNaC at h = k/20, "
                 "k = 1..60; its characteristic polynomial P(lambda) reduced to Q(mu), mu = lambda + 1/lambda; stable iff Q has "
                 "n distinct roots in (-2, 2). Prediction: every root of det(h^2 K - x M) in (0, 8) or (12, 24), the endpoints "
                 "decided (a root there is not stable)"},
      {"cases", cases},
      {"stable_cases", stable_cases},
      {"rows", rows}};
  return judged;
}

}  // namespace

void add_beyond_ndof_checks(check_registry& checks) {
  checks.add("ndof-symplectic", check_ndof_symplectic);
  checks.add("ndof-energy", check_ndof_energy);
  checks.add("ndof-stability", check_ndof_stability);
}

}  // namespace simpson::verify::detail

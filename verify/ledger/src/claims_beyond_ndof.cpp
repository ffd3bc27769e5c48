// Beyond the paper, several degrees of freedom with a quadratic Lagrangian ½ q̇ᵀMq̇ − ½ qᵀKq: Φ₃'s
// block analogue (core/ndof_linear.hpp) proved symplectic and energy-conserving in exact rational
// arithmetic by GiNaC (a second construction of the map from the step's equations, compared with
// the core's in mpfr:100), and its stability read from the generalized eigenvalues of (K, M).

#include "claims_beyond.hpp"

#include "claim_support.hpp"

#include <simpson/ndof_linear.hpp>
#include <simpson/three_term_scheme.hpp>

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

claim_result check_ndof_exact(bool energy) {
  claim_result r;
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
  r.outcome = all && same_map ? verdict::holds : verdict::fails;
  r.evidence["exact"] = {{"kernel", "GiNaC (exact rationals)"},
                         {"method", energy ? "Phi^T Q Phi - Q = 0 and Q symmetric, Q = diag(M^-1, K (I - S/12)(I - S/24)(I - S/8)^-1), "
                                             "S = h^2 M^-1 K; Phi built from the step's equations in GiNaC"
                                           : "Phi^T J Phi - J = 0, J = [[0, -I], [I, 0]] on (p, q); Phi built from the step's "
                                             "equations in GiNaC"},
                         {"cases", rows},
                         {"core", "the core's ndof_simpson_map (Eigen, mpfr:100) is GiNaC's Phi within 64 n^2 eps relative in every case"}};
  return r;
}

claim_result check_ndof_symplectic(const run_context&) { return check_ndof_exact(false); }

claim_result check_ndof_energy(const run_context&) {
  claim_result r = check_ndof_exact(true);
  r.note = "The discrete energy for n degrees of freedom is H_d = p^T M^-1 p/2 + q^T K (I - S/12)(I - S/24)(I - S/8)^-1 q/2 with "
           "S = h^2 M^-1 K: the block analogue of (hamiltonien-discret), to which it reduces for n = 1.";
  return r;
}

/// Stability: Φ's eigenvalues against the scalar stable set at each ω_k h, ω_k² the generalized
/// eigenvalues of (K, M), in double (Eigen).
claim_result check_ndof_stability(const run_context&) {
  const auto& pendulum = systems().front();
  Eigen::MatrixXd M(2, 2), K(2, 2);
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      M(i, j) = static_cast<double>(pendulum.mass[i][j].first) / pendulum.mass[i][j].second;
      K(i, j) = static_cast<double>(pendulum.stiffness[i][j].first) / pendulum.stiffness[i][j].second;
    }
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(K, M);
  const Eigen::VectorXd omega2 = modes.eigenvalues();
  // A mode is stable where its characteristic roots are complex of modulus 1: Δ(ω_k² h²) < 0 with
  // the core's discriminant (three_term_scheme.hpp), i.e. ω_k² h² in (0, 8) ∪ (12, 24).
  const auto stable_scalar = [](double x) { return x > 0 && discriminant(x) < 0; };
  json rows = json::array();
  bool all = true;
  for (int k = 1; k <= 60; ++k) {
    const double h = 0.05 * k;
    bool predicted = true;
    for (int i = 0; i < omega2.size(); ++i) {
      const double x = omega2(i) * h * h;
      if (std::abs(x - 8) < 1e-6 || std::abs(x - 12) < 1e-6 || std::abs(x - 24) < 1e-6) continue;  // an endpoint: skip
      predicted = predicted && stable_scalar(x);
    }
    const Eigen::MatrixXd phi = ndof_simpson_map<double>(M, K, h);
    const double radius = Eigen::EigenSolver<Eigen::MatrixXd>(phi).eigenvalues().cwiseAbs().maxCoeff();
    // On the unit circle up to the eigen-solver's round-off: a backward-stable QR perturbs Φ by
    // ~n eps |Φ| and, Φ being non-normal, moves its eigenvalues by up to κ(eigenvectors) times that;
    // 4096 eps max|Φ_ij| covers κ up to ~1000 at n = 4 (an unstable step has radius > 1 + 1e-3 here).
    const bool on_circle = radius <= 1 + 4096 * std::numeric_limits<double>::epsilon() * phi.cwiseAbs().maxCoeff();
    all = all && on_circle == predicted;
    if (k % 5 == 0 || on_circle != predicted) {
      rows.push_back({{"h", h}, {"omega_k2_h2", {omega2(0) * h * h, omega2(1) * h * h}}, {"predicted_stable", predicted},
                      {"spectral_radius", radius}});
    }
  }
  claim_result r;
  r.outcome = all ? verdict::holds : verdict::fails;
  r.evidence["numeric"] = {{"system", pendulum.name},
                           {"omega_k2", {omega2(0), omega2(1)}},
                           {"omega_k2_exact", "2 -+ sqrt(2)"},
                           {"method", "h = 0.05, 0.10, ..., 3.00: Phi's spectral radius (Eigen, double) against the prediction "
                                      "'every omega_k^2 h^2 in (0, 8) or (12, 24)'; rows every 0.25 and wherever they disagree"},
                           {"rows", rows}};
  return r;
}

}  // namespace

void add_beyond_ndof_claims(std::vector<claim>& claims) {
  claims.push_back({"ndof-symplectic", "beyond", "Phi3",
                    "(Beyond the paper.) For L = q'^T M q'/2 - q^T K q/2 the Simpson map Phi_3 (2n x 2n) satisfies Phi^T J Phi = J.",
                    {"exact"}, verdict::holds, check_ndof_symplectic});
  claims.push_back({"ndof-energy", "beyond", "hamiltonien-discret",
                    "(Beyond the paper.) Phi_3 conserves the block analogue of the discrete energy H_d.", {"exact"},
                    verdict::holds, check_ndof_energy});
  claims.push_back({"ndof-stability", "beyond", "stabilite",
                    "(Beyond the paper.) Phi_3 is stable iff every omega_k h lies in the stable set of the scalar case, "
                    "omega_k^2 the generalized eigenvalues of (K, M).",
                    {"numeric"}, verdict::holds, check_ndof_stability});
}

}  // namespace simpson::verify::detail

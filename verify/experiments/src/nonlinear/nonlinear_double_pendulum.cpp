// The nonlinear section's linearized double pendulum (the authors' 2024 work on quadratic
// Lagrangians): Φ₃ for two degrees of freedom against the exact modal solution in mpfr, and the
// block discrete energy H_d (ndof_linear.hpp) over long runs in double and in mpfr.

#include "nonlinear_parts.hpp"

#include <simpson/verify/floating_tools.hpp>
#include <simpson/verify/interruption.hpp>
#include <simpson/verify/progress.hpp>

#include <simpson/separable_system.hpp>  // ndof_linear.hpp, dense_vector

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace simpson::verify::detail {
namespace {

/// m1 = m2 = l1 = l2 = g = 1: L = ½ q̇ᵀ M q̇ − ½ qᵀ K q with M = [[2, 1], [1, 1]], K = diag(2, 1).
template <class Real>
std::pair<dense_matrix<Real>, dense_matrix<Real>> double_pendulum() {
  dense_matrix<Real> M(2, 2), K(2, 2);
  M << Real(2), Real(1), Real(1), Real(1);
  K << Real(2), Real(0), Real(0), Real(1);
  return {M, K};
}

/// The exact solution of M q̈ + K q = 0 for 2 × 2 M, K in Real: the modes ω_k² = λ_k, roots of
/// det(K − λ M) = 0, with eigenvectors v_k = (K₁₂ − λ_k M₁₂, −(K₁₁ − λ_k M₁₁)) (the first row's kernel);
/// q(t) = Σ_k v_k (a_k cos ω_k t + b_k sin ω_k t / ω_k), (a, b) from q(0) and q̇(0) = M⁻¹ p(0).
template <class Real>
dense_vector<Real> modal_state(const dense_matrix<Real>& M, const dense_matrix<Real>& K, const dense_vector<Real>& q0,
                               const dense_vector<Real>& p0, const Real& t) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const Real a = M.determinant(), b = -(K(0, 0) * M(1, 1) + K(1, 1) * M(0, 0) - 2 * K(0, 1) * M(0, 1)), c = K.determinant();
  const Real root = sqrt(Real(b * b - 4 * a * c));
  const Real lambda[2] = {(-b - root) / (2 * a), (-b + root) / (2 * a)};
  dense_matrix<Real> V(2, 2);
  for (int k = 0; k < 2; ++k) {
    V(0, k) = K(0, 1) - lambda[k] * M(0, 1);
    V(1, k) = -(K(0, 0) - lambda[k] * M(0, 0));
  }
  const Eigen::FullPivLU<dense_matrix<Real>> modes(V);
  const dense_vector<Real> a0 = modes.solve(q0), b0 = modes.solve(dense_vector<Real>(M.fullPivLu().solve(p0)));
  dense_vector<Real> q = dense_vector<Real>::Zero(2), p = dense_vector<Real>::Zero(2);
  for (int k = 0; k < 2; ++k) {
    const Real w = sqrt(lambda[k]);
    const Real position = a0(k) * cos(Real(w * t)) + b0(k) * sin(Real(w * t)) / w;
    const Real velocity = -a0(k) * w * sin(Real(w * t)) + b0(k) * cos(Real(w * t));
    q += scaled(dense_vector<Real>(V.col(k)), position);
    p += scaled(dense_vector<Real>(V.col(k)), velocity);
  }
  dense_vector<Real> y(4);
  y << dense_vector<Real>(M * p), q;  // (p, q) with p = M q̇
  return y;
}

template <class Real>
dense_vector<Real> start_state() {
  dense_vector<Real> y(4);
  y << Real(0), Real(0), Real(1) / 10, Real(-1) / 20;
  return y;
}

/// The largest relative change of H_d = ½ yᵀ Q y over `steps` steps of Φ₃, and of H = ½ yᵀ E y.
template <class Real>
std::pair<Real, Real> energy_changes(const Real& h, long long steps) {
  using std::abs;
  const auto [M, K] = double_pendulum<Real>();
  const dense_matrix<Real> phi = ndof_simpson_map(M, K, h), Q = ndof_discrete_energy_form(M, K, h);
  dense_matrix<Real> E = dense_matrix<Real>::Zero(4, 4);
  E.topLeftCorner(2, 2) = M.inverse();
  E.bottomRightCorner(2, 2) = K;
  dense_vector<Real> y = start_state<Real>();
  const Real Hd0 = y.dot(Q * y), H0 = y.dot(E * y);
  Real hd(0), hh(0);
  for (long long j = 1; j <= steps; ++j) {
    if ((j & 4095) == 0) throw_if_interrupted();
    y = phi * y;
    hd = std::max(hd, Real(abs(Real(y.dot(Q * y) - Hd0)) / abs(Hd0)));
    hh = std::max(hh, Real(abs(Real(y.dot(E * y) - H0)) / H0));
  }
  return {hd, hh};
}

}  // namespace

void add_double_pendulum(const nonlinear_settings& s, section_result& out) {
  const precision prec = precision::mpfr_digits(s.mpfr_digits);
  const double T = 10;
  table rows{"double_pendulum", "The linearized double pendulum: errors and the discrete energy",
             fmt::format("The system of the authors' 2024 paper (Axioms 13(4):255) with our parameters (that paper's values "
                         "were not at hand): m₁ = m₂ = l₁ = l₂ = g = 1, L = ½ q̇ᵀMq̇ − ½ qᵀKq with M = [[2, 1], [1, 1]], "
                         "K = diag(2, 1) (ω² = 2 ∓ √2), q(0) = (0.1, −0.05) rad, p(0) = 0, T = {}, h = T/N. Φ₃ is the 4 × 4 block map "
                         "(ndof_linear.hpp); errors (largest component) in {} against the exact modal solution in the same "
                         "precision. H_d is the block discrete energy ½ pᵀM⁻¹p + ½ qᵀK(I − S/12)(I − S/24)(I − S/8)⁻¹q, "
                         "S = h²M⁻¹K (claim ndof-energy proves it conserved exactly): its largest relative change over the "
                         "N steps in {} and over {} steps in double, beside H's.",
                         T, prec.name(), prec.name(), s.energy_steps),
             {{"N", "N"},
              {"h", "h"},
              {"error_q", "max |q_N − q(T)|"},
              {"error_p", "max |p_N − p(T)|"},
              {"order_q", "order q"},
              {"Hd_change_mpfr", "H_d rel. change (" + prec.name() + ")"},
              {"Hd_change_double", "H_d rel. change (double)"},
              {"H_change_double", "H rel. change (double)"},
              {"status", "status"}}};
  rows.csv_file = "nonlinear_double_pendulum.csv";
  panel errors{"Error at T against N (" + prec.name() + ")", {"N", true}, {"largest component error", true}, {}, "bottom left"};
  panel energies{"Energy over " + std::to_string(s.energy_steps) + " steps (double)", {"N (h = T/N)", true},
                 {"largest relative change", true}, {}, "center right"};
  series eq("q", line_style::lines_points, 1, 7), ep("p", line_style::lines_points, 2, 5, 2);
  series hd("H_d (conserved)", line_style::lines_points, 3, 9), hh("H", line_style::lines_points, 4, 13, 2);
  visit_mpfr(s.mpfr_digits, [&](auto tag) {
    using Real = typename decltype(tag)::type;
    const auto [M, K] = double_pendulum<Real>();
    const dense_vector<Real> y0 = start_state<Real>();
    const dense_vector<Real> end = modal_state<Real>(M, K, y0.tail(2), y0.head(2), Real(T));
    std::vector<Real> errors_q;
    std::vector<long long> ok_N;
    std::vector<table_row> pending;
    for (const long long N : s.double_pendulum_N) {
      const Real h = Real(T) / Real(N);
      using std::abs;
      table_row row{figure::integer(N), figure::of(h)};
      try {
        const dense_matrix<Real> phi = ndof_simpson_map(M, K, h), Q = ndof_discrete_energy_form(M, K, h);
        dense_vector<Real> y = y0;
        const Real Hd0 = y.dot(Q * y);
        Real hd_change(0);
        for (long long j = 1; j <= N; ++j) {
          y = phi * y;
          hd_change = std::max(hd_change, Real(abs(Real(y.dot(Q * y) - Hd0)) / abs(Hd0)));
        }
        const Real error_q = dense_vector<Real>(y.tail(2) - end.tail(2)).cwiseAbs().maxCoeff();
        const Real error_p = dense_vector<Real>(y.head(2) - end.head(2)).cwiseAbs().maxCoeff();
        const std::pair<double, double> in_double = energy_changes<double>(static_cast<double>(T) / static_cast<double>(N), s.energy_steps);
        errors_q.push_back(error_q);
        ok_N.push_back(N);
        row.insert(row.end(), {figure::of(error_q), figure::of(error_p), figure{}, figure::of(hd_change), figure::of(in_double.first),
                               figure::of(in_double.second), figure::text("ok")});
        eq.add(figure::integer(N), figure::of(error_q));
        ep.add(figure::integer(N), figure::of(error_p));
        hd.add(figure::integer(N), figure::of(in_double.first));
        hh.add(figure::integer(N), figure::of(in_double.second));
      } catch (const std::domain_error& e) {
        row.insert(row.end(), {figure{}, figure{}, figure{}, figure{}, figure{}, figure{}, figure::fault(std::string("failed: ") + e.what())});
      }
      progress_step(s.progress, "nonlinear", fmt::format("double pendulum N = {}", N));
      pending.push_back(std::move(row));
    }
    const std::vector<Real> orders = observed_orders(ok_N, errors_q);
    std::size_t ok = 0;
    for (table_row& row : pending) {
      if (row.back().is_fault()) {
        rows.add(std::move(row));
        continue;
      }
      if (ok > 0) row[4] = figure::of(orders[ok - 1]);
      ++ok;
      rows.add(std::move(row));
    }
  });
  errors.curves = {eq, ep};
  energies.curves = {hd, hh};
  out.add(std::move(rows));
  out.add(plot_description{"nonlinear_double_pendulum",
                           "The linearized double pendulum: error at T against N (log-log), and the largest relative change of "
                           "H_d and of H over long runs in double",
                           {errors, energies}, 2, 1100, 450});
}

}  // namespace simpson::verify::detail

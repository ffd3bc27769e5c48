// The family's implicit step for a general V, and its order on the pendulum (galerkin_pendulum.hpp).

#include <simpson/verify/galerkin_pendulum.hpp>

#include <simpson/pendulum_exact.hpp>

#include <boost/math/special_functions/legendre.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace simpson::verify {
namespace {

using real = long double;
using vector = Eigen::Matrix<real, Eigen::Dynamic, 1>;
using matrix = Eigen::Matrix<real, Eigen::Dynamic, Eigen::Dynamic>;

/// The zeros of P′_n on (−1, 1), increasing: one between each pair of consecutive zeros of P_n,
/// found by bisection on the sign of P′_n.
std::vector<real> legendre_prime_zeros(int n) {
  std::vector<real> zeros;  // of P_n, all of them, increasing
  for (const real z : boost::math::legendre_p_zeros<real>(n)) {
    zeros.push_back(z);
    if (z > 0) zeros.push_back(-z);
  }
  std::sort(zeros.begin(), zeros.end());
  std::vector<real> out;
  for (std::size_t k = 0; k + 1 < zeros.size(); ++k) {
    real lo = zeros[k], hi = zeros[k + 1];
    const real sign_lo = boost::math::legendre_p_prime(n, lo);
    for (int it = 0; it < 200 && hi - lo > 0; ++it) {
      const real mid = (lo + hi) / 2;
      if (mid == lo || mid == hi) break;
      ((boost::math::legendre_p_prime(n, mid) > 0) == (sign_lo > 0) ? lo : hi) = mid;
    }
    out.push_back((lo + hi) / 2);
  }
  return out;
}

/// The interpolant's basis 1 − τ, τ, τᵏ(1 − τ) (as galerkin_member.cpp) and its derivative at τ.
void basis_at(int s, real tau, std::vector<real>& value, std::vector<real>& slope) {
  value.assign(static_cast<std::size_t>(s) + 1, 0);
  slope.assign(static_cast<std::size_t>(s) + 1, 0);
  value[0] = 1 - tau, slope[0] = -1;
  value[1] = tau, slope[1] = 1;
  for (int k = 1; k < s; ++k) {
    const real power = std::pow(tau, static_cast<real>(k));
    value[static_cast<std::size_t>(k) + 1] = power * (1 - tau);
    slope[static_cast<std::size_t>(k) + 1] = k * std::pow(tau, static_cast<real>(k - 1)) * (1 - tau) - power;
  }
}

/// The step's tables: the basis and its slope at each node.
struct step_tables {
  int s;
  numeric_rule rule;
  std::vector<std::vector<real>> value, slope;  // [node][basis function]
};

/// ∂L_h/∂x and its Hessian at x = (q_j, q_{j+1}, Q_1 …), V = 1 − cos q, m = ω = 1.
void gradient(const step_tables& t, real h, const vector& x, vector& g, matrix& H) {
  const Eigen::Index n = x.size();
  g = vector::Zero(n);
  H = matrix::Zero(n, n);
  for (std::size_t i = 0; i < t.rule.nodes.size(); ++i) {
    real q = 0, dq = 0;
    for (Eigen::Index a = 0; a < n; ++a) {
      q += x(a) * t.value[i][static_cast<std::size_t>(a)];
      dq += x(a) * t.slope[i][static_cast<std::size_t>(a)];
    }
    const real w = t.rule.weights[i];
    for (Eigen::Index a = 0; a < n; ++a) {
      const real va = t.value[i][static_cast<std::size_t>(a)], sa = t.slope[i][static_cast<std::size_t>(a)];
      g(a) += w * (dq * sa / h - h * std::sin(q) * va);
      for (Eigen::Index b = 0; b < n; ++b) {
        H(a, b) += w * (sa * t.slope[i][static_cast<std::size_t>(b)] / h - h * std::cos(q) * va * t.value[i][static_cast<std::size_t>(b)]);
      }
    }
  }
}

/// One step: unknowns y = (q_{j+1}, Q_1 …) from p_j = −∂L/∂q_j and ∂L/∂Q_k = 0, by Newton; then
/// p_{j+1} = ∂L/∂q_{j+1}. False when Newton does not converge.
bool step(const step_tables& t, real h, real& p, real& q) {
  const Eigen::Index n = t.s + 1;
  vector x = vector::Zero(n);
  x(0) = q;
  x(1) = q + h * p;
  for (Eigen::Index k = 2; k < n; ++k) x(k) = 0;
  vector g;
  matrix H;
  bool converged = false;
  real previous = std::numeric_limits<real>::infinity();
  for (int it = 0; it < 60; ++it) {
    gradient(t, h, x, g, H);
    // Residual: F_0 = −g_0 − p (from p = −∂L/∂q_j), F_k = g_k for the internal unknowns; in y = x(1…).
    vector F(n - 1);
    matrix J(n - 1, n - 1);
    F(0) = -g(0) - p;
    for (Eigen::Index b = 1; b < n; ++b) J(0, b - 1) = -H(0, b);
    for (Eigen::Index a = 2; a < n; ++a) {
      F(a - 1) = g(a);
      for (Eigen::Index b = 1; b < n; ++b) J(a - 1, b - 1) = H(a, b);
    }
    const vector dy = J.fullPivLu().solve(-F);
    if (!dy.allFinite()) return false;
    x.tail(n - 1) += dy;
    // Converged at a few unit round-offs, or where the updates stop shrinking once they are below
    // 1e-9 of the unknowns' size: round-off in the residual (the internal basis is not orthogonal)
    // then decides them, and further iterations only wander.
    const real size = dy.cwiseAbs().maxCoeff(), scale = std::max<real>(1, x.cwiseAbs().maxCoeff());
    if (size <= 4 * std::numeric_limits<real>::epsilon() * scale || (previous < 1e-9L * scale && size >= previous / 2)) {
      converged = true;
      break;
    }
    previous = size;
  }
  if (!converged) return false;
  gradient(t, h, x, g, H);
  p = g(1);
  q = x(1);
  return std::isfinite(static_cast<double>(p)) && std::isfinite(static_cast<double>(q));
}

}  // namespace

numeric_rule nodes_and_weights(const quadrature_rule& rule) {
  numeric_rule out;
  const int k = rule.points;
  switch (rule.family) {
    case quadrature_family::newton_cotes:
      for (int i = 0; i < k; ++i) out.nodes.push_back(static_cast<real>(i) / (k - 1));
      break;
    case quadrature_family::gauss:
      for (const real z : boost::math::legendre_p_zeros<real>(k)) {
        out.nodes.push_back((1 + z) / 2);
        if (z > 0) out.nodes.push_back((1 - z) / 2);
      }
      break;
    case quadrature_family::lobatto:
      out.nodes = {0, 1};
      for (const real z : legendre_prime_zeros(k - 1)) out.nodes.push_back((1 + z) / 2);
      break;
  }
  std::sort(out.nodes.begin(), out.nodes.end());
  const std::vector<rational> mu = quadrature_moments(rule, k - 1);
  const Eigen::Index n = static_cast<Eigen::Index>(out.nodes.size());
  matrix V(n, n);
  vector m(n);
  for (Eigen::Index row = 0; row < n; ++row) {
    for (Eigen::Index col = 0; col < n; ++col) V(row, col) = std::pow(out.nodes[static_cast<std::size_t>(col)], static_cast<real>(row));
    m(row) = static_cast<real>(boost::multiprecision::numerator(mu[static_cast<std::size_t>(row)]).convert_to<long double>() /
                               boost::multiprecision::denominator(mu[static_cast<std::size_t>(row)]).convert_to<long double>());
  }
  const vector w = V.fullPivLu().solve(m);
  out.weights.assign(w.data(), w.data() + n);
  return out;
}

pendulum_order measure_pendulum_order(const galerkin_member& member, const std::vector<long long>& steps) {
  pendulum_order out;
  step_tables t{member.degree, nodes_and_weights(member.rule), {}, {}};
  for (const real c : t.rule.nodes) {
    std::vector<real> v, d;
    basis_at(member.degree, c, v, d);
    t.value.push_back(v);
    t.slope.push_back(d);
  }
  const pendulum_from_rest<real> exact{1, 1, 1};
  // Compared at t = 5, not after a whole period: a map that only returns to its start (an
  // inconsistent member can) must not look exact.
  const real duration = 5;
  const phase_point<real> start = exact.at(0), end = exact.at(duration);
  for (const long long n : steps) {
    real p = start.p, q = start.q;
    const real h = duration / static_cast<real>(n);
    for (long long j = 0; j < n; ++j) {
      if (!step(t, h, p, q)) {
        out.failure = "Newton's method did not converge at N = " + std::to_string(n) + ", step " + std::to_string(j);
        return out;
      }
    }
    out.steps.push_back(n);
    out.errors.push_back(std::max(std::abs(p - end.p), std::abs(q - end.q)));
  }
  for (std::size_t k = 0; k + 1 < out.errors.size(); ++k) {
    out.observed.push_back(std::log2(out.errors[k] / out.errors[k + 1]));
    if (out.errors[k + 1] > 1e-15L) out.order = out.observed.back();
  }
  out.ran = true;
  return out;
}

}  // namespace simpson::verify

#pragma once
// Beyond the paper: the Simpson variational integrator for n degrees of freedom and any smooth V,
// and its implicit peers (partitioned Runge–Kutta pairs) solved the same way. The equations are
// nonlinear_simpson_step.hpp's with the mass matrix M for m and ∇V for V' (L = ½ q̇ᵀ M q̇ − V(q)
// enters the scalar derivation only through m q̇ and V', so each term keeps its place):
//   F(x) = M (x − q) − (h/2) p + (h²/12) ∇V(q) + (h²/24) ∇V(x) = 0            (internal node)
//   q' = q + h M⁻¹ (p − (h/6)(∇V(q) + 2 ∇V(x)))
//   p' = p − (h/6)(∇V(q) + 4 ∇V(x) + ∇V(q'))                                  (Simpson's rule)
// Newton's method on F with Jacobian M + (h²/24) ∇²V(x), solved by Eigen's LU with partial pivoting.

#include <simpson/nonlinear_partitioned_rk.hpp>
#include <simpson/separable_system.hpp>

#include <array>
#include <cmath>
#include <vector>

namespace simpson {

/// What a nonlinear n-DOF step found, and how Newton's method got there.
template <class Real>
struct ndof_step_result {
  ndof_state<Real> state;
  int newton_iterations = 0;
  Real residual;        // max_i |F_i| at the end
  Real residual_bound;  // 16 eps times the largest sum of the magnitudes of a component's terms
};

namespace detail {
/// Checks a residual vector against the bound 16 eps max_i Σ|terms of component i| (normwise: a
/// component whose own terms vanish, such as a stage Q₁ = q = 0 of Lobatto IIIA, is solved to the
/// system's round-off, not to zero); records the largest residual and the bound. Returns false when
/// a value is not finite.
template <class Real>
bool record_residual(const dense_vector<Real>& residual, const dense_vector<Real>& terms, Real& largest, Real& bound,
                     bool& within) {
  using std::abs;
  largest = Real(0);
  bound = Real(0);
  for (Eigen::Index i = 0; i < residual.size(); ++i) {
    const Real r = abs(residual(i)), b = 16 * eps<Real>() * terms(i);
    if (!finite(r) || !finite(b)) return false;
    if (r > largest) largest = r;
    if (b > bound) bound = b;
  }
  within = largest <= bound;
  return true;
}

/// A Newton correction that is finite (a singular Jacobian gives ∞ or NaN in the LU solve).
template <class Real>
bool finite_vector(const dense_vector<Real>& v) {
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (!finite(v(i))) return false;
  }
  return true;
}
}  // namespace detail

/// The force a step ends with, kept for the step that starts there (first same as last): a run of
/// Störmer–Verlet steps, of Yoshida's substeps or of Simpson steps then evaluates that ∇V once, as
/// their users write them. Valid for the q it was evaluated at only.
template <class Real>
struct last_force {
  dense_vector<Real> q, gradient;
  bool valid = false;

  /// The force at `at`: the kept one when it was evaluated at these very values, else `evaluate(at)`.
  template <class Evaluate>
  dense_vector<Real> at(const dense_vector<Real>& at_q, const Evaluate& evaluate) const {
    if (valid && q.size() == at_q.size() && (q.array() == at_q.array()).all()) return gradient;
    return dense_vector<Real>(evaluate(at_q));
  }
  /// Evaluates the force at the step's end and keeps it for the next step's start.
  template <class Evaluate>
  const dense_vector<Real>& keep(const dense_vector<Real>& end_q, const Evaluate& evaluate) {
    q = end_q;
    gradient = evaluate(end_q);
    valid = true;
    return gradient;
  }
};

/// One Simpson step for n degrees of freedom: Newton's method on F from x₀ = q + (h/2) M⁻¹ p (the
/// scalar step's rule), until max_i |F_i| ≤ 16 eps max_i Σ|terms of F_i|. Throws std::domain_error like
/// simpson_nonlinear_step: never a silent result. The force at y.q is taken from `kept` when it was
/// evaluated there, and the force at the new q kept (the end of the impulse is the next step's start).
template <class Real, class Potential>
ndof_step_result<Real> simpson_ndof_step(const separable_system<Real, Potential>& s, const Real& h, const ndof_state<Real>& y,
                                         last_force<Real>& kept) {
  const Potential& V = s.potential();
  const dense_matrix<Real>& M = s.mass();
  const dense_matrix<Real> M_abs = M.cwiseAbs();
  const Real h2 = h * h;
  const auto gradient = [&V](const dense_vector<Real>& at) { return V.gradient(at); };
  const dense_vector<Real> force_q = kept.at(y.q, gradient);
  const dense_vector<Real> fixed = scaled(y.p, Real(-h / 2)) + scaled(force_q, Real(h2 / 12));
  const dense_vector<Real> fixed_terms = scaled(dense_vector<Real>(y.p.cwiseAbs()), Real(h / 2)) +
                                         scaled(dense_vector<Real>(force_q.cwiseAbs()), Real(h2 / 12)) + M_abs * y.q.cwiseAbs();
  ndof_step_result<Real> out{y, 0, Real(0), Real(0)};
  dense_vector<Real> x = y.q + scaled(s.mass_solve(y.p), Real(h / 2));
  for (;;) {
    const dense_vector<Real> force_x = V.gradient(x);
    const dense_vector<Real> residual = M * dense_vector<Real>(x - y.q) + fixed + scaled(force_x, Real(h2 / 24));
    // The condition: the sum of the magnitudes of F_i's terms.
    const dense_vector<Real> terms = fixed_terms + M_abs * x.cwiseAbs() + scaled(dense_vector<Real>(force_x.cwiseAbs()), Real(h2 / 24));
    bool within = false;
    if (!detail::record_residual(residual, terms, out.residual, out.residual_bound, within)) break;
    if (within) {
      const dense_vector<Real> impulse_half = y.p - scaled(dense_vector<Real>(force_q + 2 * force_x), Real(h / 6));
      out.state.q = y.q + scaled(s.mass_solve(impulse_half), h);
      const dense_vector<Real>& force_end = kept.keep(out.state.q, gradient);
      out.state.p = y.p - scaled(dense_vector<Real>(force_q + 4 * force_x + force_end), Real(h / 6));
      return out;
    }
    if (out.newton_iterations == max_newton_iterations) break;
    const dense_matrix<Real> jacobian = M + scaled(V.hessian(x), Real(h2 / 24));
    const dense_vector<Real> delta = jacobian.partialPivLu().solve(residual);
    if (!detail::finite_vector(delta)) break;
    x -= delta;
    ++out.newton_iterations;
  }
  detail::throw_newton_failure("simpson::simpson_ndof_step", out.newton_iterations, out.residual, out.residual_bound);
}

/// The same step evaluating both ends' forces (nothing kept).
template <class Real, class Potential>
ndof_step_result<Real> simpson_ndof_step(const separable_system<Real, Potential>& s, const Real& h, const ndof_state<Real>& y) {
  last_force<Real> none;
  return simpson_ndof_step(s, h, y, none);
}

/// One step of a partitioned Runge–Kutta pair for n degrees of freedom, its stage equations
///   R_i = Q_i − q − h c_i M⁻¹ p + h² Σ_k (A Â)_ik M⁻¹ ∇V(Q_k) = 0
/// (the stage momenta P_j = p − h Σ_k â_jk ∇V(Q_k) substituted) solved by Newton's method from
/// Q_i = q + c_i h M⁻¹ p with the block Jacobian δ_ik I + h² (A Â)_ik M⁻¹ ∇²V(Q_k), until the
/// residual is within 16 eps of the largest sum of a component's term magnitudes (record_residual);
/// then q' = q + h M⁻¹ Σ_j b_j P_j, p' = p − h Σ_k b̂_k ∇V(Q_k).
/// Explicit pairs (RK4) converge in one iteration. Throws std::domain_error like simpson_ndof_step.
template <class Real, class Potential>
ndof_step_result<Real> prk_ndof_step(const butcher_tableau<Real>& for_q, const butcher_tableau<Real>& for_p,
                                     const stage_coupling<Real>& c, const separable_system<Real, Potential>& s, const Real& h,
                                     const ndof_state<Real>& y) {
  using std::abs;
  const Potential& V = s.potential();
  const Eigen::Index n = s.dimension(), stages = static_cast<Eigen::Index>(c.nodes.size());
  const Real h2 = h * h;
  const dense_vector<Real> velocity = s.mass_solve(y.p);
  dense_vector<Real> Q(n * stages);  // the stages stacked
  for (Eigen::Index i = 0; i < stages; ++i) Q.segment(i * n, n) = y.q + scaled(velocity, Real(c.nodes[static_cast<std::size_t>(i)] * h));
  std::vector<dense_vector<Real>> accel(static_cast<std::size_t>(stages));  // M⁻¹ ∇V(Q_k)
  std::vector<dense_vector<Real>> forces(static_cast<std::size_t>(stages));
  ndof_step_result<Real> out{y, 0, Real(0), Real(0)};
  for (;;) {
    for (Eigen::Index k = 0; k < stages; ++k) {
      forces[static_cast<std::size_t>(k)] = V.gradient(dense_vector<Real>(Q.segment(k * n, n)));
      accel[static_cast<std::size_t>(k)] = s.mass_solve(forces[static_cast<std::size_t>(k)]);
    }
    dense_vector<Real> residual(n * stages), terms(n * stages);
    for (Eigen::Index i = 0; i < stages; ++i) {
      const Real ci = c.nodes[static_cast<std::size_t>(i)];
      dense_vector<Real> r = dense_vector<Real>(Q.segment(i * n, n)) - y.q - scaled(velocity, Real(h * ci));
      // The condition: the sum of the magnitudes of R_i's terms.
      dense_vector<Real> t = dense_vector<Real>(Q.segment(i * n, n).cwiseAbs()) + y.q.cwiseAbs() +
                             scaled(dense_vector<Real>(velocity.cwiseAbs()), Real(abs(Real(h * ci))));
      for (Eigen::Index k = 0; k < stages; ++k) {
        const Real w = h2 * c.product[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)];
        r += scaled(accel[static_cast<std::size_t>(k)], w);
        t += scaled(dense_vector<Real>(accel[static_cast<std::size_t>(k)].cwiseAbs()), Real(abs(w)));
      }
      residual.segment(i * n, n) = r;
      terms.segment(i * n, n) = t;
    }
    bool within = false;
    if (!detail::record_residual(residual, terms, out.residual, out.residual_bound, within)) break;
    if (within) {
      dense_vector<Real> momentum_sum = dense_vector<Real>::Zero(n);
      out.state.p = y.p;
      for (Eigen::Index j = 0; j < stages; ++j) {
        dense_vector<Real> P = y.p;
        for (Eigen::Index k = 0; k < stages; ++k) {
          P -= scaled(forces[static_cast<std::size_t>(k)], Real(h * for_p.a[static_cast<std::size_t>(j)][static_cast<std::size_t>(k)]));
        }
        momentum_sum += scaled(P, for_q.b[static_cast<std::size_t>(j)]);
        out.state.p -= scaled(forces[static_cast<std::size_t>(j)], Real(h * for_p.b[static_cast<std::size_t>(j)]));
      }
      out.state.q = y.q + scaled(s.mass_solve(momentum_sum), h);
      return out;
    }
    if (out.newton_iterations == max_newton_iterations) break;
    dense_matrix<Real> jacobian = dense_matrix<Real>::Identity(n * stages, n * stages);
    for (Eigen::Index k = 0; k < stages; ++k) {
      const dense_matrix<Real> curvature = s.mass_solve(V.hessian(dense_vector<Real>(Q.segment(k * n, n))));
      for (Eigen::Index i = 0; i < stages; ++i) {
        const Real w = h2 * c.product[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)];
        if (w != 0) jacobian.block(i * n, k * n, n, n) += scaled(curvature, w);
      }
    }
    const dense_vector<Real> delta = jacobian.partialPivLu().solve(residual);
    if (!detail::finite_vector(delta)) break;
    Q -= delta;
    ++out.newton_iterations;
  }
  detail::throw_newton_failure("simpson::prk_ndof_step", out.newton_iterations, out.residual, out.residual_bound);
}

/// One Störmer–Verlet step of size τ (kick–drift–kick): p½ = p − (τ/2) ∇V(q), q' = q + τ M⁻¹ p½,
/// p' = p½ − (τ/2) ∇V(q').
template <class Real, class Potential>
ndof_state<Real> stormer_verlet_ndof_step(const separable_system<Real, Potential>& s, const Real& tau, const ndof_state<Real>& y) {
  const dense_vector<Real> p_half = y.p - scaled(s.potential().gradient(y.q), Real(tau / 2));
  ndof_state<Real> out{p_half, y.q + scaled(s.mass_solve(p_half), tau)};
  out.p -= scaled(s.potential().gradient(out.q), Real(tau / 2));
  return out;
}

/// Yoshida's composition (stormer_verlet.hpp's weights): Störmer–Verlet steps of w₁h, w₀h, w₁h.
template <class Real, class Potential>
ndof_state<Real> yoshida_ndof_step(const separable_system<Real, Potential>& s, const std::array<Real, 3>& weights, const Real& h,
                                   ndof_state<Real> y) {
  for (const Real& w : weights) y = stormer_verlet_ndof_step(s, Real(w * h), y);
  return y;
}

/// Störmer–Verlet's step as stormer_verlet_ndof_step, the force at y.q taken from `kept` when it was
/// evaluated there, and the force at the new q kept.
template <class Real, class Potential>
ndof_state<Real> stormer_verlet_ndof_step(const separable_system<Real, Potential>& s, const Real& tau, const ndof_state<Real>& y,
                                          last_force<Real>& kept) {
  const auto gradient = [&s](const dense_vector<Real>& at) { return s.potential().gradient(at); };
  const dense_vector<Real> p_half = y.p - scaled(kept.at(y.q, gradient), Real(tau / 2));
  ndof_state<Real> out{p_half, y.q + scaled(s.mass_solve(p_half), tau)};
  out.p -= scaled(kept.keep(out.q, gradient), Real(tau / 2));
  return out;
}

/// Yoshida's composition with its substeps' forces kept across them and across steps.
template <class Real, class Potential>
ndof_state<Real> yoshida_ndof_step(const separable_system<Real, Potential>& s, const std::array<Real, 3>& weights, const Real& h,
                                   ndof_state<Real> y, last_force<Real>& kept) {
  for (const Real& w : weights) y = stormer_verlet_ndof_step(s, Real(w * h), y, kept);
  return y;
}

/// The classic RK4 step on q̇ = M⁻¹ p, ṗ = −∇V(q) (explicit: its stages are evaluated in turn).
template <class Real, class Potential>
ndof_state<Real> rk4_ndof_step(const separable_system<Real, Potential>& s, const Real& h, const ndof_state<Real>& y) {
  const auto rate = [&s](const ndof_state<Real>& z) { return ndof_state<Real>{-s.potential().gradient(z.q), s.mass_solve(z.p)}; };
  const auto shifted = [](const ndof_state<Real>& z, const ndof_state<Real>& k, const Real& a) {
    return ndof_state<Real>{z.p + scaled(k.p, a), z.q + scaled(k.q, a)};
  };
  const ndof_state<Real> k1 = rate(y), k2 = rate(shifted(y, k1, Real(h / 2))), k3 = rate(shifted(y, k2, Real(h / 2))),
                         k4 = rate(shifted(y, k3, h));
  return {y.p + scaled(dense_vector<Real>(k1.p + 2 * k2.p + 2 * k3.p + k4.p), Real(h / 6)),
          y.q + scaled(dense_vector<Real>(k1.q + 2 * k2.q + 2 * k3.q + k4.q), Real(h / 6))};
}

}  // namespace simpson

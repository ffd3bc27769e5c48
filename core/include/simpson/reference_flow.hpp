#pragma once
// Beyond the paper: a high-precision reference for the steppers' orders and errors. The Hamiltonian
// equations of a Lagrangian quadratic in v (legendre_hamiltonian.hpp), or any field on (p, q),
// integrated in mpfr by Boost.odeint's runge_kutta_fehlberg78 (order 8; its coefficients are ratios
// of integers, exact in mpfr) at fixed steps, the step halved until two runs agree to the digits
// asked for: what is returned is the finer run and the digits the two agree to (a lower bound of the
// finer run's, whose error is about 2⁻⁸ of the coarser's).

#include <simpson/legendre_hamiltonian.hpp>
#include <simpson/precision.hpp>

#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace simpson {

struct reference_state {
  ndof_state<mpfr> state;
  double agreed_digits = 0;  // −log10 of max |finer − coarser| / max(1, |finer|)
  int steps = 0;             // of the finer run
};

namespace detail {
/// N fixed steps of rkf78 on the field from y0 over [0, T], the state stacked as (p, q).
template <class Field>
ndof_state<mpfr> rkf78_run(const Field& field, const ndof_state<mpfr>& y0, const mpfr& T, int N) {
  using state_type = std::vector<mpfr>;
  const Eigen::Index n = y0.q.size();
  state_type x(static_cast<std::size_t>(2 * n));
  for (Eigen::Index i = 0; i < n; ++i) {
    x[static_cast<std::size_t>(i)] = y0.p(i);
    x[static_cast<std::size_t>(n + i)] = y0.q(i);
  }
  const auto system = [&](const state_type& z, state_type& dz, const mpfr&) {
    ndof_state<mpfr> y{dense_vector<mpfr>(n), dense_vector<mpfr>(n)};
    for (Eigen::Index i = 0; i < n; ++i) {
      y.p(i) = z[static_cast<std::size_t>(i)];
      y.q(i) = z[static_cast<std::size_t>(n + i)];
    }
    const ndof_state<mpfr> f = field(y);
    for (Eigen::Index i = 0; i < n; ++i) {
      dz[static_cast<std::size_t>(i)] = f.p(i);
      dz[static_cast<std::size_t>(n + i)] = f.q(i);
    }
  };
  boost::numeric::odeint::runge_kutta_fehlberg78<state_type, mpfr, state_type, mpfr> stepper;
  const mpfr h = T / N;
  mpfr t(0);
  for (int j = 0; j < N; ++j, t += h) stepper.do_step(system, x, t, h);
  ndof_state<mpfr> out{dense_vector<mpfr>(n), dense_vector<mpfr>(n)};
  for (Eigen::Index i = 0; i < n; ++i) {
    out.p(i) = x[static_cast<std::size_t>(i)];
    out.q(i) = x[static_cast<std::size_t>(n + i)];
  }
  return out;
}
}  // namespace detail

/// The flow of `field` (ndof_state<mpfr> → its time derivative, momentum first) over [0, T] from y0,
/// in the current mpfr digits: runs of N, 2N, 4N, … steps until two agree to `wanted_digits` or
/// `max_halvings` halvings are spent (then the digits reached are reported, fewer than wanted).
template <class Field>
reference_state reference_flow(const Field& field, const ndof_state<mpfr>& y0, const mpfr& T, double wanted_digits, int N = 16,
                               int max_halvings = 6) {
  if (N < 1 || !(T > 0)) throw std::invalid_argument("simpson::reference_flow: N must be positive and T positive");
  ndof_state<mpfr> coarse = detail::rkf78_run(field, y0, T, N);
  reference_state out{coarse, 0, N};
  for (int k = 0; k < max_halvings; ++k) {
    N *= 2;
    const ndof_state<mpfr> fine = detail::rkf78_run(field, y0, T, N);
    mpfr gap(0), size(1);
    for (Eigen::Index i = 0; i < fine.q.size(); ++i) {
      for (const mpfr* pair : {&fine.p(i), &fine.q(i)}) size = std::max(size, mpfr(abs(*pair)));
      gap = std::max(gap, mpfr(abs(mpfr(fine.p(i) - coarse.p(i)))));
      gap = std::max(gap, mpfr(abs(mpfr(fine.q(i) - coarse.q(i)))));
    }
    out = {fine, gap == 0 ? static_cast<double>(mpfr::default_precision()) : -static_cast<double>(log10(mpfr(gap / size))), N};
    if (out.agreed_digits >= wanted_digits) break;
    coarse = fine;
  }
  return out;
}

/// The Hamiltonian flow of a Lagrangian quadratic in v (hamiltonian_field).
template <class Lag>
reference_state lagrangian_reference(const Lag& L, const ndof_state<mpfr>& y0, const mpfr& T, double wanted_digits, int N = 16,
                                     int max_halvings = 6) {
  return reference_flow([&L](const ndof_state<mpfr>& y) { return hamiltonian_field(L, y); }, y0, T, wanted_digits, N, max_halvings);
}

}  // namespace simpson

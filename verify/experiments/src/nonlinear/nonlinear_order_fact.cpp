// The nonlinear section's published fact (published_fact.hpp): the Simpson scheme's global order
// on the pendulum, decided by enclosures (claims/paper.toml: nonlinear-order-4 observes it).

#include <simpson/verify/nonlinear_section.hpp>

#include <simpson/verify/enclosure_undecided.hpp>

#include <simpson/interval.hpp>
#include <simpson/interval_newton.hpp>
#include <simpson/nonlinear_simpson_step.hpp>
#include <simpson/pendulum_exact_enclosed.hpp>
#include <simpson/potential.hpp>
#include <simpson/scalar_traits.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace simpson::verify {

/// The global order on the pendulum, decided by enclosures: the scheme stepped in MPFI from the
/// exact start (q_m proved unique in its box by Krawczyk at every step), against the exact solution
/// enclosed (pendulum_exact_enclosed.hpp), at T = 10 for N = 10 ... 320. The order is proved
/// between N and 2N when log2(error_N / error_2N) is enclosed within 1/2 of 4, as for the
/// harmonic oscillator (conclusion-fourth-order), and refuted when a ratio's enclosure lies outside
/// (7/2, 9/2); every pair must prove it. A step whose q_m is not proved unique, or a ratio whose
/// enclosure straddles an end, decides nothing: enclosure_undecided.
published_fact pendulum_order_fact(unsigned digits) {
  const std::vector<int> meshes{10, 20, 40, 80, 160, 320};
  json rows = json::array();
  bool proved = true;
  std::string undecided;  // what no enclosure decided: a step's q_m, a ratio straddling 3.5 or 4.5
  std::vector<interval> error_q, error_p;
  std::vector<std::string> orders;
  {
    const scoped_interval_digits scope(digits);
    const interval one(1), T(10);
    const pendulum_potential<interval> V{one, one};
    const phase_point<interval> exact = pendulum_from_rest_enclosed(one, one, one, T);
    for (const int N : meshes) {
      const interval h = T / N;
      phase_point<interval> y{interval(0), one};
      bool node_proved = true;
      for (int j = 0; j < N && node_proved; ++j) {
        const enclosed_simpson_step step = simpson_enclosed_step(one, h, V, y);
        node_proved = step.node.proved;
        if (node_proved) y = step.state;
      }
      if (!node_proved) {
        undecided = "q_m not proved unique at some step of N = " + std::to_string(N);
        break;
      }
      error_q.push_back(abs(interval(y.q - exact.q)));
      error_p.push_back(abs(interval(y.p - exact.p)));
      json row{{"N", N}, {"error_q", enclosure_text(error_q.back(), 8)}, {"error_p", enclosure_text(error_p.back(), 8)}};
      const std::size_t k = error_q.size() - 1;
      if (k > 0) {
        const interval log2 = log(interval(2));
        const interval ratio_q = log(interval(error_q[k - 1] / error_q[k])) / log2, ratio_p = log(interval(error_p[k - 1] / error_p[k])) / log2;
        const auto within = [](const interval& r) { return lower(r) > 3.5 && upper(r) < 4.5; };
        const auto outside = [](const interval& r) { return upper(r) <= 3.5 || lower(r) >= 4.5; };
        const bool here = within(ratio_q) && within(ratio_p);
        if (!here && !outside(ratio_q) && !outside(ratio_p) && undecided.empty()) {
          undecided = "a log2 ratio of N = " + std::to_string(N) + " straddles 3.5 or 4.5";
        }
        proved = proved && here;
        row["log2_ratio_q"] = enclosure_text(ratio_q, 6);
        row["log2_ratio_p"] = enclosure_text(ratio_p, 6);
        row["order_4_proved"] = here;
        orders.push_back(simpson::to_string(boost::multiprecision::mpfr_float(median(ratio_q)), 3));
      }
      rows.push_back(std::move(row));
    }
  }
  if (!undecided.empty()) throw enclosure_undecided("nonlinear-order-4: " + undecided + " at " + std::to_string(digits) + " digits");
  // Energy over 1e5 steps in double, h = 0.1: bounded (symplectic), not drifting.
  const pendulum_potential<double> Vd{1, 1};
  phase_point<double> y{0, 1};
  const double H0 = Vd.value(1.0);
  double worst_energy = 0, worst_first_tenth = 0;
  for (int j = 1; j <= 100000; ++j) {
    y = simpson_nonlinear_step(1.0, 0.1, Vd, y).state;
    worst_energy = std::max(worst_energy, std::abs(y.p * y.p / 2 + Vd.value(y.q) - H0) / H0);
    if (j == 10000) worst_first_tenth = worst_energy;
  }
  published_fact r;
  r.holds = proved;
  r.evidence["enclosure"] = {
      {"method", "enclosures (MPFI, " + std::to_string(digits) + " digits): the scheme stepped from the exact start, q_m proved "
                 "unique at every step (Krawczyk); the exact solution q = 2 asin(k sn(K - t, k)), p = -2k cn(K - t, k), "
                 "k = sin(1/2), enclosed (K by the arithmetic-geometric mean, sn and cn by theta series with their remainders)"},
      {"problem", "pendulum V = m omega^2 (1 - cos q), m = omega = 1, q(0) = 1, p(0) = 0, T = 10, h = T/N"},
      {"rule", "the order is proved between N and 2N when log2(error_N / error_2N) is enclosed within 1/2 of 4, for q and p; "
               "every pair must prove it"},
      {"runs", rows}};
  r.evidence["energy_double_1e5_steps"] = {
      {"h", 0.1}, {"max_relative_H_error", worst_energy}, {"max_relative_H_error_first_1e4_steps", worst_first_tenth}};
  std::string ratios;
  for (std::size_t k = 0; k < orders.size(); ++k) ratios += (k ? ", " : "") + orders[k];
  r.note = std::string(proved ? "Global order 4 on a nonlinear problem, proved by enclosures: " : "Order 4 refuted by the enclosures: ") +
           "log2 ratios of successive errors in q, N = 10 ... 320: " + ratios +
           ". In double with h = 0.1 the largest relative energy error is " +
           simpson::to_string(worst_first_tenth, 3) + " over the first 1e4 steps and " + simpson::to_string(worst_energy, 3) +
           " over 1e5: it stays at that level instead of drifting, as for a symplectic method.";
  return r;
}

}  // namespace simpson::verify

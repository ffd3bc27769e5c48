// The steps that long runs and benchmarks repeat millions of times allocate nothing per step in
// double: Φ₃'s iterate, the linear and the nonlinear stage solvers of the partitioned Runge–Kutta
// peers (fixed-size arrays up to 4 stages), the nonlinear Simpson step and its Brouwer form. Counted
// by replacing the global operator new for this executable; a vector in a step's work storage makes
// the count positive.

#include <simpson/iterate.hpp>
#include <simpson/nonlinear_brouwer_step.hpp>
#include <simpson/nonlinear_partitioned_rk.hpp>
#include <simpson/nonlinear_simpson_step.hpp>
#include <simpson/partitioned_runge_kutta.hpp>
#include <simpson/potential.hpp>
#include <simpson/runge_kutta_tableaux.hpp>
#include <simpson/simpson_map.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <functional>
#include <new>
#include <utility>
#include <vector>

namespace {
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
// GCC's -Wmismatched-new-delete sees free() of memory from operator new; here operator new is ours
// and returns malloc's memory, so free() is its match.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace simpson {
namespace {

/// The allocations `body` makes.
template <class F>
long allocations_of(F&& body) {
  const long before = allocations.load();
  body();
  return allocations.load() - before;
}

TEST(AllocationFree, TheCounterSeesAVector) {
  // The check's own check: a step that builds a vector is counted.
  EXPECT_GT(allocations_of([] { std::vector<double> v(3, 1.0); EXPECT_EQ(v.size(), 3u); }), 0);
}

TEST(AllocationFree, StepsInDoubleAllocateNothing) {
  const oscillator_parameters<double> par{1, 1, 0.1};
  const pendulum_potential<double> V{1, 1};
  const auto lobatto_q = lobatto_iiia3_tableau<double>(), lobatto_p = lobatto_iiib3_tableau<double>();
  const auto gauss = gauss_legendre2_tableau<double>();
  const stage_coupling<double> coupling = couple(lobatto_q, lobatto_p);
  const brouwer_coefficients<double> k = simpson_brouwer_coefficients(0.1);
  const one_step_matrix<double> phi = simpson_map(par);
  phase_point<double> y{0.2, 1.0};
  compensated_point<double> z{y};
  // Each body is run once before counting: a function-local static or a lazy table allocates once.
  const auto linear = [&] { y = partitioned_runge_kutta_step(par, gauss, gauss, y); };
  const auto nonlinear_prk = [&] { y = prk_nonlinear_step(lobatto_q, lobatto_p, coupling, 1.0, 0.1, V, y).state; };
  const auto simpson = [&] { y = simpson_nonlinear_step(1.0, 0.1, V, y).state; };
  const auto brouwer = [&] { simpson_brouwer_step_compensated(k, 1.0, V, z); };
  const auto iterated = [&] { y = iterate(phi, y, 100, [](std::size_t, const phase_point<double>&) {}); };
  for (const auto& step : {std::pair<const char*, std::function<void()>>{"partitioned_runge_kutta_step", linear},
                           {"prk_nonlinear_step", nonlinear_prk},
                           {"simpson_nonlinear_step", simpson},
                           {"simpson_brouwer_step_compensated", brouwer},
                           {"iterate", iterated}}) {
    const std::function<void()>& body = step.second;
    body();
    EXPECT_EQ(allocations_of([&body] { for (int j = 0; j < 100; ++j) body(); }), 0) << step.first;
  }
}

}  // namespace
}  // namespace simpson

// Beyond the paper: the cost of a nonlinear Simpson step against its twin Lobatto IIIA–IIIB step
// (claim nonlinear-lobatto-equivalence), both solved by Newton's method to the same bound from the
// same starting guess, on the pendulum (m = ω = 1, h = 0.1, from q = 1 rad). Two implementations
// of each: the scalar steps (nonlinear_simpson_step.hpp, nonlinear_partitioned_rk.hpp) and the
// n-degree-of-freedom steps with Eigen at n = 1 (nonlinear_ndof_step.hpp). The last lines printed
// are the ratios: Simpson/Lobatto of the times per step, then the core's loops against raw loops
// (iterate_bench.cpp), measured in this run.

#include "ratio_reporter.hpp"

#include <simpson/nonlinear_brouwer_step.hpp>
#include <simpson/nonlinear_ndof_step.hpp>
#include <simpson/nonlinear_partitioned_rk.hpp>
#include <simpson/nonlinear_simpson_step.hpp>
#include <simpson/potential.hpp>
#include <simpson/precision.hpp>
#include <simpson/runge_kutta_tableaux.hpp>

#include <benchmark/benchmark.h>

#include <cstdio>
#include <tuple>

namespace simpson::bench {
namespace {

constexpr double step_size = 0.1;

template <class Real>
void simpson_scalar(benchmark::State& state) {
  const pendulum_potential<Real> V{Real(1), Real(1)};
  const Real m(1), h(step_size);
  phase_point<Real> y{Real(0), Real(1)};
  for (auto _ : state) {
    y = simpson_nonlinear_step(m, h, V, y).state;
    benchmark::DoNotOptimize(y);
  }
}

template <class Real>
void lobatto_scalar(benchmark::State& state) {
  const pendulum_potential<Real> V{Real(1), Real(1)};
  const Real m(1), h(step_size);
  const auto for_q = lobatto_iiia3_tableau<Real>(), for_p = lobatto_iiib3_tableau<Real>();
  const auto coupling = couple(for_q, for_p);
  phase_point<Real> y{Real(0), Real(1)};
  for (auto _ : state) {
    y = prk_nonlinear_step(for_q, for_p, coupling, m, h, V, y).state;
    benchmark::DoNotOptimize(y);
  }
}

/// The Simpson step in Brouwer form with compensated summation (nonlinear_brouwer_step.hpp): what
/// its exact coefficients, Newton to stagnation and Kahan's summation cost beside simpson_scalar.
template <class Real>
void brouwer_scalar(benchmark::State& state) {
  const pendulum_potential<Real> V{Real(1), Real(1)};
  const brouwer_coefficients<Real> k = simpson_brouwer_coefficients(Real(step_size));
  compensated_point<Real> z{phase_point<Real>{Real(0), Real(1)}};
  for (auto _ : state) {
    simpson_brouwer_step_compensated(k, Real(1), V, z);
    benchmark::DoNotOptimize(z);
  }
}

using pendulum_1d = one_dof_potential<double, pendulum_potential<double>>;

separable_system<double, pendulum_1d> pendulum_system() {
  return {dense_matrix<double>::Identity(1, 1), pendulum_1d{pendulum_potential<double>{1, 1}}};
}

void simpson_ndof(benchmark::State& state) {
  const auto s = pendulum_system();
  ndof_state<double> y{dense_vector<double>::Zero(1), dense_vector<double>::Ones(1)};
  for (auto _ : state) {
    y = simpson_ndof_step(s, step_size, y).state;
    benchmark::DoNotOptimize(y.q.data());
  }
}

void lobatto_ndof(benchmark::State& state) {
  const auto s = pendulum_system();
  const auto for_q = lobatto_iiia3_tableau<double>(), for_p = lobatto_iiib3_tableau<double>();
  const auto coupling = couple(for_q, for_p);
  ndof_state<double> y{dense_vector<double>::Zero(1), dense_vector<double>::Ones(1)};
  for (auto _ : state) {
    y = prk_ndof_step(for_q, for_p, coupling, s, step_size, y).state;
    benchmark::DoNotOptimize(y.q.data());
  }
}

void simpson_scalar_mpfr50(benchmark::State& state) {
  const scoped_mpfr_digits digits(50);
  simpson_scalar<mpfr>(state);
}
void lobatto_scalar_mpfr50(benchmark::State& state) {
  const scoped_mpfr_digits digits(50);
  lobatto_scalar<mpfr>(state);
}

BENCHMARK(simpson_scalar<double>)->Name("simpson_scalar_double");
BENCHMARK(lobatto_scalar<double>)->Name("lobatto_scalar_double");
BENCHMARK(brouwer_scalar<double>)->Name("brouwer_compensated_scalar_double");
BENCHMARK(simpson_ndof)->Name("simpson_ndof_double");
BENCHMARK(lobatto_ndof)->Name("lobatto_ndof_double");
BENCHMARK(simpson_scalar_mpfr50)->Name("simpson_scalar_mpfr50");
BENCHMARK(lobatto_scalar_mpfr50)->Name("lobatto_scalar_mpfr50");

}  // namespace
}  // namespace simpson::bench

namespace simpson::bench {
void register_scheme_benchmarks();  // iterate_bench.cpp
}

int main(int argc, char** argv) {
  simpson::bench::register_scheme_benchmarks();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  simpson::bench::ratio_reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  // Time per Simpson step over time per Lobatto IIIA–IIIB step (issue target: at most 1.5).
  for (const char* kind : {"scalar_double", "ndof_double", "scalar_mpfr50"}) {
    const std::string simpson = std::string("simpson_") + kind, lobatto = std::string("lobatto_") + kind;
    try {
      std::printf("ratio simpson_vs_lobatto_step_%s %.3f\n", kind, reporter.seconds(simpson) / reporter.seconds(lobatto));
    } catch (const std::out_of_range&) {
      // filtered out with --benchmark_filter: no ratio
    }
  }
  // Steps per second of the core's loop over a raw loop's (issue targets: at least 0.95 and 0.85):
  // the last two lines.
  for (const auto& [ours, raw, label] : {std::tuple{"iterate_double", "raw_c", "double_vs_raw_c"},
                                         std::tuple{"iterate_mpfr50", "raw_mpfr", "mpfr50_vs_raw_mpfr"}}) {
    try {
      std::printf("ratio %s %.3f\n", label, reporter.seconds(raw) / reporter.seconds(ours));
    } catch (const std::out_of_range&) {
    }
  }
  // The cost of enclosures (interval_bench.cpp): interval time over mpfr time on the same work, and
  // Arb's ball loop over MPFI's.
  for (const auto& [slower, faster, label] : {std::tuple{"phi3_det_interval50", "phi3_det_mpfr50", "interval50_vs_mpfr50_phi3_det"},
                                              std::tuple{"generic_loop_interval50", "generic_loop_mpfr50", "interval50_vs_mpfr50_step"},
                                              std::tuple{"raw_mpfi", "raw_mpfr", "raw_mpfi_vs_raw_mpfr_step"},
                                              std::tuple{"raw_arb", "raw_mpfi", "raw_arb_vs_raw_mpfi_step"}}) {
    try {
      std::printf("ratio %s %.3f\n", label, reporter.seconds(slower) / reporter.seconds(faster));
    } catch (const std::out_of_range&) {
    }
  }
  return 0;
}

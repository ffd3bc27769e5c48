// The cost of enclosures: interval arithmetic against plain MPFR on the harness's own workloads, in
// one run, at 50 digits:
// - phi3_det_{mpfr50,interval50}: a numeric claim's sample (Φ₃ from (m, ω, h), det Φ₃ − 1), the
//   core's generic formulas in mpfr_float and in Boost's mpfi_float;
// - generic_loop_interval50: y = Φ₃ y with Boost's operators on mpfi_float (beside iterate_bench's
//   generic_loop_mpfr50);
// - raw_mpfi, raw_arb: the loop of raw_mpfr (4 multiplications, 2 additions per step) on mpfi_t and
//   on Arb's arb_t (ball arithmetic) at the same bits: MPFI against Arb, the choice the issue asks for.
// main (nonlinear_step_bench.cpp) prints the ratios last.

#include <simpson/interval.hpp>

#include <simpson/precision.hpp>
#include <simpson/simpson_map.hpp>

#include <arb.h>
#include <benchmark/benchmark.h>
#include <mpfi.h>

namespace simpson::bench {
namespace {

constexpr std::size_t loop_steps = 1000;

template <class Real>
void phi3_det(benchmark::State& state) {
  // A sample of the numeric rechecks' kind: exact doubles, ω h = 0.7.
  const oscillator_parameters<Real> par{Real(0.75), Real(3.5), Real(0.2)};
  for (auto _ : state) {
    const Real residual = determinant(simpson_map(par)) - 1;
    benchmark::DoNotOptimize(residual);
  }
}

void phi3_det_mpfr50(benchmark::State& state) {
  const scoped_mpfr_digits digits(50);
  phi3_det<mpfr>(state);
}

void phi3_det_interval50(benchmark::State& state) {
  const scoped_interval_digits digits(50);
  phi3_det<interval>(state);
}

void generic_loop_interval50(benchmark::State& state) {
  const scoped_interval_digits digits(50);
  const one_step_matrix<interval> phi = simpson_map(oscillator_parameters<interval>{interval(1), interval(1), interval(interval(1) / 10)});
  phase_point<interval> y{interval(1), interval(0)};
  for (auto _ : state) {
    for (std::size_t j = 0; j < loop_steps; ++j) y = phi * y;
    benchmark::DoNotOptimize(y);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * loop_steps));
}

/// The bits Boost gives 50 digits (as raw_mpfr uses).
mpfr_prec_t bits_of_50_digits() {
  const scoped_mpfr_digits digits(50);
  return mpfr_get_prec(mpfr(1).backend().data());
}

void raw_mpfi(benchmark::State& state) {
  const mpfr_prec_t bits = bits_of_50_digits();
  mpfi_t a, b, c, d, p, q, t1, t2, t3, t4;
  for (mpfi_ptr x : {a, b, c, d, p, q, t1, t2, t3, t4}) mpfi_init2(x, bits);
  const one_step_matrix<double> phi = simpson_map(oscillator_parameters<double>{1, 1, 0.1});
  mpfi_set_d(a, phi.alpha);
  mpfi_set_d(b, phi.beta);
  mpfi_set_d(c, phi.gamma);
  mpfi_set_d(d, phi.delta);
  mpfi_set_ui(p, 1);
  mpfi_set_ui(q, 0);
  for (auto _ : state) {
    for (std::size_t j = 0; j < loop_steps; ++j) {
      mpfi_mul(t1, a, p);
      mpfi_mul(t2, b, q);
      mpfi_mul(t3, c, p);
      mpfi_mul(t4, d, q);
      mpfi_add(p, t1, t2);
      mpfi_add(q, t3, t4);
    }
    benchmark::DoNotOptimize(p);
  }
  for (mpfi_ptr x : {a, b, c, d, p, q, t1, t2, t3, t4}) mpfi_clear(x);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * loop_steps));
}

void raw_arb(benchmark::State& state) {
  const slong bits = static_cast<slong>(bits_of_50_digits());
  arb_t a, b, c, d, p, q, t1, t2, t3, t4;
  for (arb_ptr x : {a, b, c, d, p, q, t1, t2, t3, t4}) arb_init(x);
  const one_step_matrix<double> phi = simpson_map(oscillator_parameters<double>{1, 1, 0.1});
  arb_set_d(a, phi.alpha);
  arb_set_d(b, phi.beta);
  arb_set_d(c, phi.gamma);
  arb_set_d(d, phi.delta);
  arb_set_ui(p, 1);
  arb_set_ui(q, 0);
  for (auto _ : state) {
    for (std::size_t j = 0; j < loop_steps; ++j) {
      arb_mul(t1, a, p, bits);
      arb_mul(t2, b, q, bits);
      arb_mul(t3, c, p, bits);
      arb_mul(t4, d, q, bits);
      arb_add(p, t1, t2, bits);
      arb_add(q, t3, t4, bits);
    }
    benchmark::DoNotOptimize(p);
  }
  for (arb_ptr x : {a, b, c, d, p, q, t1, t2, t3, t4}) arb_clear(x);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * loop_steps));
}

}  // namespace

BENCHMARK(phi3_det_mpfr50);
BENCHMARK(phi3_det_interval50);
BENCHMARK(generic_loop_interval50);
BENCHMARK(raw_mpfi);
BENCHMARK(raw_arb);

}  // namespace simpson::bench

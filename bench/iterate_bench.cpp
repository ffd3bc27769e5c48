// Steps per second of Φ₃ and its peers on the oscillator, in each precision, beside the loops they
// are measured against, in one run:
// - raw_c: a C loop in double doing Φ₃'s 4 multiplications and 2 additions per step;
// - raw_mpfr: the same loop on mpfr_t at the bits Boost gives mpfr_float at 50 digits;
// - iterate_double, iterate_mpfr50: simpson::iterate on the same matrix (the core's loop);
// - generic_loop_mpfr50: y = Φ y with Boost's operators, the baseline iterate's mpfr path replaced;
// - <scheme>_<precision>: each scheme's own step algorithm (scheme.hpp's stepper).
// main (nonlinear_step_bench.cpp) prints the ratios last.

#include <simpson/iterate.hpp>
#include <simpson/precision.hpp>
#include <simpson/scheme.hpp>
#include <simpson/simpson_map.hpp>

#include <benchmark/benchmark.h>
#include <mpfr.h>

#include <string>

namespace simpson::bench {
namespace {

constexpr std::size_t steps_per_iteration = 1000;

void raw_c(benchmark::State& state) {
  const one_step_matrix<double> phi = simpson_map(oscillator_parameters<double>{1, 1, 0.1});
  const double a = phi.alpha, b = phi.beta, c = phi.gamma, d = phi.delta;
  double p = 1, q = 0;
  for (auto _ : state) {
    for (std::size_t j = 0; j < steps_per_iteration; ++j) {
      const double t1 = a * p, t2 = b * q, t3 = c * p, t4 = d * q;
      p = t1 + t2;
      q = t3 + t4;
    }
    benchmark::DoNotOptimize(p);
    benchmark::DoNotOptimize(q);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * steps_per_iteration));
}

template <class Real>
void iterate_matrix(benchmark::State& state) {
  const one_step_matrix<Real> phi = simpson_map(oscillator_parameters<Real>{Real(1), Real(1), Real(1) / 10});
  phase_point<Real> y{Real(1), Real(0)};
  for (auto _ : state) {
    y = iterate(phi, y, steps_per_iteration, [](std::size_t, const phase_point<Real>&) {});
    benchmark::DoNotOptimize(y);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * steps_per_iteration));
}

void iterate_double(benchmark::State& state) { iterate_matrix<double>(state); }

void iterate_mpfr50(benchmark::State& state) {
  const scoped_mpfr_digits digits(50);
  iterate_matrix<mpfr>(state);
}

/// The generic loop y = Φ y in mpfr (a new number per entry per step): the baseline the
/// allocation-free iterate replaced.
void generic_loop_mpfr50(benchmark::State& state) {
  const scoped_mpfr_digits digits(50);
  const one_step_matrix<mpfr> phi = simpson_map(oscillator_parameters<mpfr>{mpfr(1), mpfr(1), mpfr(1) / 10});
  phase_point<mpfr> y{mpfr(1), mpfr(0)};
  for (auto _ : state) {
    for (std::size_t j = 0; j < steps_per_iteration; ++j) y = phi * y;
    benchmark::DoNotOptimize(y);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * steps_per_iteration));
}

void raw_mpfr(benchmark::State& state) {
  const scoped_mpfr_digits digits(50);
  const one_step_matrix<mpfr> phi = simpson_map(oscillator_parameters<mpfr>{mpfr(1), mpfr(1), mpfr(1) / 10});
  const mpfr_prec_t bits = mpfr_get_prec(phi.alpha.backend().data());  // what Boost uses at 50 digits
  mpfr_t a, b, c, d, p, q, t1, t2, t3, t4;
  for (mpfr_ptr x : {a, b, c, d, p, q, t1, t2, t3, t4}) mpfr_init2(x, bits);
  mpfr_set(a, phi.alpha.backend().data(), MPFR_RNDN);
  mpfr_set(b, phi.beta.backend().data(), MPFR_RNDN);
  mpfr_set(c, phi.gamma.backend().data(), MPFR_RNDN);
  mpfr_set(d, phi.delta.backend().data(), MPFR_RNDN);
  mpfr_set_ui(p, 1, MPFR_RNDN);
  mpfr_set_ui(q, 0, MPFR_RNDN);
  for (auto _ : state) {
    for (std::size_t j = 0; j < steps_per_iteration; ++j) {
      mpfr_mul(t1, a, p, MPFR_RNDN);
      mpfr_mul(t2, b, q, MPFR_RNDN);
      mpfr_mul(t3, c, p, MPFR_RNDN);
      mpfr_mul(t4, d, q, MPFR_RNDN);
      mpfr_add(p, t1, t2, MPFR_RNDN);
      mpfr_add(q, t3, t4, MPFR_RNDN);
    }
    benchmark::DoNotOptimize(p);
  }
  for (mpfr_ptr x : {a, b, c, d, p, q, t1, t2, t3, t4}) mpfr_clear(x);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * steps_per_iteration));
}

/// A scheme's own step algorithm in a precision, 100 steps per iteration.
void scheme_steps(benchmark::State& state, scheme_id id, precision prec) {
  prec.visit([&](auto tag) {
    using Real = typename decltype(tag)::type;
    if constexpr (!is_exact_v<Real>) {
      const stepper<Real> runner(id, oscillator_parameters<Real>{Real(1), Real(1), Real(1) / 10});
      phase_point<Real> y{Real(1), Real(0)};
      for (auto _ : state) {
        for (int j = 0; j < 100; ++j) y = runner.step(y);
        benchmark::DoNotOptimize(y);
      }
      state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * 100));
    }
  });
}

BENCHMARK(raw_c);
BENCHMARK(iterate_double);
BENCHMARK(raw_mpfr);
BENCHMARK(iterate_mpfr50);
BENCHMARK(generic_loop_mpfr50);

}  // namespace

void register_scheme_benchmarks() {
  for (const char* name : {"double", "long double", "float128", "mpfr:50"}) {
    const precision prec = precision::parse(name);
    for (const scheme_traits& s : scheme_list) {
      std::string label = std::string(s.name) + "_" + prec.name();
      for (char& ch : label) {
        if (ch == ' ' || ch == ':') ch = '_';
      }
      benchmark::RegisterBenchmark(label.c_str(), [id = s.id, prec](benchmark::State& state) { scheme_steps(state, id, prec); });
    }
  }
}

}  // namespace simpson::bench

// The nonlinear section as a registry entry (experiment_section.hpp).

#include <simpson/verify/nonlinear_section.hpp>

#include "../precision_cost.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace simpson::verify {
namespace {

class nonlinear_section final : public typed_section<nonlinear_settings> {
 public:
  nonlinear_section() : typed_section("nonlinear", "beyond the paper: any potential, the pendulum's order, Brouwer's law, error against N and run time on nonlinear problems") {}
  std::set<std::string> keys() const override {
    return {"parts", "pendulum_q0", "pendulum_T", "pendulum_N", "mpfr_digits", "energy_steps", "brouwer_h", "brouwer_steps", "problems", "N",
            "eccentricity", "kepler_periods", "reference_digits", "fpu_T", "max_runs", "max_seconds", "double_pendulum_N"};
  }
  precisions_use precisions() const override { return precisions_use::refused; }
  bool times_runs() const override { return true; }

 protected:
  nonlinear_settings read(const section_reader& r, const std::vector<precision>&) const override {
    nonlinear_settings n;
    // q0 = π is the unstable equilibrium, where the exact solution (k = 1) has no period.
    if (r.has("pendulum_q0")) n.pendulum_q0 = r.number("pendulum_q0", 0, 3.14159);
    if (r.has("pendulum_T")) n.pendulum_T = r.number("pendulum_T", 0, 1e6);
    if (r.has("pendulum_N")) n.pendulum_N = r.integers("pendulum_N", 1, 100'000'000);
    if (r.has("mpfr_digits")) n.mpfr_digits = static_cast<unsigned>(r.integer("mpfr_digits", precision::min_mpfr_digits, precision::max_mpfr_digits));
    if (r.has("energy_steps")) n.energy_steps = r.integer("energy_steps", 1, max_steps);
    // Up to h = 1 the Newton start q + hp/2 converges for the pendulum's |p| ≤ 2.
    if (r.has("brouwer_h")) n.brouwer_h = r.number("brouwer_h", 0, 1);
    if (r.has("brouwer_steps")) n.brouwer_steps = r.integer("brouwer_steps", 1, max_steps);
    if (r.has("parts")) n.parts = r.names("parts", nonlinear_part_names());
    if (r.has("problems")) n.problems = r.names("problems", nonlinear_problem_names());
    if (r.has("kepler_periods")) n.kepler_periods = static_cast<int>(r.integer("kepler_periods", 1, 1000));
    if (r.has("N")) n.N = r.integers("N", 1, 100'000'000);
    // 0 <= e < 1 is an ellipse; e near 1 needs steps far below the perihelion distance 1 − e.
    if (r.has("eccentricity")) n.eccentricity = r.number("eccentricity", -1e-300, 0.95);
    if (r.has("reference_digits")) n.reference_digits = static_cast<unsigned>(r.integer("reference_digits", 20, precision::max_mpfr_digits));
    if (r.has("fpu_T")) n.fpu_T = r.number("fpu_T", 0, 1e4);
    if (r.has("max_runs")) n.timing.max_runs = static_cast<unsigned>(r.integer("max_runs", 1, 1000));
    if (r.has("max_seconds")) n.timing.max_seconds = r.number("max_seconds", 0, 3600);
    if (r.has("double_pendulum_N")) n.double_pendulum_N = r.integers("double_pendulum_N", 1, 100'000'000);
    return n;
  }
  nonlinear_settings initial(const std::vector<precision>&) const override { return {}; }
  section_cost estimate(const nonlinear_settings& n) const override {
    // Measured on the 2-core machine: a Newton step of the pendulum in mpfr:50 beside its Lobatto
    // run ~3e4 units; a step of a nonlinear problem in double (Eigen, dynamic sizes) ~200 units for
    // the implicit methods, with up to max_runs + 1 timed runs; Hénon–Heiles' reference, 24 times the
    // finest N of Gauss–Legendre steps in mpfr:32, ~2e4 units each (scaled by the precision's factor);
    // a step of the Brouwer part (three forms in double and the reference in long double) ~400 units.
    double pendulum = 0, problems = 0, finest = 0, double_pendulum = 0;
    const double mpfr_factor = precision_factor(precision::mpfr_digits(n.mpfr_digits)) / precision_factor(precision::mpfr_digits(50));
    for (const long long N : n.pendulum_N) pendulum += 3e4 * mpfr_factor * static_cast<double>(N) + 100 * static_cast<double>(n.energy_steps);
    for (const long long N : n.N) {
      problems += 200 * 5 * static_cast<double>(N) * static_cast<double>(n.problems.size()) * (2 + n.timing.max_runs);
      finest = std::max(finest, static_cast<double>(N));
    }
    for (const long long N : n.double_pendulum_N) double_pendulum += 300 * mpfr_factor * static_cast<double>(N) + 50 * static_cast<double>(n.energy_steps);
    const bool henon_heiles = std::find(n.problems.begin(), n.problems.end(), "henon-heiles") != n.problems.end();
    const double reference_factor = precision_factor(precision::mpfr_digits(n.reference_digits)) / precision_factor(precision::mpfr_digits(32));
    const double brouwer = 400 * static_cast<double>(n.brouwer_steps);
    // The FPU chain's reference: 24 times the finest N of Gauss–Legendre steps in long double, 2m = 6
    // degrees of freedom, ~2e3 units each (measured 12 µs a step: 1.2 s for 16 + 8 times N = 4096).
    const bool chain = std::find(n.problems.begin(), n.problems.end(), "fpu") != n.problems.end();
    const double units = pendulum + brouwer + problems + double_pendulum + (henon_heiles ? 2e4 * reference_factor * 24 * finest : 0) +
                         (chain ? 2e3 * 24 * finest : 0);
    return {units, fmt::format("nonlinear: {:.3g} units", units)};
  }
  section_result compute(const nonlinear_settings& s, const section_inputs& inputs) const override {
    nonlinear_settings settings = s;
    settings.progress = inputs.progress;
    return run_nonlinear(settings);
  }
  std::string refusal(const nonlinear_settings& n) const override {
    return "the nonlinear section runs in mpfr:" + std::to_string(n.mpfr_digits) +
           " and double by design and takes no precision list; leave it out with --sections, or set nonlinear.mpfr_digits in a scene file";
  }
  void with_options(nonlinear_settings& n, const section_options& o) const override {
    if (o.timing_runs) n.timing.max_runs = *o.timing_runs;
    if (!o.timed) n.timing.max_runs = 0;
  }
};

}  // namespace

std::unique_ptr<experiment_section> make_nonlinear_section() { return std::make_unique<nonlinear_section>(); }

}  // namespace simpson::verify

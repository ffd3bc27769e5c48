// The nonlinear_inseparable section as a registry entry (experiment_section.hpp).

#include <simpson/verify/inseparable_section.hpp>

#include <boost/math/constants/constants.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace simpson::verify {
namespace {

class inseparable_section final : public typed_section<inseparable_settings> {
 public:
  inseparable_section()
      : typed_section("nonlinear_inseparable",
                      "inseparable Hamiltonians: the Lagrange top against its exact motion enclosed, the nonlinear double pendulum against an "
                      "MPFR reference; Simpson, implicit midpoint, Lobatto IIIA-IIIB, RK4, VPRK") {}
  std::set<std::string> keys() const override {
    return {"I1",     "I3",     "Mgl",    "theta0", "theta_dot0", "phi_dot0", "psi_dot0", "top_end_time", "top_N", "long_h", "long_steps",
            "samples", "exact_digits", "reference_digits", "m1", "m2", "l1", "l2", "g", "theta1", "theta2", "omega1", "omega2",
            "pendulum_end_time", "pendulum_N", "pendulum_reference_digits", "lyapunov_time"};
  }

 protected:
  inseparable_settings read(const section_reader& r, const std::vector<precision>&) const override {
    inseparable_settings s;
    inseparable_top_settings& t = s.top;
    if (r.has("I1")) t.I1 = r.number("I1", 0, 1e6);
    if (r.has("I3")) t.I3 = r.number("I3", 0, 1e6);
    if (r.has("Mgl")) t.Mgl = r.number("Mgl", 0, 1e6);  // above its pivot: the exact motion's cubic is bracketed for Mgl > 0
    if (r.has("theta0")) {
      t.theta0 = r.number("theta0", 0, 4);
      if (!(t.theta0 < boost::math::constants::pi<double>())) r.fail(r.field("theta0") + " must lie in (0, pi): the Euler angles are singular at the vertical");
    }
    if (r.has("theta_dot0")) t.theta_dot0 = r.number("theta_dot0", -1e3, 1e3);
    if (r.has("phi_dot0")) t.phi_dot0 = r.number("phi_dot0", -1e3, 1e3);
    if (r.has("psi_dot0")) t.psi_dot0 = r.number("psi_dot0", -1e3, 1e3);
    if (r.has("top_end_time")) s.top_end_time = r.number("top_end_time", 0, 1e4);
    if (r.has("top_N")) s.top_N = r.integers("top_N", 2, 10'000'000);
    if (r.has("long_h")) s.long_h = r.numbers("long_h", 0, 100);
    if (r.has("long_steps")) s.long_steps = r.integer("long_steps", 10, 100'000'000);
    if (r.has("samples")) s.samples = static_cast<int>(r.integer("samples", 2, 100000));
    if (r.has("exact_digits")) s.exact_digits = static_cast<unsigned>(r.integer("exact_digits", 20, 1000));
    if (r.has("reference_digits")) s.reference_digits = r.number("reference_digits", 1, 100);
    inseparable_pendulum_settings& d = s.pendulum;
    if (r.has("m1")) d.m1 = r.number("m1", 0, 1e6);
    if (r.has("m2")) d.m2 = r.number("m2", 0, 1e6);
    if (r.has("l1")) d.l1 = r.number("l1", 0, 1e6);
    if (r.has("l2")) d.l2 = r.number("l2", 0, 1e6);
    if (r.has("g")) d.g = r.number("g", -1e6, 1e6);
    if (r.has("theta1")) d.theta1 = r.number("theta1", -1e3, 1e3);
    if (r.has("theta2")) d.theta2 = r.number("theta2", -1e3, 1e3);
    if (r.has("omega1")) d.omega1 = r.number("omega1", -1e3, 1e3);
    if (r.has("omega2")) d.omega2 = r.number("omega2", -1e3, 1e3);
    if (r.has("pendulum_end_time")) s.pendulum_end_time = r.number("pendulum_end_time", 0, 1e4);
    if (r.has("pendulum_N")) s.pendulum_N = r.integers("pendulum_N", 2, 10'000'000);
    if (r.has("pendulum_reference_digits")) s.pendulum_reference_digits = r.number("pendulum_reference_digits", 1, 100);
    if (r.has("lyapunov_time")) s.lyapunov_time = r.number("lyapunov_time", 0, 1e5);
    try {
      check_inseparable_top(t);
    } catch (const std::invalid_argument& e) {
      r.fail(fmt::format("the top of 'nonlinear_inseparable' is not physical: {}", e.what()));
    }
    // A step too large for Newton, refused before anything runs: one step of each implicit method from the start.
    const long long coarsest = *std::min_element(s.top_N.begin(), s.top_N.end());
    const std::string coarse = first_newton_failure(t, {s.top_end_time / static_cast<double>(coarsest)});
    if (!coarse.empty()) r.fail(fmt::format("{} with {}: too large a step for Newton: {}", r.field("top_N"), r.field("top_end_time"), coarse));
    const std::string longer = first_newton_failure(t, s.long_h);
    if (!longer.empty()) r.fail(fmt::format("{}: too large a step for Newton: {}", r.field("long_h"), longer));
    return s;
  }
  inseparable_settings initial(const std::vector<precision>&) const override { return {}; }
  section_cost estimate(const inseparable_settings& s) const override {
    // Per step in double (5 ns a unit, measured on the default size): the top's five methods together
    // ~250 µs, a long run's three ~100 µs, the pendulum's five ~150 µs; an MPFR reference ~2 s per 10
    // time units; the Lyapunov estimate two RK4 steps of ~5 µs per 0.01.
    const double top = 5e4 * static_cast<double>(std::accumulate(s.top_N.begin(), s.top_N.end(), 0LL));
    const double longer = 2e4 * static_cast<double>(s.long_steps) * static_cast<double>(s.long_h.size());
    const double pendulum = 3e4 * static_cast<double>(std::accumulate(s.pendulum_N.begin(), s.pendulum_N.end(), 0LL));
    const double references = 4e8 * (s.top_end_time + s.pendulum_end_time) / 10;
    const double lyapunov = 2e3 * s.lyapunov_time / 0.01;
    const double units = top + longer + pendulum + references + lyapunov;
    return {units, fmt::format("nonlinear_inseparable: {:.3g} units", units)};
  }
  section_result compute(const inseparable_settings& s, const section_inputs& inputs) const override {
    inseparable_settings settings = s;
    settings.progress = inputs.progress;
    return run_inseparable(settings);
  }
  void with_options(inseparable_settings& s, const section_options& o) const override {
    if (!o.timed) s.timed = false;
  }
};

}  // namespace

std::unique_ptr<experiment_section> make_inseparable_section() { return std::make_unique<inseparable_section>(); }

}  // namespace simpson::verify

// The fpu section as a registry entry (experiment_section.hpp).

#include <simpson/verify/fpu_section.hpp>

#include <fmt/format.h>

namespace simpson::verify {
namespace {

class fpu_section final : public typed_section<fpu_settings> {
 public:
  fpu_section() : typed_section("fpu", "a stiff nonlinear problem: the FPU chain of Hairer, Lubich and Wanner, five methods at equal step and equal cost") {}
  std::set<std::string> keys() const override {
    return {"m", "omega", "omega_h", "end_time", "scan_from", "scan_to", "scan_step", "scan_end_time", "samples", "exchange_time", "reference_omega_h",
            "resonances", "equal_cost_omega_h"};
  }

 protected:
  fpu_settings read(const section_reader& r, const std::vector<precision>&) const override {
    fpu_settings f;
    if (r.has("m")) f.m = static_cast<int>(r.integer("m", 1, 20));
    if (r.has("omega")) f.omega = r.number("omega", 1, 1e4);
    if (r.has("omega_h")) f.omega_h = r.numbers("omega_h", 0, 10);
    if (r.has("end_time")) f.end_time = r.number("end_time", 0, 1e6);
    if (r.has("scan_from")) f.scan_from = r.number("scan_from", 0, 10);
    if (r.has("scan_to")) f.scan_to = r.number("scan_to", 0, 10);
    if (r.has("scan_step")) f.scan_step = r.number("scan_step", 0, 10);
    if (r.has("scan_end_time")) f.scan_end_time = r.number("scan_end_time", 0, 1e5);
    if (r.has("samples")) f.samples = static_cast<int>(r.integer("samples", 10, 100000));
    if (r.has("exchange_time")) f.exchange_time = r.number("exchange_time", 0, 1e6);
    if (r.has("reference_omega_h")) f.reference_omega_h = r.number("reference_omega_h", 0.001, 10);
    if (r.has("equal_cost_omega_h")) f.equal_cost_omega_h = r.numbers("equal_cost_omega_h", 0.001, 10);
    if (r.has("resonances")) {  // θ = 2π/k: k = 2 is θ = π, a band end, where every run is at the edge of stability
      const std::vector<long long> k = r.integers("resonances", 3, 12);
      f.resonances.assign(k.begin(), k.end());
    }
    if (f.scan_to < f.scan_from) r.fail("'fpu.scan_to' must be at least 'fpu.scan_from'");
    if ((f.scan_to - f.scan_from) / f.scan_step > 1000) r.fail("'fpu.scan_step' gives more than 1000 points from 'fpu.scan_from' to 'fpu.scan_to'");
    return f;
  }
  fpu_settings initial(const std::vector<precision>&) const override { return {}; }
  section_cost estimate(const fpu_settings& f) const override {
    // A step of the chain in double: ~700 units for the implicit methods (6 to 12 unknowns, a few
    // Newton iterations; measured: the default size, 20 s), ~30 for Störmer–Verlet.
    const double per_time = f.omega * (3 * 700 + 30);
    double units = 0;
    for (const double omega_h : f.omega_h) units += per_time * f.end_time / omega_h;
    for (double omega_h = f.scan_from; omega_h <= f.scan_to + 1e-9; omega_h += f.scan_step) units += per_time * f.scan_end_time / omega_h;
    units += f.omega * 700 * f.exchange_time / f.reference_omega_h;
    return {units, fmt::format("fpu: {:.3g} units", units)};
  }
  section_result compute(const fpu_settings& s, const section_inputs& inputs) const override {
    fpu_settings settings = s;
    settings.progress = inputs.progress;
    return run_fpu(settings);
  }
  void with_options(fpu_settings& f, const section_options& o) const override {
    if (!o.timed) f.timed = false;
  }
};

}  // namespace

std::unique_ptr<experiment_section> make_fpu_section() { return std::make_unique<fpu_section>(); }

}  // namespace simpson::verify

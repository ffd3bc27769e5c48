// The work_precision section as a registry entry (experiment_section.hpp).

#include <simpson/verify/work_precision_section.hpp>

#include "../precision_cost.hpp"

#include <fmt/format.h>

namespace simpson::verify {
namespace {

class work_precision_section final : public typed_section<work_precision_settings> {
 public:
  work_precision_section() : typed_section("work_precision", "error against N and run time of the scheme and its peers on the oscillator, in every precision") {}
  std::set<std::string> keys() const override { return {"schemes", "precisions", "N", "periods", "max_runs", "max_seconds", "benchmark", "forms"}; }
  precisions_use precisions() const override { return precisions_use::applied; }
  bool times_runs() const override { return true; }

 protected:
  work_precision_settings read(const section_reader& r, const std::vector<precision>&) const override {
    work_precision_settings w;
    if (r.has("schemes")) w.schemes = r.schemes("schemes");
    if (!r.has("precisions")) r.fail(r.field("precisions") + " is missing");
    w.precisions = r.precisions("precisions");
    if (r.has("N")) w.meshes = r.integers("N", 1, max_steps);
    if (r.has("periods")) w.periods = r.integer("periods", 1, 1'000'000);
    for (const long long N : w.meshes) {
      if (static_cast<double>(N) * static_cast<double>(w.periods) > static_cast<double>(max_steps)) {
        r.fail("'work_precision': N x periods = " + std::to_string(N) + " x " + std::to_string(w.periods) + " exceeds the limit of " +
               std::to_string(max_steps) + " steps per run");
      }
    }
    if (r.has("max_runs")) w.timing.max_runs = static_cast<unsigned>(r.integer("max_runs", 1, 1000));
    if (r.has("max_seconds")) w.timing.max_seconds = r.number("max_seconds", 0, 3600);
    if (r.has("benchmark")) w.benchmark = r.flag("benchmark");
    if (r.has("forms")) w.forms = r.names("forms", {"step", "matrix"});
    return w;
  }
  work_precision_settings initial(const std::vector<precision>& floating) const override {
    work_precision_settings w;
    w.precisions = floating;
    return w;
  }
  section_cost estimate(const work_precision_settings& w) const override {
    double units = 0;
    for (const precision& p : w.precisions) {
      for (const scheme_id scheme : w.schemes) {
        for (const long long N : w.meshes) {
          // The error run and the exact solution (cos, sin: ~10 steps' worth), then up to max_runs + 1
          // timed runs; each step of a step algorithm costs ~10 matrix steps per stage.
          const double steps = static_cast<double>(N) * static_cast<double>(w.periods);
          units += steps * precision_factor(p) * (10 + 10 * traits_of(scheme).stages * (1 + (w.timing.max_runs > 0 ? 1 + w.timing.max_runs : 0)));
        }
      }
    }
    return {units, w.timing.max_runs > 0 ? fmt::format("work_precision: {:.3g} units (timing capped at {} s per configuration)", units, w.timing.max_seconds)
                                         : fmt::format("work_precision: {:.3g} units (no timing)", units)};
  }
  section_result compute(const work_precision_settings& s, const section_inputs& inputs) const override {
    work_precision_settings settings = s;
    settings.progress = inputs.progress;
    return run_work_precision(settings);
  }
  void with_precisions(work_precision_settings& s, const std::vector<precision>& p) const override { s.precisions = p; }
  void with_options(work_precision_settings& s, const section_options& o) const override {
    if (o.timing_runs) s.timing.max_runs = *o.timing_runs;
    if (!o.timed) s.timing.max_runs = 0;
  }
};

}  // namespace

std::unique_ptr<experiment_section> make_work_precision_section() { return std::make_unique<work_precision_section>(); }

}  // namespace simpson::verify

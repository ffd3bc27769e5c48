// The long_time section as a registry entry (experiment_section.hpp).

#include <simpson/verify/long_time_section.hpp>

#include "../precision_cost.hpp"

#include <fmt/format.h>

namespace simpson::verify {
namespace {

class long_time_section final : public typed_section<long_time_settings> {
 public:
  long_time_section() : typed_section("long_time", "long runs: energy drift and phase error of Φ₃'s three forms in double against mpfr") {}
  std::set<std::string> keys() const override { return {"steps_double", "steps_mpfr", "mpfr_digits", "omega_h", "windows"}; }
  precisions_use precisions() const override { return precisions_use::refused; }
  bool runs_long() const override { return true; }

 protected:
  long_time_settings read(const section_reader& r, const std::vector<precision>&) const override {
    long_time_settings l;
    if (r.has("steps_double")) l.steps_double = r.integer("steps_double", 1, max_steps);
    if (r.has("steps_mpfr")) l.steps_mpfr = r.integer("steps_mpfr", 1, max_steps);
    if (r.has("mpfr_digits")) l.mpfr_digits = static_cast<unsigned>(r.integer("mpfr_digits", precision::min_mpfr_digits, precision::max_mpfr_digits));
    if (r.has("omega_h")) l.omega_h = r.number("omega_h", 0, 2);
    if (r.has("windows")) l.windows = r.integer("windows", 1, 100'000);
    return l;
  }
  long_time_settings initial(const std::vector<precision>&) const override { return {}; }
  section_cost estimate(const long_time_settings& l) const override {
    // Each step also evaluates an energy and an angle (atan2): about 12 units in double (measured:
    // 1e7 steps of the three schemes take ~2 s). Φ₃'s three forms in double: about 2 units a step each.
    const double units = 3 * 12 * static_cast<double>(l.steps_double) + 3 * 2 * static_cast<double>(l.steps_double) +
                         3 * 12 * static_cast<double>(l.steps_mpfr) * precision_factor(precision::mpfr_digits(l.mpfr_digits));
    return {units, fmt::format("long_time: {:.3g} units", units)};
  }
  section_result compute(const long_time_settings& s, const section_inputs& inputs) const override {
    long_time_settings settings = s;
    settings.progress = inputs.progress;
    return run_long_time(settings);
  }
  std::string refusal(const long_time_settings& l) const override {
    return "the long_time section compares double with mpfr:" + std::to_string(l.mpfr_digits) +
           " by design and takes no precision list; leave it out with --sections, or set long_time.mpfr_digits in a scene file";
  }
  void with_options(long_time_settings& l, const section_options& o) const override {
    if (o.long_run) l.steps_double = 1'000'000'000;
  }
};

}  // namespace

std::unique_ptr<experiment_section> make_long_time_section() { return std::make_unique<long_time_section>(); }

}  // namespace simpson::verify

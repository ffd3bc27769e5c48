// The floating section as a registry entry (experiment_section.hpp).

#include <simpson/verify/floating_section.hpp>

#include <fmt/format.h>

namespace simpson::verify {
namespace {

class floating_section final : public typed_section<floating_settings> {
 public:
  floating_section() : typed_section("floating", "the floating-point programs: their one-step round-off proved by Gappa, checked in Coq, against the errors seen") {}
  std::set<std::string> keys() const override { return {"steppers", "formats", "h_denominator", "samples"}; }

 protected:
  floating_settings read(const section_reader& r, const std::vector<precision>&) const override {
    floating_settings f;
    if (r.has("steppers")) f.steppers = r.names("steppers", floating_stepper_names());
    if (r.has("formats")) f.formats = r.names("formats", {"float32", "double"});
    if (r.has("h_denominator")) f.h_denominator = r.integer("h_denominator", 1, 1'000'000);
    if (r.has("samples")) f.samples = static_cast<int>(r.integer("samples", 1, 10'000'000));
    return f;
  }
  floating_settings initial(const std::vector<precision>&) const override { return {}; }
  // Gappa's and coqc's runs are programs of their own: not in double-step units.
  section_cost estimate(const floating_settings&) const override { return {0, "floating: Gappa and coqc (not counted in units)"}; }
  section_result compute(const floating_settings& s, const section_inputs& inputs) const override {
    floating_settings settings = s;
    settings.progress = inputs.progress;
    return run_floating(settings);
  }
  void with_options(floating_settings& f, const section_options& o) const override { f.check_with_coqc = o.certify; }
};

}  // namespace

std::unique_ptr<experiment_section> make_floating_section() { return std::make_unique<floating_section>(); }

}  // namespace simpson::verify

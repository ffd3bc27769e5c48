// The stability section as a registry entry (experiment_section.hpp).

#include <simpson/verify/stability_section.hpp>

#include "../precision_cost.hpp"

#include <fmt/format.h>

namespace simpson::verify {
namespace {

class stability_section final : public typed_section<stability_settings> {
 public:
  stability_section() : typed_section("stability", "stiff and extreme cases: the exact stable set, the endpoints' growth, a stiff linear chain, extreme masses and steps") {}
  std::set<std::string> keys() const override { return {"precisions", "stiff_ratios", "stiff_doublings", "omega_h", "masses", "steps", "endpoint_power"}; }
  precisions_use precisions() const override { return precisions_use::applied; }

 protected:
  stability_settings read(const section_reader& r, const std::vector<precision>&) const override {
    stability_settings st;
    if (!r.has("precisions")) r.fail(r.field("precisions") + " is missing");
    st.precisions = r.precisions("precisions");
    if (r.has("stiff_ratios")) st.stiff_ratios = r.numbers("stiff_ratios", 2, 1e8);
    if (r.has("stiff_doublings")) st.stiff_doublings = static_cast<int>(r.integer("stiff_doublings", 10, 60));
    if (r.has("omega_h")) st.omega_h = r.numbers("omega_h", 0, 1e3);
    if (r.has("masses")) st.masses = r.numbers("masses", 0, 1e300);
    if (r.has("steps")) st.steps = r.integer("steps", 1, max_steps);
    if (r.has("endpoint_power")) {
      // The smallest size whose fit decides every endpoint's growth (measured: from 5e5 every power
      // up to 1e12 decides; at 3e5 the growth just above 2√2 is not yet told from linear): a value
      // below it would make expectations fail that no run of that size can decide.
      constexpr long long deciding = 1000000;
      st.endpoint_power = r.integer("endpoint_power", 1, 1000000000000LL);
      if (st.endpoint_power < deciding) {
        r.fail(fmt::format("'stability.endpoint_power' must be at least {}, the smallest size whose fit decides the endpoints' growth "
                           "(bounded, linear or exponential; docs/stiff.md), got {}",
                           deciding, st.endpoint_power));
      }
    }
    return st;
  }
  stability_settings initial(const std::vector<precision>& floating) const override {
    stability_settings st;
    st.precisions = floating;
    return st;
  }
  section_cost estimate(const stability_settings& s) const override {
    // The endpoints' closed form and the stiff chain's squarings (an 8 x 8 product, ~500 units, per
    // doubling and band) cost the same at any n: both in mpfr:50.
    double units = (9 * 100 + 500.0 * 4 * static_cast<double>(s.stiff_ratios.size() * static_cast<std::size_t>(s.stiff_doublings))) *
                   precision_factor(precision::mpfr_digits(50));
    for (const precision& p : s.precisions) {
      units += static_cast<double>(s.omega_h.size() + s.masses.size()) * static_cast<double>(s.steps) * precision_factor(p) * 2;
    }
    return {units, fmt::format("stability: {:.3g} units", units)};
  }
  section_result compute(const stability_settings& s, const section_inputs& inputs) const override {
    stability_settings settings = s;
    settings.progress = inputs.progress;
    return run_stability(settings);
  }
  void with_precisions(stability_settings& s, const std::vector<precision>& p) const override { s.precisions = p; }
};

}  // namespace

std::unique_ptr<experiment_section> make_stability_section() { return std::make_unique<stability_section>(); }

}  // namespace simpson::verify

// The family section as a registry entry (experiment_section.hpp).

#include <simpson/verify/family_section.hpp>

#include <fmt/format.h>

namespace simpson::verify {
namespace {

class family_section final : public typed_section<family_settings> {
 public:
  family_section() : typed_section("family", "the Galerkin family of the scheme: each member's map, order, symplecticity and stability") {}
  std::set<std::string> keys() const override { return {"max_degree", "budget_seconds", "ginac", "node_check_degree"}; }

 protected:
  family_settings read(const section_reader& r, const std::vector<precision>&) const override {
    family_settings f;
    if (r.has("max_degree")) f.max_degree = static_cast<int>(r.integer("max_degree", 1, 8));
    if (r.has("budget_seconds")) f.budget_seconds = r.number("budget_seconds", 0, 3600);
    if (r.has("ginac")) f.ginac = r.flag("ginac");
    if (r.has("node_check_degree")) f.node_check_degree = static_cast<int>(r.integer("node_check_degree", 0, 4));
    return f;
  }
  family_settings initial(const std::vector<precision>&) const override { return {}; }
  // Symbolic work bounded by its own budget (budget_seconds): not in double-step units.
  section_cost estimate(const family_settings& f) const override { return {0, fmt::format("family: symbolic, at most {:g} s by its own budget", f.budget_seconds)}; }
  section_result compute(const family_settings& s, const section_inputs& inputs) const override {
    family_settings settings = s;
    settings.progress = inputs.progress;
    return run_family(settings);
  }
};

}  // namespace

std::unique_ptr<experiment_section> make_family_section() { return std::make_unique<family_section>(); }

}  // namespace simpson::verify

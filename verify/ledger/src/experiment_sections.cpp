// The registry of experiment sections (ledger.hpp, experiment_sections()): one line per section. The
// book's table1 reads the paper's Table 1 and its stated solution from the run's document first, the
// knowledge of this paper the experiments layer does not have.

#include <simpson/verify/table1_reader.hpp>
#include <simpson/verify/ledger.hpp>

#include <simpson/verify/experiments.hpp>
#include <simpson/verify/paper_reading.hpp>

#include <memory>

namespace simpson::verify {
namespace {

/// Table 1 as the run's paper prints it (a changed copy is judged as printed); no printed value when
/// the table can no longer be read (table-values then says text-changed), and no stated solution when
/// its sentence is gone (its claim says when).
class paper_table1_section final : public table1_section {
 protected:
  section_result compute(const table1_settings& s, const section_inputs& inputs) const override {
    table1_settings settings = s;
    if (inputs.paper != nullptr) {
      try {
        const printed_table1 printed = read_table1(inputs.paper->source);
        settings.printed_values = printed.values;
        settings.printed_digits = printed.digits;
        settings.printed_orders = printed.orders;
      } catch (const text_changed&) {
      }
      try {
        const stated_solution stated = read_stated_solution(inputs.paper->source);
        settings.stated = {stated.amplitude, stated.phase, stated.period};
      } catch (const text_changed&) {
      }
    }
    return table1_section::compute(settings, inputs);
  }
};

}  // namespace

const std::vector<const experiment_section*>& experiment_sections() {
  static const std::vector<std::unique_ptr<const experiment_section>> owned = [] {
    std::vector<std::unique_ptr<const experiment_section>> all;
    all.push_back(std::make_unique<paper_table1_section>());
    all.push_back(make_work_precision_section());
    all.push_back(make_stability_section());
    all.push_back(make_long_time_section());
    all.push_back(make_nonlinear_section());
    all.push_back(make_floating_section());
    all.push_back(make_family_section());
    all.push_back(make_fpu_section());
    all.push_back(make_inseparable_section());
    return all;
  }();
  static const std::vector<const experiment_section*> sections = [] {
    std::vector<const experiment_section*> out;
    for (const auto& s : owned) out.push_back(s.get());
    return out;
  }();
  return sections;
}

}  // namespace simpson::verify

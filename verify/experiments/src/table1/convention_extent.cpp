// The joint extent of a fitted parameter of the convention search: see convention_units.hpp.

#include "convention_units.hpp"

#include <nlopt.hpp>

#include <algorithm>
#include <stdexcept>

namespace simpson::verify::detail {

double joint_end(const std::vector<printed_entry>& printed, const convention_choice& choice, const std::vector<continuous_parameter>& continuous,
                 const parametrised_experiment& experiment, const parameter_values& start, std::size_t which, int direction,
                 std::size_t& evaluations) {
  struct reach {
    const std::vector<printed_entry>& printed;
    const convention_choice& choice;
    const std::vector<continuous_parameter>& continuous;
    const parametrised_experiment& experiment;
    std::size_t& evaluations;
    std::size_t which;
    int direction;
    double farthest;  // the unit coordinate of the farthest point that reproduced every entry
  } data{printed, choice, continuous, experiment, evaluations, which, direction, to_unit(continuous[which], start.at(continuous[which].name))};
  const std::size_t n = continuous.size();
  std::vector<double> x;
  for (const continuous_parameter& p : continuous) x.push_back(to_unit(p, start.at(p.name)));
  nlopt::opt opt(nlopt::LN_COBYLA, static_cast<unsigned>(n));
  opt.set_lower_bounds(std::vector<double>(n, 0.0));
  opt.set_upper_bounds(std::vector<double>(n, 1.0));
  opt.set_max_objective([](unsigned, const double* w, double* grad, void* raw) {
    const reach& r = *static_cast<const reach*>(raw);
    if (grad != nullptr) std::fill(grad, grad + r.continuous.size(), 0.0);
    return r.direction * w[r.which];
  }, &data);
  opt.add_inequality_mconstraint(
      [](unsigned count, double* result, unsigned m, const double* w, double*, void* raw) {
        reach& r = *static_cast<reach*>(raw);
        parameter_values v;
        for (unsigned k = 0; k < m; ++k) v[r.continuous[k].name] = from_unit(r.continuous[k], w[k]);
        ++r.evaluations;
        const std::vector<entry_score> scores = score_entries(r.printed, r.experiment(r.choice, v));
        for (unsigned e = 0; e < count; ++e) result[e] = std::min(scores[e].residual, 1e6) - 1;
        bool all = true;
        for (const entry_score& s : scores) all = all && s.reproduced;
        if (all && r.direction * w[r.which] > r.direction * r.farthest) r.farthest = w[r.which];
      },
      &data, std::vector<double>(printed.size(), 0.0));
  opt.set_maxeval(300);
  opt.set_initial_step(std::vector<double>(n, 1e-4));
  double f = 0;
  try {
    opt.optimize(x, f);
  } catch (const nlopt::roundoff_limited&) {
  } catch (const std::invalid_argument&) {
  }
  return from_unit(continuous[which], data.farthest);
}

}  // namespace simpson::verify::detail

#include <simpson/verify/convention_search.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace simpson::verify {
namespace {

/// The fit's objective: squared log ratios of the entries not at round-off, plus a large penalty
/// for a round-off entry computed above its bound (or an entry computed as zero).
double misfit(const std::vector<printed_entry>& printed, const std::vector<computed_entry>& computed) {
  double sum = 0;
  for (std::size_t k = 0; k < printed.size(); ++k) {
    if (printed[k].round_off) {
      if (computed[k].value > computed[k].round_off_bound) sum += 100;
      continue;
    }
    if (!(computed[k].value > 0) || !std::isfinite(computed[k].value)) {
      sum += 1e6;
      continue;
    }
    const double r = std::log(computed[k].value / printed[k].value);
    sum += r * r;
  }
  return sum;
}

double to_unit(const continuous_parameter& p, double v) {
  return p.log_scale ? std::log(v / p.low) / std::log(p.high / p.low) : (v - p.low) / (p.high - p.low);
}
double from_unit(const continuous_parameter& p, double u) {
  u = std::clamp(u, 0.0, 1.0);
  return p.log_scale ? p.low * std::pow(p.high / p.low, u) : p.low + u * (p.high - p.low);
}

convention_candidate judged(const std::vector<printed_entry>& printed, const convention_choice& choice, const parameter_values& values,
                            const parametrised_experiment& experiment, std::size_t& evaluations) {
  convention_candidate c;
  c.choice = choice;
  c.values = values;
  ++evaluations;
  c.entries = score_entries(printed, experiment(choice, values));
  for (const entry_score& e : c.entries) {
    c.reproduced += e.reproduced;
    c.worst = std::max(c.worst, e.residual);
  }
  return c;
}

bool better(const convention_candidate& a, const convention_candidate& b) {
  if (a.reproduced != b.reproduced) return a.reproduced > b.reproduced;
  return a.worst < b.worst;
}

}  // namespace

bool convention_search_result::stated_reproduces() const { return stated.reproduced == stated.entries.size(); }

const convention_candidate* convention_search_result::reproducing() const {
  return !tried.empty() && tried.front().reproduced == tried.front().entries.size() ? &tried.front() : nullptr;
}

double half_unit_of_last_digit(double value, int digits) {
  const double exponent = std::floor(std::log10(std::abs(value)));
  return 0.5 * std::pow(10.0, exponent - digits + 1);
}

std::vector<entry_score> score_entries(const std::vector<printed_entry>& printed, const std::vector<computed_entry>& computed) {
  std::vector<entry_score> scores;
  for (std::size_t k = 0; k < printed.size(); ++k) {
    entry_score s;
    s.computed = computed[k].value;
    if (printed[k].round_off) {
      s.residual = computed[k].round_off_bound > 0 ? computed[k].value / computed[k].round_off_bound : 0;
      s.reproduced = computed[k].value <= computed[k].round_off_bound;
    } else {
      s.residual = std::abs(computed[k].value - printed[k].value) / half_unit_of_last_digit(printed[k].value, printed[k].digits);
      if (!std::isfinite(s.residual)) s.residual = std::numeric_limits<double>::max();
      s.reproduced = s.residual <= 1;
    }
    scores.push_back(s);
  }
  return scores;
}

convention_search_result search_conventions(const std::vector<printed_entry>& printed, const std::vector<discrete_convention>& discrete,
                                            const std::vector<continuous_parameter>& continuous, const parametrised_experiment& experiment) {
  const auto start = std::chrono::steady_clock::now();
  convention_search_result result;
  convention_choice stated_choice;
  parameter_values stated_values;
  for (const discrete_convention& d : discrete) stated_choice[d.name] = d.stated;
  for (const continuous_parameter& p : continuous) stated_values[p.name] = p.stated;
  result.stated = judged(printed, stated_choice, stated_values, experiment, result.evaluations);

  std::vector<std::size_t> index(discrete.size(), 0);
  for (;;) {
    convention_choice choice;
    for (std::size_t k = 0; k < discrete.size(); ++k) choice[discrete[k].name] = discrete[k].options[index[k]];
    // Coordinate search in the unit cube: a coarse scan of each parameter, then golden sections.
    parameter_values values = stated_values;
    const auto objective = [&](const parameter_values& v) {
      ++result.evaluations;
      return misfit(printed, experiment(choice, v));
    };
    double current = objective(values);
    for (int round = 0; round < 3; ++round) {
      for (const continuous_parameter& p : continuous) {
        double best_u = to_unit(p, values[p.name]);
        for (int g = 0; g <= 16; ++g) {
          parameter_values trial = values;
          trial[p.name] = from_unit(p, g / 16.0);
          const double f = objective(trial);
          if (f < current) current = f, best_u = g / 16.0;
        }
        double lo = std::max(0.0, best_u - 1.0 / 16), hi = std::min(1.0, best_u + 1.0 / 16);
        const double golden = (std::sqrt(5.0) - 1) / 2;
        for (int it = 0; it < 40; ++it) {
          const double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
          parameter_values ta = values, tb = values;
          ta[p.name] = from_unit(p, a);
          tb[p.name] = from_unit(p, b);
          if (objective(ta) < objective(tb)) hi = b; else lo = a;
        }
        parameter_values trial = values;
        trial[p.name] = from_unit(p, (lo + hi) / 2);
        const double f = objective(trial);
        if (f <= current) current = f, best_u = (lo + hi) / 2;
        values[p.name] = from_unit(p, best_u);
      }
    }
    result.tried.push_back(judged(printed, choice, values, experiment, result.evaluations));
    std::size_t k = 0;
    while (k < discrete.size() && ++index[k] == discrete[k].options.size()) index[k++] = 0;
    if (k == discrete.size()) break;
  }
  std::stable_sort(result.tried.begin(), result.tried.end(), better);
  // How sharply the table pins each fitted parameter of a reproducing candidate.
  if (!result.tried.empty() && result.tried.front().reproduced == printed.size()) {
    convention_candidate& best = result.tried.front();
    for (const continuous_parameter& p : continuous) {
      std::pair<double, double> interval{best.values[p.name], best.values[p.name]};
      for (const int direction : {-1, 1}) {
        double inside = to_unit(p, best.values[p.name]), step = 1e-6;
        while (step < 1) {
          parameter_values trial = best.values;
          const double u = inside + direction * step;
          if (u < 0 || u > 1) break;
          trial[p.name] = from_unit(p, u);
          if (judged(printed, best.choice, trial, experiment, result.evaluations).reproduced != printed.size()) break;
          inside = u;
          step *= 1.5;
        }
        (direction < 0 ? interval.first : interval.second) = from_unit(p, inside);
      }
      best.pinned[p.name] = interval;
    }
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::string describe(const convention_candidate& c) {
  std::vector<std::string> parts;
  for (const auto& [name, option] : c.choice) parts.push_back(fmt::format("{}: {}", name, option));
  for (const auto& [name, value] : c.values) parts.push_back(fmt::format("{} = {:.4g}", name, value));
  return fmt::format("{}", fmt::join(parts, "; "));
}

}  // namespace simpson::verify

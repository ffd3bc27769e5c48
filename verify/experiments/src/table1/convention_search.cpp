#include <simpson/verify/convention_search.hpp>

#include "convention_units.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>
#include <nlopt.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace simpson::verify {
namespace {

using detail::from_unit;
using detail::joint_end;
using detail::to_unit;


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


/// Half a unit of an entry's last printed digit, as a log ratio: an entry is reproduced when
/// |log(computed / printed)| is about at most this.
double relative_half_unit(const printed_entry& e) {
  return std::log1p(half_unit_of_last_digit(e.value, e.digits) / std::abs(e.value));
}

/// Each entry's power in each scale parameter, measured: the ratio of two runs whose parameter
/// differs by a factor 2, at two points of the scanned parameters. An entry enters the fit when both
/// give the same integer power for every scale parameter; an entry at round-off never does.
struct entry_powers {
  std::vector<std::vector<double>> power;  // [entry][scale parameter]
  std::vector<bool> fitted;
};

struct fit_setup {
  std::vector<const continuous_parameter*> scale, scanned;
  parameter_values reference;  // the scale parameters at their stated values
};

parameter_values at_units(const fit_setup& setup, const std::vector<double>& scanned_units) {
  parameter_values v = setup.reference;
  for (std::size_t k = 0; k < setup.scanned.size(); ++k) v[setup.scanned[k]->name] = from_unit(*setup.scanned[k], scanned_units[k]);
  return v;
}

entry_powers measure_powers(const std::vector<printed_entry>& printed, const convention_choice& choice, const fit_setup& setup,
                            const parametrised_experiment& experiment, std::size_t& evaluations) {
  entry_powers out{std::vector<std::vector<double>>(printed.size(), std::vector<double>(setup.scale.size(), 0)),
                   std::vector<bool>(printed.size(), true)};
  for (std::size_t k = 0; k < printed.size(); ++k) out.fitted[k] = !printed[k].round_off;
  for (const double generic : {0.3183098861837907, 0.7071067811865476}) {  // 1/π and 1/√2: points no grid hits
    const parameter_values base_values = at_units(setup, std::vector<double>(setup.scanned.size(), generic));
    ++evaluations;
    const std::vector<computed_entry> base = experiment(choice, base_values);
    for (std::size_t s = 0; s < setup.scale.size(); ++s) {
      const continuous_parameter& p = *setup.scale[s];
      parameter_values moved = base_values;
      const double factor = p.stated * 2 <= p.high ? 2.0 : 0.5;
      moved[p.name] = p.stated * factor;
      ++evaluations;
      const std::vector<computed_entry> scaled = experiment(choice, moved);
      for (std::size_t e = 0; e < printed.size(); ++e) {
        if (!out.fitted[e]) continue;
        const double power = std::log(scaled[e].value / base[e].value) / std::log(factor);
        const bool integer = std::isfinite(power) && std::abs(power - std::round(power)) < 1e-6;
        const bool first = generic < 0.5;
        if (!integer || (!first && std::round(power) != out.power[e][s])) {
          out.fitted[e] = false;
          continue;
        }
        out.power[e][s] = std::round(power);
      }
    }
  }
  return out;
}

/// The scale parameters' logarithms (relative to their stated values) that minimise the squared log
/// ratios of the fitted entries, within their bounds: every choice of free, low or high for each
/// parameter, the free ones by least squares; the best feasible one. Returns the misfit and sets `x`.
double closed_form_scales(const std::vector<printed_entry>& printed, const std::vector<computed_entry>& base, const entry_powers& powers,
                          const fit_setup& setup, std::vector<double>& x) {
  const std::size_t S = setup.scale.size();
  if (S > 3) throw std::invalid_argument("search_conventions: at most three scale parameters");
  double penalty = 0;
  std::vector<std::size_t> rows;
  for (std::size_t e = 0; e < printed.size(); ++e) {
    if (printed[e].round_off) {
      if (base[e].value > base[e].round_off_bound) penalty += 100;
    } else if (!(base[e].value > 0) || !std::isfinite(base[e].value)) {
      penalty += 1e6;
    } else if (powers.fitted[e]) {
      rows.push_back(e);
    }
  }
  // Each log ratio in units of its entry's half unit (relative): the fit weighs an entry printed as
  // 1.03 and one printed as 9.87 by what their last digits allow.
  std::vector<double> c(rows.size()), weight(rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    weight[r] = 1 / relative_half_unit(printed[rows[r]]);
    c[r] = weight[r] * std::log(base[rows[r]].value / printed[rows[r]].value);
  }
  std::vector<double> low(S), high(S);
  for (std::size_t s = 0; s < S; ++s) {
    low[s] = std::log(setup.scale[s]->low / setup.scale[s]->stated);
    high[s] = std::log(setup.scale[s]->high / setup.scale[s]->stated);
  }
  const auto misfit_at = [&](const std::vector<double>& y) {
    double sum = 0;
    for (std::size_t r = 0; r < rows.size(); ++r) {
      double v = c[r];
      for (std::size_t s = 0; s < S; ++s) v += weight[r] * powers.power[rows[r]][s] * y[s];
      sum += v * v;
    }
    return sum;
  };
  double best = std::numeric_limits<double>::infinity();
  x.assign(S, 0);
  std::size_t combinations = 1;
  for (std::size_t s = 0; s < S; ++s) combinations *= 3;
  for (std::size_t code = 0; code < combinations; ++code) {
    std::vector<double> y(S, 0);
    std::vector<std::size_t> free;
    for (std::size_t s = 0, rest = code; s < S; ++s, rest /= 3) {
      if (rest % 3 == 0) free.push_back(s);
      else y[s] = rest % 3 == 1 ? low[s] : high[s];
    }
    if (!free.empty() && !rows.empty()) {
      // The normal equations of the free parameters (at most three: no allocation), solved for the
      // least-norm solution: a parameter no fitted entry depends on stays stated.
      using small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;
      using small_vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
      const auto k = static_cast<Eigen::Index>(free.size());
      small normal = small::Zero(k, k);
      small_vector rhs = small_vector::Zero(k);
      for (std::size_t r = 0; r < rows.size(); ++r) {
        double fixed = c[r];
        for (std::size_t s = 0; s < S; ++s) fixed += weight[r] * powers.power[rows[r]][s] * y[s];
        for (std::size_t f = 0; f < free.size(); ++f) {
          const double af = weight[r] * powers.power[rows[r]][free[f]];
          rhs(static_cast<Eigen::Index>(f)) -= af * fixed;
          for (std::size_t g = 0; g < free.size(); ++g) {
            normal(static_cast<Eigen::Index>(f), static_cast<Eigen::Index>(g)) += af * weight[r] * powers.power[rows[r]][free[g]];
          }
        }
      }
      small_vector z(k);
      if (k == 1) {
        z(0) = normal(0, 0) > 0 ? rhs(0) / normal(0, 0) : 0;
      } else if (k == 2) {
        // By hand (this runs some 10^5 times): the inverse when regular; when the two columns are
        // proportional (rank 1), the least-norm solution N⁺ r = N r / trace(N)².
        const double det = normal(0, 0) * normal(1, 1) - normal(0, 1) * normal(1, 0), trace = normal(0, 0) + normal(1, 1);
        if (std::abs(det) > 1e-12 * trace * trace) {
          z(0) = (normal(1, 1) * rhs(0) - normal(0, 1) * rhs(1)) / det;
          z(1) = (normal(0, 0) * rhs(1) - normal(1, 0) * rhs(0)) / det;
        } else if (trace > 0) {
          z(0) = (normal(0, 0) * rhs(0) + normal(0, 1) * rhs(1)) / (trace * trace);
          z(1) = (normal(1, 0) * rhs(0) + normal(1, 1) * rhs(1)) / (trace * trace);
        } else {
          z.setZero();
        }
      } else {
        z = normal.completeOrthogonalDecomposition().solve(rhs);
      }
      bool feasible = true;
      for (std::size_t f = 0; f < free.size(); ++f) {
        y[free[f]] = z(static_cast<Eigen::Index>(f));
        feasible = feasible && y[free[f]] >= low[free[f]] - 1e-12 && y[free[f]] <= high[free[f]] + 1e-12;
      }
      if (!feasible) continue;
    }
    const double f = misfit_at(y);
    if (f < best) best = f, x = y;
    // The unconstrained optimum (code 0, every parameter free) inside the bounds is the constrained
    // one (a convex problem): the bounds need not be tried.
    if (code == 0) break;
  }
  return best + penalty;
}

/// The polish: the largest residual minimised as NLopt's COBYLA poses a minimax problem (minimise t
/// subject to every residual <= t), every parameter free in the unit cube, from `start`. Stops as soon
/// as every entry is reproduced. Returns the best point's units.
std::vector<double> polished_units(const std::vector<printed_entry>& printed, const convention_choice& choice,
                                   const std::vector<continuous_parameter>& continuous, const parametrised_experiment& experiment,
                                   const parameter_values& start, std::size_t& evaluations) {
  struct polish {
    const std::vector<printed_entry>& printed;
    const convention_choice& choice;
    const std::vector<continuous_parameter>& continuous;
    const parametrised_experiment& experiment;
    std::size_t& evaluations;
    std::vector<double> best;
    double best_worst = std::numeric_limits<double>::infinity();
  } data{printed, choice, continuous, experiment, evaluations, {}};
  const std::size_t n = continuous.size();
  std::vector<double> x;
  for (const continuous_parameter& p : continuous) x.push_back(to_unit(p, start.at(p.name)));
  x.push_back(0);  // t
  nlopt::opt opt(nlopt::LN_COBYLA, static_cast<unsigned>(n + 1));
  std::vector<double> low(n + 1, 0.0), high(n + 1, 1.0);
  high[n] = 1e6;
  opt.set_lower_bounds(low);
  opt.set_upper_bounds(high);
  opt.set_min_objective([](unsigned m, const double* w, double* grad, void*) {
    if (grad != nullptr) std::fill(grad, grad + m, 0.0);
    return w[m - 1];
  }, nullptr);
  opt.add_inequality_mconstraint(
      [](unsigned count, double* result, unsigned m, const double* w, double*, void* raw) {
        polish& p = *static_cast<polish*>(raw);
        parameter_values v;
        for (unsigned k = 0; k + 1 < m; ++k) v[p.continuous[k].name] = from_unit(p.continuous[k], w[k]);
        ++p.evaluations;
        const std::vector<entry_score> scores = score_entries(p.printed, p.experiment(p.choice, v));
        double worst = 0;
        for (unsigned e = 0; e < count; ++e) {
          const double r = std::min(scores[e].residual, 1e6);
          result[e] = r - w[m - 1];
          worst = std::max(worst, r);
        }
        if (worst < p.best_worst) p.best_worst = worst, p.best.assign(w, w + m - 1);
        if (worst <= 1) throw nlopt::forced_stop();  // reproduced: nothing left to polish
      },
      &data, std::vector<double>(printed.size(), 1e-9));
  {
    // t starts at the start's largest residual, so that the start is feasible.
    ++evaluations;
    double worst = 0;
    for (const entry_score& e : score_entries(printed, experiment(choice, start))) worst = std::max(worst, std::min(e.residual, 1e6));
    x[n] = worst;
    data.best.assign(x.begin(), x.begin() + static_cast<long>(n));
    data.best_worst = worst;
  }
  // A table can pin a parameter to 10^-5 of its range (an entry near a zero of the error, as a
  // function of the phase): the polish restarts from its best point with ever smaller first steps.
  opt.set_maxeval(400);
  for (const double step : {1e-3, 1e-5, 1e-7}) {
    if (data.best_worst <= 1) break;
    std::copy(data.best.begin(), data.best.end(), x.begin());
    x[n] = data.best_worst;
    opt.set_initial_step(std::vector<double>(n + 1, step));
    double f = 0;
    try {
      opt.optimize(x, f);
    } catch (const nlopt::forced_stop&) {
    } catch (const nlopt::roundoff_limited&) {
    }
  }
  return data.best;
}

/// One discrete choice's global fit (see search_conventions), judged by a full run.
convention_candidate global_fit(const std::vector<printed_entry>& printed, const convention_choice& choice,
                                const std::vector<continuous_parameter>& continuous, const parametrised_experiment& experiment,
                                std::size_t scan_points, std::size_t& evaluations) {
  fit_setup setup;
  for (const continuous_parameter& p : continuous) {
    (p.scale ? setup.scale : setup.scanned).push_back(&p);
    if (p.scale) setup.reference[p.name] = p.stated;
  }
  const entry_powers powers = measure_powers(printed, choice, setup, experiment, evaluations);
  const std::size_t d = setup.scanned.size();
  const std::size_t per_dimension = d == 0 ? 1 : std::max<std::size_t>(2, static_cast<std::size_t>(std::lround(std::pow(double(scan_points), 1.0 / double(d)))));
  std::size_t points = 1;
  for (std::size_t k = 0; k < d; ++k) points *= per_dimension;

  // The values at scanned units u, with the scale parameters in closed form; its misfit.
  const auto fitted_at = [&](const std::vector<double>& u, double& misfit) {
    parameter_values v = at_units(setup, u);
    ++evaluations;
    std::vector<double> x;
    misfit = closed_form_scales(printed, experiment(choice, v), powers, setup, x);
    for (std::size_t s = 0; s < setup.scale.size(); ++s) v[setup.scale[s]->name] = setup.scale[s]->stated * std::exp(x[s]);
    return v;
  };
  const auto units_of = [&](std::size_t g) {
    std::vector<double> u(d);
    for (std::size_t k = 0; k < d; ++k, g /= per_dimension) u[k] = double(g % per_dimension) / double(per_dimension - 1);
    return u;
  };
  // Where the table is reproduced, every fitted entry lies within half a unit of its last digit, so
  // the least-squares misfit there (and the minimum over the scales) is at most this. A start whose
  // refined misfit exceeds it several times has no reproducing point near: it is not polished.
  const double reproducible_misfit = double(std::count(powers.fitted.begin(), powers.fitted.end(), true));
  std::vector<double> scan(points);
  for (std::size_t g = 0; g < points; ++g) fitted_at(units_of(g), scan[g]);

  // The starting points: in one dimension the grid's local minima, best first; otherwise its best points.
  std::vector<std::size_t> starts;
  for (std::size_t g = 0; g < points; ++g) {
    const bool minimum = d != 1 || ((g == 0 || scan[g] <= scan[g - 1]) && (g + 1 == points || scan[g] <= scan[g + 1]));
    if (minimum) starts.push_back(g);
  }
  std::sort(starts.begin(), starts.end(), [&](std::size_t a, std::size_t b) { return scan[a] < scan[b]; });
  if (starts.size() > 4) starts.resize(4);

  convention_candidate best;
  bool have = false;
  for (const std::size_t g : starts) {
    std::vector<double> u = units_of(g);
    double misfit = scan[g];
    if (d == 1) {
      // A finer scan between the neighbouring grid points, then golden sections (one new point per
      // step) between the neighbours of its best.
      const double step = 1.0 / double(per_dimension - 1);
      const int fine = 16;
      double best_u = u[0];
      for (int i = -fine; i <= fine; ++i) {
        const double w = u[0] + step * double(i) / fine;
        if (w < 0 || w > 1 || i == 0) continue;
        double f = 0;
        fitted_at({w}, f);
        if (f < misfit) misfit = f, best_u = w;
      }
      const double golden = (std::sqrt(5.0) - 1) / 2;
      double lo = std::max(0.0, best_u - step / fine), hi = std::min(1.0, best_u + step / fine);
      double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo), fa = 0, fb = 0;
      fitted_at({a}, fa);
      fitted_at({b}, fb);
      for (int it = 0; it < 30; ++it) {
        if (fa < fb) {
          hi = b, b = a, fb = fa, a = hi - golden * (hi - lo);
          fitted_at({a}, fa);
        } else {
          lo = a, a = b, fa = fb, b = lo + golden * (hi - lo);
          fitted_at({b}, fb);
        }
      }
      if (std::min(fa, fb) < misfit) best_u = fa < fb ? a : b;
      u[0] = best_u;
    }
    parameter_values values = fitted_at(u, misfit);
    convention_candidate c = judged(printed, choice, values, experiment, evaluations);
    if (c.reproduced != printed.size() && misfit <= 4 * reproducible_misfit) {
      if (d == 1) {
        // The least-squares optimum need not be where the largest residual is least, and a table can
        // pin the scanned parameter to 10^-6 of its range: a fine scan of the largest residual
        // around it first (the scales still in closed form).
        const double step = 1.0 / double(per_dimension - 1);
        const std::size_t fine = 2000;
        for (std::size_t i = 0; i <= fine; ++i) {
          const double w = u[0] + step * (2.0 * double(i) / double(fine) - 1);
          if (w < 0 || w > 1) continue;
          double ignored = 0;
          convention_candidate t = judged(printed, choice, fitted_at({w}, ignored), experiment, evaluations);
          if (better(t, c)) values = t.values, c = std::move(t);
          if (c.reproduced == printed.size()) break;
        }
      }
    }
    if (c.reproduced != printed.size() && misfit <= 4 * reproducible_misfit) {
      const std::vector<double> z = polished_units(printed, choice, continuous, experiment, values, evaluations);
      parameter_values polished;
      for (std::size_t k = 0; k < continuous.size(); ++k) polished[continuous[k].name] = from_unit(continuous[k], z[k]);
      convention_candidate p = judged(printed, choice, polished, experiment, evaluations);
      if (better(p, c)) c = std::move(p);
    }
    if (!have || better(c, best)) best = std::move(c), have = true;
  }
  return best;
}
/// Less complex first among candidates that reproduce as many entries; then the smaller worst residual.
bool simpler(const convention_candidate& a, const convention_candidate& b) {
  if (a.reproduced != b.reproduced) return a.reproduced > b.reproduced;
  if (a.complexity != b.complexity) return a.complexity < b.complexity;
  return a.worst < b.worst;
}

/// A fitted candidate's values named with the fewest significant digits (at least 4) at which the
/// rounded values, run again, reproduce as many entries as the candidate: no printed value claims
/// more than it does.
void name_fitted_values(convention_candidate& c, const std::vector<printed_entry>& printed, const parametrised_experiment& experiment,
                        std::size_t& evaluations) {
  for (int digits = 4; digits <= 17; ++digits) {
    parameter_values rounded;
    std::map<std::string, std::string> names;
    for (const auto& [name, value] : c.values) {
      names[name] = fmt::format("{:.{}g}", value, digits);
      rounded[name] = std::stod(names[name]);
    }
    if (digits == 17 || judged(printed, c.choice, rounded, experiment, evaluations).reproduced == c.reproduced) {
      c.value_names = std::move(names);
      return;
    }
  }
}

}  // namespace

entry_miss miss_of(const printed_entry& printed, double computed) {
  const double half = half_unit_of_last_digit(printed.value, printed.digits);
  return {std::abs(computed - printed.value) - half, computed > printed.value ? printed.value + half : printed.value - half};
}

std::vector<convention_candidate> simple_hypotheses(const std::vector<printed_entry>& printed, const std::vector<discrete_convention>& discrete,
                                                    const std::vector<continuous_parameter>& continuous, const simple_values& simple,
                                                    const parametrised_experiment& experiment, std::size_t& evaluations) {
  std::vector<convention_candidate> out;
  if (simple.empty()) return out;
  // Each parameter's list: its simple values, or its stated value alone.
  std::vector<std::vector<simple_value>> lists;
  for (const continuous_parameter& p : continuous) {
    const auto it = simple.find(p.name);
    if (it != simple.end() && !it->second.empty()) lists.push_back(it->second);
    else lists.push_back({{fmt::format("{:g}", p.stated), p.stated}});
  }
  std::vector<std::size_t> d_index(discrete.size(), 0);
  for (;;) {
    convention_choice choice;
    int departures = 0;
    for (std::size_t k = 0; k < discrete.size(); ++k) {
      choice[discrete[k].name] = discrete[k].options[d_index[k]];
      departures += discrete[k].options[d_index[k]] == discrete[k].stated ? 0 : 1;
    }
    std::vector<std::size_t> v_index(lists.size(), 0);
    for (;;) {
      parameter_values values;
      std::map<std::string, std::string> names;
      int rank = 0;
      for (std::size_t k = 0; k < lists.size(); ++k) {
        values[continuous[k].name] = lists[k][v_index[k]].value;
        names[continuous[k].name] = lists[k][v_index[k]].name;
        rank += static_cast<int>(v_index[k]);
      }
      convention_candidate c = judged(printed, choice, values, experiment, evaluations);
      c.value_names = std::move(names);
      c.complexity = departures + rank;
      out.push_back(std::move(c));
      std::size_t k = 0;
      while (k < lists.size() && ++v_index[k] == lists[k].size()) v_index[k++] = 0;
      if (k == lists.size()) break;
    }
    std::size_t k = 0;
    while (k < discrete.size() && ++d_index[k] == discrete[k].options.size()) d_index[k++] = 0;
    if (k == discrete.size()) break;
  }
  std::stable_sort(out.begin(), out.end(), simpler);
  return out;
}

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
      // An "exact" entry: the printed value and the computed one must both be at round-off.
      const double larger = std::max(computed[k].value, std::abs(printed[k].value));
      s.residual = computed[k].round_off_bound > 0 ? larger / computed[k].round_off_bound : std::numeric_limits<double>::max();
      s.reproduced = larger <= computed[k].round_off_bound;
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
                                            const std::vector<continuous_parameter>& continuous, const parametrised_experiment& experiment,
                                            const simple_values& simple, std::size_t scan_points) {
  const auto start = std::chrono::steady_clock::now();
  convention_search_result result;
  convention_choice stated_choice;
  parameter_values stated_values;
  for (const discrete_convention& d : discrete) stated_choice[d.name] = d.stated;
  for (const continuous_parameter& p : continuous) {
    if (p.scale && !(p.log_scale && p.low > 0 && p.stated >= p.low && p.stated <= p.high)) {
      throw std::invalid_argument(fmt::format("search_conventions: scale parameter '{}' needs a log scale with 0 < low <= stated <= high", p.name));
    }
    stated_values[p.name] = p.stated;
  }
  result.stated = judged(printed, stated_choice, stated_values, experiment, result.evaluations);
  result.simple = simple_hypotheses(printed, discrete, continuous, simple, experiment, result.evaluations);

  std::vector<std::size_t> index(discrete.size(), 0);
  for (;;) {
    convention_choice choice;
    for (std::size_t k = 0; k < discrete.size(); ++k) choice[discrete[k].name] = discrete[k].options[index[k]];
    result.tried.push_back(global_fit(printed, choice, continuous, experiment, scan_points, result.evaluations));
    std::size_t k = 0;
    while (k < discrete.size() && ++index[k] == discrete[k].options.size()) index[k++] = 0;
    if (k == discrete.size()) break;
  }
  std::stable_sort(result.tried.begin(), result.tried.end(), better);
  // How far the table lets each fitted parameter of a reproducing candidate move, jointly with the
  // others (a slice through the optimum, the others fixed, would exclude values a joint move keeps).
  if (!result.tried.empty() && result.tried.front().reproduced == printed.size()) {
    convention_candidate& best = result.tried.front();
    for (std::size_t k = 0; k < continuous.size(); ++k) {
      const double at = best.values[continuous[k].name];
      // Each end never inside the value itself (the unit map's round trip is not exact).
      best.joint_extent[continuous[k].name] = {
          std::min(at, joint_end(printed, best.choice, continuous, experiment, best.values, k, -1, result.evaluations)),
          std::max(at, joint_end(printed, best.choice, continuous, experiment, best.values, k, 1, result.evaluations))};
    }
  }
  for (std::size_t k = 0; k < result.tried.size() && k < 12; ++k) name_fitted_values(result.tried[k], printed, experiment, result.evaluations);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::string describe(const convention_candidate& c) {
  std::vector<std::string> parts;
  for (const auto& [name, option] : c.choice) parts.push_back(fmt::format("{}: {}", name, option));
  for (const auto& [name, value] : c.values) {
    const auto named = c.value_names.find(name);
    parts.push_back(named != c.value_names.end() ? fmt::format("{} = {}", name, named->second) : fmt::format("{} = {:.4g}", name, value));
  }
  return fmt::format("{}", fmt::join(parts, "; "));
}

}  // namespace simpson::verify

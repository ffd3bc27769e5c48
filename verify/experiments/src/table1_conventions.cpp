#include <simpson/verify/table1_conventions.hpp>

namespace simpson::verify {

table1_run_errors table1_run(bool simpson_scheme, long long N, const convention_choice& c, const parameter_values& v) {
  // The conventions, decoded once (this runs some 10^5 times per search).
  const double omega = boost::math::constants::two_pi<double>(), m = v.at("m"), A = v.at("amplitude"), phase = v.at("phase");
  const std::string& steps = c.at("steps");
  const bool fewer = steps == "N - 1 steps of h = T/(N - 1)", more = steps == "N + 1 steps of h = T/N";
  const std::string& over = c.at("maximum over");
  const bool skip_start = over == "t_j, j = 1..N", end_only = over == "t_N only", internal_nodes = over == "t_j and the internal nodes";
  const bool per_mass_omega = c.at("momentum") == "p/(m omega)", relative = c.at("errors") == "relative to the amplitude";
  const bool relative_energy = c.at("energy") == "relative, |H_j - H_0|/H_0", energy_at_end = c.at("energy") == "|H_N - H_0|, at the end";

  const long long n = fewer ? N - 1 : more ? N + 1 : N;
  const double h = 1.0 / static_cast<double>(fewer ? N - 1 : N);
  const oscillator_parameters<double> par{m, omega, h};
  const phase_point<double> y0{m * omega * A * std::cos(phase), A * std::sin(phase)};
  const one_step_matrix<double> phi = simpson_scheme ? simpson_map(par) : newmark_map(par);
  table1_run_errors run;
  table_errors& e = run.errors;
  run.steps = n;
  const double H0 = energy(par, y0), Hd0 = discrete_energy(par, y0);
  // The momentum's unit: p, p/(m omega); relative errors divide by the exact amplitude of each.
  const double p_scale = (per_mass_omega ? m * omega : 1.0) * (relative ? (per_mass_omega ? A : m * omega * A) : 1.0);
  const double q_scale = relative ? A : 1.0;
  const double energy_scale = relative_energy ? H0 : 1.0;
  const auto record = [&](const phase_point<double>& y, double t, bool end) {
    const phase_point<double> exact = exact_solution(par, y0, t);
    e.p = std::max(e.p, std::abs(y.p - exact.p) / p_scale);
    e.q = std::max(e.q, std::abs(y.q - exact.q) / q_scale);
    if (energy_at_end && !end) return;
    e.energy = std::max(e.energy, std::abs(energy(par, y) - H0) / energy_scale);
    e.discrete_energy = std::max(e.discrete_energy, std::abs(discrete_energy(par, y) - Hd0) / energy_scale);
  };
  // The internal node of each interval: q_m of (qm-oscillateur-harmonique) for Simpson, the
  // midpoint of the affine interpolant for Newmark; p there m (q_r − q_l)/h, the slope of both.
  const double x = par.omega2_h2();
  phase_point<double> previous = y0;
  iterate(phi, y0, static_cast<std::size_t>(n), [&](std::size_t j, const phase_point<double>& y) {
    if (internal_nodes && j > 0) {
      const double qm = simpson_scheme ? (previous.q + y.q) / (2 * (1 - x / 8)) : (previous.q + y.q) / 2;
      record({m * (y.q - previous.q) / h, qm}, (static_cast<double>(j) - 0.5) * h, false);
    }
    previous = y;
    const bool last = static_cast<long long>(j) == n;
    if ((skip_start && j == 0) || (end_only && !last)) return;
    record(y, static_cast<double>(j) * h, last);
  });
  run.H0 = relative_energy ? 1 : H0;
  return run;
}

table_errors run_table_experiment(bool simpson_scheme, long long N, double m) {
  return table1_run(simpson_scheme, N, table1_stated_conventions(), {{"m", m}, {"amplitude", 1}, {"phase", 0}}).errors;
}

convention_choice table1_stated_conventions() {
  convention_choice c;
  for (const discrete_convention& d : table1_discrete_conventions()) c[d.name] = d.stated;
  return c;
}

std::vector<printed_entry> table1_printed(const std::array<std::array<double, 3>, 8>& values, const std::array<std::string, 8>& orders,
                                          const std::array<std::array<int, 3>, 8>* digits) {
  std::vector<printed_entry> entries;
  for (std::size_t r = 0; r < published_rows().size(); ++r) {
    const published_row& row = published_rows()[r];
    for (std::size_t k = 0; k < published_meshes.size(); ++k) {
      entries.push_back({std::string(row.scheme) + " " + row.quantity, "N = " + std::to_string(published_meshes[k]), values[r][k],
                         digits != nullptr ? (*digits)[r][k] : 3, orders[r] == "exact"});
    }
  }
  return entries;
}

std::vector<discrete_convention> table1_discrete_conventions() {
  return {{"steps", {"N steps of h = T/N", "N - 1 steps of h = T/(N - 1)", "N + 1 steps of h = T/N"}, "N steps of h = T/N"},
          {"maximum over", {"t_j, j = 0..N", "t_j, j = 1..N", "t_N only", "t_j and the internal nodes"}, "t_j, j = 0..N"},
          {"momentum", {"p", "p/(m omega)"}, "p"},
          {"errors", {"absolute", "relative to the amplitude"}, "absolute"},
          {"energy", {"|H_j - H_0|", "relative, |H_j - H_0|/H_0", "|H_N - H_0|, at the end"}, "|H_j - H_0|"}};
}

std::vector<continuous_parameter> table1_continuous_parameters() {
  // The errors are homogeneous in m and the amplitude (p and H scale with m, every error with the
  // amplitude): both are scale parameters, fitted in closed form; the phase is scanned.
  return {{"m", 1e-2, 1e2, 1, true, true}, {"amplitude", 1e-2, 1e2, 1, true, true},
          {"phase", 0, boost::math::constants::two_pi<double>(), 0, false, false}};
}

std::vector<computed_entry> table1_under(const convention_choice& choice, const parameter_values& values) {
  std::array<std::array<table1_run_errors, 3>, 2> runs{};
  for (int s = 0; s < 2; ++s) {
    for (std::size_t k = 0; k < published_meshes.size(); ++k) {
      runs[static_cast<std::size_t>(s)][k] = table1_run(s == 1, published_meshes[k], choice, values);
    }
  }
  std::vector<computed_entry> entries;
  for (const published_row& row : published_rows()) {
    for (std::size_t k = 0; k < published_meshes.size(); ++k) {
      const table1_run_errors& run = runs[row.simpson_scheme ? 1 : 0][k];
      // As at_round_off_floor: each step rounds H by a few eps relative.
      entries.push_back({run.errors.*row.field, 64 * std::numeric_limits<double>::epsilon() * static_cast<double>(run.steps) * run.H0});
    }
  }
  return entries;
}

convention_search_result search_table1(const std::vector<printed_entry>& printed) {
  // The ledger's table-values and the table1 section search the same table in one run: once.
  static std::vector<std::pair<std::vector<double>, convention_search_result>> searched;
  std::vector<double> key;
  for (const printed_entry& e : printed) key.push_back(e.round_off ? -e.value : e.value);
  for (const auto& [values, result] : searched) {
    if (values == key) return result;
  }
  searched.emplace_back(key, search_conventions(printed, table1_discrete_conventions(), table1_continuous_parameters(), table1_under));
  return searched.back().second;
}

}  // namespace simpson::verify

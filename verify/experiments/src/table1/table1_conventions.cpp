#include <simpson/verify/table1_conventions.hpp>

#include <fmt/format.h>

#include <deque>
#include <memory>

namespace simpson::verify {

namespace table1_detail {  // named: table1_basis_cache, declared in the header, holds these

/// The two quadratic forms of the table (H and H_d) on a pair of states: Q(x), Q(y) and the bilinear
/// Q(x, y), so that Q(c x + s y) = c² Q(x) + 2 c s Q(x, y) + s² Q(y).
struct form_pair {
  double xx = 0, xy = 0, yy = 0;
};

/// One point the maximum may run over (a node t_j, or the internal node of [t_(j-1), t_j]): the
/// scheme's state and the exact one from the two initial states u = (m omega, 0) and v = (0, 1)
/// (amplitude 1), and the forms H, H_d of the scheme's state there, minus their values at t_0.
struct basis_point {
  phase_point<double> yu, yv, eu, ev;
  form_pair H, Hd;
  long long j = 0;
  bool node = true;
};

/// Every run is linear in its initial state y_0 = A (cos(phase) u + sin(phase) v): the runs from u
/// and v, computed once per (scheme, N, steps, internal nodes), give any amplitude and phase by
/// combination; the energies by their quadratic forms. And m scales out (lemma-dimensional-scaling:
/// Phi(m) = S Phi(1) S^-1, S = diag(m, 1)): the runs are made with m = 1, and p, H and H_d are m times
/// theirs. The convention search evaluates the experiment some 10^5 times at phases, amplitudes and
/// masses that change while these stay.
struct basis_key {
  bool simpson_scheme = false;
  long long N = 0, n = 0;
  bool internal_nodes = false;
  double h = 0, omega = 0;
  bool operator==(const basis_key& o) const {
    return simpson_scheme == o.simpson_scheme && N == o.N && n == o.n && internal_nodes == o.internal_nodes && h == o.h && omega == o.omega;
  }
};

form_pair forms(double (*Q)(const oscillator_parameters<double>&, const phase_point<double>&), const oscillator_parameters<double>& par,
                const phase_point<double>& x, const phase_point<double>& y) {
  const double qx = Q(par, x), qy = Q(par, y), sum = Q(par, {x.p + y.p, x.q + y.q});
  return {qx, (sum - qx - qy) / 2, qy};
}

double energy_of(const oscillator_parameters<double>& par, const phase_point<double>& y) { return energy(par, y); }
double discrete_energy_of(const oscillator_parameters<double>& par, const phase_point<double>& y) { return discrete_energy(par, y); }

std::vector<basis_point> compute_basis_run(const basis_key& key);

}  // namespace table1_detail

using namespace table1_detail;

class table1_basis_cache {
 public:
  /// The basis runs of `key`, computed once.
  const std::vector<basis_point>& of(const basis_key& key) {
    for (const auto& [k, points] : entries_) {
      if (k == key) return points;
    }
    entries_.emplace_back(key, compute_basis_run(key));
    return entries_.back().second;
  }

 private:
  std::deque<std::pair<basis_key, std::vector<basis_point>>> entries_;  // stable references as it grows
};

namespace table1_detail {

std::vector<basis_point> compute_basis_run(const basis_key& key) {
  const double omega = key.omega, m = 1;
  const oscillator_parameters<double> par{m, omega, key.h};
  const phase_point<double> u{m * omega, 0}, v{0, 1};
  const one_step_matrix<double> phi = key.simpson_scheme ? simpson_map(par) : newmark_map(par);
  const double x = par.omega2_h2();
  std::vector<basis_point> points;
  phase_point<double> yu = u, yv = v, pu = u, pv = v;
  for (long long j = 0; j <= key.n; ++j) {
    if (key.internal_nodes && j > 0) {
      // The internal node of each interval: q_m of (qm-oscillateur-harmonique) for Simpson, the
      // midpoint of the affine interpolant for Newmark; p there m (q_r − q_l)/h, the slope of both.
      const auto internal = [&](const phase_point<double>& prev, const phase_point<double>& y) {
        const double qm = key.simpson_scheme ? (prev.q + y.q) / (2 * (1 - x / 8)) : (prev.q + y.q) / 2;
        return phase_point<double>{m * (y.q - prev.q) / key.h, qm};
      };
      const double t = (static_cast<double>(j) - 0.5) * key.h;
      points.push_back({internal(pu, yu), internal(pv, yv), exact_solution(par, u, t), exact_solution(par, v, t), {}, {}, j, false});
    }
    const double t = static_cast<double>(j) * key.h;
    points.push_back({yu, yv, exact_solution(par, u, t), exact_solution(par, v, t), {}, {}, j, true});
    pu = yu, pv = yv;
    yu = phi * yu, yv = phi * yv;
  }
  const form_pair H0 = forms(energy_of, par, u, v), Hd0 = forms(discrete_energy_of, par, u, v);
  for (basis_point& b : points) {
    const form_pair H = forms(energy_of, par, b.yu, b.yv), Hd = forms(discrete_energy_of, par, b.yu, b.yv);
    b.H = {H.xx - H0.xx, H.xy - H0.xy, H.yy - H0.yy};
    b.Hd = {Hd.xx - Hd0.xx, Hd.xy - Hd0.xy, Hd.yy - Hd0.yy};
  }
  return points;
}

}  // namespace

table1_run_errors table1_run(bool simpson_scheme, long long N, const convention_choice& c, const parameter_values& v, table1_basis_cache* cache) {
  // The conventions, decoded once (this runs some 10^5 times per search).
  // The period T the text states (1 unless given): ω = 2π/T, h = T/N.
  const double T = v.count("period") ? v.at("period") : 1.0;
  const double omega = boost::math::constants::two_pi<double>() / T, m = v.at("m"), A = v.at("amplitude"), phase = v.at("phase");
  const std::string& steps = c.at("steps");
  const bool fewer = steps == "N - 1 steps of h = T/(N - 1)", more = steps == "N + 1 steps of h = T/N";
  const std::string& over = c.at("maximum over");
  const bool skip_start = over == "t_j, j = 1..N", end_only = over == "t_N only", internal_nodes = over == "t_j and the internal nodes";
  const bool per_mass_omega = c.at("momentum") == "p/(m omega)", relative = c.at("errors") == "relative to the amplitude";
  const bool relative_energy = c.at("energy") == "relative, |H_j - H_0|/H_0", energy_at_end = c.at("energy") == "|H_N - H_0|, at the end";

  const long long n = fewer ? N - 1 : more ? N + 1 : N;
  const double h = T / static_cast<double>(fewer ? N - 1 : N);
  const oscillator_parameters<double> par{m, omega, h};
  const double cu = A * std::cos(phase), cv = A * std::sin(phase);
  const phase_point<double> y0{m * omega * cu, cv};  // H_0 of the run, for relative energies and the round-off bound
  table1_run_errors run;
  table_errors& e = run.errors;
  run.steps = n;
  const double H0 = energy(par, y0);
  // The momentum's unit: p, p/(m omega); relative errors divide by the exact amplitude of each.
  const double p_scale = (per_mass_omega ? m * omega : 1.0) * (relative ? (per_mass_omega ? A : m * omega * A) : 1.0);
  const double q_scale = relative ? A : 1.0;
  const double energy_scale = relative_energy ? H0 : 1.0;
  const auto combined = [&](const form_pair& f) { return cu * cu * f.xx + 2 * cu * cv * f.xy + cv * cv * f.yy; };
  // Without a cache of its caller's (a search's), the run's own: its basis runs computed here.
  table1_basis_cache own;
  table1_basis_cache& basis = cache != nullptr ? *cache : own;
  for (const basis_point& b : basis.of({simpson_scheme, N, n, internal_nodes, h, omega})) {
    const bool last = b.node && b.j == n;
    if (b.node && ((skip_start && b.j == 0) || (end_only && !last))) continue;
    const double p = m * (cu * b.yu.p + cv * b.yv.p), q = cu * b.yu.q + cv * b.yv.q;
    const double exact_p = m * (cu * b.eu.p + cv * b.ev.p), exact_q = cu * b.eu.q + cv * b.ev.q;
    e.p = std::max(e.p, std::abs(p - exact_p) / p_scale);
    e.q = std::max(e.q, std::abs(q - exact_q) / q_scale);
    if (energy_at_end && !last) continue;
    e.energy = std::max(e.energy, m * std::abs(combined(b.H)) / energy_scale);
    e.discrete_energy = std::max(e.discrete_energy, m * std::abs(combined(b.Hd)) / energy_scale);
  }
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

namespace {

/// A simple value exactly: (num/den) π^pi_power, and its name.
struct exact_simple {
  const char* name;
  long num, den;
  int pi_power;
  double value() const { return double(num) / double(den) * std::pow(boost::math::constants::pi<double>(), pi_power); }
};

// q(t) = A sin(omega t + phase): phase 0 starts at q_0 = 0 (the stated sin), pi/2 at rest at q_0 = A
// (a cos); the errors do not see the solution's sign, so pi and 3 pi/2 would repeat these. A = 1/(2 pi)
// is the unit initial velocity (omega = 2 pi).
const std::vector<exact_simple>& simple_masses() {
  static const std::vector<exact_simple> list{{"1", 1, 1, 0}, {"2", 2, 1, 0}, {"1/2", 1, 2, 0}};
  return list;
}
const std::vector<exact_simple>& simple_amplitudes() {
  static const std::vector<exact_simple> list{{"1", 1, 1, 0}, {"π/2", 1, 2, 1}, {"π/4", 1, 4, 1}, {"2", 2, 1, 0},  {"1/2", 1, 2, 0},
                                              {"π", 1, 1, 1}, {"3π/2", 3, 2, 1}, {"2π", 2, 1, 1}, {"1/(2π)", 1, 2, -1}};
  return list;
}

}  // namespace

simple_values table1_simple_values() {
  std::vector<simple_value> m, amplitude;
  for (const exact_simple& v : simple_masses()) m.push_back({v.name, v.value()});
  for (const exact_simple& v : simple_amplitudes()) amplitude.push_back({v.name, v.value()});
  return {{"m", m}, {"amplitude", amplitude}, {"phase", {{"0", 0}, {"π/2", boost::math::constants::half_pi<double>()}}}};
}

std::optional<exact_start> table1_exact_start(const convention_candidate& c) {
  if (c.choice != table1_stated_conventions() || c.value_names.empty()) return std::nullopt;
  const auto find = [&](const std::vector<exact_simple>& list, const std::string& parameter) -> const exact_simple* {
    const auto named = c.value_names.find(parameter);
    if (named == c.value_names.end()) return nullptr;
    for (const exact_simple& v : list) {
      if (named->second == v.name) return &v;
    }
    return nullptr;
  };
  const exact_simple* m = find(simple_masses(), "m");
  const exact_simple* A = find(simple_amplitudes(), "amplitude");
  const auto phase = c.value_names.find("phase");
  if (m == nullptr || A == nullptr || phase == c.value_names.end() || (phase->second != "0" && phase->second != "π/2")) return std::nullopt;
  return exact_start{m->num, m->den, A->num, A->den, A->pi_power, phase->second == "π/2"};
}

std::optional<exact_start> table1_reproducing_start(const convention_search_result& r) {
  // The enclosures run one period of ω = 2π: a table stated with another period is not enclosed.
  const auto period = r.fixed.find("period");
  if (period != r.fixed.end() && period->second != 1) return std::nullopt;
  return r.simplest() != nullptr ? table1_exact_start(*r.simplest()) : std::nullopt;
}

std::vector<std::string> table1_departures(const convention_candidate& c) {
  std::vector<std::string> departures;
  for (const discrete_convention& d : table1_discrete_conventions()) {
    if (c.choice.at(d.name) != d.stated) departures.push_back(d.name + ": " + c.choice.at(d.name));
  }
  return departures;
}

std::string table1_start(const convention_candidate& c) {
  const auto name = [&](const std::string& p) {
    const auto it = c.value_names.find(p);
    return it != c.value_names.end() ? it->second : fmt::format("{:.6g}", c.values.at(p));
  };
  const std::string A = name("amplitude"), m = name("m");
  // The two simple phases are exactly 0 and half_pi<double>() (table1_simple_values): compared exactly.
  const double phase = c.values.at("phase");
  if (phase == boost::math::constants::half_pi<double>()) return fmt::format("released from rest at q₀ = {}, p₀ = 0, m = {} (q(t) = {} cos ωt)", A, m, A);
  if (phase == 0) {
    const std::string velocity = A == "1/(2π)" ? "1" : A == "1" ? "2π" : "2π·" + A;
    return fmt::format("started at q₀ = 0 with dq/dt(0) = {}, m = {} (q(t) = {} sin ωt)", velocity, m, A == "1" ? "" : A);
  }
  return fmt::format("q(t) = {} sin(ωt + {}), m = {}", A, name("phase"), m);
}

entry_tally tally_entries(const convention_candidate& c, const std::vector<printed_entry>& printed) {
  entry_tally t;
  for (std::size_t k = 0; k < printed.size() && k < c.entries.size(); ++k) {
    (printed[k].round_off ? t.round_off : t.informative) += 1;
    (printed[k].round_off ? t.round_off_reproduced : t.informative_reproduced) += c.entries[k].reproduced;
  }
  return t;
}

std::string tally_text(const entry_tally& t) {
  std::string text = fmt::format("{} of the {} informative entries", t.informative_reproduced, t.informative);
  if (t.round_off == 0) return text;
  return text + (t.round_off_reproduced == t.round_off
                     ? fmt::format(" (the {} others, of the rows printed as exact, are at round-off level, as ours are)", t.round_off)
                     : fmt::format(" ({} of the {} others, of the rows printed as exact, round-off)", t.round_off_reproduced, t.round_off));
}

std::string table1_explanation(const convention_search_result& r, const std::vector<printed_entry>& printed) {
  const convention_candidate* s = r.simplest();
  if (s == nullptr) return "";
  const std::vector<std::string> departures = table1_departures(*s);
  std::string text = fmt::format("the oscillator {}, {}, reproduces within their printed digits {}", table1_start(*s),
                                 departures.empty() ? "under the stated discrete conventions"
                                                    : fmt::format("with {} (the other discrete conventions as stated)", fmt::join(departures, ", ")),
                                 tally_text(tally_entries(*s, printed)));
  std::vector<std::string> misses;
  for (std::size_t k = 0; k < printed.size(); ++k) {
    if (s->entries[k].reproduced) continue;
    const printed_entry& e = printed[k];
    if (e.round_off) {
      misses.push_back(fmt::format("{} at {}, printed at round-off, computes {:.4g}", e.row, e.column.substr(e.column.find("N =")), s->entries[k].computed));
      continue;
    }
    const entry_miss miss = miss_of(e, s->entries[k].computed);
    misses.push_back(fmt::format("{} at {}, computes {:.7g}, printed {:.{}g}: {:.1e} past its rounding boundary {:.{}g}", e.row, e.column,
                                 s->entries[k].computed, e.value, e.digits, miss.past, miss.boundary, e.digits + 1));
  }
  if (misses.size() == 1) text += "; the one it misses, " + misses.front();
  else if (!misses.empty() && misses.size() <= 4) text += fmt::format("; the {} it misses: {}", misses.size(), fmt::join(misses, "; "));
  else if (!misses.empty()) text += fmt::format("; it misses {} (the evidence lists each)", misses.size());
  return text;
}

std::vector<computed_entry> table1_under(const convention_choice& choice, const parameter_values& values, table1_basis_cache* cache) {
  std::array<std::array<table1_run_errors, 3>, 2> runs{};
  for (int s = 0; s < 2; ++s) {
    for (std::size_t k = 0; k < published_meshes.size(); ++k) {
      runs[static_cast<std::size_t>(s)][k] = table1_run(s == 1, published_meshes[k], choice, values, cache);
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

convention_search_result search_table1(const std::vector<printed_entry>& printed, const table1_stated& stated, run_memo* memo) {
  // The ledger's claims and the table1 section search the same table in one run: once per run. The
  // key is everything the search depends on: each entry's place, value (exactly, in hexadecimal
  // floating point), printed digits and kind, and the stated solution.
  std::string key = fmt::format("table1 search {:a} {:a} {:a}", stated.amplitude, stated.phase, stated.period);
  for (const printed_entry& e : printed) key += fmt::format(" {}/{}:{:a}:{}{}", e.row, e.column, e.value, e.digits, e.round_off ? "r" : "");
  return remembered<convention_search_result>(memo, key, [&] {
    // The stated solution is the text's: its amplitude and phase where the search starts (and what it
    // calls stated), its period fixed in every run.
    std::vector<continuous_parameter> continuous = table1_continuous_parameters();
    for (continuous_parameter& p : continuous) {
      if (p.name == "amplitude") p.stated = stated.amplitude;
      if (p.name == "phase") p.stated = stated.phase;
    }
    const double period = stated.period;
    // The search's basis runs, kept for its duration: its own value, gone with it.
    auto cache = std::make_shared<table1_basis_cache>();
    const parametrised_experiment experiment = [period, cache](const convention_choice& choice, const parameter_values& values) {
      if (period == 1) return table1_under(choice, values, cache.get());
      parameter_values with_period = values;
      with_period["period"] = period;
      return table1_under(choice, with_period, cache.get());
    };
    convention_search_result result = search_conventions(printed, table1_discrete_conventions(), continuous, experiment, table1_simple_values());
    result.fixed["period"] = period;
    return result;
  });
}

}  // namespace simpson::verify

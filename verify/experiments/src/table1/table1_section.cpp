// The table1 section: the paper's experiment (Section 8) for any list of N, beside Table 1's
// published values, with estimated orders and Figure 1 redrawn. Computed in double, as the paper.

#include <simpson/verify/table1_section.hpp>

#include <simpson/verify/floating_tools.hpp>
#include <simpson/verify/paper_table.hpp>
#include <simpson/verify/table1_conventions.hpp>
#include <simpson/verify/table1_enclosed.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>

namespace simpson::verify {
namespace {

/// The printed value of row r at N, when the run read Table 1 and it has that column.
std::optional<double> published_at(const table1_settings& s, std::size_t r, long long N) {
  if (!s.printed_values) return std::nullopt;
  for (std::size_t k = 0; k < published_meshes.size(); ++k) {
    if (published_meshes[k] == N) return (*s.printed_values)[r][k];
  }
  return std::nullopt;
}

using runs_by_mesh = std::map<long long, std::array<table_errors, 2>>;  // [newmark, simpson]

double ours(const runs_by_mesh& runs, const published_row& row, long long N) {
  return runs.at(N)[row.simpson_scheme ? 1 : 0].*row.field;
}

/// Figure 1: exact and computed p/(mω) and q over one period with N steps.
plot_description figure1_plot(double m, long long N) {
  const double omega = boost::math::constants::two_pi<double>();
  const oscillator_parameters<double> par{m, omega, step_size(1.0, N)};
  const phase_point<double> y0{m * omega, 0.0};
  series q_exact{"q exact", line_style::lines, 9}, p_exact{"p/(mω) exact", line_style::dashed, 9};
  for (int k = 0; k <= 400; ++k) {
    const double t = k / 400.0;
    const phase_point<double> y = exact_solution(par, y0, t);
    q_exact.add(figure::of(t), figure::of(y.q));
    p_exact.add(figure::of(t), figure::of(y.p / (m * omega)));
  }
  panel pan{fmt::format("Figure 1: harmonic oscillator, one period, N = {}", N),
            {"t (periods)"}, {"q and p/(mω) (dimensionless)"}, {q_exact, p_exact}, "outside right"};
  const std::array<std::pair<const char*, one_step_matrix<double>>, 2> schemes{
      {{"Newmark", newmark_map(par)}, {"Simpson", simpson_map(par)}}};
  for (std::size_t s = 0; s < schemes.size(); ++s) {
    const auto path = trajectory(schemes[s].second, y0, static_cast<std::size_t>(N));
    series q{fmt::format("q {}", schemes[s].first), line_style::lines_points, static_cast<int>(s), s ? 7 : 6};
    series p{fmt::format("p/(mω) {}", schemes[s].first), line_style::lines_points, static_cast<int>(s), s ? 5 : 4};
    for (std::size_t j = 0; j < path.size(); ++j) {
      const double t = static_cast<double>(j) * par.h();
      q.add(figure::of(t), figure::of(path[j].q));
      p.add(figure::of(t), figure::of(path[j].p / (m * omega)));
    }
    pan.curves.push_back(q);
    pan.curves.push_back(p);
  }
  return {"figure1", fmt::format("Figure 1 redrawn: exact and computed p and q over one period, N = {}", N), {pan}, 1, 900, 500};
}

/// The convention search on Table 1 (table1_conventions.hpp): the conventions tried, best first,
/// and a plot of printed against reproduced values under the stated conventions and the best found.
void add_convention_search(section_result& out, const printed_table_values& values, const printed_table_orders& orders,
                           const std::optional<std::array<std::array<int, 3>, 8>>& digits, const table1_stated& stated_solution, run_memo* memo) {
  const std::vector<printed_entry> printed = table1_printed(values, orders, digits ? &*digits : nullptr);
  const convention_search_result search = search_table1(printed, stated_solution, memo);
  const convention_candidate* found = search.reproducing();
  out.text(fmt::format(
      "### Convention search\n\nEvery convention Section 8 states or leaves implicit is a parameter: the steps (N of h = T/N, N − 1 of "
      "h = T/(N − 1), N + 1 of h = T/N), the points the maximum runs over (t_0..t_N, t_1..t_N, t_N, or also the internal nodes), the "
      "momentum (p or p/(mω)), absolute or relative errors, the energy error (the maximum, relative to H_0, or at the end); m, the amplitude and the phase of the exact "
      "solution are fitted for each of the {} combinations ({} runs of the experiment). An entry is reproduced when the "
      "computed value lies within half a unit of its last printed digit; the round-off rows when the computed value is below "
      "64 eps N H_0. {}",
      search.tried.size(), search.evaluations,
      found ? "**Reproduced by a fit** under: " + describe(*found) + ". Figure 1's statements (figure1-statements) are checked under the "
                  "stated conventions; under this one they may read otherwise."
            : fmt::format("**No convention of this family reproduces Table 1**: the best reproduces {} of {} entries (the {} "
                          "round-off entries among them); under the stated conventions, {}. With no convention found, Figure 1's "
                          "statements stand as checked under the stated ones (figure1-statements).",
                          search.tried.front().reproduced, printed.size(),
                          std::count_if(printed.begin(), printed.end(), [](const printed_entry& e) { return e.round_off; }),
                          search.stated.reproduced)));
  if (search.simplest() != nullptr) {
    out.text(fmt::format("**Before any fit**, every combination of the discrete conventions with simple values of m (1, 2, 1/2), the "
                         "amplitude (1, π/2, π/4, 2, 1/2, π, 3π/2, 2π, and 1/(2π), the unit initial velocity) and the start (q₀ = 0 as "
                         "stated, or released from rest at q₀ = A) was judged by a full run ({} hypotheses). The simplest that explains "
                         "the most entries: {}.",
                         search.simple.size(), table1_explanation(search, printed)));
    table simple{"simple_hypotheses", "", "", {{"rank", "rank"}, {"start", "exact solution"}, {"conventions", "discrete conventions"},
                                               {"reproduced", "entries reproduced"}, {"worst", "worst residual", "half-units of the last digit"}}};
    for (std::size_t k = 0; k < search.simple.size() && k < 5; ++k) {
      const convention_candidate& c = search.simple[k];
      const std::vector<std::string> departures = table1_departures(c);
      simple.add({figure::integer(static_cast<long long>(k + 1)), figure::text(table1_start(c)),
                  figure::text(departures.empty() ? "as stated" : fmt::format("{}", fmt::join(departures, "; "))),
                  figure::integer(static_cast<long long>(c.reproduced)), figure::text(fmt::format("{:.7g}", c.worst))});
    }
    out.add(std::move(simple));
  }
  out.text("Then the fit: m, the amplitude and the phase free for each combination of the discrete conventions, best first (the "
           "values printed with the digits that reproduce what the row says).");
  table tried{"convention_search", "", "", {{"rank", "rank"}, {"conventions", "conventions and fitted values"},
                                            {"reproduced", "entries reproduced"}, {"worst", "worst residual", "half-units of the last digit"}}};
  for (std::size_t k = 0; k < search.tried.size() && k < 10; ++k) {
    tried.add({figure::integer(static_cast<long long>(k + 1)), figure::text(describe(search.tried[k])),
               figure::integer(static_cast<long long>(search.tried[k].reproduced)), figure::of(search.tried[k].worst)});
  }
  out.add(std::move(tried));
  panel scatter{"Table 1: computed over printed, entry by entry", {"printed value", true}, {"computed / printed"}, {}, "bottom right"};
  scatter.y.range = std::make_pair(0.0, 1.3);  // the key below the points
  series unit{"reproduced: 1 (± half a unit of the last digit)", line_style::dashed, 8};
  unit.reference = true;
  series stated{"stated conventions", line_style::points, 0, 6}, best{"best fit", line_style::points, 1, 7};
  const convention_candidate* simplest = search.simplest();
  series simple{simplest != nullptr ? "simplest: " + table1_start(*simplest).substr(0, table1_start(*simplest).find(" (")) : "simplest",
                line_style::points, 2, 5};
  double low = 1e300, high = 0;
  for (std::size_t k = 0; k < printed.size(); ++k) {
    if (printed[k].round_off) continue;
    low = std::min(low, printed[k].value);
    high = std::max(high, printed[k].value);
    stated.add(figure::of(printed[k].value), figure::of(search.stated.entries[k].computed / printed[k].value));
    best.add(figure::of(printed[k].value), figure::of(search.tried.front().entries[k].computed / printed[k].value));
    if (simplest != nullptr) simple.add(figure::of(printed[k].value), figure::of(simplest->entries[k].computed / printed[k].value));
  }
  unit.add(figure::of(low), figure::of(1.0));
  unit.add(figure::of(high), figure::of(1.0));
  // The best fit drawn over the simplest: both sit on 1 where they reproduce.
  scatter.curves = {unit, stated};
  if (simplest != nullptr) scatter.curves.push_back(simple);
  scatter.curves.push_back(best);
  out.add(plot_description{"table1_search",
                           "Table 1's entries (round-off rows left out): computed over printed under the stated conventions "
                           ", under the simplest hypothesis and under the best fit; an entry is reproduced only within half a unit of its third "
                           "digit (about ±0.05 to ±0.5%)",
                           {scatter}, 1, 900, 600});
}

/// The exact schemes' errors at the paper's meshes, enclosed (table1_enclosed.hpp): guaranteed digits
/// beside the double run, and the orders they prove.
std::array<enclosed_table_row, 8> add_enclosed_table(section_result& out, run_memo* memo) {
  const std::array<enclosed_table_row, 8> enclosed = enclosed_table1_of_run(memo);
  out.text("The same errors for the exact schemes (no rounding), enclosed in interval arithmetic (MPFI, 40 digits, π "
           "enclosed): every digit shown is guaranteed, the radius covers the rest. They are what the double run "
           "approximates; the orders are proved from them (both log₂ ratios within ½ of the integer; 'exact' when every "
           "enclosure holds 0).");
  table t{"exact_scheme_enclosed", "", "", {{"scheme", "scheme"}, {"quantity", "quantity"}, {"N_10", "N = 10"}, {"N_20", "N = 20"},
                                            {"N_40", "N = 40"}, {"order", "order (proved)"}}};
  for (std::size_t r = 0; r < enclosed.size(); ++r) {
    const published_row& row = published_rows()[r];
    t.add({figure::text(row.scheme), figure::text(row.quantity), figure::text(enclosed[r].short_values[0]),
           figure::text(enclosed[r].short_values[1]), figure::text(enclosed[r].short_values[2]), figure::text(enclosed[r].order)});
  }
  out.add(std::move(t));
  return enclosed;
}

/// "Symplectic Simpson", "energy (HH-exact)" as "symplectic-simpson-energy-hh-exact".
std::string slug(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (std::isalnum(static_cast<unsigned char>(c))) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    else if (!out.empty() && out.back() != '-') out += '-';
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out;
}

/// Each row's order in double against the order its exact scheme's enclosures prove: the prediction
/// rests on the exact scheme alone, so a changed step, error or fit in the double run fails it.
void add_order_expectations(section_result& out, const std::array<enclosed_table_row, 8>& enclosed,
                            const std::vector<std::optional<double>>& least_squares, const std::vector<long long>& meshes) {
  for (std::size_t r = 0; r < enclosed.size() && r < least_squares.size(); ++r) {
    const std::optional<bool> agrees = order_agrees(enclosed[r].order, least_squares[r]);
    if (!agrees) continue;  // the enclosures decided no order: nothing is predicted
    const published_row& row = published_rows()[r];
    out.expect({"order-" + slug(std::string(row.scheme) + " " + row.quantity),
                fmt::format("The order of {}'s {} error in double is the order of the exact scheme.", row.scheme, row.quantity),
                enclosed[r].order == "exact" ? std::string("exact: every error of the exact scheme's run encloses 0 (MPFI)")
                                             : fmt::format("order {}, proved by MPFI enclosures of the exact scheme's errors at N = 10, 20, 40 "
                                                           "(both log₂ ratios within ½ of it)",
                                                           enclosed[r].order),
                least_squares[r] ? fmt::format("least-squares order {:.3f} over N = {}", *least_squares[r], fmt::join(meshes, ", "))
                                 : std::string("every error at the round-off floor: exact"),
                *agrees});
  }
}

}  // namespace

std::optional<bool> order_agrees(const std::string& proved, std::optional<double> least_squares) {
  if (proved == "exact") return !least_squares.has_value();
  if (proved.empty() || proved.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
  return least_squares && std::abs(*least_squares - std::stod(proved)) < 0.5;
}

section_result run_table1(const table1_settings& s) {
  const std::array<published_row, 8>& rows = published_rows();
  const double omega = boost::math::constants::two_pi<double>(), H0 = s.m * omega * omega / 2;  // (mω)²/(2m) for y_0 = (mω, 0)
  runs_by_mesh runs;
  for (const long long N : s.meshes) {
    runs[N] = {run_table_experiment(false, N, s.m), run_table_experiment(true, N, s.m)};
  }
  section_result out;
  out.name = "table1";
  out.title = "Table 1: the paper's experiment";
  out.conventions = {{"m", s.m}, {"omega", "2 pi"}, {"T", 1}, {"start", "y_0 = (m omega, 0) exact"},
                     {"errors", "maximum over t_j = j h, j = 0..N"}, {"precision", "double"},
                     {"round_off_floor", "error <= 64 eps N H_0 is masked in orders"}, {"figure_N", s.figure_meshes}};
  out.text(fmt::format(
      "Conventions: m = {}, ω = 2π, T = 1 (one period), h = T/N; y₀ = (mω, 0) exactly, so q(t) = sin ωt and "
      "p(t) = mω cos ωt; then y_(j+1) = Φ y_j with Φ₃ (Simpson) or (matrice-symplectique-ordre-2) (Newmark), in double. "
      "Errors are maxima over t_j = jh, j = 0..N, of |p_j − p(t_j)|, |q_j − q(t_j)|, |H(y_j) − H(y₀)| and "
      "|H_d(y_j) − H_d(y₀)|. Orders: least-squares slope of log error against log h, and the pairwise "
      "log₂(e_k/e_(k+1))/log₂(N_(k+1)/N_k); points at the round-off floor (error ≤ 64 eps N H₀) are masked, and a row "
      "whose every point is masked is 'exact'. Published values are Table 1's; the ratio is published/ours.",
      simpson::to_string(s.m, 3)));

  table entries{"entries", "", "", {{"scheme", "scheme"}, {"quantity", "quantity"}, {"N", "N"}, {"h", "h", "", 6},
                                    {"ours", "ours"}, {"published", "published"}, {"published_over_ours", "published/ours"},
                                    {"at_round_off_floor", "at round-off floor"}}};
  entries.csv_file = "table1.csv";
  entries.markdown = false;
  std::vector<column> wide{{"scheme", "scheme"}, {"quantity", "quantity"}};
  for (const long long N : s.meshes) {
    wide.push_back({fmt::format("ours_{}", N), fmt::format("N = {}", N)});
    wide.push_back({fmt::format("paper_{}", N), "paper"});
    wide.push_back({fmt::format("ratio_{}", N), "ratio"});
  }
  std::vector<column> order_columns{{"scheme", "scheme"}, {"quantity", "quantity"}, {"order_least_squares", "order (least squares)"}};
  for (std::size_t k = 0; k + 1 < s.meshes.size(); ++k) {
    order_columns.push_back({fmt::format("order_{}_{}", s.meshes[k], s.meshes[k + 1]),
                             fmt::format("order {}→{}", s.meshes[k], s.meshes[k + 1])});
  }
  order_columns.push_back({"order_published", "published order"});
  table overview{"overview", "", "Ours, the paper's value and the ratio paper/ours at each N ('round-off' where ours is at the floor):",
                 wide};
  overview.json = false;
  table orders{"orders", "", "", order_columns};

  std::vector<std::string> not_reproduced;
  std::vector<std::optional<double>> least_squares;  // each row's order in double; none when exact
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const published_row& row = rows[r];
    std::vector<double> h, e;
    std::vector<bool> use;
    table_row wide_row{figure::text(row.scheme), figure::text(row.quantity)};
    for (const long long N : s.meshes) {
      const double error = ours(runs, row, N);
      h.push_back(1.0 / static_cast<double>(N));
      e.push_back(error);
      use.push_back(!at_round_off_floor(error, N, H0));
      const auto published = published_at(s, r, N);
      const figure ratio = published ? figure::of(*published / error) : figure{};
      entries.add({figure::text(row.scheme), figure::text(row.quantity), figure::integer(N), figure::of(h.back()),
                   figure::of(error), published ? figure::of(*published) : figure{}, ratio, figure::flag(!use.back())});
      wide_row.push_back(figure::of(error));
      wide_row.push_back(published ? figure::of(*published) : figure{});
      wide_row.push_back(published && !use.back() ? figure::text("round-off") : ratio);
      if (published && use.back()) {
        const double r = *published / error;
        if (r < 0.95 || r > 1.05) {
          not_reproduced.push_back(fmt::format("{} {} at N = {}: paper {}, ours {} (ratio {})", row.scheme, row.quantity, N,
                                               display(figure::of(*published), 3), display(figure::of(error), 3),
                                               display(ratio, 3)));
        }
      }
    }
    overview.add(std::move(wide_row));
    const bool all_masked = std::none_of(use.begin(), use.end(), [](bool u) { return u; });
    least_squares.push_back(all_masked ? std::nullopt : std::optional<double>(log_log_slope(h, e, use)));
    table_row order_row{figure::text(row.scheme), figure::text(row.quantity),
                        all_masked ? figure::text("exact") : figure::of(log_log_slope(h, e, use))};
    for (std::size_t k = 0; k + 1 < e.size(); ++k) {
      order_row.push_back(!use[k] || !use[k + 1] ? figure::text("masked")
                                                 : figure::of(std::log2(e[k] / e[k + 1]) / std::log2(h[k] / h[k + 1])));
    }
    order_row.push_back(figure::text(s.printed_orders ? (*s.printed_orders)[r] : std::string("not read")));
    orders.add(std::move(order_row));
  }
  out.add(std::move(entries)).add(std::move(overview)).add(std::move(orders));
  if (!s.printed_values || !s.printed_orders) {
    out.text("Table 1 could not be read from the paper: ours are shown beside no printed value.");
  } else if (not_reproduced.empty()) {
    out.text("Every published entry with a counterpart here is reproduced within 5%.");
  } else {
    out.text(fmt::format("**Not reproduced** (outside ±5%): {}.\n\n{} Also tried: {}. See the ledger claims table-values, "
                         "table-orders and table-conservation.",
                         fmt::join(not_reproduced, "; "), table_not_reproduced(*s.printed_values, *s.printed_orders, s.m),
                         table_also_tried(*s.printed_values, s.m)));
  }
  table not_reproduced_list{"not_reproduced", "", "", {{"entry", "entry"}}};
  not_reproduced_list.markdown = false;
  for (const std::string& n : not_reproduced) not_reproduced_list.add({figure::text(n)});
  out.add(std::move(not_reproduced_list));

  if (s.m == 1) add_order_expectations(out, add_enclosed_table(out, s.memo), least_squares, s.meshes);
  out.add(figure1_plot(s.m, s.figure_meshes));
  if (s.printed_values && s.printed_orders) {
    add_convention_search(out, *s.printed_values, *s.printed_orders, s.printed_digits, s.stated, s.memo);
  } else {
    out.text("### Convention search\n\nTable 1 could not be read from the paper: no printed value to search conventions for "
             "(the claim table-values says where the reading failed).");
  }

  // Errors of p and q against N: ours (lines), published (open points), and slopes h² and h⁴ a factor
  // 4 below the first Newmark and Simpson state errors (beside the curves, not on them).
  panel convergence{"Table 1: maximum errors against N (one period)", {"N (steps per period)", true},
                    {"maximum error: |Δp| (absolute, m = 1) and |Δq|", true}, {}, "outside right"};
  for (std::size_t r = 0; r < 4; ++r) {
    const published_row& row = rows[r];
    const std::string name = fmt::format("{} {}", row.simpson_scheme ? "Simpson" : "Newmark", r < 2 ? "p" : "q");
    series mine{name + " ours", line_style::lines_points, static_cast<int>(r), 7};
    series paper{name + " paper", line_style::points, static_cast<int>(r), 6};
    for (const long long N : s.meshes) {
      mine.add(figure::integer(N), figure::of(ours(runs, row, N)));
      if (const auto published = published_at(s, r, N)) paper.add(figure::integer(N), figure::of(*published));
    }
    convergence.curves.push_back(mine);
    convergence.curves.push_back(paper);
  }
  if (!s.meshes.empty()) {
    const long long N0 = s.meshes.front();
    for (const int order : {2, 4}) {
      const double e0 = ours(runs, rows[order == 2 ? 2 : 3], N0);  // the state rows, the lower curves
      const series slope = slope_guide(fmt::format("slope h^{}", order), order == 2 ? 8 : 9, static_cast<double>(N0), e0 / 4,
                                       s.meshes, order);
      convergence.curves.push_back(slope);
    }
  }
  out.add(plot_description{"table1_convergence",
                           "Table 1: maximum errors of p and q against N, ours (lines) and published (open points), "
                           "with slopes h² and h⁴ (dashed guides)",
                           {convergence}, 1, 900, 500});
  return out;
}

}  // namespace simpson::verify

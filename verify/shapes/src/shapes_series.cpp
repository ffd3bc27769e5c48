// The series shapes on the oscillator (shape_support.hpp): a printed truncation error, and the order a
// sentence states of a scheme or a map, each a series GiNaC expands and our kernel confirms on the
// exact solution's Taylor polynomials. The shapes on smooth states are in shapes_consistency.cpp.

#include <simpson/shapes/shape_support.hpp>

#include <simpson/prove/coq_export.hpp>
#include <simpson/prove/printed_check_support.hpp>

#include <simpson/verify/quoted_words.hpp>
#include <simpson/verify/tex_math.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <optional>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

/// The scheme a series shape expands: as printed, or divided by the record's `scale` (the text's
/// "the scheme divided by m"), a factor free of the states.
ex scaled_scheme(shape_reader& read) {
  const ex scheme = read.formula("scheme");
  if (!read.has("scale")) return scheme;
  const ex scale = read.formula("scale");
  if (GiNaC::normal(scale).is_zero()) throw argument_error("scale", "the scale is 0");
  for (const GiNaC::symbol& state : read.symbols("sequence")) {
    if (scale.has(state)) throw argument_error("scale", "the scale depends on the state " + state.get_name());
  }
  return scheme / scale;
}

/// The function and the index of a state named "<base>_<index>" ("q_j": q and j); empty when the
/// state is not so named.
struct node_names {
  std::string base, index;
};

node_names node_names_of(const GiNaC::symbol& state) {
  const std::string name = state.get_name();
  const std::size_t bar = name.find('_');
  if (bar == std::string::npos || bar == 0 || bar + 1 == name.size()) return {};
  return {name.substr(0, bar), name.substr(bar + 1)};
}

/// The scheme (= 0, in three consecutive states) on the Taylor polynomials of degree `degree` of the
/// exact solution of q'' = −ω² q through the middle state, q(t_j ± h) = q_j cos ωh ± (v_j/ω) sin ωh.
ex on_taylor_solution(const ex& scheme, const std::vector<GiNaC::symbol>& sequence, const GiNaC::symbol& h, const ex& omega, int degree) {
  const GiNaC::symbol velocity("v_j");
  ex c = 0, sn = 0, term = 1;
  for (int k = 0; k <= degree; ++k) {
    if (k > 0) term = term * omega * h / k;
    if (k % 2 == 0) c += (k % 4 == 0 ? 1 : -1) * term;
    else sn += (k % 4 == 1 ? 1 : -1) * term;
  }
  const ex shift = velocity / omega * sn;
  return scheme.subs(GiNaC::lst{sequence[0] == sequence[1] * c - shift, sequence[2] == sequence[1] * c + shift});
}

/// GiNaC's series in h to O(h^order) of the scheme on the solution (on_taylor_solution, exact to that order).
ex series_of(const ex& on_taylor, const GiNaC::symbol& h, int order) {
  return GiNaC::expand(GiNaC::series_to_poly(GiNaC::series(on_taylor, h == 0, order)));
}

/// Our kernel's line of evidence: `verdict` ("holds" or "fails", the claim's as our kernel decided it)
/// and what it proved, or where it contradicts GiNaC's witness, or why it could not decide.
std::string own_text(const kernel_decision& own, const std::string& verdict, const std::string& what) {
  switch (own.outcome) {
    case kernel_decision::result::zero: return verdict + ": " + what + " (" + own.evidence + ")";
    case kernel_decision::result::nonzero: return "contradicts GiNaC: " + own.evidence;
    default: return "not applicable: " + own.evidence;
  }
}

/// The evidence on the order a sentence states, `order` being GiNaC's and `own` our kernel's decision
/// of its witness: ours confirms GiNaC's answer, or contradicts it (`on` says of what); when the two
/// orders differ, `correction` is the erratum's and the note says `as_printed`.
decider_evidence order_evidence(claim_result result, const kernel_decision& own, int stated, int order, const std::string& on, const std::string& correction,
                                const std::string& as_printed) {
  decider_evidence e;
  e.statement = on;
  e.ginac = answer_of(order == stated);
  e.own = confirming(e.ginac, own);
  if (own.outcome == kernel_decision::result::not_applicable) result.note = "Our kernel could not decide it (" + own.evidence + "): GiNaC's series alone. ";
  if (order != stated) {
    result.correction = correction;
    result.note += as_printed;
  }
  e.found = std::move(result);
  return e;
}

}  // namespace

/// A printed truncation error: the scheme (an expression in three consecutive states, = 0) on the
/// exact solution of q'' = −ω² q through the middle state, q(t_j ± h) = q_j cos ωh ± (v_j/ω) sin ωh,
/// as a series in h, against the printed terms and order O(h^N). GiNaC expands the series; our kernel
/// decides, on the Taylor polynomials of the solution (exact through h^(N−1), taylor_degree), that
/// the scheme there is the terms plus h^N times a function regular at h = 0, GiNaC's quotient being
/// only the witness: the printed terms when they hold, GiNaC's series (and that it differs from the
/// printed terms) when they do not. That identity is the Coq certificate.
decider_evidence truncation_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex printed = read.formula("printed");
  const ex scheme = scaled_scheme(read);
  const ex omega = read.formula("frequency");
  const std::vector<GiNaC::symbol> sequence = read.symbols("sequence"), step = read.symbols("step");
  const GiNaC::symbol& h = step.front();
  claim_result result;
  result.printed = read.printed();
  // The printed terms and its order term O(h^N); the exact solution at the nodes, where the text
  // writes it so (q(t_j), q(t_j + h): the states the scheme is put on), read as those states.
  const node_names nodes = node_names_of(sequence[1]);
  const ex printed_states = nodes.base.empty() ? printed : solution_at_nodes(printed, *call.declared, nodes.base, nodes.index, h, "printed");
  const bool written_at_nodes = !printed_states.is_equal(printed);
  const auto [printed_terms, order] = split_order(printed_states, h);
  if (order <= 0) throw std::invalid_argument(reference_of(call, "printed") + " has no order term O(" + h.get_name() + "^k)");
  const int degree = taylor_degree(call, scheme, sequence, h, order);
  const ex on_taylor = on_taylor_solution(scheme, sequence, h, omega, degree);
  const ex series = series_of(on_taylor, h, order);
  // Printed terms at the neighbouring nodes are the solution there too: expanded like the scheme.
  const ex terms = printed_terms.has(sequence[0]) || printed_terms.has(sequence[2])
                       ? series_of(on_taylor_solution(printed_terms, sequence, h, omega, degree), h, order)
                       : printed_terms;
  // The next terms, for the reader (two more even powers), from the Taylor polynomials of a higher degree.
  const int further = order + 4;
  const ex series_further = series_of(on_taylor_solution(scheme, sequence, h, omega, taylor_degree(call, scheme, sequence, h, further)), h, further);
  const ex gap = GiNaC::normal(series - terms);
  const std::string big_o = "O(" + h.get_name() + "^" + std::to_string(order) + ")";
  const std::string what = fmt::format("({}) on the exact solution = ({}) + {}", reference_of(call, "scheme"), reference_of(call, "printed"), big_o);
  const bool ginac_holds = gap.is_zero();
  // Our kernel: the printed terms when GiNaC finds them right, else GiNaC's series and its difference
  // from the printed terms.
  kernel_decision own = kernel_confirms_order(on_taylor - (ginac_holds ? terms : series), h, order, false);
  std::string own_claim = fmt::format("the scheme on the solution's Taylor polynomials of degree {} = {} + {}", degree,
                                      ginac_holds ? "the printed terms" : "GiNaC's series", big_o);
  if (!ginac_holds && own.outcome == kernel_decision::result::zero) {
    const kernel_decision differs = kernel_decides_zero(series - terms);
    if (differs.outcome == kernel_decision::result::nonzero) {
      own.evidence += "; series − printed terms " + differs.evidence;
    } else {
      own = {differs.outcome == kernel_decision::result::zero ? kernel_decision::result::nonzero : differs.outcome,
             "series − printed terms: " + differs.evidence};
    }
    own_claim += ", and the printed terms differ from it";
  }
  result.evidence["exact"] = {{"statement", what},
                              {"series", text_of(series) + " + " + big_o},
                              {"series_further", text_of(series_further) + " + O(" + h.get_name() + "^" + std::to_string(further) + ")"},
                              {"leading_power", lowest_power(series, h).value_or(-1)},
                              {"taylor_degree", degree},
                              {"ginac", ginac_holds ? "holds: series − printed terms = 0 through the printed order"
                                                    : "fails: series − printed terms = " + text_of(gap)},
                              {"own", own_text(own, ginac_holds ? "holds" : "fails", own_claim)}};
  // What Coq certifies: the scheme on the Taylor polynomials is the terms plus h^N times GiNaC's quotient.
  const ex remainder = GiNaC::normal((on_taylor - (ginac_holds ? terms : series)) / GiNaC::pow(h, order));
  std::vector<proof_goal> goals{decided(ginac_holds ? "printed_taylor_remainder" : "derived_taylor_remainder", on_taylor,
                                        (ginac_holds ? terms : series) + GiNaC::pow(h, order) * remainder)};
  if (!ginac_holds) goals.push_back(decided("printed", series, terms));
  // Our kernel confirms (or refutes) the series GiNaC's answer rests on.
  decider_evidence e;
  e.statement = what;
  e.ginac = answer_of(ginac_holds);
  e.own = confirming(e.ginac, own);
  e.goals = std::move(goals);
  if (own.outcome == kernel_decision::result::not_applicable) result.note = "Our kernel could not decide it (" + own.evidence + "): GiNaC's series alone. ";
  if (!ginac_holds) {
    // In the text's notation: the exact solution at the node where it writes it so.
    const ex shown = written_at_nodes ? series.subs(sequence[1] == apply_function(nodes.base, {paper_symbols()["t_" + nodes.index]})) : series;
    result.correction = "as derived: " + text_of(shown) + " + " + big_o;
    result.note += "As printed: " + what + " is false; the series differs by " + text_of(gap) + ".";
  }
  e.found = std::move(result);
  return e;
}

/// The order a sentence states ("the scheme is of {order} order"), its words quoted from the
/// document and parsed, against the order computed: the scheme on the exact solution of
/// q'' = −ω² q is O(h^(p + s + 2)) when its q_{j+1} coefficient is of order h^s, so p = that power − s − 2.
/// GiNaC finds both powers; our kernel decides each (f = h^k w, w(0) finite and nonzero, as in
/// kernel_confirms_order).
decider_evidence stated_order_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex scheme = scaled_scheme(read);
  const ex omega = read.formula("frequency");
  const std::vector<GiNaC::symbol> sequence = read.symbols("sequence"), step = read.symbols("step");
  const GiNaC::symbol& h = step.front();
  const quoted_sentence sentence = quote(ctx, call.with.at("sentence").values.front());
  const int stated = sentence.number("order");
  claim_result result;
  result.printed = read.printed();
  const ex next_coefficient = GiNaC::diff(scheme, sequence[2]);
  const std::optional<int> scale = lowest_power(GiNaC::expand(GiNaC::normal(next_coefficient)), h);
  constexpr int series_order = 10;
  const ex on_taylor = on_taylor_solution(scheme, sequence, h, omega, taylor_degree(call, scheme, sequence, h, series_order));
  const ex series = series_of(on_taylor, h, series_order);
  const std::optional<int> leading = lowest_power(series, h);
  if (!scale) throw std::invalid_argument(reference_of(call, "scheme") + " has no " + sequence[2].get_name() + " term");
  result.evidence["exact"] = {{"statement", "the order the sentence states, against the order computed"},
                              {"stated", stated},
                              {"series", text_of(series) + " + O(" + h.get_name() + "^" + std::to_string(series_order) + ")"},
                              {"q_next_coefficient_power", *scale}};
  if (!leading) {
    result.note = "The series vanishes through O(h^" + std::to_string(series_order) + "): the order is at least " +
                  std::to_string(series_order - *scale - 2) + ", beyond what the shape expands.";
    return beyond_reach(std::move(result));
  }
  const int order = *leading - *scale - 2;
  result.evidence["exact"]["computed"] = order;
  kernel_decision own = kernel_confirms_order(next_coefficient, h, *scale, true);
  if (own.outcome == kernel_decision::result::zero) {
    const kernel_decision on_solution = kernel_confirms_order(on_taylor, h, *leading, true);
    own = {on_solution.outcome, "the " + sequence[2].get_name() + " coefficient: " + own.evidence + "; the scheme on the solution: " + on_solution.evidence};
  }
  // What Coq certifies: the two factorisations by powers of h (that their cofactors are finite and
  // nonzero at h = 0 is our kernel's alone).
  const auto factored = [&h](const std::string& name, const ex& f, int power) {
    return decided(name, f, GiNaC::pow(h, power) * GiNaC::normal(f / GiNaC::pow(h, power)));
  };
  const std::vector<proof_goal> goals{factored("next_coefficient", next_coefficient, *scale), factored("taylor_order", on_taylor, *leading)};
  const std::string verdict_word = order == stated ? "holds" : "fails";
  result.evidence["exact"]["ginac"] = fmt::format("{}: the series' leading power {}^{} less the {} coefficient's {}^{} less 2 is order {}",
                                                  verdict_word, h.get_name(), *leading, sequence[2].get_name(), h.get_name(), *scale, order);
  result.evidence["exact"]["own"] = own_text(own, verdict_word, fmt::format("the {} coefficient is of order {}^{} and the scheme on the solution of order {}^{}",
                                                              sequence[2].get_name(), h.get_name(), *scale, h.get_name(), *leading));
  decider_evidence e = order_evidence(std::move(result), own, stated, order, "the powers of the series", fmt::format("the scheme is of order {}", order),
                                      fmt::format("As printed: the sentence states order {}; on the exact solution the scheme is {} + O(h^{}).", stated,
                                                  text_of(series), series_order));
  e.goals = goals;
  return e;
}

/// The order of accuracy a sentence states ({order}) against the printed one-step map's: each entry
/// of the map minus the exact flow of q'' = −ω²q over one step (q' = p/m) is O(h^(p+1)), and one is
/// not O(h^(p+2)): a local error of order p + 1, so the order p. GiNaC expands the entries; our kernel
/// decides, on the flow's Taylor polynomials through h^(p+1), that each entry is h^(p+1) times a
/// function finite at h = 0, nonzero there for the entries of the lowest power; Coq certifies the
/// factorisations. Over a fixed time the global error is then O(h^p) wherever the map is stable.
decider_evidence map_order_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const GiNaC::matrix map = as_square_matrix(read.formula("map"), reference_of(call, "map"));
  const ex mass = read.formula("mass"), omega = read.formula("frequency");
  const GiNaC::symbol h = read.symbols("step").front();
  const bool momentum_first = read.has("order") && call.with.at("order").values.front() == "p q";
  const quoted_sentence sentence = quote(ctx, call.with.at("sentence").values.front());
  const int stated = sentence.number("order");
  claim_result result;
  result.printed = read.printed();
  // The exact flow over one step, in the printed map's state order, and its Taylor polynomials.
  const auto flow = [&](const ex& c, const ex& s) {
    return momentum_first ? GiNaC::matrix{{c, -mass * omega * s}, {s / (mass * omega), c}}
                          : GiNaC::matrix{{c, s / (mass * omega)}, {-mass * omega * s, c}};
  };
  const auto taylor_flow = [&](int degree) {
    ex c = 0, s = 0, term = 1;
    for (int k = 0; k <= degree; ++k) {
      if (k > 0) term = term * omega * h / k;
      if (k % 2 == 0) c += (k % 4 == 0 ? 1 : -1) * term;
      else s += (k % 4 == 1 ? 1 : -1) * term;
    }
    return flow(c, s);
  };
  constexpr int series_order = 12;
  const GiNaC::matrix exact = flow(GiNaC::cos(omega * h), GiNaC::sin(omega * h));
  const char* const names[2][2] = {{"(1,1)", "(1,2)"}, {"(2,1)", "(2,2)"}};
  std::optional<int> lowest;
  json local = json::object();
  ex series[2][2];
  for (unsigned i = 0; i < 2; ++i) {
    for (unsigned j = 0; j < 2; ++j) {
      series[i][j] = series_of(map(i, j) - exact(i, j), h, series_order);
      const std::optional<int> power = lowest_power(series[i][j], h);
      local[names[i][j]] = (series[i][j].is_zero() ? std::string("0") : text_of(series[i][j])) + " + O(" + h.get_name() + "^" + std::to_string(series_order) + ")";
      if (power && (!lowest || *power < *lowest)) lowest = power;
    }
  }
  result.evidence["exact"] = {{"statement", fmt::format("({}) minus the exact flow over one step, entry by entry, as a series in {}", reference_of(call, "map"),
                                                        h.get_name())},
                              {"flow", text_of(ex(exact))},
                              {"local_error", local},
                              {"stated", stated}};
  if (!lowest) {
    result.note = fmt::format("The map is the flow through O({}^{}): the order is at least {}, beyond what the shape expands.", h.get_name(), series_order,
                              series_order - 1);
    return beyond_reach(std::move(result));
  }
  const int order = *lowest - 1;
  result.evidence["exact"]["computed"] = order;
  result.evidence["exact"]["lowest_power"] = *lowest;
  // Our kernel, and what Coq certifies: each entry minus the flow's Taylor polynomials through
  // h^lowest is h^lowest times a function finite at h = 0 (nonzero there where GiNaC's series starts).
  const GiNaC::matrix near = taylor_flow(*lowest);
  std::vector<proof_goal> goals;
  kernel_decision own{kernel_decision::result::zero, ""};
  std::vector<std::string> own_parts;
  for (unsigned i = 0; i < 2 && own.outcome == kernel_decision::result::zero; ++i) {
    for (unsigned j = 0; j < 2 && own.outcome == kernel_decision::result::zero; ++j) {
      const ex f = map(i, j) - near(i, j);
      const bool leading = lowest_power(series[i][j], h) == lowest;
      const kernel_decision entry = kernel_confirms_order(f, h, *lowest, leading);
      if (entry.outcome != kernel_decision::result::zero) own = {entry.outcome, std::string("entry ") + names[i][j] + ": " + entry.evidence};
      if (leading) own_parts.push_back(names[i][j]);
      // An entry equal to the flow's Taylor polynomial has nothing to certify.
      if (!GiNaC::normal(f).is_zero()) {
        goals.push_back(decided(fmt::format("entry_{}{}", i + 1, j + 1), f, GiNaC::pow(h, *lowest) * GiNaC::normal(f / GiNaC::pow(h, *lowest))));
      }
    }
  }
  const std::string verdict_word = order == stated ? "holds" : "fails";
  result.evidence["exact"]["ginac"] = fmt::format("{}: the entries' series start at {}^{} (local error), order {}", verdict_word, h.get_name(), *lowest, order);
  result.evidence["exact"]["own"] =
      own_text(own, verdict_word,
               fmt::format("each entry minus the flow's Taylor polynomials of degree {} is {}^{} times a function finite at {} = 0, nonzero there for the entries {}", *lowest,
                           h.get_name(), *lowest, h.get_name(), fmt::join(own_parts, ", ")));
  decider_evidence e = order_evidence(std::move(result), own, stated, order, "the map's local error",
                                      fmt::format("the map is of order {}: its local error is O({}^{})", order, h.get_name(), *lowest),
                                      fmt::format("As printed: the sentence states order {}; the map differs from the exact flow over one step at {}^{}.", stated,
                                                  h.get_name(), *lowest));
  e.goals = std::move(goals);
  return e;
}

/// The shapes of this file, each one's name, summary, principal argument and parameters beside the
/// function that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> series_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  add({"truncation", "the scheme on the exact solution of q'' = -omega^2 q is the printed series, to its printed order", "printed",
       with_where(with_series({{"printed", argument_kind::formula, true,
                                "the printed truncation error, with its order term O(h^N); the exact solution at the nodes may be written "
                                "q(t_j), q(t_j + h), q(t_{j+1}) when [symbols] declares q a solution"}})),
       truncation_shape,
       [](shape_reader& read, const shape_call& call) {  // q(t_j): the declarations must say it is the exact solution
         const std::vector<GiNaC::symbol> sequence = read.symbols("sequence");
         const node_names nodes = node_names_of(sequence[1]);
         if (!nodes.base.empty()) solution_at_nodes(read.formula("printed"), *call.declared, nodes.base, nodes.index, read.symbols("step").front(), "printed");
       }});
  add({"stated-order", "the order a sentence states ({order} in its pattern) is the scheme's order on q'' = -omega^2 q", "scheme",
       with_where(with_series({pattern_with_hole("sentence", "the sentence's pattern, with the hole {order}", "order")})),
       stated_order_shape});
  add({"map-order", "the order a sentence states ({order} in its pattern) is the printed one-step map's on q'' = -omega^2 q: its local error against the exact flow is O(h^(order+1))",
       "map",
       with_where({{"map", argument_kind::matrix, true, "the printed one-step map", 2},
                   {"mass", argument_kind::formula, true, "m of q' = p/m"},
                   {"frequency", argument_kind::formula, true, "omega of q'' = -omega^2 q"},
                   {"step", argument_kind::symbols, true, "the step h", 1},
                   {"order", argument_kind::word, false, "the printed map's state order: 'q p' (the default) or 'p q'", 0, "", false, {"q p", "p q"}},
                   pattern_with_hole("sentence", "the sentence's pattern, with the hole {order}", "order")}),
       map_order_shape});
  return all;
}

}  // namespace simpson::verify::detail

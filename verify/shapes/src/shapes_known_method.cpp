// Whether a method a text presents as its own is a known one on its test problem, and whether the
// text says so. See shape_support.hpp.

#include <simpson/shapes/shape_support.hpp>

#include <simpson/prove/coq_export.hpp>
#include <simpson/prove/printed_check_support.hpp>

#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/prose_words.hpp>
#include <simpson/verify/quoted_words.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

/// A tableau argument as an s x s matrix of numbers, or a weights argument as a 1 x s row.
GiNaC::matrix numeric_matrix(shape_reader& read, const std::string& parameter, unsigned rows, unsigned cols) {
  const ex m = read.formula(parameter).evalm();
  if (!GiNaC::is_a<GiNaC::matrix>(m)) throw std::invalid_argument("'" + parameter + "' is not a matrix");
  const GiNaC::matrix& out = GiNaC::ex_to<GiNaC::matrix>(m);
  if ((rows != 0 && out.rows() != rows) || (cols != 0 && out.cols() != cols)) {
    throw std::invalid_argument(fmt::format("'{}' is {} x {}, not {} x {}", parameter, out.rows(), out.cols(), rows, cols));
  }
  for (unsigned r = 0; r < out.rows(); ++r) {
    for (unsigned c = 0; c < out.cols(); ++c) {
      if (!GiNaC::is_a<GiNaC::numeric>(out(r, c))) throw std::invalid_argument(fmt::format("'{}' has an entry that is not a number", parameter));
    }
  }
  return out;
}

}  // namespace

/// The one-step map of a partitioned Runge-Kutta method (tableau_position for q, tableau_momentum
/// for p, common weights) on H = p^2/(2m) + m omega^2 q^2/2, its stage equations solved in GiNaC,
/// against the printed map (in the state's order): the same map, entry by entry in both kernels (a
/// Coq lemma each), makes the printed scheme that method on this problem. The text is then judged on
/// whether its prose names the method (`names`, any of them): presented as its own without the

namespace {

/// A word without its possessive ending ("Verlet's", "Verlet’s": Verlet).
std::string without_possessive(const std::string& word) {
  for (const std::string ending : {"'s", "\u2019s"}) {
    if (word.size() > ending.size() && word.compare(word.size() - ending.size(), ending.size(), ending) == 0) return word.substr(0, word.size() - ending.size());
  }
  return word;
}

}  // namespace

/// name, a finding (the record's class: naming). Not the same map: the method is not that one here.
decider_evidence known_method_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const GiNaC::matrix printed = as_square_matrix(read.formula("map"), reference_of(call, "map"));
  const std::vector<GiNaC::symbol> state = read.symbols("state");
  const GiNaC::symbol q = read.symbols("position").front();
  const GiNaC::symbol h = read.symbols("step").front();
  const ex omega = read.formula("frequency"), m = read.formula("mass");
  const GiNaC::matrix a = numeric_matrix(read, "tableau_position", 0, 0);
  const unsigned s = a.rows();
  const GiNaC::matrix a_hat = numeric_matrix(read, "tableau_momentum", s, s), b = numeric_matrix(read, "weights", 1, s);
  const quoted_sentence said = quote(ctx, call.with.at("sentence").values.front());
  const std::string method = call.with.at("method").values.front();
  if (printed.rows() != 2 || state.size() != 2) throw std::invalid_argument(reference_of(call, "map") + " is not the 2 x 2 map of one degree of freedom");
  const bool q_first = state[0].get_name() == q.get_name();
  // The stages Q_i = q0 + h sum_j a_ij P_j/m, P_i = p0 - h sum_j â_ij m omega^2 Q_j, solved for (q0, p0) symbols.
  const GiNaC::symbol q0("known_q0"), p0("known_p0");
  std::vector<GiNaC::symbol> Q, P;
  GiNaC::lst equations, unknowns;
  for (unsigned i = 0; i < s; ++i) {
    Q.emplace_back("known_Q" + std::to_string(i));
    P.emplace_back("known_P" + std::to_string(i));
  }
  for (unsigned i = 0; i < s; ++i) {
    ex sum_q = 0, sum_p = 0;
    for (unsigned j = 0; j < s; ++j) {
      sum_q += a(i, j) * P[j] / m;
      sum_p += a_hat(i, j) * m * omega * omega * Q[j];
    }
    equations.append(Q[i] == q0 + h * sum_q);
    equations.append(P[i] == p0 - h * sum_p);
    unknowns.append(Q[i]);
    unknowns.append(P[i]);
  }
  const ex solved = GiNaC::lsolve(equations, unknowns);
  ex q1 = q0, p1 = p0;
  for (unsigned i = 0; i < s; ++i) {
    const ex q_stage = ex(Q[i]).subs(solved), p_stage = ex(P[i]).subs(solved);
    q1 += h * b(0, i) * p_stage / m;
    p1 -= h * b(0, i) * m * omega * omega * q_stage;
  }
  const ex q1n = GiNaC::normal(q1), p1n = GiNaC::normal(p1);
  // The method's map in the state's order.
  GiNaC::matrix known(2, 2);
  const ex first = q_first ? q1n : p1n, second = q_first ? p1n : q1n;
  const GiNaC::symbol& x0 = q_first ? q0 : p0;
  const GiNaC::symbol& y0 = q_first ? p0 : q0;
  known(0, 0) = GiNaC::normal(first.coeff(x0, 1).subs(y0 == 0));
  known(0, 1) = GiNaC::normal(first.coeff(y0, 1).subs(x0 == 0));
  known(1, 0) = GiNaC::normal(second.coeff(x0, 1).subs(y0 == 0));
  known(1, 1) = GiNaC::normal(second.coeff(y0, 1).subs(x0 == 0));
  bool ginac_same = true, own_contradicts = false, own_decided = true;
  std::vector<proof_goal> goals;
  json entries = json::array();
  for (unsigned r = 0; r < 2; ++r) {
    for (unsigned c = 0; c < 2; ++c) {
      const bool same = GiNaC::normal(printed(r, c) - known(r, c)).is_zero();
      const kernel_decision own = kernel_decides_zero(printed(r, c) - known(r, c));
      ginac_same = ginac_same && same;
      own_decided = own_decided && own.outcome != kernel_decision::result::not_applicable;
      own_contradicts = own_contradicts || (own.outcome != kernel_decision::result::not_applicable && (own.outcome == kernel_decision::result::zero) != same);
      entries.push_back({{"entry", fmt::format("({}, {})", r + 1, c + 1)}, {"printed", text_of(printed(r, c))}, {"method", text_of(known(r, c))},
                         {"same", same}, {"own", own.evidence}});
      goals.push_back(decided(fmt::format("entry_{}{}", r + 1, c + 1), printed(r, c), known(r, c)));
    }
  }
  // The names the prose carries (a citation's key is no name: without a bibliography it says nothing).
  std::vector<std::string> named;
  const std::vector<std::string> names = call.with.at("names").values;
  for (const prose_word& w : prose_words(paper_of(ctx).source, document_of(ctx))) {
    const std::string word = without_possessive(w.word);  // "Verlet's method" names Verlet
    if (std::find(names.begin(), names.end(), word) != names.end() && std::find(named.begin(), named.end(), word) == named.end()) named.push_back(word);
  }
  claim_result result;
  result.printed = read.printed();
  result.evidence["exact"] = {{"statement", fmt::format("({}) is {}'s map on q'' = -omega^2 q", reference_of(call, "map"), method)},
                              {"entries", entries},
                              {"ginac", ginac_same ? "holds: every entry equal in normal form (the stage equations solved by lsolve)"
                                                   : "fails: an entry differs in normal form"},
                              {"own", own_contradicts ? "contradicts GiNaC on an entry"
                                      : own_decided   ? std::string(ginac_same ? "holds" : "fails") + ": each entry's difference decided on a grid"
                                                      : "not applicable for an entry: GiNaC's proof alone"}};
  result.evidence["stated"] = said.words("novelty");
  said.record("novelty", "quoted in the remark, not parsed: the verdict rests on the map and on the names looked for");
  result.evidence["names"] = {{"looked_for", names}, {"found", named}};
  // Whether the map is the method's is the kernels' (entry by entry); whether the prose names it is
  // read. The sentence ("we propose a ... method") holds either way: a method that is known prior
  // work, left unnamed, is a naming remark, not a falsehood (the policy: an erratum is false under
  // every reasonable reading). Not the method's map: nothing to name.
  decider_evidence e;
  e.statement = "an entry of the map";
  e.parts_differ = own_contradicts;
  e.ginac = answer::holds;
  e.own = own_decided ? answer::holds : answer::none;
  if (!ginac_same) {
    result.note = fmt::format("The printed map is not {}'s on this problem: there is no known method to name.", method);
    result.certificate_missing = "a difference of maps: nothing to certify";
    e.found = std::move(result);
    return e;
  }
  e.goals = std::move(goals);
  if (!named.empty()) {
    result.note = fmt::format("The printed map is {}'s on this problem, and the text names it ({}).", method, fmt::format("{}", fmt::join(named, ", ")));
    e.found = std::move(result);
    return e;
  }
  result.remark_kind = finding::naming;
  result.evidence["prior_work"] = method;  // the referee's summary names it: a known method derived anew
  // What the proof covers is this problem's map; the construction's general equivalence with the
  // method is the literature's theorem (the record's `construction`, its words), not proved here.
  const std::string construction = read.has("construction") ? call.with.at("construction").values.front() : std::string();
  result.remark = fmt::format("Known prior work, never named: the method is {}{}. Proved here on this problem only: the printed map ({}) is that "
                              "method's on q'' = -omega^2 q, entry by entry{}. The text never names it ({} looked for in its prose). Whether "
                              "one of its citations covers it cannot be verified: the source has no bibliography.",
                              method, construction.empty() ? std::string() : ", " + construction, reference_of(call, "map"),
                              construction.empty() ? std::string() : "; that the construction gives the method beyond this problem is that work's theorem, not checked here",
                              fmt::format("{}", fmt::join(names, ", ")));
  result.amendments.push_back(amendment_in_words("what the method is", said.words("novelty"),
                                                 said.words("novelty") + ", named: " + method + " (known prior work, with its citation)"));
  e.found = std::move(result);
  return e;
}

/// The shapes of this file, each one's name, summary, principal argument and parameters beside the
/// function that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> known_method_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  add({"known-method",
       "the sentence presenting the printed one-step map's method as the text's own holds; a naming remark when the map is a named partitioned Runge-Kutta method's on q'' = -omega^2 q that the text never names",
       "map",
       with_where({{"map", argument_kind::matrix, true, "the printed 2 x 2 one-step map", 2},
                   {"state", argument_kind::symbols, true, "the map's state, in its order ('p', 'q')", 2},
                   {"position", argument_kind::symbols, true, "which of the state is the position q", 1, "", false, {}, "state"},
                   {"step", argument_kind::symbols, true, "the step h", 1},
                   {"frequency", argument_kind::formula, true, "omega"},
                   {"mass", argument_kind::formula, true, "the mass m"},
                   {"tableau_position", argument_kind::matrix, true, "the method's s x s tableau for the position (Lobatto IIIA)"},
                   {"tableau_momentum", argument_kind::matrix, true, "its s x s tableau for the momentum (Lobatto IIIB)"},
                   {"weights", argument_kind::formula, true, "its weights, a 1 x s row"},
                   {"method", argument_kind::word, true, "the method's name, in words ('the 3-stage Lobatto IIIA-IIIB pair')"},
                   {"names", argument_kind::words, true, "words whose presence in the prose names it ('Lobatto')"},
                   {"construction", argument_kind::word, false,
                    "the construction in the literature that gives the method in general, with its source, in words ('the Galerkin variational "
                    "integrator of ... (Marsden and West 2001)'): the remark says the proof is of this problem's map only"},
                   pattern_with_hole("sentence", "the sentence presenting the method as the text's own, with the hole {novelty}", "novelty")}),
       known_method_shape});
  return all;
}

}  // namespace simpson::verify::detail

// The proof shapes of claims files: see proof_shapes.hpp and docs/claims-file.md.

#include "proof_shapes.hpp"

#include "coq_export.hpp"
#include "kernel_zero.hpp"
#include "printed_check_support.hpp"

#include <simpson/verify/quoted_words.hpp>

#include <simpson/verify/formula_reference.hpp>
#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/stability_analysis.hpp>
#include <simpson/verify/tex_math.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <set>
#include <sstream>

namespace simpson::verify::detail {
namespace {

using GiNaC::ex;

/// The symbol a TeX name parses to ('q_0', '\omega', 'q_{j+1}'); throws std::invalid_argument.
GiNaC::symbol symbol_named(const std::string& tex) {
  ex e;
  try {
    e = parse_tex_math(tex, paper_symbols());
  } catch (const tex_parse_error& error) {
    throw std::invalid_argument("'" + tex + "' does not parse: " + error.what());
  }
  if (!GiNaC::is_a<GiNaC::symbol>(e)) throw std::invalid_argument("'" + tex + "' is not one symbol");
  return GiNaC::ex_to<GiNaC::symbol>(e);
}

/// The GiNaC names of the symbols a document declares.
std::set<std::string> declared_names(const claims_document& d) {
  std::set<std::string> names;
  for (const auto* list : {&d.positive, &d.real}) {
    for (const std::string& tex : *list) names.insert(symbol_named(tex).get_name());
  }
  return names;
}

/// Reads the formulas of one call from the run's document, with the call's definitions put in, and
/// keeps what it read for the report.
class shape_reader {
 public:
  shape_reader(const shape_call& call, const paper_source& document) : call_(call), document_(document), macros_(defined_macros(document.text)) {
    if (call.document) declared_ = declared_names(*call.document);
    const auto where = call.with.find("where");
    if (where != call.with.end()) {
      for (const std::string& reference : where->second.values) {
        definitions_.push_back(read_definition(document_, macros_, reference));
        definitions_read_.push_back({{"reference", reference}, {"label", definitions_.back().locator + ", put in"}, {"line", 0}});
      }
      // A symbol a definition defines is declared by it (Phi = (map)); what it is defined as must be declared.
      for (const definition& d : definitions_) declared_.insert(d.name.get_name());
      for (const definition& d : definitions_) declared_only(d.value, d.locator);
    }
  }

  bool has(const std::string& parameter) const { return call_.with.count(parameter) > 0; }

  /// The formula the argument names, definitions put in.
  ex formula(const std::string& parameter) {
    const referenced_formula f = raw(parameter);
    return with_definitions(f.value, definitions_);
  }

  /// The formula as read, no definition put in.
  referenced_formula raw(const std::string& parameter) {
    const std::string& reference = call_.with.at(parameter).values.front();
    referenced_formula f = read_reference(document_, macros_, reference);
    declared_only(f.value, f.locator);
    record(reference, f.locator, f.line, f.tex, f.value);
    return f;
  }

  std::vector<GiNaC::symbol> symbols(const std::string& parameter) const {
    std::vector<GiNaC::symbol> out;
    for (const std::string& tex : call_.with.at(parameter).values) out.push_back(symbol_named(tex));
    return out;
  }

  const std::set<std::string>& declared() const { return declared_; }

  /// What was read, the principal formula first (each shape reads it first), the definitions last.
  json printed() const {
    json all = read_;
    for (const json& d : definitions_read_) all.push_back(d);
    return {{"source", document_.origin}, {"formulas", all}};
  }

 private:
  void declared_only(const ex& e, const std::string& where) const {
    if (!call_.document) return;
    for (const std::string& name : symbol_names(e)) {
      if (!declared_.count(name)) throw std::invalid_argument(where + ": the symbol '" + name + "' is not declared in [symbols]");
    }
  }

  void record(const std::string& reference, const std::string& locator, int line, const std::string& tex, const std::optional<ex>& value) {
    json entry = {{"reference", reference}, {"label", locator}, {"line", line}};
    if (!tex.empty()) entry["tex"] = folded_space(tex);
    if (value) entry["parsed"] = json::array({text_of(*value)});
    for (const json& seen : read_) {
      if (seen == entry) return;
    }
    read_.push_back(entry);
  }

  const shape_call& call_;
  const paper_source& document_;
  std::map<std::string, tex_macro> macros_;
  std::set<std::string> declared_;
  std::vector<definition> definitions_;
  json read_ = json::array();
  json definitions_read_ = json::array();
};

const paper_source& document_of(const run_context& ctx) {
  if (!ctx.paper) throw std::invalid_argument("a proof shape reads its formulas from the run's document, and this run has none");
  return ctx.paper->source;
}

/// The verdict on an identity lhs = rhs, decided by GiNaC's normal form and by our kernel's grid:
/// holds when both find it zero, erratum (with `correction`) when both find it not, kernels-disagree
/// otherwise; our kernel not applicable leaves GiNaC's verdict, and says so.
claim_result identity_verdict(const shape_call& call, shape_reader& read, const std::string& what, const ex& lhs, const ex& rhs,
                              const std::string& correction, verdict when_false = verdict::erratum) {
  claim_result result;
  const ex difference = normal_difference(lhs, rhs);
  const bool ginac_zero = is_zero_expression(difference);
  const kernel_decision own = kernel_decides_zero((lhs - rhs).evalm());
  result.evidence["exact"] = {
      {"statement", what},
      {"ginac", ginac_zero ? "holds: lhs − rhs = 0 (normal form, every symbol free)" : "fails: lhs − rhs = " + text_of(difference) + " ≠ 0"},
      {"own", (own.outcome == kernel_decision::result::zero      ? "holds: "
               : own.outcome == kernel_decision::result::nonzero ? "fails: "
                                                                 : "not applicable: ") +
                  own.evidence}};
  const bool own_decided = own.outcome != kernel_decision::result::not_applicable;
  const bool own_zero = own.outcome == kernel_decision::result::zero;
  if (own_decided && own_zero != ginac_zero) {
    result.outcome = verdict::kernels_disagree;
    result.note = "GiNaC and our kernel reached different conclusions on " + what + ": a bug in one of them.";
  } else if (ginac_zero) {
    result.outcome = verdict::holds;
    if (!own_decided) result.note = "Our kernel could not decide it (" + own.evidence + "): GiNaC's proof alone.";
  } else {
    result.outcome = when_false;
    result.correction = correction;
    result.note = "As printed: " + what + " is false; " + text_of(lhs) + " − (" + text_of(rhs) + ") = " + text_of(difference) + " ≠ 0.";
    if (!own_decided) result.note += " Our kernel could not decide it (" + own.evidence + "): GiNaC's proof alone.";
  }
  result.printed = read.printed();
  const coq_export certificate = coq_certificate(call.claim_id, call.statement, {decided(what, lhs, rhs)});
  result.certificate = certificate.text;
  result.certificate_lemmas = certificate.lemmas;
  result.certificate_missing = certificate.not_exported;
  result.refutation = certificate.refutation;
  result.refutation_lemmas = certificate.refutation_lemmas;
  return result;
}

GiNaC::matrix as_square_matrix(const ex& e, const std::string& what) {
  const ex m = e.evalm();
  if (!GiNaC::is_a<GiNaC::matrix>(m)) throw std::invalid_argument(what + " is not a matrix");
  const GiNaC::matrix& out = GiNaC::ex_to<GiNaC::matrix>(m);
  if (out.rows() != out.cols()) throw std::invalid_argument(what + " is not square");
  return out;
}

std::string reference_of(const shape_call& call, const std::string& parameter) { return call.with.at(parameter).values.front(); }

// ---- the shapes ----

claim_result identity(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex rhs = read.formula("rhs"), lhs = read.formula("lhs");
  const std::string what = fmt::format("({}) = ({})", reference_of(call, "lhs"), reference_of(call, "rhs"));
  return identity_verdict(call, read, what, lhs, rhs,
                          fmt::format("as derived from ({}): ({}) = {}", reference_of(call, "lhs"), reference_of(call, "rhs"), text_of(lhs)));
}

claim_result determinant(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex equals = read.formula("equals");
  const GiNaC::matrix m = as_square_matrix(read.formula("matrix"), reference_of(call, "matrix"));
  // As written (a d − b c for 2 × 2): the statement a certificate proves, not GiNaC's evaluated value.
  const ex det = m.rows() == 2 ? determinant_2x2(m) : m.determinant(GiNaC::determinant_algo::laplace);
  const std::string what = fmt::format("det ({}) = {}", reference_of(call, "matrix"), text_of(equals));
  return identity_verdict(call, read, what, det, equals,
                          fmt::format("det ({}) = {}", reference_of(call, "matrix"), text_of(GiNaC::normal(det))));
}

GiNaC::matrix canonical_j(unsigned n) {
  GiNaC::matrix j(2 * n, 2 * n);
  for (unsigned k = 0; k < n; ++k) {
    j(k, n + k) = 1;
    j(n + k, k) = -1;
  }
  return j;
}

claim_result symplectic(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const GiNaC::matrix m = as_square_matrix(read.formula("matrix"), reference_of(call, "matrix"));
  if (m.rows() % 2 != 0) throw std::invalid_argument(reference_of(call, "matrix") + " has an odd dimension: no symplectic form");
  const GiNaC::matrix j = canonical_j(m.rows() / 2);
  const ex lhs = (m.transpose() * j * m).evalm();
  const std::string what = fmt::format("({})^T J ({}) = J", reference_of(call, "matrix"), reference_of(call, "matrix"));
  GiNaC::matrix normal = GiNaC::ex_to<GiNaC::matrix>(lhs);
  for (unsigned r = 0; r < normal.rows(); ++r) {
    for (unsigned c = 0; c < normal.cols(); ++c) normal(r, c) = GiNaC::normal(normal(r, c));
  }
  return identity_verdict(call, read, what, lhs, ex(j), fmt::format("({})^T J ({}) = {}", reference_of(call, "matrix"), reference_of(call, "matrix"), text_of(normal)));
}

claim_result conserved(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex h = read.formula("function");
  const GiNaC::matrix m = as_square_matrix(read.formula("map"), reference_of(call, "map"));
  const std::vector<GiNaC::symbol> state = read.symbols("state");
  if (state.size() != m.rows()) {
    throw std::invalid_argument(fmt::format("the state has {} symbols and the map {} rows", state.size(), m.rows()));
  }
  GiNaC::matrix y(m.rows(), 1);
  for (unsigned k = 0; k < m.rows(); ++k) y(k, 0) = state[k];
  const GiNaC::matrix next = GiNaC::ex_to<GiNaC::matrix>((m * y).evalm());
  GiNaC::lst step;
  for (unsigned k = 0; k < m.rows(); ++k) step.append(state[k] == next(k, 0));
  const ex after = h.subs(step);
  const std::string what = fmt::format("({})(({}) y) = ({})(y)", reference_of(call, "function"), reference_of(call, "map"), reference_of(call, "function"));
  return identity_verdict(call, read, what, after, h,
                          fmt::format("({})(({}) y) − ({})(y) = {}", reference_of(call, "function"), reference_of(call, "map"),
                                      reference_of(call, "function"), text_of(GiNaC::normal(after - h))));
}

claim_result euler_lagrange(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex printed = read.formula("printed"), lagrangian = read.formula("lagrangian");
  const std::vector<GiNaC::symbol> nodes = read.symbols("nodes"), sequence = read.symbols("sequence");
  if (nodes.size() != 2) throw std::invalid_argument("'nodes' names the Lagrangian's two arguments (q_0, q_1)");
  if (sequence.size() != 3) throw std::invalid_argument("'sequence' names three consecutive states (q_{j-1}, q_j, q_{j+1})");
  const auto at = [&](const ex& e, const ex& a, const ex& b) { return e.subs(GiNaC::lst{nodes[0] == a, nodes[1] == b}); };
  // D_2 L(q_{j-1}, q_j) + D_1 L(q_j, q_{j+1}) = 0.
  const ex derived = at(lagrangian.diff(nodes[1]), sequence[0], sequence[1]) + at(lagrangian.diff(nodes[0]), sequence[1], sequence[2]);
  const std::vector<ex> unknowns(sequence.begin(), sequence.end());
  const auto factor = equation_factor(printed, derived, unknowns);
  const std::string what = fmt::format("({}) = 0 is the discrete Euler-Lagrange equation of ({})", reference_of(call, "printed"),
                                       reference_of(call, "lagrangian"));
  if (factor) {
    // The printed equation times the factor GiNaC found is the derived one: an identity both kernels decide.
    claim_result result = identity_verdict(call, read, what, *factor * printed, derived, "");
    result.evidence["exact"]["factor"] = text_of(*factor);
    return result;
  }
  claim_result result;
  result.outcome = verdict::erratum;
  result.correction = "as derived: " + text_of(GiNaC::normal(derived)) + " = 0";
  result.note = "As printed: no factor free of the states makes the printed equation the derived one (GiNaC: the ratio depends on them); our kernel decides identities only, not this refutation.";
  result.evidence["exact"] = {{"statement", what}, {"ginac", "fails: derived / printed depends on the states"},
                              {"own", "not applicable: a refutation of proportionality"}};
  result.printed = read.printed();
  result.certificate_missing = "a refuted proportionality: no identity to state";
  return result;
}

/// The one-step map of a discrete Lagrangian L(q_0, q_1) of a linear system, derived: each internal
/// node eliminated by its equation D_{q_m} L = 0, then p_0 = −D_1 L solved for q_1 and p_1 = D_2 L,
/// as a matrix in (q_0, p_0); compared with the printed map in both kernels.
claim_result discrete_map(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const GiNaC::matrix printed = as_square_matrix(read.formula("map"), reference_of(call, "map"));
  const ex lagrangian = read.formula("lagrangian");
  const std::vector<GiNaC::symbol> nodes = read.symbols("nodes"), momenta = read.symbols("momenta");
  const std::vector<GiNaC::symbol> internal = read.has("internal") ? read.symbols("internal") : std::vector<GiNaC::symbol>{};
  const auto no_map = [&](const std::string& why) {
    claim_result result;
    result.outcome = verdict::fails;
    result.note = why;
    result.printed = read.printed();
    result.certificate_missing = "no map derived";
    return result;
  };
  const auto not_linear = [&](const std::string& step) {
    return no_map("The shape derives the map of a linear system: " + step + " is not linear in its unknowns.");
  };
  ex reduced = lagrangian;
  if (!internal.empty()) {
    GiNaC::lst equations, unknowns;
    for (const GiNaC::symbol& q : internal) {
      equations.append(lagrangian.diff(q) == 0);
      unknowns.append(q);
    }
    ex solution;
    try {
      solution = GiNaC::lsolve(equations, unknowns);
    } catch (const std::exception&) {
      return not_linear("the internal nodes' equations");
    }
    if (solution.nops() != internal.size()) return not_linear("the internal nodes' equations");
    reduced = lagrangian.subs(solution);
  }
  // p_0 = −D_1 L(q_0, q_1), solved for q_1; then p_1 = D_2 L.
  ex q1;
  try {
    // GiNaC's lsolve of one equation in one symbol returns the value itself; of lists, a list of
    // relations, empty when there is no unique solution.
    const ex solved = GiNaC::lsolve(GiNaC::lst{momenta[0] == -reduced.diff(nodes[0])}, GiNaC::lst{nodes[1]});
    if (solved.nops() != 1 || !GiNaC::is_a<GiNaC::relational>(solved.op(0))) return not_linear("p_0 = -D_1 L");
    q1 = GiNaC::normal(solved.op(0).rhs());
  } catch (const std::exception& e) {
    return not_linear(std::string("p_0 = -D_1 L (") + e.what() + ")");
  }
  const ex p1 = GiNaC::normal(reduced.diff(nodes[1]).subs(nodes[1] == q1));
  GiNaC::matrix derived(2, 2);
  const ex state[2] = {nodes[0], momenta[0]};
  for (unsigned c = 0; c < 2; ++c) {
    derived(0, c) = GiNaC::normal(q1.diff(GiNaC::ex_to<GiNaC::symbol>(state[c])));
    derived(1, c) = GiNaC::normal(p1.diff(GiNaC::ex_to<GiNaC::symbol>(state[c])));
  }
  // Linear: nothing of the state is left in the matrix; and no other symbol the document declares
  // real (a node left free: an internal node not named in `internal`).
  std::set<std::string> real;
  if (call.document) {
    for (const std::string& tex : call.document->real) real.insert(symbol_named(tex).get_name());
  }
  for (unsigned r = 0; r < 2; ++r) {
    for (unsigned c = 0; c < 2; ++c) {
      if (derived(r, c).has(nodes[0]) || derived(r, c).has(momenta[0])) return not_linear("the map");
      for (const std::string& name : symbol_names(derived(r, c))) {
        if (real.count(name)) {
          return no_map("The derived map depends on " + name +
                        ", which the document declares real (a state, not a parameter): an internal node left free? Name it in 'internal'.");
        }
      }
    }
  }
  const std::string what = fmt::format("({}) is the one-step map of ({})", reference_of(call, "map"), reference_of(call, "lagrangian"));
  claim_result result = identity_verdict(call, read, what, ex(printed), ex(derived),
                                         fmt::format("as derived from ({}): ({}) = {}", reference_of(call, "lagrangian"), reference_of(call, "map"),
                                                     text_of(ex(derived))));
  result.evidence["exact"]["derivation"] = {{"q_1", text_of(q1)}, {"p_1", text_of(p1)},
                                            {"internal_nodes", internal.empty() ? std::string("none") : std::to_string(internal.size()) + " eliminated"}};
  return result;
}

/// The scheme (= 0, in three consecutive states) on the exact solution of q'' = −ω² q through the
/// middle state, q(t_j ± h) = q_j cos ωh ± (v_j/ω) sin ωh, as GiNaC's series in h to O(h^order):
/// cos and sin as Taylor polynomials through h^(order + 2), the scheme dividing by h² at most.
ex series_on_solution(const ex& scheme, const std::vector<GiNaC::symbol>& sequence, const GiNaC::symbol& h, const ex& omega, int order) {
  const GiNaC::symbol velocity("v_j");
  ex c = 0, sn = 0, term = 1;
  for (int k = 0; k <= order + 2; ++k) {
    if (k > 0) term = term * omega * h / k;
    if (k % 2 == 0) c += (k % 4 == 0 ? 1 : -1) * term;
    else sn += (k % 4 == 1 ? 1 : -1) * term;
  }
  const ex shift = velocity / omega * sn;
  const ex on_solution = scheme.subs(GiNaC::lst{sequence[0] == sequence[1] * c - shift, sequence[2] == sequence[1] * c + shift});
  return GiNaC::expand(GiNaC::series_to_poly(GiNaC::series(on_solution, h == 0, order)));
}

/// The lowest power of h with a nonzero coefficient, or nothing.
std::optional<int> lowest_power(const ex& e, const GiNaC::symbol& h) {
  const ex expanded = GiNaC::expand(e);
  for (int k = expanded.ldegree(h); k <= expanded.degree(h); ++k) {
    if (!GiNaC::normal(expanded.coeff(h, k)).is_zero()) return k;
  }
  return std::nullopt;
}

/// A printed truncation error: the scheme (an expression in three consecutive states, = 0) on the
/// exact solution of q'' = −ω² q through the middle state, q(t_j ± h) = q_j cos ωh ± (v_j/ω) sin ωh,
/// as GiNaC's series in h, against the printed terms and order O(h^N).
claim_result truncation(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex printed = read.formula("printed");
  const ex scheme = read.formula("scheme");
  const ex omega = read.formula("frequency");
  const std::vector<GiNaC::symbol> sequence = read.symbols("sequence"), step = read.symbols("step");
  const GiNaC::symbol& h = step.front();
  claim_result result;
  result.printed = read.printed();
  result.certificate_missing = "a series in h to an order: no Coq statement for this shape yet";
  // The printed terms and its order term O(h^N).
  const auto [terms, order] = split_order(printed, h);
  if (order <= 0) throw std::invalid_argument(reference_of(call, "printed") + " has no order term O(" + h.get_name() + "^k)");
  const ex series = series_on_solution(scheme, sequence, h, omega, order);
  const ex gap = GiNaC::normal(series - terms);
  const std::string what = fmt::format("({}) on the exact solution = ({}) + O({}^{})", reference_of(call, "scheme"), reference_of(call, "printed"),
                                       h.get_name(), order);
  const int lowest = lowest_power(series, h).value_or(-1);  // the series' first nonzero power
  result.evidence["exact"] = {{"statement", what},
                              {"series", text_of(series) + " + O(" + h.get_name() + "^" + std::to_string(order) + ")"},
                              {"leading_power", lowest},
                              {"ginac", gap.is_zero() ? "holds: series − printed terms = 0 through the printed order"
                                                      : "fails: series − printed terms = " + text_of(gap)},
                              {"own", "not applicable: a series (GiNaC's alone)"}};
  if (gap.is_zero()) {
    result.outcome = verdict::holds;
    return result;
  }
  result.outcome = verdict::erratum;
  result.correction = "as derived: " + text_of(series) + " + O(" + h.get_name() + "^" + std::to_string(order) + ")";
  result.note = "As printed: " + what + " is false; the series differs by " + text_of(gap) + ".";
  return result;
}

/// The order a sentence states ("the scheme is of {order} order"), its words quoted from the
/// document and parsed, against the order computed: the scheme on the exact solution of
/// q'' = −ω² q is O(h^(p + s + 2)) when its q_{j+1} coefficient is of order h^s, so p = that power − s − 2.
claim_result stated_order(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex scheme = read.formula("scheme");
  const ex omega = read.formula("frequency");
  const std::vector<GiNaC::symbol> sequence = read.symbols("sequence"), step = read.symbols("step");
  const GiNaC::symbol& h = step.front();
  const quoted_sentence sentence = quote(ctx, call.with.at("sentence").values.front());
  const int stated = sentence.number("order");
  claim_result result;
  result.printed = read.printed();
  result.certificate_missing = "an order of accuracy: a statement about a series, no Coq statement for this shape yet";
  const std::optional<int> scale = lowest_power(GiNaC::expand(GiNaC::normal(scheme)).coeff(sequence[2], 1), h);
  constexpr int series_order = 10;
  const ex series = series_on_solution(scheme, sequence, h, omega, series_order);
  const std::optional<int> leading = lowest_power(series, h);
  if (!scale) throw std::invalid_argument(reference_of(call, "scheme") + " has no " + sequence[2].get_name() + " term");
  result.evidence["exact"] = {{"statement", "the order the sentence states, against the order computed"},
                              {"stated", stated},
                              {"series", text_of(series) + " + O(" + h.get_name() + "^" + std::to_string(series_order) + ")"},
                              {"q_next_coefficient_power", *scale}};
  if (!leading) {
    result.outcome = verdict::undecided;
    result.note = "The series vanishes through O(h^" + std::to_string(series_order) + "): the order is at least " +
                  std::to_string(series_order - *scale - 2) + ", beyond what the shape expands.";
    return result;
  }
  const int order = *leading - *scale - 2;
  result.evidence["exact"]["computed"] = order;
  if (order == stated) {
    result.outcome = verdict::holds;
    return result;
  }
  result.outcome = verdict::erratum;
  result.correction = fmt::format("the scheme is of order {}", order);
  result.note = fmt::format("As printed: the sentence states order {}; on the exact solution the scheme is {} + O(h^{}).", stated,
                            text_of(series), series_order);
  return result;
}

/// GiNaC's polynomial in t (rational coefficients) as our kernel's.
polynomial as_polynomial(const ex& p, const GiNaC::symbol& t) {
  const ex expanded = GiNaC::expand(p);
  std::vector<rational> c;
  for (int k = 0; k <= expanded.degree(t); ++k) {
    const ex coefficient = expanded.coeff(t, k);
    if (!GiNaC::is_a<GiNaC::numeric>(coefficient) || !GiNaC::ex_to<GiNaC::numeric>(coefficient).is_rational()) {
      throw std::invalid_argument("a coefficient that is not a rational number: " + text_of(coefficient));
    }
    std::ostringstream num, den;
    num << GiNaC::ex_to<GiNaC::numeric>(coefficient).numer();
    den << GiNaC::ex_to<GiNaC::numeric>(coefficient).denom();
    c.emplace_back(boost::multiprecision::cpp_int(num.str()), boost::multiprecision::cpp_int(den.str()));
  }
  return make_polynomial(c);
}

bool even(const polynomial& p) {
  for (long k = 1; k <= degree(p); k += 2) {
    if (p[static_cast<std::size_t>(k)] != 0) return false;
  }
  return true;
}

/// A function of the condition's variable v alone, for our kernel: every symbol of v but one
/// eliminated by v's scaling (s = t / (v / s) for a symbol s of v with exponent 1), its numerator
/// and denominator as polynomials in t = v, or in x = v² when both are even (roots exact more often).
struct one_variable {
  GiNaC::symbol t{"interval_variable"};
  ex of_t;  // normal form in t
  polynomial numerator, denominator;
  bool in_square = false;
  std::vector<positive_root> ends;  // positive roots of both, increasing

  int sign_at(const rational& x) const {
    const rational value = numerator.evaluate(x) / denominator.evaluate(x);
    return value < 0 ? -1 : value > 0 ? 1 : 0;
  }
  std::string text(const positive_root& r) const { return in_square ? omega_h_text(r) : root_text(r); }
  /// The printed end c as our kernel's rational (c, or c² in x), when it is one.
  std::optional<rational> exact(const ex& c) const {
    const ex value = GiNaC::expand(in_square ? c * c : c);
    if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_rational()) return std::nullopt;
    const polynomial p = as_polynomial(value, t);
    return degree(p) < 0 ? rational(0) : p[0];
  }
};

/// `f` as a function of v alone, or nothing when it is not one.
std::optional<one_variable> in_variable(const ex& f, const ex& v) {
  one_variable out;
  std::optional<ex> of_t;
  for (const std::string& name : symbol_names(v)) {
    const GiNaC::symbol s = paper_symbols()[name];
    if (v.degree(s) != 1 || v.ldegree(s) != 1 || GiNaC::normal(v / s).has(s)) continue;
    of_t = GiNaC::normal(f.subs(s == out.t / GiNaC::normal(v / s)));
    break;
  }
  if (!of_t) return std::nullopt;
  for (const std::string& name : symbol_names(*of_t)) {
    if (name != out.t.get_name()) return std::nullopt;
  }
  out.of_t = *of_t;
  out.numerator = as_polynomial(GiNaC::numer(out.of_t), out.t);
  out.denominator = as_polynomial(GiNaC::denom(out.of_t), out.t);
  out.in_square = even(out.numerator) && even(out.denominator);
  if (out.in_square) {
    out.numerator = even_in_theta_to_x(out.numerator);
    out.denominator = even_in_theta_to_x(out.denominator);
  }
  out.ends = positive_roots(out.numerator);
  for (const positive_root& pole : positive_roots(out.denominator)) out.ends.push_back(pole);
  std::sort(out.ends.begin(), out.ends.end(), [](const positive_root& a, const positive_root& b) { return a.low < b.low; });
  return out;
}

/// The printed condition 0 < v < c: c, or an exception naming the condition when it is not so.
ex interval_end(const referenced_formula& condition, const ex& v) {
  if (condition.sides.size() != 3) throw std::invalid_argument(condition.locator + ": not a condition '0 < ... < c'");
  ex low, middle, high;
  try {
    low = parse_tex_math(condition.sides[0], paper_symbols());
    middle = parse_tex_math(condition.sides[1], paper_symbols());
    high = parse_tex_math(condition.sides[2], paper_symbols());
  } catch (const tex_parse_error& e) {
    throw std::invalid_argument(condition.locator + ": " + e.what());
  }
  if (!GiNaC::normal(low).is_zero() || !GiNaC::normal(middle - v).is_zero()) {
    throw std::invalid_argument(condition.locator + ": the condition is not '0 < " + text_of(v) + " < c'");
  }
  return high;
}

claim_result stability_interval(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const referenced_formula condition = read.raw("condition");
  const GiNaC::matrix m = as_square_matrix(read.formula("map"), reference_of(call, "map"));
  if (m.rows() != 2) throw std::invalid_argument(reference_of(call, "map") + " is not a 2 x 2 map");
  const ex v = read.formula("variable");
  claim_result result;
  result.printed = read.printed();
  result.certificate_missing = "a stability set: our kernel's Sturm sequences decide it; no Coq statement for this shape yet";
  // det = 1, in both kernels: then the map is power-bounded exactly where |trace| < 2.
  const ex det = m.determinant();
  const kernel_decision det_own = kernel_decides_zero(det - 1);
  if (!GiNaC::normal(det - 1).is_zero() || det_own.outcome == kernel_decision::result::nonzero) {
    result.outcome = verdict::fails;
    result.note = "The shape decides maps with det 1; det (" + reference_of(call, "map") + ") = " + text_of(GiNaC::normal(det)) + ".";
    return result;
  }
  const ex high = interval_end(condition, v);
  const ex trace = m(0, 0) + m(1, 1);
  const std::optional<one_variable> excess = in_variable(trace * trace - 4, v);  // < 0 exactly on the stable set
  if (!excess) {
    result.outcome = verdict::fails;
    result.note = "The trace of " + reference_of(call, "map") + " is not a function of " + text_of(v) + " alone.";
    return result;
  }
  const std::string var = text_of(v);
  // The stable bands: between consecutive ends, where trace² − 4 < 0 at a point inside.
  std::vector<std::string> bands;
  rational from = 0;
  std::string from_text = "0";
  for (std::size_t k = 0; k <= excess->ends.size(); ++k) {
    const rational inside = k < excess->ends.size() ? rational((from + excess->ends[k].low) / 2) : rational(from + 1);
    if (excess->sign_at(inside) < 0) {
      bands.push_back(k < excess->ends.size() ? fmt::format("{} < {} < {}", from_text, var, excess->text(excess->ends[k]))
                                              : fmt::format("{} > {}", var, from_text));
    }
    if (k < excess->ends.size()) {
      from = excess->ends[k].high;
      from_text = excess->text(excess->ends[k]);
    }
  }
  const bool stable_near_zero = !excess->ends.empty() && excess->sign_at(excess->ends.front().low / 2) < 0;
  // Is the printed c the first end? Exactly: c (or c² in x) is rational and equal to an exact root,
  // or a root of the numerator inside the first end's isolating interval.
  bool equal = false;
  std::string how;
  if (stable_near_zero) {
    const positive_root& first = excess->ends.front();
    if (const std::optional<rational> value = excess->exact(high)) {
      equal = first.exact() ? *value == first.low : (*value >= first.low && *value <= first.high && excess->numerator.evaluate(*value) == 0);
      how = fmt::format("{} = {} (exact)", excess->in_square ? "c^2" : "c", value->str());
    } else {
      how = "c = " + text_of(high) + " is not rational" + std::string(excess->in_square ? " in its square" : "") + ": not compared";
    }
  }
  const ex trace_in_v = GiNaC::normal(trace);
  result.evidence["exact"] = {
      {"statement", fmt::format("the stable set of ({}) in {} > 0 begins with 0 < {} < {}", reference_of(call, "map"), var, var, text_of(high))},
      {"det", "det = 1 (GiNaC normal form; our kernel: " + det_own.evidence + ")"},
      {"trace", text_of(trace_in_v)},
      {"boundary_polynomial", to_string(excess->numerator, excess->in_square ? "x" : "t") + (excess->in_square ? " (x = (" + var + ")^2)" : "")},
      {"stable_bands", bands},
      {"printed_end", how}};
  if (stable_near_zero && equal) {
    result.outcome = verdict::holds;
    return result;
  }
  result.outcome = verdict::erratum;
  result.correction = bands.empty() ? "never stable for " + var + " > 0" : "stable exactly for " + fmt::format("{}", fmt::join(bands, ", "));
  result.note = "As printed: " + folded_space(condition.tex) + " is not the first stable band of " + reference_of(call, "map") +
                " (trace = " + text_of(trace_in_v) + ", stable where |trace| < 2).";
  return result;
}

/// The claimed sign of a function of v on the printed interval 0 < v < c: no root or pole of it
/// inside (our kernel's Sturm sequences, the end compared exactly), and the sign at a point inside.
claim_result sign_on_interval(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex f = read.formula("expression");
  const referenced_formula condition = read.raw("condition");
  const ex v = read.formula("variable");
  const std::string claimed = call.with.at("sign").values.front();
  const int want = claimed == "positive" ? 1 : -1;
  claim_result result;
  result.printed = read.printed();
  result.certificate_missing = "a sign on an interval: our kernel's Sturm sequences decide it; no Coq statement for this shape yet";
  const ex high = interval_end(condition, v);
  const std::optional<one_variable> g = in_variable(f, v);
  if (!g) {
    result.outcome = verdict::fails;
    result.note = "(" + reference_of(call, "expression") + ") is not a function of " + text_of(v) + " alone.";
    return result;
  }
  const std::string var = text_of(v);
  const std::optional<rational> c = g->exact(high);
  if (!c || *c <= 0) {
    result.outcome = verdict::undecided;
    result.note = "The interval's end " + text_of(high) + " is not a positive rational" + (g->in_square ? " in its square" : "") +
                  ": our kernel compares ends exactly, and cannot here.";
    return result;
  }
  // The first root or pole of f inside (0, c), if any.
  std::optional<positive_root> inside;
  for (const positive_root& e : g->ends) {
    if (e.exact() ? e.low < *c : e.high < *c) {
      inside = e;
      break;
    }
    if (!e.exact() && e.low < *c && g->numerator.evaluate(*c) != 0 && g->denominator.evaluate(*c) != 0) {
      result.outcome = verdict::undecided;
      result.note = "A root of " + text_of(f) + " lies within 2^-40 of the interval's end; its isolating interval holds the end.";
      return result;
    }
  }
  const rational probe = inside ? rational(inside->low / 2) : rational(*c / 2);
  const int sign = g->sign_at(probe);
  const std::string expression = text_of(f);
  result.evidence["exact"] = {
      {"statement", fmt::format("({}) is {} for 0 < {} < {}", reference_of(call, "expression"), claimed, var, text_of(high))},
      {"in_variable", text_of(g->of_t.subs(g->t == v))},
      {"roots_and_poles", [&] {
         json all = json::array();
         for (const positive_root& e : g->ends) all.push_back(g->text(e));
         return all;
       }()},
      {"interval_end", fmt::format("{} = {} (exact)", g->in_square ? "c^2" : "c", c->str())}};
  if (!inside && sign == want) {
    result.outcome = verdict::holds;
    return result;
  }
  result.outcome = verdict::erratum;
  const std::string sign_text = sign > 0 ? "positive" : "negative";
  result.correction = inside ? fmt::format("{} is {} for 0 < {} < {} only, and changes sign there", expression, sign_text, var, g->text(*inside))
                             : fmt::format("{} is {} for 0 < {} < {}", expression, sign_text, var, text_of(high));
  result.note = "As printed: (" + reference_of(call, "expression") + ") is said to be " + claimed + " for " + folded_space(condition.tex) + ".";
  return result;
}

const std::vector<shape_parameter> where_parameter{
    {"where", argument_kind::definitions, false, "displays 'x = ...' whose definitions are put in the other formulas"}};

std::vector<shape_parameter> with_where(std::vector<shape_parameter> parameters) {
  parameters.push_back(where_parameter.front());
  return parameters;
}

}  // namespace

const std::map<std::string, proof_shape>& proof_shapes() {
  static const std::map<std::string, proof_shape> shapes = [] {
    std::map<std::string, proof_shape> all;
    const auto add = [&](proof_shape s) { all.emplace(s.name, std::move(s)); };
    add({"identity", "lhs = rhs, the definitions put in", "rhs",
         with_where({{"lhs", argument_kind::formula, true, "a formula"}, {"rhs", argument_kind::formula, true, "the formula it equals"}}),
         identity});
    add({"determinant", "det matrix = equals", "equals",
         with_where({{"matrix", argument_kind::matrix, true, "a square matrix"}, {"equals", argument_kind::formula, true, "its determinant"}}),
         determinant});
    add({"symplectic", "matrix^T J matrix = J, J = [[0, I], [-I, 0]]", "matrix",
         with_where({{"matrix", argument_kind::matrix, true, "a one-step map of (q, p)"}}), symplectic});
    add({"conserved", "function(map y) = function(y), y the state", "function",
         with_where({{"map", argument_kind::matrix, true, "a one-step map"},
                     {"function", argument_kind::formula, true, "a function of the state"},
                     {"state", argument_kind::symbols, true, "the state's symbols, in the map's order", 0, "map"}}),
         conserved});
    add({"euler-lagrange", "printed = 0 is D_2 L(q_{j-1}, q_j) + D_1 L(q_j, q_{j+1}) = 0, up to a factor free of the states", "printed",
         with_where({{"lagrangian", argument_kind::formula, true, "the discrete Lagrangian L(q_0, q_1)"},
                     {"nodes", argument_kind::symbols, true, "its two arguments", 2},
                     {"sequence", argument_kind::symbols, true, "three consecutive states", 3},
                     {"printed", argument_kind::formula, true, "the printed equation's side that is 0"}}),
         euler_lagrange});
    add({"stability-interval", "the printed 0 < variable < c is the first band where the map (det 1) is power-bounded", "condition",
         with_where({{"map", argument_kind::matrix, true, "a 2 x 2 one-step map with det 1", 2},
                     {"variable", argument_kind::formula, true, "the variable of the condition, a product of positive symbols", 0, "", true},
                     {"condition", argument_kind::condition, true, "the printed condition 0 < variable < c"}}),
         stability_interval});
    add({"discrete-map", "map is the one-step map of the discrete Lagrangian (internal nodes eliminated), p_0 = -D_1 L, p_1 = D_2 L", "map",
         with_where({{"map", argument_kind::matrix, true, "the printed one-step map of (q_0, p_0)", 2},
                     {"lagrangian", argument_kind::formula, true, "the discrete Lagrangian L(q_0, q_1), quadratic"},
                     {"nodes", argument_kind::symbols, true, "its end nodes q_0, q_1", 2},
                     {"momenta", argument_kind::symbols, true, "the momenta p_0, p_1", 2},
                     {"internal", argument_kind::symbols, false, "its internal nodes, eliminated by their equations"}}),
         discrete_map});
    add({"truncation", "the scheme on the exact solution of q'' = -omega^2 q is the printed series, to its printed order", "printed",
         with_where({{"printed", argument_kind::formula, true, "the printed truncation error, with its order term O(h^N)"},
                     {"scheme", argument_kind::formula, true, "the scheme's expression (= 0) in three consecutive states"},
                     {"sequence", argument_kind::symbols, true, "the three states q_{j-1}, q_j, q_{j+1}", 3},
                     {"step", argument_kind::symbols, true, "the step h", 1},
                     {"frequency", argument_kind::formula, true, "omega of q'' = -omega^2 q"}}),
         truncation});
    add({"stated-order", "the order a sentence states ({order} in its pattern) is the scheme's order on q'' = -omega^2 q", "scheme",
         with_where({{"sentence", argument_kind::word, true, "the sentence's pattern, with the hole {order}", 0, "", false, {}},
                     {"scheme", argument_kind::formula, true, "the scheme's expression (= 0) in three consecutive states"},
                     {"sequence", argument_kind::symbols, true, "the three states q_{j-1}, q_j, q_{j+1}", 3},
                     {"step", argument_kind::symbols, true, "the step h", 1},
                     {"frequency", argument_kind::formula, true, "omega of q'' = -omega^2 q"}}),
         stated_order});
    add({"sign-on-interval", "expression has the stated sign on the printed interval 0 < variable < c", "expression",
         with_where({{"expression", argument_kind::formula, true, "a function of the variable alone once scaled"},
                     {"variable", argument_kind::formula, true, "the variable of the condition, a product of positive symbols", 0, "", true},
                     {"condition", argument_kind::condition, true, "the printed interval 0 < variable < c"},
                     {"sign", argument_kind::word, true, "positive or negative", 0, "", false, {"positive", "negative"}}}),
         sign_on_interval});
    return all;
  }();
  return shapes;
}

void check_shape_arguments(const claim_record& record, const std::string& file) {
  const proof_shape& shape = proof_shapes().at(record.shape);
  for (const auto& entry : record.with) {
    const std::string& name = entry.first;  // not a structured binding: clang's C++17 lambdas cannot capture one
    const shape_argument& argument = entry.second;
    const auto it = std::find_if(shape.parameters.begin(), shape.parameters.end(), [&](const shape_parameter& p) { return p.name == name; });
    if (it == shape.parameters.end()) {
      std::string names;
      for (const shape_parameter& p : shape.parameters) names += (names.empty() ? "" : ", ") + p.name;
      throw claims_file_error(file, argument.line, "with." + name, "not an argument of the shape '" + shape.name + "' (" + names + ")");
    }
    const bool list = it->kind == argument_kind::definitions || it->kind == argument_kind::symbols;
    if (argument.list != list) {
      throw claims_file_error(file, argument.line, "with." + name, list ? "must be an array of strings" : "must be one string (a formula reference)");
    }
    if (list && argument.values.empty()) throw claims_file_error(file, argument.line, "with." + name, "must not be empty");
  }
  for (const shape_parameter& p : shape.parameters) {
    if (p.required && !record.with.count(p.name)) {
      throw claims_file_error(file, record.line, "with." + p.name, "missing: the shape '" + shape.name + "' needs it (" + p.meaning + ")");
    }
  }
}

std::string check_shape_formulas(const claim_record& record, const std::string& file, const paper_source& document, const claims_document* declared) {
  const std::map<std::string, tex_macro> macros = defined_macros(document.text);
  std::set<std::string> names, positive;
  if (declared) {
    names = declared_names(*declared);
    for (const std::string& tex : declared->positive) positive.insert(symbol_named(tex).get_name());
  }
  const auto declared_only = [&](const ex& e, const std::string& field, int line) {
    if (!declared) return;
    for (const std::string& name : symbol_names(e)) {
      if (!names.count(name)) throw claims_file_error(file, line, field, "the symbol '" + name + "' is not declared in [symbols]");
    }
  };
  const proof_shape& shape = proof_shapes().at(record.shape);
  std::string principal;
  std::vector<definition> definitions;
  const auto where = record.with.find("where");
  if (where != record.with.end()) {
    for (const std::string& value : where->second.values) {
      try {
        definitions.push_back(read_definition(document, macros, value));
      } catch (const std::invalid_argument& e) {
        throw claims_file_error(file, where->second.line, "with.where", e.what());
      }
      names.insert(definitions.back().name.get_name());  // a defined symbol is declared by its definition
    }
  }
  std::map<std::string, unsigned> rows;  // of each matrix argument
  for (const shape_parameter& p : shape.parameters) {
    const auto it = record.with.find(p.name);
    if (it == record.with.end()) continue;
    const std::string field = "with." + p.name;
    const int line = it->second.line;
    try {
      switch (p.kind) {
        case argument_kind::formula:
        case argument_kind::matrix:
        case argument_kind::condition: {
          const referenced_formula f = read_reference(document, macros, it->second.values.front());
          declared_only(f.value, field, line);
          if (p.name == shape.principal) principal = "$" + folded_space(f.tex) + "$ (" + f.locator + ")";
          if (p.kind == argument_kind::matrix) {
            const ex m = with_definitions(f.value, definitions);
            if (!GiNaC::is_a<GiNaC::matrix>(m) || GiNaC::ex_to<GiNaC::matrix>(m).rows() != GiNaC::ex_to<GiNaC::matrix>(m).cols()) {
              throw claims_file_error(file, line, field, f.locator + " is not a square matrix");
            }
            rows[p.name] = GiNaC::ex_to<GiNaC::matrix>(m).rows();
            if (p.size != 0 && rows[p.name] != p.size) {
              throw claims_file_error(file, line, field, fmt::format("{} is {} x {}, not {} x {}", f.locator, rows[p.name], rows[p.name], p.size, p.size));
            }
          }
          if (p.kind == argument_kind::condition && f.sides.size() != 3) {
            throw claims_file_error(file, line, field, f.locator + " is not a condition 'a < x < b' (it has " + std::to_string(f.sides.size()) + " sides)");
          }
          if (p.positive && declared) {
            for (const std::string& name : symbol_names(f.value)) {
              if (!positive.count(name)) throw claims_file_error(file, line, field, "the symbol '" + name + "' is not declared positive in [symbols]");
            }
          }
          break;
        }
        case argument_kind::definitions: break;  // read above
        case argument_kind::word:
          if (!p.words.empty() && std::find(p.words.begin(), p.words.end(), it->second.values.front()) == p.words.end()) {
            throw claims_file_error(file, line, field, "'" + it->second.values.front() + "' is not one of: " + fmt::format("{}", fmt::join(p.words, ", ")));
          }
          break;
        case argument_kind::symbols: {
          for (const std::string& value : it->second.values) declared_only(symbol_named(value), field, line);
          if (p.size != 0 && it->second.values.size() != p.size) {
            throw claims_file_error(file, line, field, fmt::format("{} symbols, not {}", it->second.values.size(), p.size));
          }
          if (!p.same_size_as.empty() && rows.count(p.same_size_as) && it->second.values.size() != rows[p.same_size_as]) {
            throw claims_file_error(file, line, field, fmt::format("{} symbols for the {} rows of '{}'", it->second.values.size(),
                                                                   rows[p.same_size_as], p.same_size_as));
          }
          break;
        }
      }
    } catch (const claims_file_error&) {
      throw;
    } catch (const std::invalid_argument& e) {
      throw claims_file_error(file, line, field, e.what());
    }
  }
  return principal;
}

}  // namespace simpson::verify::detail

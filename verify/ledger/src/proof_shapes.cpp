// The proof shapes of claims files: see proof_shapes.hpp and docs/claims-file.md.

#include "proof_shapes.hpp"

#include "coq_export.hpp"
#include "kernel_zero.hpp"
#include "printed_check_support.hpp"

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
  // The printed condition: 0 < v < c.
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
  // v as one variable t: a symbol s of v with exponent 1 is t / (v / s).
  if (call.document) {
    std::set<std::string> positive;
    for (const std::string& tex : call.document->positive) positive.insert(symbol_named(tex).get_name());
    for (const std::string& name : symbol_names(v)) {
      if (!positive.count(name)) throw std::invalid_argument("the variable's symbol '" + name + "' is not declared positive in [symbols]");
    }
  }
  const GiNaC::symbol t("stability_variable");
  std::optional<ex> trace;
  for (const std::string& name : symbol_names(v)) {
    const GiNaC::symbol s = paper_symbols()[name];
    if (v.degree(s) != 1 || v.ldegree(s) != 1 || GiNaC::normal(v / s).has(s)) continue;
    trace = GiNaC::normal((m(0, 0) + m(1, 1)).subs(s == t / GiNaC::normal(v / s)));
    break;
  }
  const std::vector<std::string> left = trace ? symbol_names(*trace) : std::vector<std::string>{"?"};
  if (!trace || !(left.empty() || (left.size() == 1 && left.front() == t.get_name()))) {
    result.outcome = verdict::fails;
    result.note = "The trace of " + reference_of(call, "map") + " is not a function of " + text_of(v) + " alone.";
    return result;
  }
  const ex excess = GiNaC::normal(*trace * *trace - 4);  // < 0 exactly on the stable set
  polynomial numerator = as_polynomial(GiNaC::numer(excess), t), denominator = as_polynomial(GiNaC::denom(excess), t);
  const bool in_square = even(numerator) && even(denominator);  // roots in x = v², exact more often
  if (in_square) {
    numerator = even_in_theta_to_x(numerator);
    denominator = even_in_theta_to_x(denominator);
  }
  std::vector<positive_root> ends = positive_roots(numerator);
  for (const positive_root& pole : positive_roots(denominator)) ends.push_back(pole);
  std::sort(ends.begin(), ends.end(), [](const positive_root& a, const positive_root& b) { return a.low < b.low; });
  const auto sign_at = [&](const rational& x) {
    const rational value = numerator.evaluate(x) / denominator.evaluate(x);
    return value < 0 ? -1 : value > 0 ? 1 : 0;
  };
  const std::string var = text_of(v);
  const auto text = [&](const positive_root& r) { return in_square ? omega_h_text(r) : root_text(r); };
  // The stable bands: between consecutive ends, where trace² − 4 < 0 at a point inside.
  std::vector<std::string> bands;
  rational from = 0;
  std::string from_text = "0";
  for (std::size_t k = 0; k <= ends.size(); ++k) {
    const rational inside = k < ends.size() ? rational((from + ends[k].low) / 2) : rational(from + 1);
    if (sign_at(inside) < 0) bands.push_back(k < ends.size() ? fmt::format("{} < {} < {}", from_text, var, text(ends[k])) : fmt::format("{} > {}", var, from_text));
    if (k < ends.size()) {
      from = ends[k].high;
      from_text = text(ends[k]);
    }
  }
  const bool stable_near_zero = !ends.empty() && sign_at(ends.front().low / 2) < 0;
  // Is the printed c the first end? Exactly: c (or c² in x) is rational and equal to an exact root,
  // or a root of the numerator inside the first end's isolating interval.
  bool equal = false;
  std::string how;
  if (stable_near_zero) {
    const ex c = GiNaC::expand(in_square ? high * high : high);
    const positive_root& first = ends.front();
    if (GiNaC::is_a<GiNaC::numeric>(c) && GiNaC::ex_to<GiNaC::numeric>(c).is_rational()) {
      const polynomial as_rational = as_polynomial(c, t);
      const rational value = degree(as_rational) < 0 ? rational(0) : as_rational[0];
      equal = first.exact() ? value == first.low : (value >= first.low && value <= first.high && numerator.evaluate(value) == 0);
      how = fmt::format("{} = {} (exact)", in_square ? "c^2" : "c", value.str());
    } else {
      how = "c = " + text_of(high) + " is not rational" + std::string(in_square ? " in its square" : "") + ": not compared";
    }
  }
  result.evidence["exact"] = {
      {"statement", fmt::format("the stable set of ({}) in {} > 0 begins with 0 < {} < {}", reference_of(call, "map"), var, var, text_of(high))},
      {"det", "det = 1 (GiNaC normal form; our kernel: " + det_own.evidence + ")"},
      {"trace", text_of(trace->subs(t == v))},
      {"boundary_polynomial", to_string(numerator, in_square ? "x" : "t") + (in_square ? " (x = (" + var + ")^2)" : "")},
      {"stable_bands", bands},
      {"printed_end", how}};
  if (stable_near_zero && equal) {
    result.outcome = verdict::holds;
    return result;
  }
  result.outcome = verdict::erratum;
  result.correction = bands.empty() ? "never stable for " + var + " > 0" : "stable exactly for " + fmt::format("{}", fmt::join(bands, ", "));
  result.note = "As printed: " + folded_space(condition.tex) + " is not the first stable band of " + reference_of(call, "map") +
                " (trace = " + text_of(trace->subs(t == v)) + ", stable where |trace| < 2).";
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
         with_where({{"matrix", argument_kind::formula, true, "a square matrix"}, {"equals", argument_kind::formula, true, "its determinant"}}),
         determinant});
    add({"symplectic", "matrix^T J matrix = J, J = [[0, I], [-I, 0]]", "matrix",
         with_where({{"matrix", argument_kind::formula, true, "a one-step map of (q, p)"}}), symplectic});
    add({"conserved", "function(map y) = function(y), y the state", "function",
         with_where({{"map", argument_kind::formula, true, "a one-step map"},
                     {"function", argument_kind::formula, true, "a function of the state"},
                     {"state", argument_kind::symbols, true, "the state's symbols, in the map's order"}}),
         conserved});
    add({"euler-lagrange", "printed = 0 is D_2 L(q_{j-1}, q_j) + D_1 L(q_j, q_{j+1}) = 0, up to a factor free of the states", "printed",
         with_where({{"lagrangian", argument_kind::formula, true, "the discrete Lagrangian L(q_0, q_1)"},
                     {"nodes", argument_kind::symbols, true, "its two arguments"},
                     {"sequence", argument_kind::symbols, true, "three consecutive states"},
                     {"printed", argument_kind::formula, true, "the printed equation's side that is 0"}}),
         euler_lagrange});
    add({"stability-interval", "the printed 0 < variable < c is the first band where the map (det 1) is power-bounded", "condition",
         with_where({{"map", argument_kind::formula, true, "a 2 x 2 one-step map with det 1"},
                     {"variable", argument_kind::formula, true, "the variable of the condition, a product of positive symbols"},
                     {"condition", argument_kind::formula, true, "the printed condition 0 < variable < c"}}),
         stability_interval});
    return all;
  }();
  return shapes;
}

void check_shape_arguments(const claim_record& record, const std::string& file) {
  const proof_shape& shape = proof_shapes().at(record.shape);
  for (const auto& [name, argument] : record.with) {
    const auto it = std::find_if(shape.parameters.begin(), shape.parameters.end(), [&](const shape_parameter& p) { return p.name == name; });
    if (it == shape.parameters.end()) {
      std::string names;
      for (const shape_parameter& p : shape.parameters) names += (names.empty() ? "" : ", ") + p.name;
      throw claims_file_error(file, argument.line, "with." + name, "not an argument of the shape '" + shape.name + "' (" + names + ")");
    }
    const bool list = it->kind != argument_kind::formula;
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
  std::set<std::string> names;
  if (declared) names = declared_names(*declared);
  const auto declared_only = [&](const ex& e, const std::string& field, int line) {
    if (!declared) return;
    for (const std::string& name : symbol_names(e)) {
      if (!names.count(name)) throw claims_file_error(file, line, field, "the symbol '" + name + "' is not declared in [symbols]");
    }
  };
  const proof_shape& shape = proof_shapes().at(record.shape);
  std::string principal;
  const auto where = record.with.find("where");
  if (where != record.with.end() && declared) {
    for (const std::string& value : where->second.values) {
      try {
        names.insert(read_definition(document, macros, value).name.get_name());
      } catch (const std::invalid_argument& e) {
        throw claims_file_error(file, where->second.line, "with.where", e.what());
      }
    }
  }
  for (const shape_parameter& p : shape.parameters) {
    const auto it = record.with.find(p.name);
    if (it == record.with.end()) continue;
    const std::string field = "with." + p.name;
    for (const std::string& value : it->second.values) {
      try {
        switch (p.kind) {
          case argument_kind::formula: {
            const referenced_formula f = read_reference(document, macros, value);
            declared_only(f.value, field, it->second.line);
            if (p.name == shape.principal) principal = "$" + folded_space(f.tex) + "$ (" + f.locator + ")";
            break;
          }
          case argument_kind::definitions: declared_only(read_definition(document, macros, value).value, field, it->second.line); break;
          case argument_kind::symbols: declared_only(symbol_named(value), field, it->second.line); break;
        }
      } catch (const std::invalid_argument& e) {
        if (dynamic_cast<const claims_file_error*>(&e)) throw;
        throw claims_file_error(file, it->second.line, field, e.what());
      }
    }
  }
  return principal;
}

}  // namespace simpson::verify::detail

// What the proof shapes share: see shape_support.hpp.

#include "shape_support.hpp"

#include "coq_export.hpp"
#include "kernel_zero.hpp"
#include "printed_check_support.hpp"

#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/quoted_words.hpp>
#include <simpson/verify/tex_math.hpp>

namespace simpson::verify::detail {

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

shape_reader::shape_reader(const shape_call& call, const paper_source& document)
    : call_(call), document_(document), macros_(defined_macros(document.text)) {
  if (call.document) declared_ = declared_names(*call.document);
  const auto where = call.with.find("where");
  if (where == call.with.end()) return;
  for (const std::string& reference : where->second.values) {
    definitions_.push_back(read_definition(document_, macros_, reference));
    const definition& d = definitions_.back();
    definitions_read_.push_back({{"reference", reference},
                                 {"label", d.locator + ", put in"},
                                 {"line", d.line},
                                 {"tex", folded_space(d.tex)},
                                 {"parsed", json::array({text_of(d.name) + " = " + text_of(d.value)})}});
  }
  // A symbol a definition defines is declared by it (Phi = (map)); what it is defined as must be declared.
  for (const definition& d : definitions_) declared_.insert(d.name.get_name());
  for (const definition& d : definitions_) declared_only(d.value, d.locator);
}

ex shape_reader::formula(const std::string& parameter) {
  const referenced_formula f = raw(parameter);
  return with_definitions(f.value, definitions_);
}

referenced_formula shape_reader::raw(const std::string& parameter) {
  const std::string& reference = call_.with.at(parameter).values.front();
  referenced_formula f = read_reference(document_, macros_, reference);
  declared_only(f.value, f.locator);
  // Shown with its matrix products multiplied out (1/(1 + x) times a matrix, as printed), unless a
  // definition is still to make one of its symbols a matrix.
  GiNaC::ex shown = f.value;
  if (definitions_.empty()) {
    try {
      shown = with_definitions(f.value, {});
    } catch (const std::exception&) {
    }
  }
  record(reference, f.place, f.line, f.tex, shown);
  return f;
}

std::vector<GiNaC::symbol> shape_reader::symbols(const std::string& parameter) const {
  std::vector<GiNaC::symbol> out;
  for (const std::string& tex : call_.with.at(parameter).values) {
    out.push_back(symbol_named(tex));
    declared_only(out.back(), "'" + tex + "'");
  }
  return out;
}

json shape_reader::printed() const {
  json all = read_;
  for (const json& d : definitions_read_) all.push_back(d);
  return {{"source", document_.origin}, {"formulas", all}};
}

void shape_reader::declared_only(const ex& e, const std::string& where) const {
  if (!call_.document) return;
  for (const std::string& name : symbol_names(e)) {
    if (!declared_.count(name)) throw std::invalid_argument(where + ": the symbol '" + name + "' is not declared in [symbols]");
  }
}

void shape_reader::record(const std::string& reference, const std::string& locator, int line, const std::string& tex,
                          const std::optional<ex>& value) {
  if (line < 1) return;  // the record's own TeX ('$\omega h$'): not read from the document
  json entry = {{"reference", reference}, {"label", locator}, {"line", line}};
  if (!tex.empty()) entry["tex"] = folded_space(tex);
  if (value) entry["parsed"] = json::array({text_of(*value)});
  for (const json& seen : read_) {
    if (seen == entry) return;
  }
  read_.push_back(entry);
}

const paper_source& document_of(const run_context& ctx) {
  // The run's paper, or the embedded one when the run has none (a note's run always has one: its
  // claims file's [document] requires --paper).
  return paper_of(ctx).source;
}

claim_result identity_verdict(const shape_call& call, shape_reader& read, const std::string& goal, const std::string& what, const ex& lhs, const ex& rhs,
                              const std::string& correction, verdict when_false, const std::optional<kernel_decision>& given) {
  claim_result result;
  const ex difference = normal_difference(lhs, rhs);
  const bool ginac_zero = is_zero_expression(difference);
  const kernel_decision own = given ? *given : kernel_decides_zero((lhs - rhs).evalm());
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
  record_certificate(result, coq_certificate(call.claim_id, call.statement, {decided(goal, lhs, rhs)}));
  return result;
}

GiNaC::matrix as_square_matrix(const ex& e, const std::string& what) {
  const ex m = e.evalm();
  if (!GiNaC::is_a<GiNaC::matrix>(m)) throw std::invalid_argument(what + " is not a matrix");
  const GiNaC::matrix& out = GiNaC::ex_to<GiNaC::matrix>(m);
  if (out.rows() != out.cols()) throw std::invalid_argument(what + " is not square");
  return out;
}

std::optional<three_term_coefficients> linear_three_term(const ex& scheme, const std::vector<GiNaC::symbol>& q) {
  const three_term_coefficients c{GiNaC::diff(scheme, q[0]), GiNaC::diff(scheme, q[1]), GiNaC::diff(scheme, q[2])};
  if (!GiNaC::normal(scheme - (c.previous * q[0] + c.current * q[1] + c.next * q[2])).is_zero()) return std::nullopt;
  for (const GiNaC::symbol& state : q) {
    for (const ex& coefficient : {c.previous, c.current, c.next}) {
      if (GiNaC::normal(coefficient).has(state)) return std::nullopt;
    }
  }
  return c;
}

bool reversible(const three_term_coefficients& terms, kernel_decision& own) {
  own = kernel_decides_zero(terms.next - terms.previous);
  return GiNaC::normal(terms.next - terms.previous).is_zero() && own.outcome != kernel_decision::result::nonzero;
}

ex monic_discriminant(const three_term_coefficients& terms) {
  return GiNaC::normal((terms.current * terms.current - 4 * terms.previous * terms.next) / (terms.next * terms.next));
}

std::string reference_of(const shape_call& call, const std::string& parameter) { return call.with.at(parameter).values.front(); }

}  // namespace simpson::verify::detail

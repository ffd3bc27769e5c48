// Our core bound to the print (core_bindings.hpp): a record's bindings read, instantiated
// (core_formulas.hpp) and decided in both kernels.

#include "core_bindings.hpp"

#include <simpson/verify/formula_reference.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/tex_math.hpp>

#include <simpson/prove/kernel_zero.hpp>
#include "derivation_support.hpp"
#include <simpson/shapes/shape_support.hpp>

#include <fmt/format.h>

#include <stdexcept>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

/// A binding read: the printed formula (definitions put in), the core's value (the same definitions
/// put in), and where the printed one is.
struct bound_pair {
  ex printed, core;
  referenced_formula read;
};

bound_pair read_binding(const core_binding& b, const shape_call& record_call, const tex_document& document) {
  const core_formula* formula = find_core_formula(b.function);
  if (!formula) throw std::logic_error("read_binding: no core formula '" + b.function + "' (checked when the file was read)");
  if (b.variables.size() != formula->variables.size()) {
    throw argument_error("variables", fmt::format("the core's {} takes {} variable(s) ({}); {} given", b.function, formula->variables.size(),
                                                  fmt::join(formula->variables, ", "), b.variables.size()));
  }
  // The record's own `where` (the definitions it reads) with the binding's formula and symbols.
  shape_call call{record_call.claim_id, record_call.statement, {}, record_call.declared, record_call.corrections};
  if (const auto where = record_call.with.find("where"); where != record_call.with.end()) call.with.emplace("where", where->second);
  call.with.emplace("formula", shape_argument{{b.formula}, false, b.line});
  call.with.emplace("variables", shape_argument{b.variables, true, b.line});
  call.with.emplace("parameters", shape_argument{b.parameters, true, b.line});
  shape_reader read(call, document);
  bound_pair out;
  out.read = read.raw("formula");
  out.printed = read.formula("formula").evalm();
  const std::vector<GiNaC::symbol> parameters = read.symbols("parameters");
  const std::vector<GiNaC::symbol> variables = read.symbols("variables");
  core_arguments a{parameters[0], parameters[1], parameters[2], {variables.begin(), variables.end()}, {}, {}};
  const std::string potential = b.potential;
  a.potential = [potential](const ex& x) { return apply_function(potential, {x}); };
  a.force_gradient = [potential](const ex& x) {
    const GiNaC::symbol t("core_binding_t");
    return GiNaC::diff(apply_function(potential, {ex(t)}), t).subs(t == x);
  };
  out.core = read.defined(formula->value(a)).evalm();
  return out;
}

/// "(1, 2): ..." for each entry where core − printed is not zero in normal form.
std::vector<std::string> differing_entries(const ex& core, const ex& printed) {
  std::vector<std::string> out;
  if (GiNaC::is_a<GiNaC::matrix>(core) && GiNaC::is_a<GiNaC::matrix>(printed)) {
    const GiNaC::matrix& c = GiNaC::ex_to<GiNaC::matrix>(core);
    const GiNaC::matrix& p = GiNaC::ex_to<GiNaC::matrix>(printed);
    for (unsigned i = 0; i < c.rows(); ++i) {
      for (unsigned j = 0; j < c.cols(); ++j) {
        if (GiNaC::normal(c(i, j) - p(i, j)).is_zero()) continue;
        out.push_back(fmt::format("entry ({}, {}): printed {}, the core {}", i + 1, j + 1, text_of(GiNaC::normal(p(i, j))), text_of(GiNaC::normal(c(i, j)))));
      }
    }
    return out;
  }
  if (!GiNaC::normal(core - printed).is_zero()) {
    out.push_back(fmt::format("printed {}, the core {}", text_of(GiNaC::normal(printed)), text_of(GiNaC::normal(core))));
  }
  return out;
}

/// core − printed as our kernel is to see it: the printed side's symbols replaced by twins (the
/// same names, other GiNaC symbols), so that GiNaC, which builds a sum by collecting like terms,
/// cannot cancel the two trees before our kernel evaluates them. Our kernel knows a symbol by its
/// name: the twins are the same variable there.
ex kernel_difference(const ex& core, const ex& printed) {
  GiNaC::exmap twins;
  for (GiNaC::const_preorder_iterator it = printed.preorder_begin(); it != printed.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::symbol>(*it) && !twins.count(*it)) twins.emplace(*it, GiNaC::symbol(GiNaC::ex_to<GiNaC::symbol>(*it).get_name()));
  }
  return (core - printed.subs(twins)).evalm();
}

bool same_shape(const ex& a, const ex& b) {
  const bool am = GiNaC::is_a<GiNaC::matrix>(a), bm = GiNaC::is_a<GiNaC::matrix>(b);
  if (am != bm) return false;
  if (!am) return true;
  const GiNaC::matrix &x = GiNaC::ex_to<GiNaC::matrix>(a), &y = GiNaC::ex_to<GiNaC::matrix>(b);
  return x.rows() == y.rows() && x.cols() == y.cols();
}

}  // namespace

void check_core_bindings(const claim_record& record, const std::string& file, const tex_document& document,
                         const claim_declarations& declared) {
  const shape_call call{record.id, record.statement, record.with, std::make_shared<const claim_declarations>(declared)};
  for (const core_binding& b : record.core) {
    bound_pair pair;
    try {
      pair = read_binding(b, call, document);
    } catch (const document_error&) {
      throw;
    } catch (const argument_error& e) {
      throw claims_file_error(file, b.line, e.argument == "formula" ? "core.formula" : "core." + e.argument, e.what());
    } catch (const std::invalid_argument& e) {
      throw claims_file_error(file, b.line, "core", e.what());
    } catch (const std::domain_error& e) {
      throw claims_file_error(file, b.line, "core", e.what());
    }
    if (!same_shape(pair.core, pair.printed)) {
      throw claims_file_error(file, b.line, "core.formula",
                              fmt::format("{} is {} and the core's {} {}", pair.read.locator, GiNaC::is_a<GiNaC::matrix>(pair.printed) ? "a matrix" : "not a matrix",
                                          b.function, GiNaC::is_a<GiNaC::matrix>(pair.core) ? "a matrix of another size" : "a scalar"));
    }
  }
}

decider_evidence bound_to_core(decider_evidence e, const std::vector<core_binding>& bindings, const shape_call& call, const run_context& ctx) {
  if (bindings.empty()) return e;
  claim_result& result = e.found;
  const bool refuted = refutes_the_print(e);  // the claim's own evidence, before the bindings
  json evidence = json::array();
  std::vector<std::string> differ;
  bool own_refutes = false;
  for (const core_binding& b : bindings) {
    bound_pair pair = read_binding(b, call, document_of(ctx));
    // A formula this claim proves wrong, with its correction: the core is compared with the correction.
    std::string against = "as printed";
    for (const auto& corrected : result.corrected_formulas) {
      if (corrected->identity != pair.read.identity) continue;
      pair.printed = corrected->value.evalm();
      against = "as corrected by this claim";
    }
    const std::vector<std::string> entries = differing_entries(pair.core, pair.printed);
    if (against == "as printed" && refuted && !entries.empty()) {
      // The claim proves the printed formula wrong but gives no formula to stand in its place: the
      // core cannot be compared with what should be printed, and that is said, not counted.
      evidence.push_back({{"core", b.function},
                          {"formula", pair.read.locator},
                          {"line", pair.read.line},
                          {"not_compared", "this claim proves the printed formula wrong and gives no formula to stand in its place"}});
      continue;
    }
    const kernel_decision own = kernel_decides_zero(kernel_difference(pair.core, pair.printed));
    const bool ginac_zero = entries.empty();
    json row = {{"core", b.function},
                {"formula", pair.read.locator + ", " + against},
                {"line", pair.read.line},
                {"ginac", ginac_zero ? "core − formula = 0 in normal form" : "core − formula ≠ 0 in normal form"},
                {"own_kernel", own.evidence}};
    if (own.outcome != kernel_decision::result::not_applicable && ginac_zero != (own.outcome == kernel_decision::result::zero)) {
      row["agrees"] = false;
      evidence.push_back(row);
      result.evidence["core_bound"] = evidence;
      e.parts_differ = true;
      e.disagreement = kernels_differ_on(fmt::format("the core's {} against {}", b.function, pair.read.locator));
      return e;
    }
    own_refutes = own_refutes || own.outcome == kernel_decision::result::nonzero;
    row["agrees"] = ginac_zero;
    if (!ginac_zero) {
      row["differs"] = entries;
      differ.push_back(fmt::format("the core's {} is not {} {} ({})", b.function, pair.read.locator, against, fmt::join(entries, "; ")));
    }
    evidence.push_back(row);
  }
  result.evidence["core_bound"] = evidence;
  if (!differ.empty()) {
    // Code and print differ: decide's rule (a verdict that says so, fails), the differences named.
    e = code_differs_from_print(std::move(e), own_refutes,
                                fmt::format("Our code and the print disagree: {}. One of them is wrong (a changed core formula, or a changed "
                                            "printed one). ",
                                            fmt::join(differ, "; ")));
  }
  return e;
}

}  // namespace simpson::verify::detail

namespace simpson::verify {

std::string core_formulas_markdown(const claim_book& book) {
  std::string out = "| core formula | implements | variables, in order | what it is | bound by |\n|---|---|---|---|---|\n";
  for (const detail::core_formula& f : detail::core_formulas()) {
    std::vector<std::string> by;
    for (const claim_record& r : book.records) {
      for (const core_binding& b : r.core) {
        if (b.function == f.name) by.push_back("`" + r.id + "`");
      }
    }
    const bool label = f.implements.find(' ') == std::string::npos;
    out += fmt::format("| `{}` | {} | {} | {} | {} |\n", f.name, label ? "(" + f.implements + ")" : f.implements, f.variables.empty() ? "none" : fmt::format("{}", fmt::join(f.variables, ", ")),
                       f.summary, by.empty() ? "none" : fmt::format("{}", fmt::join(by, ", ")));
  }
  return out;
}

}  // namespace simpson::verify

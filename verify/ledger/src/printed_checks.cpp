#include <simpson/verify/printed_checks.hpp>
#include <simpson/verify/enclosure_decision.hpp>
#include <simpson/verify/ledger.hpp>

#include "coq_export.hpp"
#include "check_registry.hpp"
#include "printed_check_support.hpp"
#include "proof_shapes.hpp"

#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/quoted_words.hpp>

#include <algorithm>
#include <chrono>

namespace simpson::verify {
namespace detail {

using GiNaC::ex;

std::string text_of(const ex& e) { return canonical_text(e); }

ex sym(const std::string& name) { return paper_symbols()[name]; }

oscillator_parameters<ex> parameters(const symbolic_derivation& d) { return {d.m, d.omega, d.h}; }


ex with_gear(const ex& e, const symbolic_derivation& d) {
  return e.subs(GiNaC::lst{sym("g_l") == d.g_l, sym("g_m") == d.g_m, sym("g_r") == d.g_r});
}

namespace {

/// Each function application's arguments in their expanded normal form, inside out: GiNaC's normal
/// form takes V(q (q + 1)) and V(q^2 + q) for two unknowns unless their arguments are one expression.
struct canonical_arguments : GiNaC::map_function {
  ex operator()(const ex& e) override {
    if (!GiNaC::is_a<GiNaC::function>(e)) return e.map(*this);
    ex out = e;
    for (std::size_t k = 0; k < e.nops(); ++k) {
      const ex argument = (*this)(e.op(k));
      const ex normal = GiNaC::normal(argument);
      out.let_op(k) = GiNaC::expand(GiNaC::numer(normal)) / GiNaC::expand(GiNaC::denom(normal));
    }
    return out;
  }
};

/// GiNaC's normal form, function arguments first made canonical.
ex normal_form(const ex& e) {
  canonical_arguments canonical;
  return GiNaC::normal(canonical(e));
}

}  // namespace

ex normal_difference(const ex& a, const ex& b) {
  const ex difference = (a - b).evalm();
  if (!GiNaC::is_a<GiNaC::matrix>(difference)) return normal_form(difference);
  GiNaC::matrix m = GiNaC::ex_to<GiNaC::matrix>(difference);
  for (unsigned r = 0; r < m.rows(); ++r) {
    for (unsigned c = 0; c < m.cols(); ++c) m(r, c) = normal_form(m(r, c));
  }
  return m;
}

bool is_zero_expression(const ex& e) {
  if (!GiNaC::is_a<GiNaC::matrix>(e)) return normal_form(e).is_zero();
  const GiNaC::matrix& m = GiNaC::ex_to<GiNaC::matrix>(e);
  for (unsigned r = 0; r < m.rows(); ++r) {
    for (unsigned c = 0; c < m.cols(); ++c) {
      if (!normal_form(m(r, c)).is_zero()) return false;
    }
  }
  return true;
}

const ex& printed_side(const paper_reading& r, const std::string& name, std::size_t side) { return r.at(name).sides.at(side); }

bool kernels_disagree_if(claim_result& result, bool disagree, const std::string& why) {
  if (!disagree) return false;
  result.outcome = verdict::kernels_disagree;
  result.note = why;
  return true;
}

std::string kernels_differ_on(const std::string& what) {
  return "GiNaC and our kernel reached different conclusions on " + what + ": a bug in one of them.";
}

proof_goal decided(const std::string& name, const ex& lhs, const ex& rhs) {
  return {name, lhs, rhs, is_zero_expression(normal_difference(lhs, rhs))};
}

void add_goal(printed_outcome& o, const proof_goal& g, bool about_printed) {
  o.goals.push_back(g);
  if (about_printed) {
    o.holds = o.holds && g.holds;
  } else {
    o.derived_holds = o.derived_holds && g.holds;
  }
}

ex determinant_2x2(const ex& e) {
  const GiNaC::matrix& M = GiNaC::ex_to<GiNaC::matrix>(e);
  return M(0, 0) * M(1, 1) - M(0, 1) * M(1, 0);
}

ex after_step(const ex& H, const ex& phi, const ex& p, const ex& q) {
  const GiNaC::matrix& M = GiNaC::ex_to<GiNaC::matrix>(phi);
  return H.subs(GiNaC::lst{p == M(0, 0) * p + M(0, 1) * q, q == M(1, 0) * p + M(1, 1) * q});
}

void compare_core(printed_outcome& o, const std::string& what, const ex& derived, const ex& core) {
  const ex d = normal_difference(core, derived);
  o.derived_holds = is_zero_expression(d);
  o.goals.push_back({"core", core, derived, o.derived_holds});
  o.derived = o.derived_holds ? "core " + what + " − derived = 0 (normal form, all symbols free)"
                              : "core " + what + " − derived = " + text_of(d) + " ≠ 0";
}

printed_outcome compare(const std::string& what, const ex& printed, const ex& derived, const ex& core) {
  printed_outcome o;
  const ex d = normal_difference(printed, derived);
  o.holds = is_zero_expression(d);
  o.goals.push_back({"printed", printed, derived, o.holds});
  o.proved = o.holds ? "printed " + what + " − derived = 0 (normal form, all symbols free)"
                     : "printed " + what + " − derived = " + text_of(d) + " ≠ 0";
  if (!o.holds) o.correction = "as derived: " + what + " = " + text_of(derived);
  compare_core(o, what, derived, core);
  return o;
}

std::optional<ex> equation_factor(const ex& e1, const ex& e2, const std::vector<ex>& unknowns) {
  if (GiNaC::normal(e1).is_zero() || GiNaC::normal(e2).is_zero()) return std::nullopt;
  const ex ratio = GiNaC::normal(e2 / e1);
  for (const ex& x : unknowns) {
    if (!GiNaC::normal(ratio.diff(GiNaC::ex_to<GiNaC::symbol>(x))).is_zero()) return std::nullopt;
  }
  return ratio;
}

printed_outcome both(const printed_outcome& a, const printed_outcome& b) {
  printed_outcome o;
  o.holds = a.holds && b.holds;
  o.property = (!a.holds && a.property) || (!b.holds && b.property);
  o.proved = a.proved + "; " + b.proved;
  o.correction = a.correction.empty() ? b.correction : b.correction.empty() ? a.correction : a.correction + "; " + b.correction;
  o.derived_holds = a.derived_holds && b.derived_holds;
  o.derived = a.derived.empty() ? b.derived : b.derived.empty() ? a.derived : a.derived + "; " + b.derived;
  o.goals = a.goals;
  o.goals.insert(o.goals.end(), b.goals.begin(), b.goals.end());
  return o;
}

smooth_expansion expand_on_smooth(const ex& e, const std::vector<smooth_state>& states, const ex& h, int order) {
  const GiNaC::symbol t("t_smooth");
  GiNaC::exmap on_solution;
  std::vector<std::string> functions;
  for (const smooth_state& s : states) {
    on_solution[s.state] = apply_function(s.function, {t + s.shift});
    if (std::find(functions.begin(), functions.end(), s.function) == functions.end()) functions.push_back(s.function);
  }
  const auto rename = [&](ex x) {
    for (const std::string& f : functions) {
      for (int k = 8; k >= 1; --k) {
        x = x.subs(GiNaC::diff(apply_function(f, {t}), t, static_cast<unsigned>(k)) == paper_symbols()[derivative_name(f, "t", k, k)]);
      }
      x = x.subs(apply_function(f, {t}) == paper_symbols()[f]);
    }
    return x;
  };
  const GiNaC::symbol& hs = GiNaC::ex_to<GiNaC::symbol>(h);
  // A Laurent series (at most h^-2 in the paper's schemes), up to O(h^order).
  const ex series = GiNaC::expand(GiNaC::series_to_poly(GiNaC::series(e.subs(on_solution), h == 0, order)));
  smooth_expansion out;
  out.lowest_power = series.ldegree(hs);
  out.leading = GiNaC::normal(rename(series.coeff(hs, out.lowest_power)));
  out.series = rename(series);
  return out;
}

}  // namespace detail

namespace {

using detail::printed_outcome;

/// The registered check that decides `c`, with its facets; null for a claim a proof shape decides.
const detail::registered_check* bespoke_check(const claim& c) { return detail::registered_checks().find(c.check_name); }

/// The GiNaC check of the printed formulas `c` reads; null when it reads none.
const detail::registered_check* printed_facet(const claim& c) {
  const detail::registered_check* check = bespoke_check(c);
  return check != nullptr && check->printed ? check : nullptr;
}

/// Two pieces of prose as sentences: a full stop after the first unless it has one.
std::string then(const std::string& first, const std::string& second) {
  if (second.empty()) return first;
  if (first.empty()) return second;
  const char last = first.back();
  return first + (last == '.' || last == ':' || last == ';' ? " " : ". ") + second;
}

/// The verdict from the two kernels. Each proves the derived statement (ours on our
/// transcription, in θ with the grid lemma; GiNaC from first principles, every symbol free); they
/// must agree, or the verdict is kernels-disagree. When they agree that it holds, the printed side
/// decides: holds, erratum (the derived formula is the correction) or fails (a printed property).
void decide(claim_result& result, const printed_outcome& g, const std::string& claim_id) {
  const bool own_derived = result.outcome != verdict::fails;
  const verdict own = result.outcome;
  // An erratum of the quoted words (a claim that reads a formula and also judges prose about it)
  // stands whatever the printed formula: the words, not the transcription, were refuted.
  const bool words_refuted = own == verdict::erratum && !result.quoted.empty();
  if (detail::kernels_disagree_if(result, own_derived != g.derived_holds,
                          "The two kernels disagree on '" + claim_id + "': ours " + (own_derived ? "proved" : "did not prove") +
                              " the derived statement, GiNaC " + (g.derived_holds ? "proved" : "did not prove") + " it (" + g.derived + ")." +
                              (result.note.empty() ? "" : " " + result.note))) {
    return;
  }
  if (!g.derived_holds) {
    result.outcome = verdict::fails;
    return;
  }
  if (g.holds && words_refuted) {
    result.note = then("The printed formula holds (" + g.proved + "); the quoted words do not.", result.note);
    return;
  }
  if (g.holds) {
    result.outcome = verdict::holds;
    if (own == verdict::erratum) {
      result.note = "This copy of the paper prints the derived formula: " + g.proved +
                    ". (Our kernel's transcription of the printed formula, typed from the GSI 2023 text, is the erratum it refutes.)";
      result.correction.clear();
    }
    return;
  }
  result.outcome = g.property || g.correction.empty() ? verdict::fails : verdict::erratum;
  if (result.outcome == verdict::erratum && own != verdict::erratum) result.correction = g.correction;
  result.note = then((own == verdict::erratum ? "As printed: " : "The formula as printed in the paper's source differs from the derived one: ") +
                         g.proved,
                     result.note);
}


}  // namespace

namespace {

/// A claim a proof shape decides: it reads every formula from the run's document, when its shape
/// judges a formula (a principal argument; the prose's shapes, spelling and citations, read none).
bool decided_by_shape(const claim& c) {
  if (c.check_name.rfind("shape ", 0) != 0) return false;
  const auto shape = detail::proof_shapes().find(c.check_name.substr(6));
  return shape == detail::proof_shapes().end() || !shape->second.principal.empty();
}

bool reads_printed(const claim& c) { return printed_facet(c) != nullptr || decided_by_shape(c); }

}  // namespace

bool reads_printed_formula(const claim& c) { return reads_printed(c); }

std::vector<std::string> claims_reading_formula(const std::vector<claim>& claims, const std::string& label) {
  std::vector<std::string> ids;
  for (const claim& c : claims) {
    const detail::registered_check* check = printed_facet(c);
    std::vector<std::string> names = check != nullptr ? check->formulas : std::vector<std::string>{};
    names.insert(names.end(), c.labels_read.begin(), c.labels_read.end());
    for (const std::string& name : names) {
      if (name == label || name.rfind(label + "#", 0) == 0) {
        ids.push_back(c.id);
        break;
      }
    }
  }
  return ids;
}

double ginac_derivation_seconds() { return detail::derivation().seconds; }

std::size_t printed_formula_claim_count(const std::vector<claim>& claims) {
  std::size_t count = 0;
  for (const claim& c : claims) count += reads_printed(c) ? 1 : 0;
  return count;
}

namespace {

/// The claim's own check, with the sentences it quotes recorded; a sentence gone or words that no
/// longer parse make the verdict text-changed, the check's other findings dropped.
claim_result checked_with_quotes(const claim& c, const run_context& ctx) {
  json quotes = json::array();
  run_context quoting = ctx;
  quoting.quotes = &quotes;
  claim_result result;
  try {
    result = c.check(quoting);
  } catch (const enclosure_undecided& e) {
    result = claim_result{};
    result.outcome = verdict::undecided;
    result.evidence["undecided"] = e.what();
    result.note = std::string("No enclosure decided this claim within the run's digits: ") + e.what() +
                  ". Raise --enclosure-budget, or find why the enclosure is wide.";
  } catch (const text_changed& e) {
    result = claim_result{};
    result.outcome = verdict::text_changed;
    result.evidence["text_changed"] = e.what();
    result.note = std::string("The words this claim quotes did not read: ") + e.what() +
                  ". Its check judges only words it reads: a new wording is judged once the claim's sentence pattern matches it "
                  "(docs/claims-file.md, sentence patterns).";
  }
  result.quoted = std::move(quotes);
  return result;
}

}  // namespace

claim_result check_claim(const claim& c, const run_context& ctx) {
  claim_result result = checked_with_quotes(c, ctx);
  if (result.outcome == verdict::text_changed || result.outcome == verdict::undecided) return result;
  const detail::registered_check* facet = printed_facet(c);
  if (facet == nullptr) {
    // The check wrote its own, or why there is none (the floating claims: Gappa's and the lifting
    // lemma; the proof shapes of claims files).
    if (!result.certificate.empty() || !result.certificate_missing.empty()) return result;
    const detail::registered_check* check = bespoke_check(c);
    if (check == nullptr || !check->coq_goals) {
      result.certificate_missing = detail::without_coq_statement(c, "its exact proof is our kernel's alone: no Coq statement yet");
      return result;
    }
    detail::record_certificate(result, detail::coq_certificate(c.id, c.statement, check->coq_goals()));
    return result;
  }
  if (!ctx.paper) {
    result.certificate_missing = "the run has no paper to read the printed formula from";
    return result;
  }
  const paper_reading& reading = *ctx.paper;
  const auto start = std::chrono::steady_clock::now();
  const printed_outcome outcome = facet->printed(reading);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  json printed = json::array();
  for (const std::string& name : facet->formulas) {
    const printed_formula& f = reading.at(name);
    json parsed = json::array();
    for (const GiNaC::ex& side : f.sides) parsed.push_back(detail::text_of(side));
    printed.push_back({{"label", f.source.locator}, {"line", f.source.line}, {"tex", folded_space(f.tex)},
                       {"parsed", parsed}});
  }
  result.printed = {{"source", reading.origin}, {"formulas", printed}};
  // What the claim's own check did, in its words when it says (evidence "exact"'s method).
  const bool says = result.evidence.contains("exact") && result.evidence["exact"].is_object() && result.evidence["exact"].contains("method");
  const std::string own_statement = says ? "the claim's check above: " + result.evidence["exact"]["method"].get<std::string>()
                                         : "the claim's check above: our transcription, rational functions of theta with the grid lemma";
  result.evidence["kernels"] = {
      {"own", {{"statement", own_statement},
               {"derived_holds", result.outcome != verdict::fails}}},
      {"ginac", {{"printed", outcome.proved}, {"printed_holds", outcome.holds}, {"derived", outcome.derived},
                 {"derived_holds", outcome.derived_holds}}}};
  result.printed_seconds = seconds;
  decide(result, outcome, c.id);
  detail::coq_export certificate = detail::coq_certificate(c.id, c.statement, outcome.goals);
  if (outcome.goals.empty()) certificate.not_exported = detail::without_coq_statement(c, certificate.not_exported);
  detail::record_certificate(result, certificate);
  return result;
}

}  // namespace simpson::verify

// The invariance shape on a printed form (shape_support.hpp): once the printed conditions are put in,
// the printed form's coefficients span the kernel of the printed system, as Section 7 of the paper
// derives its conserved form (invariance-kernel). The system and its determinant and singularity:
// shapes_invariance.cpp; what they share: invariance_support.hpp.

#include "invariance_support.hpp"

#include <simpson/shapes/shape_support.hpp>

#include <simpson/prove/coq_export.hpp>
#include <simpson/prove/printed_check_support.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace invariance {
namespace {

/// The printed form's coefficients, solved from form = printed in every monomial of the state, with
/// the conditions put in (v, and "u = value" for each unknown); `wrong` says why there are none when
/// the printed form is not the form for one value of its coefficients.
struct form_coefficients {
  std::vector<ex> v;
  std::vector<std::string> text;
  std::string wrong;
};

form_coefficients printed_form_coefficients(const shape_call& call, const printed_system& p, const ex& printed_form) {
  const invariance_rows& d = p.d;
  const std::vector<GiNaC::symbol>& state = p.state;
  const std::vector<GiNaC::symbol>& unknowns = p.unknowns;
  const std::string printed_ref = reference_of(call, "printed");
  // The printed form's coefficients: form = printed in every monomial of the state.
  GiNaC::lst equations, names;
  const ex difference = GiNaC::expand(GiNaC::normal(p.form - printed_form));
  ex rest = difference;  // what no monomial y_i y_j holds: a form has nothing else
  for (const ex& monomial : d.monomials) {
    ex coefficient = difference;
    for (const GiNaC::symbol& s : state) coefficient = coefficient.coeff(s, monomial.degree(s));
    equations.append(coefficient == 0);
    rest -= monomial * coefficient;
  }
  for (const GiNaC::symbol& u : unknowns) names.append(u);
  ex coefficients = GiNaC::lst{};
  try {
    coefficients = GiNaC::lsolve(equations, names);
  } catch (const std::exception&) {  // the form is not linear in its coefficients: no one value
  }
  const bool determined = coefficients.nops() == unknowns.size() &&
                          std::none_of(coefficients.begin(), coefficients.end(), [&](const ex& r) {
                            return std::any_of(unknowns.begin(), unknowns.end(), [&](const GiNaC::symbol& u) { return r.rhs().has(u); });
                          });
  std::string wrong = p.wrong;
  if (wrong.empty() && (!determined || !GiNaC::normal(rest).is_zero())) {
    wrong = fmt::format("({}) is not ({}) for one value of its coefficients {}.", printed_ref, reference_of(call, "form"), fmt::join(call.with.at("unknowns").values, ", "));
  }
  form_coefficients out;
  out.wrong = wrong;
  if (!wrong.empty()) return out;
  std::vector<ex>& v = out.v;
  std::vector<std::string>& v_text = out.text;
  for (std::size_t u = 0; u < unknowns.size(); ++u) {
    v.push_back(GiNaC::normal(coefficients.op(u).rhs().subs(p.solved.values)));
    v_text.push_back(unknowns[u].get_name() + " = " + text_of(v.back()));
  }
  return out;
}

/// The kernel of the system as derived there: the printed form's coefficients v when they are in it,
/// else the first nonzero column of its adjugate.
std::vector<ex> derived_kernel_vector(const GiNaC::matrix& derived_there, const std::vector<ex>& v, bool printed_in_derived) {
  std::vector<ex> w = v;
  if (printed_in_derived) return w;
  for (unsigned j = 0; j < derived_there.rows(); ++j) {  // a nonzero column of the adjugate
    std::vector<ex> column;
    bool nonzero = false;
    for (unsigned i = 0; i < derived_there.cols(); ++i) {
      const ex cofactor = ((i + j) % 2 ? -1 : 1) * minor_matrix(normalised(derived_there), j, i).determinant(GiNaC::determinant_algo::laplace);
      column.push_back(GiNaC::normal(cofactor));
      nonzero = nonzero || !column.back().is_zero();
    }
    if (nonzero) {
      w = column;
      break;
    }
  }
  return w;
}

/// The ranks found: the printed system's by GiNaC and by our kernel's minor, and the derived one's.
json rank_evidence(const corank_one& printed_rank, const GiNaC::matrix& printed_there, const corank_one& derived_rank,
                   const GiNaC::matrix& derived_there) {
  return {
      {"printed", printed_rank.ginac ? "n - 1 (GiNaC)" : fmt::format("{} (GiNaC), not {}", normalised(printed_there).rank(), printed_there.rows() - 1)},
      {"own_minor", printed_rank.own.outcome == kernel_decision::result::nonzero ? "nonzero: " + printed_rank.own.evidence
                                                                                : "not decided nonzero: " + printed_rank.own.evidence},
      {"where", "rank n - 1 wherever the gcd of the (n - 1)-minors' numerators, " + printed_rank.where + ", is not zero"},
      {"derived", derived_rank.ginac ? "n - 1 (GiNaC) wherever the gcd of the (n - 1)-minors' numerators, " + derived_rank.where + ", is not zero"
                                     : fmt::format("{} (GiNaC), not {}", normalised(derived_there).rank(), derived_there.rows() - 1)}};
}

/// Where the printed system fails to give the printed form: its rows times the coefficients that are
/// not 0 (the kernel is wrong), or the rank (the kernel too large), from the note already made.
std::string where_printed_fails(const GiNaC::matrix& printed_there, const std::vector<ex>& v, const std::string& note) {
  std::vector<std::string> rows_off;
  for (unsigned k = 0; k < printed_there.rows(); ++k) {
    ex row = 0;
    for (unsigned u = 0; u < printed_there.cols(); ++u) row += printed_there(k, u) * v[u];
    const ex value = GiNaC::factor(GiNaC::normal(row));
    if (!value.is_zero()) rows_off.push_back(fmt::format("row {} gives {}", k + 1, text_of(value)));
  }
  const std::string printed_fails = !rows_off.empty()
                                        ? fmt::format("the printed system times those coefficients is not 0 there: {}, not 0.", fmt::join(rows_off, ", "))
                                    : note.rfind("As printed: ", 0) == 0 ? note.substr(12)
                                                                               : std::string("the printed system does not determine them.");
  return printed_fails;
}

}  // namespace
}  // namespace invariance


/// "When α = δ, we obtain η = 0 and a conserved quadratic form Q_c = γp²/2 − βq²/2, up to a
/// multiplicative constant": once the printed conditions are put in, the printed form's coefficients
/// (the unknowns that make `form` the printed one) are in the kernel of the printed system, and the
/// kernel is one-dimensional (rank n − 1), so every solution is a multiple of them; each printed
/// `obtains` (η = 0) holds there. Kernel membership in both kernels and Coq; the rank by GiNaC and
/// by our kernel's nonzero minor. An erratum's correction is the kernel of the system as derived
/// (invariance-system): the printed form when it spans it, else a column of its adjugate.
decider_evidence invariance_kernel_shape(const shape_call& call, const run_context& ctx) {
  using namespace invariance;
  shape_reader read(call, document_of(ctx));
  const ex printed_form = read.formula("printed");
  const printed_system p = read_printed_system(call, read);
  const invariance_rows& d = p.d;
  const solved_conditions& solved = p.solved;
  const std::vector<GiNaC::symbol>& unknowns = p.unknowns;
  const std::string printed_ref = reference_of(call, "printed");
  std::vector<std::pair<referenced_formula, std::vector<ex>>> obtains;
  if (read.has("obtains")) {
    for (const referenced_formula& f : read.equations("obtains")) obtains.emplace_back(f, read.sides(f));
  }
  claim_result result;
  result.printed = read.printed();
  const form_coefficients coefficients = printed_form_coefficients(call, p, printed_form);
  if (!coefficients.wrong.empty()) {
    result.note = coefficients.wrong;
    return beyond_reach(std::move(result));
  }
  const std::vector<ex>& v = coefficients.v;
  const std::vector<std::string>& v_text = coefficients.text;
  const auto obtained_at = [&](const std::vector<ex>& at, std::vector<std::string>& failing) {
    GiNaC::exmap put;
    for (std::size_t u = 0; u < unknowns.size(); ++u) put[unknowns[u]] = at[u];
    for (const auto& [equation, sides] : obtains) {
      if (!is_zero_expression(GiNaC::normal((sides.front() - sides.back()).subs(put).subs(solved.values)))) failing.push_back(folded_space(equation.tex));
    }
    return failing.empty();
  };
  const std::string on = fmt::format("{}", fmt::join(solved.text, ", "));
  const GiNaC::matrix printed_there = substituted(p.coefficients, solved.values), derived_there = substituted(d.derived, solved.values);
  // The system as derived: its kernel there, the printed form's coefficients when they are in it.
  const corank_one derived_rank = decide_corank_one(derived_there);
  const bool printed_in_derived = is_zero_expression(GiNaC::normal(rows_times(d.monomials, derived_there, v)));
  const std::vector<ex> w = derived_kernel_vector(derived_there, v, printed_in_derived);
  // The form with those coefficients is conserved: form(map y) − form(y) as written, w and the
  // conditions put in (the derived rows times w, in the tree Coq checks).
  GiNaC::exmap at_w;
  for (std::size_t u = 0; u < unknowns.size(); ++u) at_w[unknowns[u]] = w[u];
  const ex conserved_w = d.change.subs(at_w).subs(solved.values);
  const bool derived_spans = derived_rank.ginac && is_zero_expression(GiNaC::normal(conserved_w));
  std::vector<std::string> w_text, w_failing;
  for (std::size_t u = 0; u < unknowns.size(); ++u) w_text.push_back(unknowns[u].get_name() + " = " + text_of(w[u]));
  const bool w_obtains = obtained_at(w, w_failing);
  const std::string correction =
      derived_spans ? fmt::format("the system as derived (the rows invariance-system derives) has, with {}, a one-dimensional kernel spanned by {}{}{}", on,
                                  fmt::join(w_text, ", "), printed_in_derived ? ": the coefficients of the printed form, which follows from that system" : "",
                                  w_obtains ? "" : fmt::format("; there {} does not hold", fmt::join(w_failing, ", ")))
                    : "";
  const std::string what = fmt::format("the printed system times the printed form's coefficients ({}) = 0, with {}", fmt::join(v_text, ", "), on);
  decider_evidence e = identity_evidence(read, "kernel", what, rows_times(d.monomials, printed_there, v), 0, correction,
                                         derived_spans ? verdict::erratum : verdict::fails);
  claim_result& found = e.found;
  const corank_one printed_rank = decide_corank_one(printed_there);
  std::vector<std::string> v_failing;
  const bool v_obtains = obtained_at(v, v_failing);
  found.evidence["exact"]["conditions_solved"] = solved.text;
  found.evidence["exact"]["rank"] = rank_evidence(printed_rank, printed_there, derived_rank, derived_there);
  found.evidence["exact"]["derived_kernel"] = w_text;
  const bool own_rank = printed_rank.own.outcome == kernel_decision::result::nonzero;
  if (e.found_holds() && (!printed_rank.ginac || !v_obtains)) {
    // In the kernel, but GiNaC finds the rank or an `obtains` wrong: the statement fails on those,
    // which are GiNaC's alone.
    e.ginac = answer::fails;
    e.own = answer::none;
    e.if_false = derived_spans && w_obtains ? verdict::erratum : verdict::fails;
    found.correction = e.if_false == verdict::erratum ? correction : "";
    found.note = !printed_rank.ginac ? fmt::format("As printed: ({}) is in the kernel, but the kernel has dimension {}: not every solution is a multiple of it.",
                                                    printed_ref, printed_there.rows() - normalised(printed_there).rank())
                                      : fmt::format("As printed: {} does not hold for the coefficients of ({}).", fmt::join(v_failing, ", "), printed_ref);
  } else if (e.found_holds() && !own_rank && printed_rank.own.outcome != kernel_decision::result::not_applicable) {
    e.own = answer::fails;  // our kernel's minor is zero: the rank is not n - 1 by it
    e.disagreement = "GiNaC finds rank n - 1 and our kernel finds the chosen (n - 1)-minor zero: a bug in one of them.";
  }
  const bool fails_plainly = e.found_false() && e.if_false == verdict::fails;
  if (fails_plainly && found.note.find("As printed") != std::string::npos && !derived_spans) {
    found.note += " The system as derived has no one-dimensional kernel there either.";
  }
  // Coq: the printed system's rows times the coefficients (a tree GiNaC may already have made 0),
  // and the form with them conserved, as written: when it holds, or as the correction.
  GiNaC::exmap at_v;
  for (std::size_t u = 0; u < unknowns.size(); ++u) at_v[unknowns[u]] = v[u];
  if (e.found_holds()) {
    e.goals = std::vector<proof_goal>{decided("kernel", rows_times(d.monomials, printed_there, v), 0), decided("conserved", d.change.subs(at_v).subs(solved.values), 0)};
  }
  if (e.found_false() && e.if_false == verdict::erratum && printed_in_derived && w_obtains) {
    // The printed form is conserved, and follows from the system as derived; only its derivation from
    // the printed system fails (that system's own erratum): it holds, with that remark.
    decider_evidence derived =
        identity_evidence(read, "derived", fmt::format("the system as derived times the printed form's coefficients ({}) = 0, with {}", fmt::join(v_text, ", "), on),
                          rows_times(d.monomials, derived_there, v), 0, "", verdict::fails);
    derived.found.evidence["exact"]["printed_system"] = found.evidence["exact"];
    derived.found.evidence["exact"]["derived_kernel"] = w_text;
    derived.found.remark_kind = finding::derivation_gap;
    // Where the printed system fails: its rows times the coefficients that are not 0 (the kernel is
    // wrong), or the rank (the kernel too large).
    const std::string printed_fails = where_printed_fails(printed_there, v, found.note);
    derived.found.remark = fmt::format("The printed derivation fails only through {}; the conclusion holds: {}. With the printed entries {}",
                                       entries_differing(p.coefficients, d.derived), correction, printed_fails);
    derived.found.amendments.push_back(amendment_in_words("the system the conclusion is derived from", "the printed system",
                                                          "the system as derived (its entries corrected)"));
    if (derived.found_holds()) derived.goals = std::vector<proof_goal>{decided("derived", rows_times(d.monomials, derived_there, v), 0), decided("conserved", conserved_w, 0)};
    return derived;
  }
  if (e.found_false() && e.if_false == verdict::erratum) {  // the correction certified beside the refutation
    e.goals = std::vector<proof_goal>{decided("kernel", rows_times(d.monomials, printed_there, v), 0), decided("derived", conserved_w, 0)};
  }
  return e;
}

/// The shape of this file, its name, summary, principal argument and parameters beside the function
/// that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> invariance_kernel_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  std::vector<shape_parameter> kernel = with_conditions(with_invariance({"printed", argument_kind::formula, true, "the printed form whose coefficients span the kernel"}));
  kernel.push_back({"system", argument_kind::formula, true, "the printed system: a column linear in the unknowns"});
  kernel.push_back({"obtains", argument_kind::equations, false, "printed equations in the unknowns that every solution satisfies (eta = 0)"});
  add({"invariance-kernel",
       "once the printed conditions are put in, the printed form's coefficients span the kernel of the printed system (rank n - 1), and each 'obtains' holds there",
       "printed", with_where(std::move(kernel)), invariance_kernel_shape});
  return all;
}

}  // namespace simpson::verify::detail

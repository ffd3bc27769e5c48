// The invariance shapes (shape_support.hpp): what a quadratic form's invariance under a one-step map
// asks of the form's coefficients, as Section 7 of the paper derives its conserved form. The system
// (invariance-system), its determinant (invariance-determinant), its singularity on a printed
// condition (invariance-singular) and its kernel there (invariance-kernel).

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

namespace {

/// What a quadratic form's invariance under a map asks of its coefficients: form(map y) − form(y)
/// as written, the monomials y_i y_j (i ≤ j, in the state's order), and the derived system, the
/// coefficient of each monomial (a row) in each unknown; `not_quadratic` says what is left when the
/// change is not a quadratic form in the state.
struct invariance_rows {
  std::vector<ex> monomials;
  std::vector<std::string> named;
  ex change;
  GiNaC::matrix derived;
  std::vector<std::string> rows_text;
  std::string not_quadratic;
};

invariance_rows derive_invariance_rows(const ex& form, const GiNaC::matrix& m, const std::vector<GiNaC::symbol>& state,
                                       const std::vector<GiNaC::symbol>& unknowns) {
  invariance_rows d;
  for (std::size_t i = 0; i < state.size(); ++i) {
    for (std::size_t j = i; j < state.size(); ++j) {
      d.monomials.push_back(state[i] * state[j]);
      d.named.push_back(text_of(d.monomials.back()));
    }
  }
  GiNaC::matrix y(m.rows(), 1);
  for (unsigned k = 0; k < m.rows(); ++k) y(k, 0) = state[k];
  const GiNaC::matrix next = GiNaC::ex_to<GiNaC::matrix>((m * y).evalm());
  GiNaC::exmap step;
  for (unsigned k = 0; k < m.rows(); ++k) step[state[k]] = next(k, 0);
  d.change = form.subs(step) - form;  // as written
  const ex expanded = GiNaC::expand(d.change);
  d.derived = GiNaC::matrix(static_cast<unsigned>(d.monomials.size()), static_cast<unsigned>(unknowns.size()));
  ex rest = expanded;
  for (std::size_t k = 0; k < d.monomials.size(); ++k) {
    ex coefficient = expanded;
    for (const GiNaC::symbol& s : state) coefficient = coefficient.coeff(s, d.monomials[k].degree(s));
    coefficient = GiNaC::normal(coefficient);
    rest -= d.monomials[k] * coefficient;
    d.rows_text.push_back(d.named[k] + ": " + text_of(coefficient));
    for (std::size_t u = 0; u < unknowns.size(); ++u) {
      d.derived(static_cast<unsigned>(k), static_cast<unsigned>(u)) = GiNaC::normal(GiNaC::expand(coefficient).coeff(unknowns[u], 1));
    }
  }
  if (!GiNaC::normal(rest).is_zero()) d.not_quadratic = text_of(GiNaC::normal(rest));
  return d;
}

}  // namespace

/// "Q(Φy) = Q(y) for all y iff Γ (ξ, η, ζ)ᵀ = 0": the printed system's rows are the coefficients of
/// the state's degree-2 monomials y_i y_j (i ≤ j, in the state's order: p², pq, q²) in
/// form(map y) − form(y), the form's coefficients its unknowns. Decided as one identity, the change
/// as written against Σ monomial × printed row, every symbol free (the state's too): GiNaC's normal
/// form, our kernel's grid, and the Coq lemma. An erratum's correction is the derived rows, whose
/// identity Coq checks beside the printed one's refutation.
decider_evidence invariance_system_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex system = read.formula("system").evalm();
  const ex form = read.formula("form");
  const GiNaC::matrix m = as_square_matrix(read.formula("map"), reference_of(call, "map"));
  const std::vector<GiNaC::symbol> state = read.symbols("state"), unknowns = read.symbols("unknowns");
  const std::string system_ref = reference_of(call, "system"), form_ref = reference_of(call, "form"), map_ref = reference_of(call, "map");
  const invariance_rows d = derive_invariance_rows(form, m, state, unknowns);
  const std::vector<ex>& monomials = d.monomials;
  const std::vector<std::string>& named = d.named;
  const GiNaC::matrix& derived = d.derived;
  const ex& change = d.change;
  claim_result result;
  result.printed = read.printed();
  if (!GiNaC::is_a<GiNaC::matrix>(system) || GiNaC::ex_to<GiNaC::matrix>(system).cols() != 1 ||
      GiNaC::ex_to<GiNaC::matrix>(system).rows() != monomials.size()) {
    result.note = fmt::format("({}) is not a column of {} rows, one for each of {}.", system_ref, monomials.size(), fmt::join(named, ", "));
    return beyond_reach(std::move(result));
  }
  if (!d.not_quadratic.empty()) {
    result.note = fmt::format("({})(({}) y) − ({})(y) is not a quadratic form in the state: {} is left beyond the monomials {}.", form_ref, map_ref,
                              form_ref, d.not_quadratic, fmt::join(named, ", "));
    return beyond_reach(std::move(result));
  }
  const GiNaC::matrix& rows = GiNaC::ex_to<GiNaC::matrix>(system);
  ex printed_sum = 0;
  for (std::size_t k = 0; k < monomials.size(); ++k) printed_sum += monomials[k] * rows(static_cast<unsigned>(k), 0);
  // The entries that differ, first: what a reader corrects in the printed matrix.
  std::vector<std::string> differing;
  std::vector<amendment> amendments;
  for (unsigned k = 0; k < derived.rows(); ++k) {
    for (unsigned u = 0; u < derived.cols(); ++u) {
      const ex printed_entry = GiNaC::normal(GiNaC::expand(rows(k, 0)).coeff(unknowns[u], 1));
      if (!GiNaC::normal(printed_entry - derived(k, u)).is_zero()) {
        differing.push_back(fmt::format("entry ({}, {}) is {}, not {}", k + 1, u + 1, text_of(derived(k, u)), text_of(printed_entry)));
        if (auto a = amendment_between(fmt::format("entry ({}, {}) of the system's matrix", k + 1, u + 1), printed_entry, derived(k, u))) {
          amendments.push_back(*a);
        }
      }
    }
  }
  const std::string what = fmt::format("({})(({}) y) − ({})(y) = {} times the rows of ({})", form_ref, map_ref, form_ref, fmt::join(named, ", "), system_ref);
  decider_evidence e = identity_evidence(read, "system", what, change, printed_sum,
                            fmt::format("{}{}as derived from ({})(({}) y) − ({})(y), the coefficients of {} in the unknowns: {}", fmt::join(differing, "; "),
                                        differing.empty() ? "" : "; ", form_ref, map_ref, form_ref, fmt::join(named, ", "), text_of(derived)));
  e.found.evidence["exact"]["derived_rows"] = d.rows_text;
  if (e.found_false()) {  // the correction certified beside the refutation
    e.found.amendments = amendments;
    ex derived_sum = 0;
    for (std::size_t k = 0; k < monomials.size(); ++k) {
      for (std::size_t u = 0; u < unknowns.size(); ++u) {
        derived_sum += monomials[k] * derived(static_cast<unsigned>(k), static_cast<unsigned>(u)) * unknowns[u];
      }
    }
    e.goals = std::vector<proof_goal>{decided("system", change, printed_sum), decided("derived", change, derived_sum)};
    GiNaC::matrix column(derived.rows(), 1);  // the system as it should be printed: the derived rows times the unknowns
    for (unsigned k = 0; k < derived.rows(); ++k) {
      for (std::size_t u = 0; u < unknowns.size(); ++u) column(k, 0) += derived(k, static_cast<unsigned>(u)) * unknowns[u];
    }
    e.found.corrected_formulas.push_back(read.correction_of("system", column));
  }
  return e;
}

/// "We have det Γ = ...": the printed value against the determinant of the system a quadratic
/// form's invariance under the map gives, derived as `invariance-system` derives its rows (the system
/// as it should be printed: a misprinted entry of the printed system is that claim's finding, not
/// this one's). Decided in both kernels, one Coq lemma; an erratum's correction is the printed value
/// times a number when the two differ by one (certified beside the refutation), else the determinant.
decider_evidence invariance_determinant_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex printed = read.formula("printed");
  const ex form = read.formula("form");
  const GiNaC::matrix m = as_square_matrix(read.formula("map"), reference_of(call, "map"));
  const std::vector<GiNaC::symbol> state = read.symbols("state"), unknowns = read.symbols("unknowns");
  const std::string form_ref = reference_of(call, "form"), map_ref = reference_of(call, "map");
  const invariance_rows d = derive_invariance_rows(form, m, state, unknowns);
  claim_result result;
  result.printed = read.printed();
  if (!d.not_quadratic.empty() || d.derived.rows() != d.derived.cols()) {
    result.note = d.not_quadratic.empty()
                      ? fmt::format("The system has {} rows ({}) and {} unknowns: no determinant.", d.derived.rows(), fmt::join(d.named, ", "),
                                    d.derived.cols())
                      : fmt::format("({})(({}) y) − ({})(y) is not a quadratic form in the state: {} is left.", form_ref, map_ref, form_ref, d.not_quadratic);
    return beyond_reach(std::move(result));
  }
  const ex det = d.derived.determinant(GiNaC::determinant_algo::laplace);
  const std::string printed_ref = reference_of(call, "printed");
  // A printed value off by a constant factor (a lost 1/4) is corrected as that multiple of itself,
  // which says what to change; otherwise by the determinant (in normal form: the report's canonical
  // text expands products).
  const ex ratio = is_zero_expression(GiNaC::normal(printed)) ? ex(0) : GiNaC::normal(det / printed);
  const bool multiple = GiNaC::is_a<GiNaC::numeric>(ratio) && !ratio.is_zero();
  const ex corrected = multiple ? ratio * printed : GiNaC::normal(det);
  const std::string what = fmt::format("det of the system ({})(({}) y) = ({})(y) asks of the unknowns = ({})", form_ref, map_ref, form_ref, printed_ref);
  decider_evidence e = identity_evidence(read, "determinant", what, det, printed,
                            multiple ? fmt::format("as derived: det = {} × ${}$ (as printed): a constant factor, the same zeros", text_of(ratio),
                                                   folded_space(read.raw("printed").sides.back()))
                                     : "as derived: det = " + text_of(corrected));
  claim_result& found = e.found;
  found.evidence["exact"]["derived_rows"] = d.rows_text;
  if (e.found_false()) {  // the correction certified beside the refutation
    e.goals = std::vector<proof_goal>{decided("determinant", det, printed), decided("derived", det, corrected)};
    found.constant_factor = multiple;
    found.amendments.push_back(multiple ? amendment{"the printed determinant, off by a constant factor (its zeros the same)",
                                                     folded_space(read.raw("printed").sides.back()), canonical_tex(ratio) + " \\times \\text{the printed}"}
                                         : *amendment_between("the printed determinant", printed, corrected));
    // What should stand where the determinant is printed: the claims that read it are judged again with it.
    found.corrected_formulas.push_back(read.correction_of("printed", corrected));
  }
  return e;
}


namespace {

/// The system's coefficient matrix: row k's coefficient of each unknown, in normal form; none when a
/// row is not linear and homogeneous in the unknowns.
std::optional<GiNaC::matrix> coefficient_matrix(const GiNaC::matrix& column, const std::vector<GiNaC::symbol>& unknowns) {
  GiNaC::matrix out(column.rows(), static_cast<unsigned>(unknowns.size()));
  for (unsigned k = 0; k < column.rows(); ++k) {
    ex rest = GiNaC::expand(column(k, 0));
    for (std::size_t u = 0; u < unknowns.size(); ++u) {
      const ex c = GiNaC::normal(GiNaC::expand(column(k, 0)).coeff(unknowns[u], 1));
      out(k, static_cast<unsigned>(u)) = c;
      rest -= c * unknowns[u];
    }
    if (!GiNaC::normal(rest).is_zero()) return std::nullopt;
  }
  return out;
}

/// What the printed conditions give: each solved for its symbol (linear in it once the earlier
/// solutions are put in), the later solutions put back into the earlier ones; `not_solved` says which
/// one could not be.
struct solved_conditions {
  GiNaC::exmap values;
  std::vector<std::string> text;  // "delta = alpha", in the order solved
  std::string not_solved;
};

solved_conditions solve_conditions(shape_reader& read, const std::string& conditions, const std::string& solve_for) {
  solved_conditions out;
  const std::vector<referenced_formula> equations = read.equations(conditions);
  const std::vector<GiNaC::symbol> unknowns = read.symbols(solve_for);
  for (std::size_t i = 0; i < equations.size() && i < unknowns.size(); ++i) {
    const std::vector<ex> sides = read.sides(equations[i]);
    const GiNaC::symbol& s = unknowns[i];
    const ex e = GiNaC::normal((sides.front() - sides.back()).subs(out.values));
    const ex numerator = GiNaC::expand(GiNaC::numer(e));
    const ex slope = numerator.coeff(s, 1);
    if (numerator.degree(s) != 1 || slope.is_zero()) {
      out.not_solved = fmt::format("${}$ ({}) is not linear in {} once {} put in", folded_space(equations[i].tex), equations[i].locator,
                                   s.get_name(), out.text.empty() ? "nothing is" : fmt::format("{} are", fmt::join(out.text, ", ")));
      return out;
    }
    const ex value = GiNaC::normal(-numerator.coeff(s, 0) / slope);
    for (auto& solved : out.values) solved.second = GiNaC::normal(solved.second.subs(GiNaC::exmap{{s, value}}));
    out.values[s] = value;
  }
  for (const GiNaC::symbol& s : unknowns) {
    if (out.values.count(s)) out.text.push_back(s.get_name() + " = " + text_of(out.values.at(s)));
  }
  return out;
}

/// What the two shapes on a printed system read and check alike: the printed system's coefficient
/// matrix, the rows as derived (invariance-system) and the printed conditions solved; `wrong` says
/// why they cannot be judged (the note of a fails verdict).
struct printed_system {
  ex form;
  std::vector<GiNaC::symbol> state, unknowns;
  invariance_rows d;
  solved_conditions solved;
  GiNaC::matrix coefficients;
  std::string wrong;
};

printed_system read_printed_system(const shape_call& call, shape_reader& read) {
  printed_system out;
  const ex system = read.formula("system").evalm();
  out.form = read.formula("form");
  const GiNaC::matrix m = as_square_matrix(read.formula("map"), reference_of(call, "map"));
  out.state = read.symbols("state");
  out.unknowns = read.symbols("unknowns");
  out.d = derive_invariance_rows(out.form, m, out.state, out.unknowns);
  out.solved = solve_conditions(read, "conditions", "solve_for");
  const std::optional<GiNaC::matrix> printed =
      GiNaC::is_a<GiNaC::matrix>(system) && GiNaC::ex_to<GiNaC::matrix>(system).cols() == 1 ? coefficient_matrix(GiNaC::ex_to<GiNaC::matrix>(system), out.unknowns)
                                                                                            : std::nullopt;
  if (!printed || printed->rows() != printed->cols()) {
    out.wrong = fmt::format("({}) is not a column of {} rows linear in {}: no determinant, no kernel.", reference_of(call, "system"), out.unknowns.size(),
                            fmt::join(call.with.at("unknowns").values, ", "));
  } else if (!out.d.not_quadratic.empty() || out.d.derived.rows() != out.d.derived.cols()) {
    out.wrong = fmt::format("The invariance of ({}) under ({}) is not a square system in the unknowns.", reference_of(call, "form"), reference_of(call, "map"));
  } else if (!out.solved.not_solved.empty()) {
    out.wrong = out.solved.not_solved + ".";
  } else {
    out.coefficients = *printed;
  }
  return out;
}

/// Where the printed system's matrix differs from the one derived (invariance-system): "entry (i, j),
/// printed X where derived Y", each; the rest agree.
std::string entries_differing(const GiNaC::matrix& printed, const GiNaC::matrix& derived) {
  std::vector<std::string> out;
  for (unsigned i = 0; i < printed.rows(); ++i) {
    for (unsigned j = 0; j < printed.cols(); ++j) {
      if (!GiNaC::normal(printed(i, j) - derived(i, j)).is_zero()) {
        out.push_back(fmt::format("entry ({}, {}) (printed {} where derived {})", i + 1, j + 1, text_of(GiNaC::normal(printed(i, j))),
                                  text_of(GiNaC::normal(derived(i, j)))));
      }
    }
  }
  const std::size_t n = printed.rows() * printed.cols();
  return out.size() == 1 ? fmt::format("the printed system's {} alone, its {} other entries as derived", out.front(), n - 1)
                         : fmt::format("the printed system's {}, {} of its {} entries", fmt::join(out, "; "), out.size(), n);
}

/// m with the values put in, as written (not normalised: our kernel and Coq decide the tree).
GiNaC::matrix substituted(const GiNaC::matrix& m, const GiNaC::exmap& values) {
  GiNaC::matrix out(m.rows(), m.cols());
  for (unsigned i = 0; i < m.rows(); ++i) {
    for (unsigned j = 0; j < m.cols(); ++j) out(i, j) = m(i, j).subs(values);
  }
  return out;
}

GiNaC::matrix normalised(const GiNaC::matrix& m) {
  GiNaC::matrix out(m.rows(), m.cols());
  for (unsigned i = 0; i < m.rows(); ++i) {
    for (unsigned j = 0; j < m.cols(); ++j) out(i, j) = GiNaC::normal(m(i, j));
  }
  return out;
}

/// m without row r and column c.
GiNaC::matrix minor_matrix(const GiNaC::matrix& m, unsigned r, unsigned c) {
  GiNaC::matrix out(m.rows() - 1, m.cols() - 1);
  for (unsigned i = 0, oi = 0; i < m.rows(); ++i) {
    if (i == r) continue;
    for (unsigned j = 0, oj = 0; j < m.cols(); ++j) {
      if (j != c) out(oi, oj++) = m(i, j);
    }
    ++oi;
  }
  return out;
}

/// The determinant by cofactors of the first row, as written (GiNaC's determinant normalises, and a
/// zero it finds leaves Coq nothing to check).
ex written_determinant(const GiNaC::matrix& m) {
  if (m.rows() == 1) return m(0, 0);
  ex sum = 0;
  for (unsigned c = 0; c < m.cols(); ++c) sum += (c % 2 ? -1 : 1) * m(0, c) * written_determinant(minor_matrix(m, 0, c));
  return sum;
}

/// Σ_k monomial_k × (m v)_k: zero for every state exactly when m v = 0 (the monomials are distinct),
/// one identity for both kernels and Coq.
ex rows_times(const std::vector<ex>& monomials, const GiNaC::matrix& m, const std::vector<ex>& v) {
  ex sum = 0;
  for (unsigned k = 0; k < m.rows(); ++k) {
    for (unsigned u = 0; u < m.cols(); ++u) sum += monomials[k] * m(k, u) * v[u];
  }
  return sum;
}

/// Whether an n × n matrix has rank exactly n − 1 given that its kernel holds a nonzero vector:
/// GiNaC's rank over the rational functions, and our kernel's decision that one (n − 1)-minor is not
/// zero; `where` is the gcd of the minors' numerators (the rank is n − 1 wherever it is not zero).
struct corank_one {
  bool ginac = false;
  kernel_decision own;
  std::string where;
};

corank_one decide_corank_one(const GiNaC::matrix& m) {
  corank_one out;
  const GiNaC::matrix n = normalised(m);
  out.ginac = n.rows() > 0 && n.rank() + 1 == n.rows();
  ex common = 0;
  bool chosen = false;
  for (unsigned r = 0; r < m.rows(); ++r) {
    for (unsigned c = 0; c < m.cols(); ++c) {
      const ex minor = written_determinant(minor_matrix(m, r, c));
      const ex numerator = GiNaC::numer(GiNaC::normal(minor));
      if (!chosen && !numerator.is_zero()) {
        out.own = kernel_decides_zero(minor);
        chosen = true;
      }
      common = common.is_zero() ? numerator : GiNaC::gcd(common, numerator);
    }
  }
  if (!chosen) out.own = kernel_decides_zero(written_determinant(minor_matrix(m, 0, 0)));
  out.where = text_of(common);
  return out;
}

}  // namespace

/// "det Γ vanishes when αδ − βγ = 1": the determinant of the printed system's coefficient matrix is
/// zero once the printed conditions are put in (each solved for its symbol in `solve_for`), decided
/// in both kernels and in Coq. An erratum when the system as derived (invariance-system) is singular
/// there and the printed one is not: the derived determinant's identity certified beside the
/// refutation. Fails when neither is.
decider_evidence invariance_singular_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  read.equations("conditions");  // read first: the principal formula the report lists
  const printed_system p = read_printed_system(call, read);
  const invariance_rows& d = p.d;
  const solved_conditions& solved = p.solved;
  claim_result result;
  result.printed = read.printed();
  if (!p.wrong.empty()) {
    result.note = p.wrong;
    return beyond_reach(std::move(result));
  }
  const ex det_printed = written_determinant(substituted(p.coefficients, solved.values));
  const ex det_derived = written_determinant(substituted(d.derived, solved.values));
  const bool derived_singular = is_zero_expression(GiNaC::normal(det_derived));
  const std::string on = fmt::format("{}", fmt::join(solved.text, ", "));
  const std::string what = fmt::format("det of the printed system's coefficients, with {}, = 0", on);
  decider_evidence e = identity_evidence(read, "printed", what, det_printed, 0,
                            derived_singular ? fmt::format("the system as derived (the rows invariance-system derives) is singular there: with {} its determinant is 0, "
                                                           "and the printed system's is {}",
                                                           on, text_of(GiNaC::factor(GiNaC::normal(det_printed))))
                                             : "",
                            derived_singular ? verdict::erratum : verdict::fails);
  e.found.evidence["exact"]["conditions_solved"] = solved.text;
  e.found.evidence["exact"]["derived_determinant_there"] = text_of(GiNaC::normal(det_derived));
  if (e.found_false() && !derived_singular) {
    e.found.note += fmt::format(" The system as derived is not singular there either: its determinant is {}.", text_of(GiNaC::normal(det_derived)));
  }
  if (e.found_false() && derived_singular) {
    // The conclusion holds of the system as derived; only its derivation from the printed system
    // fails (a consequence of the printed system's own erratum): it holds, with that remark.
    const json evidence = e.found.evidence;
    decider_evidence derived = identity_evidence(read, "derived", fmt::format("det of the system as derived (invariance-system's rows), with {}, = 0", on),
                                                 det_derived, 0, "", verdict::fails);
    derived.found.evidence["exact"]["printed_system"] = evidence["exact"];
    derived.found.evidence["exact"]["conditions_solved"] = solved.text;
    derived.found.remark_kind = finding::derivation_gap;
    derived.found.remark = fmt::format("The conclusion holds: the system as derived (the rows invariance-system derives) is singular with {}. The gap is "
                                       "{}: with it the printed system's determinant there is {}, not 0.",
                                       on, entries_differing(p.coefficients, d.derived), text_of(GiNaC::factor(GiNaC::normal(det_printed))));
    derived.found.amendments.push_back(amendment_in_words("the system the conclusion is derived from", "the printed system",
                                                          "the system as derived (its entries corrected)"));
    return derived;
  }
  return e;
}

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

/// "When α = δ, we obtain η = 0 and a conserved quadratic form Q_c = γp²/2 − βq²/2, up to a
/// multiplicative constant": once the printed conditions are put in, the printed form's coefficients
/// (the unknowns that make `form` the printed one) are in the kernel of the printed system, and the
/// kernel is one-dimensional (rank n − 1), so every solution is a multiple of them; each printed
/// `obtains` (η = 0) holds there. Kernel membership in both kernels and Coq; the rank by GiNaC and
/// by our kernel's nonzero minor. An erratum's correction is the kernel of the system as derived
/// (invariance-system): the printed form when it spans it, else a column of its adjugate.
decider_evidence invariance_kernel_shape(const shape_call& call, const run_context& ctx) {
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
    derived.found.remark = fmt::format("The conclusion holds: {}. The gap is {}: with it {}", correction, entries_differing(p.coefficients, d.derived),
                                       printed_fails);
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

/// The shapes of this file, each one's name, summary, principal argument and parameters beside the
/// function that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> invariance_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  add({"invariance-system", "the printed system's rows are the coefficients of y_i y_j (i <= j, in the state's order) in form(map y) - form(y)",
       "system",
       with_where(with_invariance({"system", argument_kind::formula, true, "the printed system: a column with a row for each y_i y_j, linear in the unknowns"})),
       invariance_system_shape});
  add({"invariance-determinant", "printed = det of the system form(map y) = form(y) asks of the form's coefficients (the rows as invariance-system derives them)",
       "printed", with_where(with_invariance({"printed", argument_kind::formula, true, "the printed determinant"})), invariance_determinant_shape});
  add({"invariance-singular", "det of the printed system's coefficients is 0 once the printed conditions are put in (each solved for its symbol)",
       "conditions", with_where(with_conditions(with_invariance({"system", argument_kind::formula, true, "the printed system: a column linear in the unknowns"}))),
       invariance_singular_shape});
  std::vector<shape_parameter> kernel = with_conditions(with_invariance({"printed", argument_kind::formula, true, "the printed form whose coefficients span the kernel"}));
  kernel.push_back({"system", argument_kind::formula, true, "the printed system: a column linear in the unknowns"});
  kernel.push_back({"obtains", argument_kind::equations, false, "printed equations in the unknowns that every solution satisfies (eta = 0)"});
  add({"invariance-kernel",
       "once the printed conditions are put in, the printed form's coefficients span the kernel of the printed system (rank n - 1), and each 'obtains' holds there",
       "printed", with_where(std::move(kernel)), invariance_kernel_shape});
  return all;
}

}  // namespace simpson::verify::detail

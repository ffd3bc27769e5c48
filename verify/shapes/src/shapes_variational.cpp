// The variational shapes (shape_support.hpp) for any Lagrangian, its functions left general:
// symplecticity of the one-step map that printed relations define, by implicit differentiation; the
// discrete Noether identity of a coordinate the discrete Lagrangian is invariant under shifting; and
// the cyclic coordinates of a Lagrangian, whose conjugate momenta the Euler-Lagrange equations keep.

#include <simpson/shapes/shape_support.hpp>

#include <simpson/prove/printed_check_support.hpp>

#include <fmt/format.h>

#include <algorithm>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

std::string names_of(const std::vector<GiNaC::symbol>& symbols) {
  std::string out;
  for (const GiNaC::symbol& s : symbols) out += (out.empty() ? "" : ", ") + s.get_name();
  return out;
}

}  // namespace

/// The one-step map the printed relations define, (from) -> (to) with the internal nodes solved
/// along the way, is symplectic: by implicit differentiation its Jacobian is M = -A^{-1} B, A the
/// relations' derivatives by the unknowns (to, then internal), B by the data (from). With P = adj(A)
/// B restricted to the rows of `to` (P = -det(A) M), the statement is polynomial in the functions'
/// derivatives: P^T J P = det(A)^2 J, or det P = det(A)^(2n) times the printed determinant. The
/// Jacobian and what it is are read from the print: \frac{\partial(q_r, p_r)}{\partial(q_l, p_l)},
/// or its \det = 1.
decider_evidence symplectic_step_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex printed = read.formula("jacobian");
  const bool determinant = GiNaC::is_a<GiNaC::function>(printed) && GiNaC::ex_to<GiNaC::function>(printed).get_name() == "det" && is_jacobian(printed.op(0));
  if (!determinant && !is_jacobian(printed)) {
    throw argument_error("jacobian", "'" + reference_of(call, "jacobian") + "' is no Jacobian \\frac{\\partial(q_r, p_r)}{\\partial(q_l, p_l)}, nor its \\det");
  }
  const auto [to, from] = jacobian_names(determinant ? printed.op(0) : printed);
  if (to.size() % 2 != 0) throw argument_error("jacobian", "a Jacobian of " + std::to_string(to.size()) + " names: positions and momenta come in pairs");
  if (determinant && !read.has("equals")) throw argument_error("equals", "the printed determinant's value is needed with a \\det");
  const std::vector<GiNaC::symbol> internal = read.has("internal") ? read.symbols("internal") : std::vector<GiNaC::symbol>{};
  std::vector<ex> relations;
  for (const referenced_formula& f : read.equations("relations")) {
    // a = b, or a chain a = b = ... (p_n = -dL_d/dq_n = ...): its first side against its last, as printed.
    const std::vector<ex> sides = read.sides(f);
    if (sides.size() < 2) throw argument_error("relations", "'" + f.locator + "' is no equation");
    relations.push_back(sides.front() - sides.back());
  }
  std::vector<GiNaC::symbol> unknowns = to;
  unknowns.insert(unknowns.end(), internal.begin(), internal.end());
  if (relations.size() != unknowns.size()) {
    throw argument_error("relations", fmt::format("{} relations for {} unknowns ({}): a step solves as many as it has", relations.size(), unknowns.size(),
                                                  names_of(unknowns)));
  }
  const unsigned u = static_cast<unsigned>(unknowns.size()), d = static_cast<unsigned>(from.size());
  GiNaC::matrix a(u, u), b(u, d);
  for (unsigned r = 0; r < u; ++r) {
    for (unsigned c = 0; c < u; ++c) a(r, c) = relations[r].diff(unknowns[c]);
    for (unsigned c = 0; c < d; ++c) b(r, c) = relations[r].diff(from[c]);
  }
  // adj(A) by cofactors, by Laplace's expansion and left unexpanded: a polynomial in A's entries that
  // our kernel evaluates entry by entry at each point of its grid, as it would the matrix itself.
  const auto minor_det = [&](unsigned skip_row, unsigned skip_col) {
    if (u == 1) return ex(1);
    GiNaC::matrix m(u - 1, u - 1);
    for (unsigned r = 0, rr = 0; r < u; ++r) {
      if (r == skip_row) continue;
      for (unsigned c = 0, cc = 0; c < u; ++c) {
        if (c == skip_col) continue;
        m(rr, cc++) = a(r, c);
      }
      ++rr;
    }
    return m.determinant(GiNaC::determinant_algo::laplace);
  };
  GiNaC::matrix adjugate(u, u);
  for (unsigned r = 0; r < u; ++r) {
    for (unsigned c = 0; c < u; ++c) adjugate(c, r) = ((r + c) % 2 == 0 ? 1 : -1) * minor_det(r, c);
  }
  const ex det_a = a.determinant(GiNaC::determinant_algo::laplace);
  const GiNaC::matrix adj_b = adjugate.mul(b);
  const unsigned n = static_cast<unsigned>(to.size());
  GiNaC::matrix p(n, d);
  for (unsigned r = 0; r < n; ++r) {
    for (unsigned c = 0; c < d; ++c) p(r, c) = adj_b(r, c);
  }
  const std::string map = fmt::format("the step ({}) -> ({}) of the relations ({}){}", names_of(from), names_of(to), reference_of(call, "relations"),
                                      internal.empty() ? "" : ", " + names_of(internal) + " solved along the way");
  if (determinant) {
    const ex equals = read.formula("equals");
    const std::string what = fmt::format("det M = ({}) for M = d({})/d({}), {}: det(adj(A) B) = det(A)^{} ({})", reference_of(call, "equals"), names_of(to),
                                          names_of(from), map, n, reference_of(call, "equals"));
    decider_evidence e = identity_evidence(read, "symplectic_step", what, p.determinant(GiNaC::determinant_algo::laplace), GiNaC::pow(det_a, n) * equals, "",
                                           verdict::erratum);
    if (e.found_false()) {  // det M itself is long for a general L: in the evidence, not the one line
      e.found.correction = fmt::format("as derived: det M is not ({}) for the relations as printed (det M in the evidence, exact.det_M)", reference_of(call, "equals"));
      e.found.evidence["exact"]["det_M"] = text_of(GiNaC::normal(p.determinant(GiNaC::determinant_algo::laplace) / GiNaC::pow(det_a, n)));
    }
    return e;
  }
  const GiNaC::matrix j = canonical_j(n / 2);
  const std::string what = fmt::format("M^T J M = J for M = d({})/d({}), {}: P^T J P = det(A)^2 J, P = adj(A) B", names_of(to), names_of(from), map);
  decider_evidence e = identity_evidence(read, "symplectic_step", what, p.transpose().mul(j).mul(p), j.mul_scalar(GiNaC::pow(det_a, 2)), "", verdict::erratum);
  if (e.found_false()) e.found.correction = "as derived: the step is not symplectic (M^T J M - J is not 0)";
  return e;
}

/// Discrete Noether for a coordinate the discrete Lagrangian is invariant under shifting at every
/// node (a cyclic coordinate: L depends on it through velocities only): Σ_k ∂L_h/∂x_k = 0, and the
/// printed momenta at the step's ends then agree wherever the internal nodes' equations hold,
/// p_end − p_start + Σ_internal ∂L_h/∂x_i = 0, identically in the functions the note leaves general.
decider_evidence discrete_noether_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex lagrangian = read.formula("lagrangian");
  const std::vector<GiNaC::symbol> nodes = read.symbols("coordinate");
  const std::vector<GiNaC::symbol> internal = read.has("internal") ? read.symbols("internal") : std::vector<GiNaC::symbol>{};
  for (const GiNaC::symbol& i : internal) {
    if (std::none_of(nodes.begin(), nodes.end(), [&](const GiNaC::symbol& x) { return x.is_equal(i); })) {
      throw argument_error("internal", i.get_name() + " is not one of the coordinate's nodes (" + names_of(nodes) + ")");
    }
  }
  // A coordinate the Lagrangian does not hold at all (a velocity's definition left out of `where`)
  // would make every statement below 0 = 0: refused, not held.
  if (std::none_of(nodes.begin(), nodes.end(), [&](const GiNaC::symbol& x) { return lagrangian.has(x); })) {
    throw argument_error("coordinate", fmt::format("({}) does not hold {} at any node: are the definitions of its velocities in 'where'?",
                                                   reference_of(call, "lagrangian"), names_of(nodes)));
  }
  ex shift = 0, stationary = 0;
  for (const GiNaC::symbol& x : nodes) shift += lagrangian.diff(x);
  for (const GiNaC::symbol& i : internal) stationary += lagrangian.diff(i);
  const ex start = read.formula("start"), end = read.formula("end");
  GiNaC::matrix lhs(2, 1);
  lhs(0, 0) = shift;
  lhs(1, 0) = end - start + stationary;
  const std::string what =
      fmt::format("({}) is invariant under shifting {} at every node (the sum of its partial derivatives is 0), and ({}) − ({}){} = 0",
                  reference_of(call, "lagrangian"), names_of(nodes), reference_of(call, "end"), reference_of(call, "start"),
                  internal.empty() ? "" : " + d(" + reference_of(call, "lagrangian") + ")/d(" + names_of(internal) + ")");
  decider_evidence e = identity_evidence(read, "discrete_noether", what, lhs, GiNaC::matrix(2, 1), "", verdict::erratum);
  if (e.found_false()) {
    const ex s = GiNaC::normal(shift), c = GiNaC::normal(end - start + stationary);
    e.found.correction = !s.is_zero() ? "as derived: not invariant: the sum of the partial derivatives of (" + reference_of(call, "lagrangian") + ") is " + text_of(s)
                                       : "as derived: the printed momenta differ by " + text_of(c) + " where the internal equations hold";
  }
  return e;
}

/// The coordinates are cyclic: the Lagrangian does not depend on them, ∂L/∂φ = 0 for each, so along
/// the Euler-Lagrange equations d/dt ∂L/∂φ̇ = 0 (the conjugate momentum is a constant of the motion).
/// A Lagrangian that holds neither a coordinate nor its velocity says nothing of it (a definition
/// left out of `where`, or another system's Lagrangian): refused, never held.
decider_evidence cyclic_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex lagrangian = read.formula("lagrangian");
  const std::vector<GiNaC::symbol> coordinates = read.symbols("coordinates");
  GiNaC::matrix lhs(static_cast<unsigned>(coordinates.size()), 1);
  for (std::size_t k = 0; k < coordinates.size(); ++k) {
    const GiNaC::symbol& c = coordinates[k];
    const std::string velocity = "d" + c.get_name() + "/dt";
    bool holds_velocity = false;
    for (GiNaC::const_preorder_iterator it = lagrangian.preorder_begin(); it != lagrangian.preorder_end() && !holds_velocity; ++it) {
      holds_velocity = GiNaC::is_a<GiNaC::symbol>(*it) && GiNaC::ex_to<GiNaC::symbol>(*it).get_name() == velocity;
    }
    if (!holds_velocity && !lagrangian.has(c)) {
      throw argument_error("coordinates", fmt::format("({}) holds neither {} nor its velocity: it says nothing of that coordinate",
                                                      reference_of(call, "lagrangian"), c.get_name()));
    }
    lhs(static_cast<unsigned>(k), 0) = lagrangian.diff(c);
  }
  const std::string what = fmt::format("({}) does not depend on {}: its partial derivative by each is 0, so each conjugate momentum "
                                       "(its partial derivative by the velocity) is constant along the Euler-Lagrange equations",
                                       reference_of(call, "lagrangian"), names_of(coordinates));
  decider_evidence e = identity_evidence(read, "cyclic", what, lhs, GiNaC::matrix(static_cast<unsigned>(coordinates.size()), 1), "", verdict::erratum);
  if (e.found_false()) {
    std::string depends;
    for (std::size_t k = 0; k < coordinates.size(); ++k) {
      const ex d = GiNaC::normal(lhs(static_cast<unsigned>(k), 0));
      if (!d.is_zero()) depends += (depends.empty() ? "" : "; ") + fmt::format("d({})/d{} = {}", reference_of(call, "lagrangian"), coordinates[k].get_name(), text_of(d));
    }
    e.found.correction = "as derived: not cyclic: " + depends;
  }
  return e;
}

std::vector<proof_shape> variational_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  add({"symplectic-step",
       "the one-step map the printed relations define is symplectic, by implicit differentiation of the relations (their functions left general): "
       "M^T J M = J, or det M = the printed value",
       "jacobian",
       with_where({{"jacobian", argument_kind::formula, true,
                    "the printed Jacobian \\frac{\\partial(q_r, p_r)}{\\partial(q_l, p_l)} of the step, or its \\det: the names of the step's data and unknowns"},
                   {"equals", argument_kind::formula, false, "the printed value of its \\det (1)"},
                   {"relations", argument_kind::equations, true, "the printed equations that define the step, as many as its unknowns"},
                   {"internal", argument_kind::symbols, false, "the internal nodes the relations solve along the way (q_m)"}}),
       symplectic_step_shape});
  add({"discrete-noether",
       "the discrete Lagrangian is invariant under shifting the coordinate at every node (the sum of its partial derivatives is 0), and the printed "
       "momenta at the step's ends agree wherever the internal nodes' equations hold",
       "end",
       with_where({{"lagrangian", argument_kind::formula, true, "the discrete Lagrangian of one step, in the nodes"},
                   {"coordinate", argument_kind::symbols, true, "the coordinate's value at every node of the step (psi_l, psi_m, psi_r)"},
                   {"internal", argument_kind::symbols, false, "those of its nodes that are internal, each stationary (psi_m)", 0, "", false, {}, "coordinate"},
                   {"start", argument_kind::formula, true, "the printed momentum at the step's start (p_l, = -dL_h/dpsi_l)"},
                   {"end", argument_kind::formula, true, "the printed momentum at the step's end (p_r, = dL_h/dpsi_r)"}}),
       discrete_noether_shape});
  add({"cyclic",
       "the Lagrangian does not depend on the coordinates (its partial derivative by each is 0): each is cyclic, and its conjugate momentum is "
       "a constant of the motion",
       "lagrangian",
       with_where({{"lagrangian", argument_kind::formula, true, "the Lagrangian, in the coordinates and their velocities"},
                   {"coordinates", argument_kind::symbols, true, "the coordinates said cyclic (\\phi, \\psi)"}}),
       cyclic_shape});
  return all;
}

}  // namespace simpson::verify::detail

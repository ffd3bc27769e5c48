// The GiNaC kernel's helpers shared by every check and shape: see printed_check_support.hpp.

#include <simpson/prove/printed_check_support.hpp>

#include <simpson/verify/tex_math.hpp>

#include <algorithm>

namespace simpson::verify::detail {

using GiNaC::ex;

std::string text_of(const ex& e) { return canonical_text(e); }

ex sym(const std::string& name) { return paper_symbols()[name]; }

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


proof_goal sign_goal(const std::string& name, const ex& lhs, int sign, std::vector<ex> positive, GiNaC::exmap inside) {
  proof_goal g;
  g.name = name;
  g.lhs = lhs;
  g.rhs = 0;
  g.sign = sign;
  g.factored = GiNaC::factor(GiNaC::normal(lhs));
  g.inside = std::move(inside);
  bool in_region = true;
  for (const ex& e : positive) {
    const ex at = GiNaC::normal(e.subs(g.inside));
    in_region = in_region && GiNaC::is_a<GiNaC::numeric>(at) && GiNaC::ex_to<GiNaC::numeric>(at).is_positive();
  }
  const ex at = GiNaC::normal(lhs.subs(g.inside) * sign);
  g.holds = in_region && GiNaC::is_a<GiNaC::numeric>(at) && GiNaC::ex_to<GiNaC::numeric>(at).is_positive();
  g.positive = std::move(positive);
  return g;
}

std::string without_coq_statement(const std::string& coq_none, const std::string& otherwise) { return coq_none.empty() ? otherwise : coq_none; }

/// The polynomial part of e (its Order terms dropped) and the order k of its O(h^k), 0 when none.
std::pair<GiNaC::ex, int> split_order(const GiNaC::ex& e, const GiNaC::ex& h) {
  const ex expanded = GiNaC::expand(e);
  ex terms = 0;
  int order = 0;
  for (std::size_t k = 0; k < (GiNaC::is_a<GiNaC::add>(expanded) ? expanded.nops() : 1); ++k) {
    const ex term = GiNaC::is_a<GiNaC::add>(expanded) ? expanded.op(k) : expanded;
    if (GiNaC::is_a<GiNaC::function>(term) && GiNaC::ex_to<GiNaC::function>(term).get_name() == "Order") {
      order = term.op(0).degree(h);
    } else {
      terms += term;
    }
  }
  return {terms, order};
}

}  // namespace simpson::verify::detail

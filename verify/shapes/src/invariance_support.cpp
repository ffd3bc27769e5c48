// The invariance shapes' shared work: invariance_support.hpp.

#include "invariance_support.hpp"

#include <simpson/prove/printed_check_support.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace simpson::verify::detail::invariance {

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

ex written_determinant(const GiNaC::matrix& m) {
  if (m.rows() == 1) return m(0, 0);
  ex sum = 0;
  for (unsigned c = 0; c < m.cols(); ++c) sum += (c % 2 ? -1 : 1) * m(0, c) * written_determinant(minor_matrix(m, 0, c));
  return sum;
}

ex rows_times(const std::vector<ex>& monomials, const GiNaC::matrix& m, const std::vector<ex>& v) {
  ex sum = 0;
  for (unsigned k = 0; k < m.rows(); ++k) {
    for (unsigned u = 0; u < m.cols(); ++u) sum += monomials[k] * m(k, u) * v[u];
  }
  return sum;
}

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

}  // namespace simpson::verify::detail::invariance

namespace simpson::verify::detail {

/// What the invariance shapes share besides the printed formula they judge: the quadratic form, the
/// map it is invariant under, the state and the form's coefficients.
std::vector<shape_parameter> with_invariance(shape_parameter printed) {
  return {std::move(printed),
          {"form", argument_kind::formula, true, "the quadratic form of the state, its coefficients the unknowns"},
          {"map", argument_kind::matrix, true, "the one-step map"},
          {"state", argument_kind::symbols, true, "the state's symbols, in the map's order", 0, "map"},
          {"unknowns", argument_kind::symbols, true, "the form's coefficients: the system's unknowns (as many as the y_i y_j for its determinant)"}};
}

/// The printed conditions a shape puts in, each solved for one symbol of `solve_for`, in order.
std::vector<shape_parameter> with_conditions(std::vector<shape_parameter> parameters) {
  parameters.push_back({"conditions", argument_kind::equations, true, "printed equations a = b (alpha delta - beta gamma = 1), put in in order"});
  parameters.push_back({"solve_for", argument_kind::symbols, true, "the symbol each condition is solved for (linear in it)", 0, "conditions"});
  return parameters;
}

}  // namespace simpson::verify::detail

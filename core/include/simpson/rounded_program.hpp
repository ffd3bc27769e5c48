#pragma once
// A floating-point step as a straight-line program (issue 29): the operations a stepper executes,
// in order, each result rounded to the working format. One description serves twice:
//   - evaluated in a format by evaluate() (core/tests/rounded_program_test.cpp checks that it agrees
//     bit for bit with the stepper, and that a reordered program does not);
//   - written as a Gappa script (verify/floating/gappa_script.hpp) that bounds its round-off.
// The programs of the steppers whose round-off is proved: Φ₃ and Newmark as matrices
// (one_step_map.hpp's operator*), Φ₃ in shear form (shear_form.hpp's shear_step) and VeriNum's
// leapfrog (verinum_leapfrog.hpp).

#include <simpson/one_step_map.hpp>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace simpson {

enum class rounded_op { add, sub, mul, neg };

/// target = round(left op right); for neg, target = −left (exact).
struct rounded_instruction {
  std::string target;
  rounded_op op;
  std::string left;
  std::string right;
};

struct rounded_program {
  std::string name;
  std::vector<std::string> coefficients;  // the stepper's stored coefficients: values of the format
  std::vector<rounded_instruction> body;  // in order; reads "p", "q", coefficients and earlier targets
  std::string p_result, q_result;         // the names holding the new p and q
};

/// The program evaluated in Real (each operation rounded to Real, as the stepper's are) from the
/// state y and the coefficients' values. Throws std::invalid_argument for a name never assigned.
template <class Real>
phase_point<Real> evaluate(const rounded_program& program, const std::map<std::string, Real>& coefficients,
                           const phase_point<Real>& y) {
  std::map<std::string, Real> values = coefficients;
  values["p"] = y.p;
  values["q"] = y.q;
  const auto at = [&](const std::string& name) -> const Real& {
    const auto it = values.find(name);
    if (it == values.end()) throw std::invalid_argument("rounded program " + program.name + ": '" + name + "' is not assigned");
    return it->second;
  };
  for (const rounded_instruction& i : program.body) {
    Real r;
    switch (i.op) {
      case rounded_op::add: r = at(i.left) + at(i.right); break;
      case rounded_op::sub: r = at(i.left) - at(i.right); break;
      case rounded_op::mul: r = at(i.left) * at(i.right); break;
      case rounded_op::neg: r = -at(i.left); break;
    }
    values[i.target] = r;
  }
  return {at(program.p_result), at(program.q_result)};
}

/// The matrix of a program's map, from the unit states (the map is linear in (p, q) for every
/// program here; in exact rationals it is the map's exact matrix).
template <class Real>
one_step_matrix<Real> matrix_of(const rounded_program& program, const std::map<std::string, Real>& coefficients) {
  const phase_point<Real> from_p = evaluate(program, coefficients, {Real(1), Real(0)});
  const phase_point<Real> from_q = evaluate(program, coefficients, {Real(0), Real(1)});
  return {from_p.p, from_q.p, from_p.q, from_q.q};
}

/// A one-step matrix applied to (p, q): p' = α p + β q, q' = γ p + δ q (Φ₃, Newmark).
inline rounded_program matrix_program(const std::string& name) {
  return {name,
          {"alpha", "beta", "gamma", "delta"},
          {{"ap", rounded_op::mul, "alpha", "p"},
           {"bq", rounded_op::mul, "beta", "q"},
           {"p1", rounded_op::add, "ap", "bq"},
           {"gp", rounded_op::mul, "gamma", "p"},
           {"dq", rounded_op::mul, "delta", "q"},
           {"q1", rounded_op::add, "gp", "dq"}},
          "p1",
          "q1"};
}

/// Φ₃ in shear form: q += c p, p += b q, q += c p (c the drift, b the kick).
inline rounded_program shear_program() {
  return {"phi3-shear",
          {"c", "b"},
          {{"cp", rounded_op::mul, "c", "p"},
           {"q1", rounded_op::add, "q", "cp"},
           {"bq", rounded_op::mul, "b", "q1"},
           {"p1", rounded_op::add, "p", "bq"},
           {"cp1", rounded_op::mul, "c", "p1"},
           {"q2", rounded_op::add, "q1", "cp1"}},
          "p1",
          "q2"};
}

/// VeriNum's leapfrog (verinum_leapfrog.hpp), its constants computed from h and 0.5 as in C.
inline rounded_program verinum_leapfrog_program() {
  return {"leapfrog-verinum",
          {"h", "half"},
          {{"a", rounded_op::neg, "q", ""},
           {"hp", rounded_op::mul, "h", "p"},
           {"s1", rounded_op::add, "q", "hp"},
           {"hh", rounded_op::mul, "h", "h"},
           {"c", rounded_op::mul, "half", "hh"},
           {"ca", rounded_op::mul, "c", "a"},
           {"q1", rounded_op::add, "s1", "ca"},
           {"a1", rounded_op::neg, "q1", ""},
           {"s2", rounded_op::add, "a", "a1"},
           {"d", rounded_op::mul, "half", "h"},
           {"ds", rounded_op::mul, "d", "s2"},
           {"p1", rounded_op::add, "p", "ds"}},
          "p1",
          "q1"};
}

/// The coefficients of a matrix program from the stepper's matrix.
template <class Real>
std::map<std::string, Real> matrix_coefficients(const one_step_matrix<Real>& phi) {
  return {{"alpha", phi.alpha}, {"beta", phi.beta}, {"gamma", phi.gamma}, {"delta", phi.delta}};
}

}  // namespace simpson

// A rounded program as a Gappa script (gappa_script.hpp).

#include <simpson/verify/gappa_script.hpp>

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace simpson::verify {

binary_format float32_format() { return {"float32", "ieee_32", 24, 128}; }
binary_format double_format() { return {"double", "ieee_64", 53, 1024}; }

rational exact_binary_value(double x) {
  if (!std::isfinite(x)) throw std::invalid_argument("exact_binary_value: not a finite number");
  int exponent = 0;
  const double mantissa = std::frexp(x, &exponent);  // x = mantissa 2^exponent, |mantissa| in [0.5, 1)
  // 53 bits of the mantissa as an integer, exactly.
  const auto integer = static_cast<long long>(std::ldexp(mantissa, 53));
  const int shift = exponent - 53;
  rational out(integer);
  if (shift >= 0) return out * rational(boost::multiprecision::pow(boost::multiprecision::cpp_int(2), static_cast<unsigned>(shift)));
  return out / rational(boost::multiprecision::pow(boost::multiprecision::cpp_int(2), static_cast<unsigned>(-shift)));
}

std::string gappa_number(const rational& x) {
  using boost::multiprecision::cpp_int;
  cpp_int n = numerator(x), d = denominator(x);
  int exponent = 0;
  while (d > 1 && (d & 1) == 0) {
    d >>= 1;
    --exponent;
  }
  if (d != 1) return "(" + numerator(x).str() + "/" + denominator(x).str() + ")";
  if (n == 0) return "0";
  while ((n & 1) == 0) {
    n >>= 1;
    ++exponent;
  }
  return exponent == 0 ? n.str() : n.str() + "b" + std::to_string(exponent);
}

namespace {

const char* operator_text(rounded_op op) {
  switch (op) {
    case rounded_op::add: return "+";
    case rounded_op::sub: return "-";
    case rounded_op::mul: return "*";
    case rounded_op::neg: return "-";
  }
  return "?";
}

/// Gappa identifiers may not contain '-': the program's names are plain identifiers already, the
/// exact entries get a suffix.
std::string exact_name(const char* entry) { return std::string(entry) + "_exact"; }

/// The ideal twin's name of a program value: the state and the coefficients are their own twins.
std::string ideal_name(const std::string& name, const rounded_program& program) {
  if (name == "p" || name == "q") return name;
  for (const std::string& c : program.coefficients) {
    if (c == name) return name;
  }
  return name + "_ideal";
}

}  // namespace

one_step_matrix<rational> ideal_matrix(const roundoff_problem& problem) { return matrix_of(problem.program, problem.stored); }

std::string largest_finite_text(const binary_format& f) {
  // (2^p − 1) 2^(emax − p): the largest finite number of the format.
  const boost::multiprecision::cpp_int mantissa = (boost::multiprecision::cpp_int(1) << f.mantissa_bits) - 1;
  return mantissa.str() + "b" + std::to_string(f.max_exponent - f.mantissa_bits);
}

std::string gappa_script(const roundoff_problem& problem, const std::optional<claimed_bounds>& claimed) {
  const rounded_program& program = problem.program;
  std::string s = fmt::format("# {}: one step in {}, every operation rounded to nearest-even, against the exact map.\n"
                              "# Generated from the program's description (simpson::rounded_program): not typed.\n",
                              program.name, problem.format.name);
  s += fmt::format("@rnd = float<{}, ne>;\n\n", problem.format.gappa);
  s += "# The stored coefficients: their values in the format, exactly.\n";
  for (const std::string& c : program.coefficients) {
    const auto it = problem.stored.find(c);
    if (it == problem.stored.end()) throw std::invalid_argument("gappa_script: no stored value for coefficient " + c);
    s += fmt::format("{} = {};\n", c, gappa_number(it->second));
  }
  s += "\n# The exact map Phi (its entries exactly).\n";
  const std::pair<const char*, const rational*> entries[] = {
      {"alpha", &problem.exact.alpha}, {"beta", &problem.exact.beta}, {"gamma", &problem.exact.gamma}, {"delta", &problem.exact.delta}};
  for (const auto& [name, value] : entries) s += fmt::format("{} = {};\n", exact_name(name), gappa_number(*value));
  s += "\n# The state: numbers of the format.\np = rnd(p_input);\nq = rnd(q_input);\n\n# The step, operation by operation.\n";
  for (const rounded_instruction& i : program.body) {
    if (i.op == rounded_op::neg) {
      s += fmt::format("{} = -{};\n", i.target, i.left);
    } else {
      s += fmt::format("{} = rnd({} {} {});\n", i.target, i.left, operator_text(i.op), i.right);
    }
  }
  s += "\n# The same operations without rounding: the ideal twin of each.\n";
  for (const rounded_instruction& i : program.body) {
    if (i.op == rounded_op::neg) {
      s += fmt::format("{} = -{};\n", ideal_name(i.target, program), ideal_name(i.left, program));
    } else {
      s += fmt::format("{} = {} {} {};\n", ideal_name(i.target, program), ideal_name(i.left, program), operator_text(i.op),
                       ideal_name(i.right, program));
    }
  }
  s += fmt::format("\np_exact = alpha_exact * p + beta_exact * q;\nq_exact = gamma_exact * p + delta_exact * q;\n\n");
  const std::string box = fmt::format("p in [{}, {}] /\\ q in [{}, {}]", gappa_number(-problem.p_bound), gappa_number(problem.p_bound),
                                      gappa_number(-problem.q_bound), gappa_number(problem.q_bound));
  std::string goal;
  const std::string largest = largest_finite_text(problem.format);
  if (claimed) {
    goal = fmt::format("{} - p_exact in [{}, {}] /\\ {} - q_exact in [{}, {}]", program.p_result, gappa_number(-claimed->p),
                       gappa_number(claimed->p), program.q_result, gappa_number(-claimed->q), gappa_number(claimed->q));
    // No overflow: every intermediate strictly inside the format's range (Gappa's formats have none).
    for (const rounded_instruction& i : program.body) {
      if (i.op != rounded_op::neg) goal += fmt::format(" /\\ |{}| <= {}", i.target, largest);  // a negation is exact
    }
  } else {
    goal = fmt::format("{} - p_exact in ? /\\ {} - q_exact in ?", program.p_result, program.q_result);
    for (const rounded_instruction& i : program.body) {
      if (i.op != rounded_op::neg) goal += fmt::format(" /\\ {} in ?", i.target);
    }
  }
  s += fmt::format("{{ {} ->\n  {} }}\n\n", box, goal);
  // Hints: each error is the rounding (the program against its ideal twin, which Gappa bounds
  // operation by operation) plus the ideal twin against Φ, a linear form whose coefficients are
  // the differences of the stored coefficients' exact map and Φ, computed here exactly (Gappa
  // checks each rewriting is an identity; gappa_run refuses one it cannot).
  const one_step_matrix<rational> ideal = ideal_matrix(problem);
  const std::string p_ideal = ideal_name(program.p_result, program), q_ideal = ideal_name(program.q_result, program);
  s += fmt::format("{} - p_exact -> ({} - {}) + ({} - p_exact);\n", program.p_result, program.p_result, p_ideal, p_ideal);
  s += fmt::format("{} - q_exact -> ({} - {}) + ({} - q_exact);\n", program.q_result, program.q_result, q_ideal, q_ideal);
  s += fmt::format("{} - p_exact -> {} * p + {} * q;\n", p_ideal, gappa_number(ideal.alpha - problem.exact.alpha),
                   gappa_number(ideal.beta - problem.exact.beta));
  s += fmt::format("{} - q_exact -> {} * p + {} * q;\n", q_ideal, gappa_number(ideal.gamma - problem.exact.gamma),
                   gappa_number(ideal.delta - problem.exact.delta));
  return s;
}

}  // namespace simpson::verify

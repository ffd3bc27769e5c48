// The steppers' round-off problems (stepper_roundoff.hpp).

#include <simpson/verify/stepper_roundoff.hpp>

#include <simpson/newmark_map.hpp>
#include <simpson/shear_form.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/verinum_leapfrog.hpp>

#include <boost/math/constants/constants.hpp>

#include <cmath>
#include <random>
#include <stdexcept>

namespace simpson::verify {

const std::vector<std::string>& proved_steppers() {
  static const std::vector<std::string> names{"phi3-matrix", "phi3-shear", "newmark-matrix", "leapfrog-verinum"};
  return names;
}

rational paper_omega() {
  return exact_binary_value(boost::math::constants::two_pi<double>());
}

namespace {

/// A rational parameter as the format holds it: numerator and denominator converted, then divided
/// (as a program reading "1/10" would compute it).
template <class Real>
Real in_format(const rational& x) {
  return Real(static_cast<Real>(numerator(x))) / Real(static_cast<Real>(denominator(x)));
}

template <class Real>
std::map<std::string, rational> exactly(const std::map<std::string, Real>& values) {
  std::map<std::string, rational> out;
  for (const auto& [name, v] : values) out[name] = exact_binary_value(static_cast<double>(v));
  return out;
}

template <class Real>
roundoff_problem problem_in(const std::string& stepper, const binary_format& format, const rational& m, const rational& omega,
                            const rational& h) {
  const oscillator_parameters<Real> par{in_format<Real>(m), in_format<Real>(omega), in_format<Real>(h)};
  const oscillator_parameters<rational> exact{m, omega, h};
  roundoff_problem out;
  out.format = format;
  if (stepper == "phi3-matrix" || stepper == "newmark-matrix") {
    const bool simpson = stepper == "phi3-matrix";
    out.program = matrix_program(stepper);
    out.stored = exactly(matrix_coefficients(simpson ? simpson_map(par) : newmark_map(par)));
    out.exact = simpson ? simpson_map(exact) : newmark_map(exact);
  } else if (stepper == "phi3-shear") {
    const shear_coefficients<Real> s = simpson_shear_coefficients(par);
    out.program = shear_program();
    out.stored = exactly(std::map<std::string, Real>{{"c", s.drift}, {"b", s.kick}});
    out.exact = simpson_map(exact);
  } else if (stepper == "leapfrog-verinum") {
    if (m != 1 || omega != 1) throw std::invalid_argument("leapfrog-verinum: VeriNum's program has m = omega = 1");
    out.program = verinum_leapfrog_program();
    out.stored = exactly(std::map<std::string, Real>{{"h", par.h()}, {"half", Real(0.5)}});
    out.exact = matrix_of<rational>(out.program, {{"h", h}, {"half", rational(1, 2)}});
  } else {
    throw std::invalid_argument("unknown stepper '" + stepper + "' (expected phi3-matrix, phi3-shear, newmark-matrix, leapfrog-verinum)");
  }
  return out;
}

}  // namespace

roundoff_problem stepper_roundoff_problem(const std::string& stepper, const std::string& format, const rational& m,
                                          const rational& omega, const rational& h, const rational& p_bound,
                                          const rational& q_bound) {
  roundoff_problem out;
  if (format == "float32") {
    out = problem_in<float>(stepper, float32_format(), m, omega, h);
  } else if (format == "double") {
    out = problem_in<double>(stepper, double_format(), m, omega, h);
  } else {
    throw std::invalid_argument("unknown format '" + format + "' (expected float32, double)");
  }
  out.p_bound = p_bound;
  out.q_bound = q_bound;
  return out;
}

}  // namespace simpson::verify

namespace simpson::verify {
namespace {

template <class Real>
claimed_bounds measured_in(const roundoff_problem& problem, int samples, unsigned long long seed) {
  std::map<std::string, Real> stored;
  for (const auto& [name, value] : problem.stored) stored[name] = static_cast<Real>(value);  // exact: the format's own values
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const double P = static_cast<double>(problem.p_bound), Q = static_cast<double>(problem.q_bound);
  claimed_bounds worst{rational(0), rational(0)};
  for (int k = 0; k < samples; ++k) {
    const phase_point<Real> y{static_cast<Real>(u(g) * P), static_cast<Real>(u(g) * Q)};
    const phase_point<Real> computed = evaluate(problem.program, stored, y);
    const phase_point<rational> exact =
        problem.exact * phase_point<rational>{exact_binary_value(static_cast<double>(y.p)), exact_binary_value(static_cast<double>(y.q))};
    const rational ep = abs(exact_binary_value(static_cast<double>(computed.p)) - exact.p);
    const rational eq = abs(exact_binary_value(static_cast<double>(computed.q)) - exact.q);
    if (ep > worst.p) worst.p = ep;
    if (eq > worst.q) worst.q = eq;
  }
  return worst;
}

}  // namespace

claimed_bounds measured_roundoff(const roundoff_problem& problem, int samples, unsigned long long seed) {
  return problem.format.mantissa_bits == 24 ? measured_in<float>(problem, samples, seed) : measured_in<double>(problem, samples, seed);
}

std::string decimal_text(const rational& x, int digits) {
  using real = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<50>>;
  return real(real(numerator(x)) / real(denominator(x))).str(digits - 1, std::ios_base::scientific);  // digits − 1 after the point
}

std::string decimal_rounded_up(const rational& x, int digits) {
  using boost::multiprecision::cpp_int;
  if (x == 0) return "0";
  const bool negative = x < 0;
  const rational a = negative ? rational(-x) : x;
  // The decimal exponent e with 10^e <= a < 10^(e+1).
  int e = static_cast<int>(std::floor(std::log10(static_cast<double>(a))));
  const auto power = [](int k) { return rational(boost::multiprecision::pow(cpp_int(10), static_cast<unsigned>(k < 0 ? -k : k))); };
  const auto scaled = [&](int k) { return k >= 0 ? rational(a / power(k)) : rational(a * power(k)); };
  while (scaled(e) >= 10) ++e;
  while (scaled(e) < 1) --e;
  // m = ceil(a / 10^(e − digits + 1)) (for a negative x, the floor of |x|'s: still outward).
  const rational units = scaled(e - digits + 1);
  cpp_int m = numerator(units) / denominator(units);
  if (!negative && rational(m) < units) ++m;
  std::string text = m.str();
  if (static_cast<int>(text.size()) > digits) {  // 9.99… rounded up to 10.0…
    text = text.substr(0, static_cast<std::size_t>(digits));
    ++e;
  }
  const std::string mantissa = text.size() > 1 ? text.substr(0, 1) + "." + text.substr(1) : text;
  return (negative ? "-" : "") + mantissa + "e" + (e < 0 ? "-" : "+") + (std::abs(e) < 10 ? "0" : "") + std::to_string(std::abs(e));
}

}  // namespace simpson::verify

#pragma once
// The grid lemma of our kernel's proofs, with its premise computed. A difference D that is a
// polynomial of degree ≤ d_i in each further variable x_i (coefficients rational functions of θ)
// and vanishes on a grid of d_i + 1 values of each is zero. Our kernel evaluates D on the grid; the
// premise (that D is such a polynomial) is computed by running the same generic code once more
// with GiNaC, every grid variable and θ a symbol: the normal form of each difference must have a
// denominator free of the grid variables and a degree ≤ d_i in each.
//
// A difference is written once, generic over the scalar S: `f(values)` with `values` a
// std::vector<S>, S our kernel's `symbolic` (the grid) or GiNaC::ex (the premise). Inside it the
// oscillator m = ω = 1, h = θ and θ itself come from theta_oscillator<S>() and theta_variable<S>().

#include <simpson/verify/exact_proof.hpp>

#include <simpson/oscillator_parameters.hpp>

#include <ginac/ginac.h>

#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace simpson::verify::detail {

/// The premise run's scalar.
template <class S>
inline constexpr bool is_ginac_v = std::is_same_v<S, GiNaC::ex>;

/// θ: our kernel's variable, or the premise run's symbol.
inline const GiNaC::symbol& theta_symbol() {
  static const GiNaC::symbol theta("theta");
  return theta;
}

template <class S>
S theta_variable() {
  if constexpr (is_ginac_v<S>) {
    return GiNaC::ex(theta_symbol());
  } else {
    return symbolic::variable();
  }
}

/// m = ω = 1, h = θ (exact_proof.hpp's unit_oscillator_in_theta) in either scalar.
template <class S>
oscillator_parameters<S> theta_oscillator() {
  if constexpr (is_ginac_v<S>) {
    return {GiNaC::ex(1), GiNaC::ex(1), theta_variable<S>()};
  } else {
    return unit_oscillator_in_theta();
  }
}

/// A premise of our kernel's proof that the premise run found false (a difference that is not a
/// polynomial of the stated degree, a derivative by differences of a function of too high a degree).
class premise_failure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The symbolic value of an exact-difference derivative, (4 D(1) − D(2)) / 3 with D(e) the central
/// difference: exact when f is a polynomial of degree ≤ 4 in the differentiated variable. In the
/// premise run that is computed (f at a fresh symbol) and a premise_failure thrown when false.
template <class F, class S>
S exact_derivative(F&& f, const S& at) {
  if constexpr (is_ginac_v<S>) {
    const GiNaC::symbol u("exact_derivative_variable");
    const GiNaC::ex of_u = f(GiNaC::ex(u));
    // Expanded first (cheap; exact when it is already a polynomial of low degree), the normal form
    // only when the expansion is not.
    const GiNaC::ex expanded = GiNaC::expand(of_u);
    if (!(expanded.is_polynomial(u) && expanded.degree(u) <= 4)) {
      const GiNaC::ex normal = GiNaC::normal(of_u);
      if (GiNaC::denom(normal).has(u) || GiNaC::expand(GiNaC::numer(normal)).degree(u) > 4) {
        throw premise_failure("a derivative by exact differences of a function that is not a polynomial of degree <= 4 in its variable");
      }
    }
  }
  const S d1 = (f(at + 1) - f(at - 1)) / 2;
  const S d2 = (f(at + 2) - f(at - 2)) / 4;
  return (4 * d1 - d2) / 3;
}

/// The differences of one evaluation as a list (f returns one, or a std::vector of several).
template <class S, class Value>
std::vector<S> differences_of(const Value& value) {
  if constexpr (std::is_same_v<std::decay_t<Value>, std::vector<S>>) {
    return value;
  } else {
    return {S(value)};
  }
}

/// The premise, computed: each difference f returns with every grid variable a GiNaC symbol is a
/// polynomial in them of degree ≤ its bound. Returns whether it holds; one line of evidence into
/// `evidence` ("holds (GiNaC): degrees x 1, y 0", or "fails (GiNaC): " and why).
template <class F, class Json>
bool grid_premise_holds(const std::vector<std::string>& variables, const std::vector<int>& bounds, F&& f, Json& evidence) {
  std::vector<GiNaC::symbol> symbols;
  std::vector<GiNaC::ex> values;
  for (const std::string& name : variables) {
    symbols.emplace_back(name);
    values.emplace_back(symbols.back());
  }
  std::vector<int> degrees(variables.size(), 0);
  std::string failure;
  bool all_zero = true, all_expanded = true;
  try {
    for (const GiNaC::ex& difference : differences_of<GiNaC::ex>(f(values))) {
      // The expanded form first: when it is a polynomial in the grid variables within the bounds,
      // so is the difference (its terms' coefficients may be rational in theta). Otherwise the
      // normal form decides (a denominator in a grid variable, or a degree that cancels). The
      // expansion is the cheap one: 7-variable polynomials of Section 7 normalise ten times slower.
      const GiNaC::ex expanded = GiNaC::expand(difference);
      std::vector<int> expanded_degrees(symbols.size(), 0);
      bool within = true;
      for (std::size_t k = 0; k < symbols.size() && within; ++k) {
        within = expanded.is_polynomial(symbols[k]) && (expanded_degrees[k] = expanded.degree(symbols[k])) <= bounds[k];
      }
      if (within) {
        all_zero = all_zero && expanded.is_zero();
        for (std::size_t k = 0; k < symbols.size(); ++k) degrees[k] = std::max(degrees[k], expanded_degrees[k]);
        continue;
      }
      all_expanded = false;
      const GiNaC::ex normal = GiNaC::normal(difference);
      all_zero = all_zero && normal.is_zero();
      const GiNaC::ex numerator = GiNaC::expand(GiNaC::numer(normal)), denominator = GiNaC::denom(normal);
      for (std::size_t k = 0; k < symbols.size(); ++k) {
        if (denominator.has(symbols[k])) {
          failure = "a difference has " + variables[k] + " in its denominator: not a polynomial in it";
        } else {
          degrees[k] = std::max(degrees[k], numerator.degree(symbols[k]));
        }
      }
    }
  } catch (const premise_failure& e) {
    failure = e.what();
  }
  // One line of evidence per proof (the report shows 55 of them): what was found, and the verdict.
  bool holds = failure.empty();
  std::string found;
  for (std::size_t k = 0; k < variables.size(); ++k) {
    const bool within = degrees[k] <= bounds[k];
    holds = holds && within;
    found += (k ? ", " : "") + variables[k] + " " + std::to_string(degrees[k]) + (within ? "" : " > " + std::to_string(bounds[k]));
  }
  if (!failure.empty()) {
    evidence = "fails (GiNaC): " + failure;
  } else if (all_zero) {
    evidence = "holds (GiNaC): every difference is 0";
  } else {
    evidence = std::string(holds ? "holds" : "fails") + " (GiNaC, " + (all_expanded ? "expanded" : "normal form") + "): degrees " + found;
  }
  return holds;
}

}  // namespace simpson::verify::detail

#pragma once
// A stepper's one-step round-off as a Gappa script (issue 29), written from its rounded program
// (core's rounded_program.hpp: the one description of the operations, also checked bit for bit
// against the stepper). Gappa bounds
//   fl(step(y)) − Φ y
// over a stated box of states y (floating-point numbers of the format), where fl(step) is the
// program with every operation rounded to nearest-even in the format and its coefficients as the
// stepper stores them (exact binary values), and Φ is the scheme's exact map (rational entries): the
// bound covers the rounding of the coefficients themselves (Φ̂ against Φ) and of every operation.
// Gappa's formats have no overflow: the script also asks for every intermediate's range, and the
// run (gappa_run.hpp) proves them below the format's largest finite number.

#include <simpson/one_step_map.hpp>
#include <simpson/precision.hpp>
#include <simpson/rounded_program.hpp>

#include <map>
#include <optional>
#include <string>

namespace simpson::verify {

/// An IEEE binary format: its name in Gappa, its precision and largest finite number's exponent.
struct binary_format {
  std::string name;      // "float32", "double"
  std::string gappa;     // "ieee_32", "ieee_64"
  int mantissa_bits = 53;
  int max_exponent = 1024;  // the largest finite number is below 2^max_exponent
};
binary_format float32_format();
binary_format double_format();

/// What is proved: the program in a format, its stored coefficients, the exact map, and the box
/// |p| ≤ p_bound, |q| ≤ q_bound of input states.
struct roundoff_problem {
  rounded_program program;
  binary_format format;
  std::map<std::string, rational> stored;  // each coefficient's value in the format (a dyadic rational)
  one_step_matrix<rational> exact;         // Φ
  rational p_bound, q_bound;
};

/// The bounds a script claims: |fl(step(y)).p − (Φy).p| ≤ p, the same for q.
struct claimed_bounds {
  rational p, q;
};

/// The Gappa script: without `claimed`, the goal asks Gappa for enclosures of the two errors and
/// of every intermediate ("in ?"); with it, the goal states the claimed bounds and every
/// intermediate's range below the format's largest finite number, for a proof Gappa can export
/// to Coq (gappa -Bcoq).
std::string gappa_script(const roundoff_problem& problem, const std::optional<claimed_bounds>& claimed = std::nullopt);

/// The map the program computes without rounding, from its stored coefficients, exactly (the
/// program evaluated in rationals on the unit states): Φ̂, against which Φ's difference is linear.
one_step_matrix<rational> ideal_matrix(const roundoff_problem& problem);

/// The format's largest finite number in Gappa's notation: (2^p − 1) 2^(emax − p).
std::string largest_finite_text(const binary_format& f);

/// A dyadic rational in Gappa's binary notation ("825b-62"), any other rational as "(n/d)".
std::string gappa_number(const rational& x);

/// The exact value of a float or double, a dyadic rational.
rational exact_binary_value(double x);

}  // namespace simpson::verify

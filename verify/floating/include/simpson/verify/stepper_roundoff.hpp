#pragma once
// The round-off problems of the steppers issue 29 proves (gappa_script.hpp): Φ₃ as a matrix and in
// shear form, Newmark as a matrix, and VeriNum's leapfrog, in float32 and double, at rational
// parameters. The stored coefficients are the stepper's own (computed in the format by the core's
// formulas); the exact map is the same formula in exact rationals at the intended parameters, so the
// bound covers the rounding of the parameters and coefficients too.

#include <simpson/verify/gappa_script.hpp>

#include <string>
#include <vector>

namespace simpson::verify {

/// The steppers: "phi3-matrix", "phi3-shear", "newmark-matrix", "leapfrog-verinum".
const std::vector<std::string>& proved_steppers();

/// The paper's ω = 2π (Section 8) as an exact rational: 2π rounded to double, the ω a double program
/// holds (a float32 program holds it rounded again to float32). Small rationals keep Gappa's and
/// Coq's constants short; the scheme's difference from Φ at 2π itself is enclosed with the
/// discretization error (global_roundoff.hpp's flow_oscillator).
rational paper_omega();

/// The problem of `stepper` in `format` ("float32" or "double") at m, ω, h (leapfrog-verinum: m = ω
/// = 1 only, as VeriNum's program), on the box |p| ≤ p_bound, |q| ≤ q_bound. Throws
/// std::invalid_argument for an unknown stepper or format, or leapfrog with m or ω other than 1.
roundoff_problem stepper_roundoff_problem(const std::string& stepper, const std::string& format, const rational& m,
                                          const rational& omega, const rational& h, const rational& p_bound,
                                          const rational& q_bound);

}  // namespace simpson::verify

namespace simpson::verify {

/// The largest one-step errors seen: the program run in its format (float or double) from `samples`
/// random states of the box (fixed seed), each result against Φ y exactly (rationals).
claimed_bounds measured_roundoff(const roundoff_problem& problem, int samples, unsigned long long seed);

/// x as a decimal with `digits` significant digits, rounded to nearest (from 50-digit MPFR, not
/// through double): a figure computed exactly, for people.
std::string decimal_text(const rational& x, int digits = 3);

/// x as a decimal with `digits` significant digits, rounded up (a bound shown is never below the
/// bound proved); 0 as "0".
std::string decimal_rounded_up(const rational& x, int digits = 3);

}  // namespace simpson::verify

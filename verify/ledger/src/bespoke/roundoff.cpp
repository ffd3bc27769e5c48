// Table 1's digits against the proved round-off of a double program: what a double program stepping
// Φ₃ can do to the paper's Table 1, proved by Gappa and the lifting lemma (verify/floating), not measured.
//
// For each mesh N of Table 1, Φ₃ at the paper's configuration (m = 1, ω = 2π, h = 1/N) stepped in
// double: Gappa bounds one step's round-off on a box 9/8 of the amplitudes of the orbit that
// reproduces Table 1 (the simplest hypothesis of table-values' convention search: from rest at
// q₀ = π/2, m = 1, on the embedded paper), the bound is lifted over N steps in the norm of Φ₃'s invariant form, and the
// result, n ε c for every n ≤ N, bounds how far the double iterates can be from the exact scheme's in
// each of p and q over the period. A printed error can only be the scheme's own if that is below half
// a unit of its last printed digit.

#include <simpson/verify/table1_reader.hpp>
#include <simpson/verify/the_paper.hpp>
#include "bespoke_checks.hpp"

#include <simpson/verify/gappa_run.hpp>
#include <simpson/verify/global_roundoff.hpp>
#include <simpson/verify/paper_table.hpp>
#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/stepper_roundoff.hpp>
#include <simpson/verify/table1_conventions.hpp>

#include <boost/math/constants/constants.hpp>

#include <fmt/format.h>

#include <cmath>
#include <sstream>

namespace simpson::verify::detail {
namespace {

/// The rows of Table 1 the claim judges: symplectic Simpson's momentum and state (published_rows()).
constexpr std::array<std::size_t, 2> simpson_rows{1, 3};

/// Half a unit of the last digit of a value printed with `digits` significant digits, exactly.
rational half_unit(double value, int digits) {
  const int exponent = static_cast<int>(std::floor(std::log10(std::abs(value)))) - digits + 1;
  const rational power(boost::multiprecision::pow(boost::multiprecision::cpp_int(10), static_cast<unsigned>(std::abs(exponent))));
  const rational unit = exponent >= 0 ? power : rational(1 / power);
  return unit / 2;
}

/// The text of a Coq file without its Require lines (they are stated once, at the top).
std::string without_requires(const std::string& text) {
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line)) {
    if (line.rfind("Require Import", 0) != 0) out += line + "\n";
  }
  return out;
}

decider_evidence check_table_roundoff(const run_context& ctx) {
  // The run's paper, or the embedded one; text_changed when the rows are gone.
  const printed_table1 printed = read_table1(ctx.paper != nullptr ? ctx.paper->source : embedded_paper());
  const std::array<std::array<double, 3>, 8>& values = printed.values;
  const std::array<std::array<int, 3>, 8>& digits = printed.digits;
  decider_evidence judged;
  claim_result& out = judged.found;
  json meshes = json::array();
  std::string coq = "(* Table 1's meshes: for each N, Gappa's proof of the double program's one-step round-off (module\n"
                    "   Gappa_N<N>, gappa -Bcoq) and the lifting lemma with the harness's constants (module Lifting_N<N>). *)\n"
                    "Require Import Gappa.Gappa_library.\nRequire Import Reals Lra.\n";
  std::vector<std::string> lemmas;
  bool below = true;
  // The orbit of the experiment that reproduces Table 1: the simplest hypothesis of its convention
  // search (table-values), when it keeps the stated discrete conventions; else the stated y₀ = (mω, 0).
  // Its start in double, m exactly, and a box 9/8 of its amplitudes (in eighths, rounded up).
  const std::vector<printed_entry> entries = table1_printed(values, printed.orders, &digits);
  const convention_search_result search = search_table1(entries, stated_table1_solution(ctx), ctx.memo);
  const std::optional<exact_start> start = table1_reproducing_start(search);
  const exact_start orbit = start.value_or(exact_start{});
  const rational m(orbit.m_num, orbit.m_den);
  const double omega_double = boost::math::constants::two_pi<double>(), m_double = orbit.mass(), amplitude = orbit.amplitude();
  const auto eighths_up = [](double x) { return rational(static_cast<long long>(std::ceil(x * 9 / 8 * 8)), 8); };
  const rational box_p = eighths_up(m_double * omega_double * amplitude), box_q = eighths_up(amplitude);
  const phase_point<rational> y0 = orbit.at_rest ? phase_point<rational>{rational(0), exact_binary_value(amplitude)}
                                                 : phase_point<rational>{exact_binary_value(m_double * omega_double * amplitude), rational(0)};
  const std::string orbit_words = start ? "the orbit of the simplest hypothesis that explains Table 1 (table-values): " + table1_start(*search.simplest())
                                        : "the stated orbit y₀ = (mω, 0), m = 1 (no simple hypothesis under the stated discrete conventions explains Table 1)";
  for (std::size_t c = 0; c < published_meshes.size(); ++c) {
    const long long N = published_meshes[c];
    const roundoff_problem problem = stepper_roundoff_problem("phi3-matrix", "double", m, paper_omega(), rational(1, N), box_p, box_q);
    const roundoff_proof proof = prove_roundoff(problem, false);  // coqc by --certify, on this claim's certificate
    if (proof.status == proof_status::skipped) {
      out.evidence["skipped"] = proof.reason;
      return stopped(decider_evidence::reach::tool_missing, std::move(out));
    }
    if (proof.status == proof_status::unproved) {
      out.evidence["unproved"] = fmt::format("N = {}: {}", N, proof.reason);
      return stopped(decider_evidence::reach::not_proved, std::move(out));
    }
    const std::optional<lifting_constants> lifting = lifting_for(problem, proof.bounds, y0);
    if (!lifting || lifting->valid_steps < N) {
      out.evidence["unproved"] = fmt::format("N = {}: {}", N, !lifting ? "Φ₃ conserves no diagonal form in double's parameters"
                                                                     : "the box does not hold the orbit for N steps");
      return stopped(decider_evidence::reach::not_proved, std::move(out));
    }
    const rational bound = rational(N) * lifting->epsilon * lifting->to_euclidean;
    json entries = json::array();
    for (const std::size_t r : simpson_rows) {
      const rational half = half_unit(values[r][c], digits[r][c]);
      const bool ok = bound < half;
      below = below && ok;
      entries.push_back({{"row", published_rows()[r].quantity},
                         {"printed", fmt::format("{:.{}e}", values[r][c], digits[r][c] - 1)},
                         {"half_unit_of_last_digit", decimal_text(half)},
                         {"roundoff_below_it", ok}});
    }
    meshes.push_back({{"N", N},
                      {"one_step_bound", {{"p", decimal_rounded_up(proof.bounds.p)}, {"q", decimal_rounded_up(proof.bounds.q)}}},
                      {"epsilon", decimal_rounded_up(lifting->epsilon)},
                      {"roundoff_bound_over_the_period", decimal_rounded_up(bound)},
                      {"entries", entries}});
    const std::string suffix = "N" + std::to_string(N);
    coq += fmt::format("\nModule Gappa_{}.\n{}End Gappa_{}.\n", suffix, without_requires(proof.certificate), suffix);
    coq += fmt::format("\nModule Lifting_{}.\n{}End Lifting_{}.\n", suffix,
                       without_requires(lifting_lemma_coq(problem, proof.bounds, *lifting)), suffix);
    lemmas.push_back("Gappa_" + suffix + ".l1");
    lemmas.push_back("Lifting_" + suffix + ".lifting");
  }
  judged.own = answer_of(below);
  judged.if_false = verdict::fails;
  out.evidence["floating"] = {
      {"method", fmt::format("Gappa: one step of the double program (Φ₃ as a matrix, its coefficients computed in double from m = {}, "
                             "ω = 2π rounded to double, h = 1/N) against Φ₃ at that ω exactly, on |p| ≤ {}, |q| ≤ {}; lifted over N "
                             "steps from y₀ = ({}, {}) (the start in double) in the norm of Φ₃'s invariant form (the lifting lemma, Coq); "
                             "the bound n ε c holds for every n ≤ N in p and in q; judged exactly against half a unit of each entry's last "
                             "printed digit",
                             m.str(), box_p.str(), box_q.str(), decimal_text(y0.p, 17), decimal_text(y0.q, 17))},
      {"orbit", orbit_words},
      {"meshes", meshes}};
  out.note = "Bounds the double program's distance from the exact scheme over the period, on " + orbit_words +
             "; not the printed table's conventions (table-values) nor the paper's own code.";
  out.certificate = coq;
  out.certificate_lemmas = lemmas;
  return judged;
}

}  // namespace

void add_roundoff_checks(check_registry& checks) {
  checks.add("table-roundoff", check_table_roundoff);
}

}  // namespace simpson::verify::detail

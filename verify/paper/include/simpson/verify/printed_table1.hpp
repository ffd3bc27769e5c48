#pragma once
// Table 1 as a copy of the paper prints it, row by row in the order of the experiments'
// published_rows() (Newmark and Simpson for momentum, state, energy (HH-exact), energy
// (hamiltonien-discret)): the three values of each row ("$ 1.91 \,\, 10^{0} $"), their significant
// digits, and the order cell ("2", "4" or "exact"). Each row is quoted as a sentence
// (quoted_sentence.hpp), so a row that is gone or a cell that does not parse throws text_changed.

#include <simpson/verify/json.hpp>
#include <simpson/verify/paper_source.hpp>

#include <array>
#include <string>

namespace simpson::verify {

struct printed_table1 {
  std::array<std::array<double, 3>, 8> values{};
  std::array<std::array<int, 3>, 8> digits{};  // significant digits of each value as printed
  std::array<std::string, 8> orders;
};

/// The table of `paper`, each row recorded in `quotes` when given. Throws text_changed when a row is
/// gone or its cells do not parse.
printed_table1 read_table1(const paper_source& paper, json* quotes = nullptr);

/// The exact solution the text states for Table 1's experiment, "We have chosen $q(t) = {q}$ and
/// $p(t) = {p}$, with a period $T = {T}$.", its q and p read as TeX (GiNaC): q is taken as
/// amplitude · sin(ω t + phase), from q(0) and q'(0)/ω, with ω = 2π/T.
struct stated_solution {
  std::string q_tex, p_tex;   // as printed
  int line = 0;
  double amplitude = 1, phase = 0, period = 1;
  bool solves = false;        // q'' + ω² q = 0 (GiNaC)
  bool momentum = false;      // p = m dq/dt (GiNaC)
  std::string q_text, p_text, m_dq_dt;  // GiNaC's reading, for the evidence
};

/// The stated solution's sentence the pattern of read_stated_solution finds.
inline constexpr const char* stated_solution_pattern =
    "We have chosen $ \\, q(t) = {q_exact} $ and $ \\, p(t) = {p_exact} $, with a period $ \\, T = {period} $.";

/// The solution `paper` states (recorded in `quotes` when given). Throws text_changed when the
/// sentence is gone, or when q or p does not read, or q's amplitude and phase are not numbers.
stated_solution read_stated_solution(const paper_source& paper, json* quotes = nullptr);

}  // namespace simpson::verify

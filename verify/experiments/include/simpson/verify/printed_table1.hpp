#pragma once
// Table 1 as a copy of the paper prints it, row by row in the order of the experiments'
// published_rows() (Newmark and Simpson for momentum, state, energy (HH-exact), energy
// (hamiltonien-discret)): the three values of each row, their significant digits, and the order
// cell ("2", "4" or "exact"); and the exact solution the text states for the experiment. The book
// reads both from the paper (table1_reader.hpp); the experiment takes them as values.

#include <array>
#include <string>

namespace simpson::verify {

struct printed_table1 {
  std::array<std::array<double, 3>, 8> values{};
  std::array<std::array<int, 3>, 8> digits{};  // significant digits of each value as printed
  std::array<std::string, 8> orders;
};

/// The exact solution the text states for Table 1's experiment, its q and p read as TeX (GiNaC): q
/// is taken as amplitude · sin(ω t + phase), from q(0) and q'(0)/ω, with ω = 2π/T.
struct stated_solution {
  std::string q_tex, p_tex;   // as printed
  int line = 0;
  double amplitude = 1, phase = 0, period = 1;
  bool solves = false;        // q'' + ω² q = 0 (GiNaC)
  bool momentum = false;      // p = m dq/dt (GiNaC)
  std::string q_text, p_text, m_dq_dt;  // GiNaC's reading, for the evidence
};

}  // namespace simpson::verify

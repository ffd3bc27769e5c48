// Table 1 as printed, and the solution the text states for it: see table1_reader.hpp.

#include <simpson/verify/table1_reader.hpp>

#include <simpson/verify/quoted_sentence.hpp>
#include <simpson/verify/tex_math.hpp>

#include <ginac/ginac.h>

#include <cmath>

#include <algorithm>
#include <optional>
#include <utility>

namespace simpson::verify {
namespace {

/// The TeX of Table 1's first two cells for each row, in the order of published_rows().
constexpr std::array<const char*, 8> table_row_labels{
    "Newmark & momentum",         "Symplectic Simpson & momentum",
    "Newmark & state",            "Symplectic Simpson & state",
    "Newmark & energy (\\ref{HH-exact})", "Symplectic Simpson & energy (\\ref{HH-exact})",
    "Newmark & energy (\\ref{hamiltonien-discret})", "Symplectic Simpson & energy (\\ref{hamiltonien-discret})"};

/// A number printed as "1.91 10^{0}" or "1.91 10^{-1}": its value (as the literal 1.91e-1 reads,
/// correctly rounded) and its significant digits; none when the words are not so.
std::optional<std::pair<double, int>> table_number(const std::string& words) {
  const std::size_t space = words.find(' ');
  const std::size_t power = words.find("10^{");
  if (space == std::string::npos || power == std::string::npos || words.back() != '}') return std::nullopt;
  const std::string mantissa = words.substr(0, space), exponent = words.substr(power + 4, words.size() - power - 5);
  if (mantissa.empty() || mantissa.find_first_not_of("0123456789.") != std::string::npos) return std::nullopt;
  try {
    std::size_t used = 0;
    const int e = std::stoi(exponent, &used);
    if (used != exponent.size()) return std::nullopt;
    std::string digits = mantissa;
    digits.erase(std::remove(digits.begin(), digits.end(), '.'), digits.end());
    digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size()));
    return std::make_pair(std::stod(mantissa + "e" + std::to_string(e)), std::max<int>(1, static_cast<int>(digits.size())));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

printed_table1 read_table1(const paper_source& paper, json* quotes) {
  printed_table1 table;
  for (std::size_t k = 0; k < table_row_labels.size(); ++k) {
    const quoted_sentence row =
        quote_sentence(paper, std::string(table_row_labels[k]) + " & {n_ten} & {n_twenty} & {n_forty} & {order} \\\\", quotes);
    const char* holes[] = {"n_ten", "n_twenty", "n_forty"};
    for (std::size_t c = 0; c < 3; ++c) {
      const auto v = table_number(row.words(holes[c]));
      if (!v) row.unparsed(holes[c], "a number printed as 'm 10^{e}'");
      row.record(holes[c], row.words(holes[c]));
      table.values[k][c] = v->first;
      table.digits[k][c] = v->second;
    }
    if (row.words("order") == "exact") {
      row.record("order", "exact");
      table.orders[k] = "exact";
    } else {
      table.orders[k] = std::to_string(row.number("order"));
    }
  }
  return table;
}

stated_solution read_stated_solution(const paper_source& paper, json* quotes) {
  const quoted_sentence said = quote_sentence(paper, stated_solution_pattern, quotes);
  stated_solution s;
  s.q_tex = said.words("q_exact");
  s.p_tex = said.words("p_exact");
  s.line = said.span().line;
  s.period = said.number("period");
  if (s.period <= 0) said.unparsed("period", "a positive period");
  // Read apart from the paper's own symbol table: names here are this sentence's.
  tex_symbols symbols;
  const GiNaC::symbol &t = symbols["t"], &omega = symbols["omega"], &m = symbols["m"];
  GiNaC::ex q, p;
  try {
    q = read_tex(s.q_tex, tex_declarations{}, symbols);
  } catch (const std::exception&) {
    said.unparsed("q_exact", "a function of t in TeX");
  }
  try {
    p = read_tex(s.p_tex, tex_declarations{}, symbols);
  } catch (const std::exception&) {
    said.unparsed("p_exact", "a function of t in TeX");
  }
  const GiNaC::ex dq = GiNaC::diff(q, t);
  s.solves = GiNaC::normal(GiNaC::diff(dq, t) + omega * omega * q).is_zero();
  s.momentum = GiNaC::normal(p - m * dq).is_zero();
  s.q_text = canonical_text(q);
  s.p_text = canonical_text(p);
  s.m_dq_dt = canonical_text(m * dq);
  said.record("q_exact", s.q_text);
  said.record("p_exact", s.p_text);
  // q = A sin(ω t + φ): q(0) = A sin φ, q'(0)/ω = A cos φ, both numbers (ω a positive symbol).
  const GiNaC::ex q0 = GiNaC::normal(q.subs(t == 0)), v0 = GiNaC::normal(dq.subs(t == 0) / omega);
  const GiNaC::ex q0n = GiNaC::evalf(q0), v0n = GiNaC::evalf(v0);
  if (!GiNaC::is_a<GiNaC::numeric>(q0n) || !GiNaC::is_a<GiNaC::numeric>(v0n)) said.unparsed("q_exact", "a number times sin(omega t + phase)");
  const double a = GiNaC::ex_to<GiNaC::numeric>(q0n).to_double(), b = GiNaC::ex_to<GiNaC::numeric>(v0n).to_double();
  s.amplitude = std::hypot(a, b);
  s.phase = std::atan2(a, b);
  if (s.phase < 0) s.phase += 2 * std::acos(-1.0);
  if (!(s.amplitude > 0)) said.unparsed("q_exact", "a solution of nonzero amplitude");
  return s;
}

}  // namespace simpson::verify

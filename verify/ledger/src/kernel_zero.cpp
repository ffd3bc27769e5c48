// Our kernel's decision that an expression is zero: see kernel_zero.hpp.

#include "kernel_zero.hpp"

#include <simpson/verify/exact_proof.hpp>

#include <fmt/format.h>

#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace simpson::verify::detail {
namespace {

/// What our kernel does not compute (a square root, a function application).
class outside_kernel : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

rational rational_of(const GiNaC::numeric& n) {
  if (!n.is_rational()) throw outside_kernel("a number that is not rational");
  std::ostringstream num, den;
  num << n.numer();
  den << n.denom();
  return rational(boost::multiprecision::cpp_int(num.str()), boost::multiprecision::cpp_int(den.str()));
}

symbolic power_of(const symbolic& base, long exponent) {
  symbolic out(1);
  for (long k = 0; k < (exponent < 0 ? -exponent : exponent); ++k) out = out * base;
  return exponent < 0 ? symbolic(1) / out : out;
}

/// The tree as GiNaC holds it, evaluated in our kernel: sums, products, integer powers, rationals
/// and the symbols' values.
symbolic evaluate(const GiNaC::ex& e, const std::map<std::string, symbolic>& values) {
  if (GiNaC::is_a<GiNaC::numeric>(e)) return symbolic(rational_of(GiNaC::ex_to<GiNaC::numeric>(e)));
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    const auto it = values.find(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
    if (it == values.end()) throw std::logic_error("kernel_decides_zero: no value for " + GiNaC::ex_to<GiNaC::symbol>(e).get_name());
    return it->second;
  }
  if (GiNaC::is_a<GiNaC::add>(e)) {
    symbolic sum(0);
    for (const GiNaC::ex& term : e) sum = sum + evaluate(term, values);
    return sum;
  }
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    symbolic product(1);
    for (const GiNaC::ex& factor : e) product = product * evaluate(factor, values);
    return product;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const GiNaC::ex exponent = e.op(1);
    if (!GiNaC::is_a<GiNaC::numeric>(exponent) || !GiNaC::ex_to<GiNaC::numeric>(exponent).is_integer()) {
      throw outside_kernel("a power that is not an integer one");
    }
    return power_of(evaluate(e.op(0), values), GiNaC::ex_to<GiNaC::numeric>(exponent).to_long());
  }
  std::ostringstream text;
  text << e;
  throw outside_kernel("'" + text.str() + "'");
}

struct entry_decision {
  kernel_decision::result outcome = kernel_decision::result::zero;
  std::string evidence;
};

entry_decision decide_entry(const GiNaC::ex& e, std::size_t most_points) {
  std::vector<GiNaC::symbol> symbols;
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (!GiNaC::is_a<GiNaC::symbol>(*it)) continue;
    const GiNaC::symbol& s = GiNaC::ex_to<GiNaC::symbol>(*it);
    bool seen = false;
    for (const GiNaC::symbol& t : symbols) seen = seen || t.get_name() == s.get_name();
    if (!seen) symbols.push_back(s);
  }
  // The premise, from GiNaC: the numerator's degree in each symbol, and the denominator.
  const GiNaC::ex normal = GiNaC::normal(e);
  const GiNaC::ex numerator = GiNaC::expand(GiNaC::numer(normal)), denominator = GiNaC::expand(GiNaC::denom(normal));
  std::vector<int> degrees;
  std::size_t theta = 0;
  for (std::size_t k = 0; k < symbols.size(); ++k) {
    if (!numerator.is_polynomial(symbols[k]) || !denominator.is_polynomial(symbols[k])) {
      throw outside_kernel("not a rational function of " + symbols[k].get_name());
    }
    degrees.push_back(numerator.degree(symbols[k]));
    if (degrees[k] > degrees[theta]) theta = k;
  }
  std::size_t points = 1;
  for (std::size_t k = 0; k < symbols.size(); ++k) {
    if (k == theta) continue;
    points *= static_cast<std::size_t>(degrees[k] + 1);
    if (points > most_points) return {kernel_decision::result::not_applicable, fmt::format("a grid of more than {} points", most_points)};
  }
  std::string grid;
  for (std::size_t k = 0; k < symbols.size(); ++k) {
    if (k != theta) grid += (grid.empty() ? "" : ", ") + fmt::format("{} {}", symbols[k].get_name(), degrees[k] + 1);
  }
  // Three grids in turn (values k + 1, then shifted by 1/7, 2/7): the first whose every point keeps
  // the expression and the denominator defined and the denominator nonzero decides.
  for (int attempt = 0; attempt < 3; ++attempt) {
    std::vector<std::size_t> index(symbols.size(), 0);
    bool defined = true;
    for (;;) {
      std::map<std::string, symbolic> values;
      std::string point;
      for (std::size_t k = 0; k < symbols.size(); ++k) {
        if (k == theta) {
          values[symbols[k].get_name()] = symbolic::variable();
          continue;
        }
        const rational v = rational(static_cast<long>(index[k] + 1)) + rational(attempt, 7);
        values[symbols[k].get_name()] = symbolic(v);
        point += (point.empty() ? "" : ", ") + symbols[k].get_name() + " = " + v.str();
      }
      try {
        if (evaluate(denominator, values).is_zero()) {
          defined = false;
          break;
        }
        if (!evaluate(e, values).is_zero()) {
          return {kernel_decision::result::nonzero,
                  fmt::format("not zero at {}{}", point.empty() ? "" : point + ", ",
                              symbols.empty() ? "a constant" : "as a function of " + symbols[theta].get_name())};
        }
      } catch (const std::domain_error&) {  // a pole of the expression as written at this point
        defined = false;
        break;
      }
      std::size_t k = 0;
      for (; k < symbols.size(); ++k) {
        if (k == theta) continue;
        if (++index[k] <= static_cast<std::size_t>(degrees[k])) break;
        index[k] = 0;
      }
      if (k == symbols.size()) break;
    }
    if (defined) {
      return {kernel_decision::result::zero,
              symbols.empty() ? "zero (a constant)"
                              : fmt::format("zero as a rational function of {} on a grid of {} point(s) ({}; degrees from GiNaC's numerator)",
                                            symbols[theta].get_name(), points, grid.empty() ? "no other symbol" : grid)};
    }
  }
  return {kernel_decision::result::not_applicable, "every grid tried meets a pole of the expression"};
}

}  // namespace

kernel_decision kernel_decides_zero(const GiNaC::ex& given, std::size_t most_points) {
  const GiNaC::ex e = given.evalm();
  std::vector<GiNaC::ex> entries;
  if (GiNaC::is_a<GiNaC::matrix>(e)) {
    const GiNaC::matrix& m = GiNaC::ex_to<GiNaC::matrix>(e);
    for (unsigned r = 0; r < m.rows(); ++r) {
      for (unsigned c = 0; c < m.cols(); ++c) entries.push_back(m(r, c));
    }
  } else {
    entries.push_back(e);
  }
  kernel_decision out;
  out.outcome = kernel_decision::result::zero;
  std::vector<std::string> lines;
  try {
    for (std::size_t k = 0; k < entries.size(); ++k) {
      const entry_decision d = decide_entry(entries[k], most_points);
      const std::string where = entries.size() > 1 ? fmt::format("entry {}: ", k + 1) : "";
      if (d.outcome == kernel_decision::result::nonzero) return {kernel_decision::result::nonzero, where + d.evidence};
      if (d.outcome == kernel_decision::result::not_applicable) return {kernel_decision::result::not_applicable, where + d.evidence};
      lines.push_back(where + d.evidence);
    }
  } catch (const outside_kernel& e) {
    return {kernel_decision::result::not_applicable, std::string("holds what our kernel does not compute: ") + e.what()};
  }
  std::string all;
  for (const std::string& line : lines) all += (all.empty() ? "" : "; ") + line;
  out.evidence = all;
  return out;
}

}  // namespace simpson::verify::detail

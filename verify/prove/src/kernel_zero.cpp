// Our kernel's decision that an expression is zero: see kernel_zero.hpp.

#include <simpson/prove/kernel_zero.hpp>

#include <simpson/verify/exact_proof.hpp>
#include <simpson/verify/formula_reference.hpp>
#include <simpson/verify/tex_math.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>
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

template <class T>
T power_of(const T& base, long exponent) {
  T out(1);
  for (long k = 0; k < (exponent < 0 ? -exponent : exponent); ++k) out = out * base;
  return exponent < 0 ? T(1) / out : out;  // 1/0 throws (cpp_rational: std::overflow_error): a pole
}

/// The tree as GiNaC holds it, evaluated at one point in our kernel's exact arithmetic T (rationals,
/// or rational functions of one free symbol): sums, products, integer powers, rationals and the
/// symbols' values. A subtree met twice (a matrix entry put in twice) is evaluated once (`seen`,
/// keyed by the subtree itself: GiNaC rebuilds the operands of a sum or a product on each visit, so
/// an object's address is no key).
template <class T>
class point_evaluation {
 public:
  explicit point_evaluation(const std::map<std::string, T>& values) : values_(values) {}

  T operator()(const GiNaC::ex& e) {
    if (GiNaC::is_a<GiNaC::numeric>(e)) return T(rational_of(GiNaC::ex_to<GiNaC::numeric>(e)));
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
      const auto it = values_.find(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
      if (it == values_.end()) throw std::logic_error("kernel_decides_zero: no value for " + GiNaC::ex_to<GiNaC::symbol>(e).get_name());
      return it->second;
    }
    const auto it = seen_.find(e);
    if (it != seen_.end()) return it->second;
    T v = compute(e);
    seen_.emplace(e, v);
    return v;
  }

 private:
  T compute(const GiNaC::ex& e) {
    if (GiNaC::is_a<GiNaC::add>(e)) {
      T sum(0);
      for (const GiNaC::ex& term : e) sum = sum + (*this)(term);
      return sum;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
      T product(1);
      for (const GiNaC::ex& factor : e) product = product * (*this)(factor);
      return product;
    }
    if (GiNaC::is_a<GiNaC::power>(e)) {
      const GiNaC::ex exponent = e.op(1);
      if (!GiNaC::is_a<GiNaC::numeric>(exponent) || !GiNaC::ex_to<GiNaC::numeric>(exponent).is_integer()) {
        throw outside_kernel("a power that is not an integer one");
      }
      return power_of((*this)(e.op(0)), GiNaC::ex_to<GiNaC::numeric>(exponent).to_long());
    }
    std::ostringstream text;
    text << e;
    throw outside_kernel("'" + text.str() + "'");
  }

  const std::map<std::string, T>& values_;
  std::map<GiNaC::ex, T, GiNaC::ex_is_less> seen_;
};

/// A bound on the degree in one symbol of the numerator of an expression written as one fraction
/// the way the tree builds it, and its denominator as the factors the tree divides by (each keyed by
/// itself, with its multiplicity and its degree): a sum takes the least common multiple of its
/// terms' denominators (the same factor twice is one factor), a product adds, an integer power
/// multiplies or turns its base into a denominator. From the tree alone: GiNaC's normal form is not
/// consulted.
struct degree_bound {
  long numerator = 0;
  std::map<GiNaC::ex, std::pair<long, long>, GiNaC::ex_is_less> denominator;  // factor -> (multiplicity, degree)
  long denominator_degree() const {
    long d = 0;
    for (const auto& [factor, md] : denominator) d += md.first * md.second;
    return d;
  }
};

degree_bound bound_in(const GiNaC::ex& e, const std::string& name) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) return {GiNaC::ex_to<GiNaC::symbol>(e).get_name() == name ? 1 : 0, {}};
  if (GiNaC::is_a<GiNaC::add>(e)) {
    std::vector<degree_bound> terms;
    degree_bound out;
    for (const GiNaC::ex& term : e) {
      terms.push_back(bound_in(term, name));
      for (const auto& [factor, md] : terms.back().denominator) {
        auto& lcm = out.denominator[factor];
        lcm = {std::max(lcm.first, md.first), md.second};
      }
    }
    const long lcm_degree = out.denominator_degree();
    for (const degree_bound& t : terms) out.numerator = std::max(out.numerator, t.numerator + lcm_degree - t.denominator_degree());
    return out;
  }
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    degree_bound out;
    for (const GiNaC::ex& factor : e) {
      const degree_bound f = bound_in(factor, name);
      out.numerator += f.numerator;
      for (const auto& [key, md] : f.denominator) {
        auto& sum = out.denominator[key];
        sum = {sum.first + md.first, md.second};
      }
    }
    return out;
  }
  if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) && GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_integer()) {
    const degree_bound base = bound_in(e.op(0), name);
    const long k = GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_long();
    degree_bound out;
    if (k >= 0) {
      out.numerator = k * base.numerator;
      for (const auto& [key, md] : base.denominator) out.denominator[key] = {k * md.first, md.second};
    } else {  // (N/D)^-k = D^k / N^k: the base's numerator, as a factor of its own
      out.numerator = -k * base.denominator_degree();
      out.denominator[e.op(0)] = {-k, base.numerator};
    }
    return out;
  }
  return {};  // a number (anything else is outside the kernel: evaluate says so)
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
  // By name: GiNaC's order of a tree's operands is not the same from run to run.
  std::sort(symbols.begin(), symbols.end(), [](const GiNaC::symbol& a, const GiNaC::symbol& b) { return a.get_name() < b.get_name(); });
  // The premise, from the tree itself (bound_in): the degree of its numerator in each symbol. The
  // symbol of the highest bound stays free (the values are rational functions of it); each other
  // takes a grid of that many values plus one.
  std::vector<int> degrees;
  std::size_t theta = 0;
  for (std::size_t k = 0; k < symbols.size(); ++k) {
    degrees.push_back(static_cast<int>(bound_in(e, symbols[k].get_name()).numerator));
    if (degrees[k] > degrees[theta]) theta = k;
  }
  std::size_t points = 1;
  std::string grid;
  for (std::size_t k = 0; k < symbols.size(); ++k) {
    if (k == theta) continue;
    points *= static_cast<std::size_t>(degrees[k] + 1);
    if (points > most_points) return {kernel_decision::result::not_applicable, fmt::format("a grid of more than {} points", most_points)};
    grid += (grid.empty() ? "" : ", ") + fmt::format("{} {}", symbols[k].get_name(), degrees[k] + 1);
  }
  // Three grids in turn (values k + 1, then shifted by 1/7, 2/7): the first on which every point
  // keeps every denominator of the tree nonzero decides.
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
        if (!point_evaluation<symbolic>(values)(e).is_zero()) {
          return {kernel_decision::result::nonzero,
                  fmt::format("not zero at {}{}", point.empty() ? "" : point + ", ",
                              symbols.empty() ? "a constant" : "as a function of " + symbols[theta].get_name())};
        }
      } catch (const std::domain_error&) {  // a pole of the expression as written (of a denominator in it) at this point
        defined = false;
        break;
      } catch (const std::overflow_error&) {  // cpp_rational's division by zero: the same
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
                              : fmt::format("zero as a rational function of {} on a grid of {} point(s) ({}; degrees bounded from the expression as read)",
                                            symbols[theta].get_name(), points, grid.empty() ? "no other symbol" : grid)};
    }
  }
  return {kernel_decision::result::not_applicable, "every grid tried meets a pole of the expression"};
}


/// The uninterpreted functions of one argument `e` applies (V(x), and V'(x) as V): those the TeX
/// reader makes (is_reader_function), not GiNaC's own (sin, exp, Order), which stay outside the kernel.
std::set<std::string> applied_functions(const GiNaC::ex& e) {
  std::set<std::string> names;
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (it->nops() != 1 || !is_reader_function(*it)) continue;
    names.insert(GiNaC::ex_to<GiNaC::function>(*it).get_name());
  }
  return names;
}

/// Whether an application of `name` holds another in its argument (V(V(x)): not linear in V).
bool nested(const GiNaC::ex& e, const std::string& name) {
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::function>(*it) && GiNaC::ex_to<GiNaC::function>(*it).get_name() == name && it->nops() == 1 &&
        !applied_functions(it->op(0)).empty()) {
      return true;
    }
  }
  return false;
}

/// Each application of the function `name` (or a derivative of it) times `scale`: linear in the
/// function when the result is of degree 1 in the scale.
struct function_scaled : GiNaC::map_function {
  std::string name;
  GiNaC::ex scale;
  function_scaled(std::string n, GiNaC::ex s) : name(std::move(n)), scale(std::move(s)) {}
  GiNaC::ex operator()(const GiNaC::ex& e) override {
    if (GiNaC::is_a<GiNaC::function>(e) && e.nops() == 1 && GiNaC::ex_to<GiNaC::function>(e).get_name() == name) return scale * e;
    return e.map(*this);
  }
};

kernel_decision decide_entries(const GiNaC::ex& e, std::size_t most_points);

}  // namespace

GiNaC::ex with_monomial(const GiNaC::ex& e, const std::string& name, int power) {
  const GiNaC::symbol x("monomial_variable");
  definition monomial{GiNaC::symbol(name), GiNaC::pow(x, power), "V(x) = x^k", 0, "", name, x};
  return with_definitions(e, {monomial});
}

/// The degree of the polynomial potentials an identity linear in an uninterpreted V is proved for.
constexpr int potential_degree = 4;

namespace {

/// Each application of a function the reader made, and each partial derivative of one, at each point
/// (its arguments in normal form) replaced by an unknown of its own, arguments first: the jets of the
/// functions at the points the expression evaluates them at. Zero in them is zero for every smooth
/// function; nonzero in them is nonzero for some, since finitely many jet values at distinct points
/// can be given any values.
struct jet_unknowns : GiNaC::map_function {
  std::map<std::string, GiNaC::symbol> unknowns;
  GiNaC::ex operator()(const GiNaC::ex& e) override {
    if (!is_reader_function(e)) return e.map(*this);
    const GiNaC::ex inner = e.map(*this);
    std::string key = GiNaC::ex_to<GiNaC::function>(e).get_name();
    if (GiNaC::is_a<GiNaC::fderivative>(e)) {
      std::string slots;
      for (const unsigned s : GiNaC::ex_to<GiNaC::fderivative>(e).derivatives()) slots += (slots.empty() ? "" : ",") + std::to_string(s);
      key = "D[" + slots + "](" + key + ")";
    }
    std::string args;
    for (std::size_t k = 0; k < inner.nops(); ++k) args += (k ? "," : "") + canonical_text(GiNaC::normal(inner.op(k)));
    key += "(" + args + ")";
    const auto it = unknowns.find(key);
    if (it != unknowns.end()) return it->second;
    return unknowns.emplace(key, GiNaC::symbol(key)).first->second;
  }
};

bool applies_several_arguments(const GiNaC::ex& e) {
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (it->nops() > 1 && is_reader_function(*it)) return true;
  }
  return false;
}

}  // namespace

kernel_decision kernel_decides_zero(const GiNaC::ex& given, std::size_t most_points) {
  const GiNaC::ex e = given.evalm();
  if (applies_several_arguments(e)) {  // L(q, v): its jets at the points are the unknowns
    jet_unknowns jets;
    const GiNaC::ex abstracted = jets(e);
    const kernel_decision d = decide_entries(abstracted, most_points);
    std::string names;
    for (const auto& [key, symbol] : jets.unknowns) names += (names.empty() ? "" : ", ") + key;
    return {d.outcome, fmt::format("with each function value and partial derivative at each point an unknown ({} of them: {}): {}", jets.unknowns.size(),
                                   names, d.evidence)};
  }
  const std::set<std::string> functions = applied_functions(e);
  if (functions.size() > 1) return {kernel_decision::result::not_applicable, "holds what our kernel does not compute: more than one function (" + fmt::format("{}", fmt::join(functions, ", ")) + ")"};
  if (functions.size() == 1) {
    // An uninterpreted V: when e is linear in V's applications (each one times λ, e of degree 1 in λ
    // and λ in no denominator, from the tree), e is zero for every polynomial V of degree at most
    // `potential_degree` when it is zero for each monomial V(x) = x^k up to it.
    const std::string& name = *functions.begin();
    const GiNaC::symbol lambda("kernel_lambda");
    const GiNaC::ex scaled = function_scaled(name, lambda)(e);
    const degree_bound in_lambda = bound_in(scaled, lambda.get_name());
    if (nested(e, name) || in_lambda.numerator > 1 || in_lambda.denominator_degree() > 0) {
      return {kernel_decision::result::not_applicable, "not linear in " + name + ": our kernel decides identities linear in an uninterpreted function"};
    }
    std::string last;
    for (int k = 0; k <= potential_degree; ++k) {
      const kernel_decision d = decide_entries(with_monomial(e, name, k), most_points);
      if (d.outcome != kernel_decision::result::zero) return {d.outcome, fmt::format("for {}(x) = x^{}: {}", name, k, d.evidence)};
      last = d.evidence;
    }
    return {kernel_decision::result::zero,
            fmt::format("zero for {0}(x) = x^k, k = 0..{1}, and linear in {0}: for every polynomial {0} of degree <= {1} (at k = {1}: {2})", name,
                        potential_degree, last)};
  }
  return decide_entries(e, most_points);
}

namespace {

kernel_decision decide_entries(const GiNaC::ex& e, std::size_t most_points) {
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

}  // namespace

long kernel_denominator_degree(const GiNaC::ex& e, const std::string& symbol) { return bound_in(e.evalm(), symbol).denominator_degree(); }

}  // namespace simpson::verify::detail

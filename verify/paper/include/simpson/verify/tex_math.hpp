#pragma once
// A reader for the TeX math the paper uses, into GiNaC expressions. No maintained C++ library
// parses TeX math into a CAS expression, so this one is ours: small and table-driven.
//
// The subset: numbers; single-letter and Greek symbols with subscripts (q_\ell, q_r, q_{j+1},
// \Phi_3); implicit products, + and −, \cdot; ^ with TeX's one-token argument (h^24 is h²·4);
// {a \over b} and \frac{a}{b}; \sqrt{a}; ( ) [ ] and { } groups with \big \Big \left \right and
// friends; spacing (\, \! \; \quad) and \displaystyle ignored; array and pmatrix matrices; the
// relations =, \equiv and <; derivatives {{\dd^k q}\over{\dd t^n}} (a symbol named d^kq/dt^n, so
// that a misprinted order stays visible) and {{\dd V}\over{\dd q}}(x) (the derivative of an
// uninterpreted function at x); function application V(x), L_d(a, b) for the names of
// function_names(); \sum_{j=a}^{b} s as sum(s, j, a, b). Anything else is an error naming the token.

#include <ginac/ginac.h>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace simpson::verify {

/// The symbols of the paper by name ("m", "omega", "h", "q_l", "q_r", "p", "q", ...): the parser
/// and the derived formulas share them, so that the same name is the same GiNaC symbol.
class tex_symbols {
 public:
  const GiNaC::symbol& operator[](const std::string& name);

 private:
  std::map<std::string, GiNaC::symbol> symbols_;
};

/// The one table of the paper's symbols in this process: every reading of every copy of the paper,
/// and every derivation, use it, so that a name is one symbol everywhere.
tex_symbols& paper_symbols();

/// The names the reader applies as functions when followed by parentheses: V, L_d, L_h, H_d, Q, Q_c,
/// q (q(t); q_\ell and q_j are other names), the basis functions varphi_0, varphi_1/2, varphi_1,
/// and psi (a quadrature's integrand).
const std::vector<std::string>& function_names();

/// Adds `name` (as the reader names it: "f", "phi", "V_1") to function_names() for the rest of the
/// process: a claims file's declared functions ([symbols] functions).
void declare_function(const std::string& name);

/// The name under which the function `name` of `arity` arguments is registered with GiNaC: `name`,
/// or "<name>_f" when GiNaC has a function of that name and arity of its own (psi, the digamma).
std::string function_name(const std::string& name, std::size_t arity);

/// The uninterpreted function `name` of `args.size()` arguments applied to `args` (GiNaC
/// differentiates it to D[k](name)(args)). One function per name and arity in the process.
GiNaC::ex apply_function(const std::string& name, const GiNaC::exvector& args);

/// The symbol the reader makes of {{\dd^k x}\over{\dd t^n}}: "dq/dt", "d^2q/dt^2", and for a
/// misprint such as k = 6, n = 5, "d^6q/dt^5".
std::string derivative_name(const std::string& of, const std::string& by, int k, int n);

/// \sum_{j=a}^{b} s as read: sum(s, j, a, b).
bool is_sum(const GiNaC::ex& e);

/// The equations of a display: an array's rows (a row that starts with '=' continues the one
/// before it; rows of spacing only are dropped), or the parts separated by top-level commas
/// ("g_l = ... \,,\,\, g_r = ..."). \vspace is dropped.
std::vector<std::string> display_equations(const std::string& tex);

/// A formula the reader could not parse: the offending token and its offset in the TeX.
class tex_parse_error : public std::invalid_argument {
 public:
  tex_parse_error(const std::string& why, std::string token, std::size_t offset)
      : std::invalid_argument(why), token_(std::move(token)), offset_(offset) {}
  const std::string& token() const noexcept { return token_; }
  std::size_t offset() const noexcept { return offset_; }

 private:
  std::string token_;
  std::size_t offset_;
};

/// The sides of a display split at its top-level relations (=, \equiv, \simeq, <, \leq), trailing
/// punctuation dropped: "p_r = A" gives {"p_r", "A"}.
std::vector<std::string> relation_sides(const std::string& tex);

/// The canonical text of an expression: its normal form as (expanded numerator)/(expanded
/// denominator), each a sum of monomials with symbols in name order and terms in a fixed order, and
/// a matrix entry by entry. GiNaC's own printing orders terms by symbol serial numbers, which
/// depend on what a process created first; reports must not.
std::string canonical_text(const GiNaC::ex& e);

/// Parses one side (no relation) into an expression; matrices are GiNaC matrices. Throws
/// tex_parse_error.
GiNaC::ex parse_tex_math(const std::string& tex, tex_symbols& symbols);

}  // namespace simpson::verify

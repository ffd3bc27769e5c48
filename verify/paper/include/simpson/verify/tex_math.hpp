#pragma once
// What the math of a document means, read from its tree (tex_tree.hpp) into GiNaC expressions.
// TeX leaves a few things open that mathematics does not; the document's declarations (a claims
// file's [symbols]) decide them, and nothing else does:
//   - V(x) is V applied to x when V is declared a function, and V times x otherwise;
//   - a name declared both a function and a symbol is a state (q(t), q at t; dq/dt a quantity), a
//     name declared a function only is applied (dV/dq, V' at q);
//   - d in \frac{dV}{dq} is a differential unless d is declared a symbol, when the fraction is
//     refused as ambiguous.
// Everything else has one reading, or none, and is refused with the construct named (tex_error):
// numbers (1.57 is 157/100); symbols with subscripts (q_\ell is q_l, q_{j+1/2}, {\Phi}_3); sums,
// products (implicit, \cdot, \times), a / b with one factor after it; \frac, \over, \sqrt; powers;
// ( ) [ ] \left \right \big; matrices (pmatrix, bmatrix, array, and vmatrix as a determinant);
// derivatives as people write them (V'(x), V''(x), V^{(k)}(x), \dot q, \ddot q, \frac{dV}{dq}(x),
// \frac{\mathrm d^2 q}{\mathrm d t^2}, {{\rm d}V \over {\rm d}q}, \frac{\partial L}{\partial q},
// \partial_q L); functions of several arguments declared with their variables (L(q, \dot q)) and
// their partial derivatives at points, by name or by slot (\frac{\partial L}{\partial \dot q}(a, b),
// \partial_{\dot q} L, D_2 L_d(a, b), \partial L_h / \partial q_m ending its term); \frac{d}{dt} X
// along a trajectory; Landau's O(h^k), \mathcal O(h^k), {\rm O}(h^k); \det and \operatorname{tr} (also
// \mathrm{tr}, {\rm det}) of what follows; \sin, \cos, \exp, \log (also \operatorname{sin}, ...);
// \sum_{j=a}^{b} s; \int_a^b f \, dx.

#include <simpson/verify/tex_tree.hpp>

#include <ginac/ginac.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace simpson::verify {

/// The symbols by name ("m", "omega", "q_l", "d^2q/dt^2"): the same name is the same GiNaC symbol
/// wherever it is read and derived.
class tex_symbols {
 public:
  const GiNaC::symbol& operator[](const std::string& name);

 private:
  std::map<std::string, GiNaC::symbol> symbols_;
};

/// The one table of symbols in this process (a GiNaC symbol is its identity: a name must be one
/// symbol in every formula a run reads and derives).
tex_symbols& paper_symbols();

/// What a document declares of its names, in the reader's names ("V", "L_d", "q_j+1", "omega").
struct tex_declarations {
  std::set<std::string> functions;  // applied to what follows in parentheses
  std::set<std::string> symbols;    // real or positive symbols: a function also declared here is a state
  /// A function's variables, slot by slot, where the file declares them (L(q, \dot q): "q", "dq/dt"):
  /// its partial derivatives by a variable's name are by that slot, it is applied to as many
  /// arguments, and written alone (L, V') it stands at its variables.
  std::map<std::string, std::vector<std::string>> variables;
  bool is_function(const std::string& name) const { return functions.count(name) > 0; }
  const std::vector<std::string>* variables_of(const std::string& name) const {
    const auto it = variables.find(name);
    return it == variables.end() ? nullptr : &it->second;
  }
  bool is_state(const std::string& name) const { return functions.count(name) > 0 && symbols.count(name) > 0; }
};

/// The names the reader refuses to be declared, and why: O is Landau's, \pi is the constant.
const std::map<std::string, std::string>& reserved_names();

/// The name under which the function `name` of `arity` arguments is registered with GiNaC: `name`,
/// or "<name>_f" when GiNaC has a function of that name and arity of its own (psi, the digamma).
std::string function_name(const std::string& name, std::size_t arity);

/// The uninterpreted function `name` of `args.size()` arguments applied to `args` (GiNaC
/// differentiates it to D[k](name)(args)).
GiNaC::ex apply_function(const std::string& name, const GiNaC::exvector& args);

/// Whether `e` is an application of a function the reader made (V(x), D[0](V)(x)), not one of
/// GiNaC's own (sin, exp, Order) nor a sum.
bool is_reader_function(const GiNaC::ex& e);

/// The symbol the reader makes of a state's derivative {{\dd^k x}\over{\dd t^n}}: "dq/dt",
/// "d^2q/dt^2", and for a misprint such as k = 6, n = 5, "d^6q/dt^5".
std::string derivative_name(const std::string& of, const std::string& by, int k, int n);

/// \frac{\partial(q_{j+1}, p_{j+1})}{\partial(q_j, p_j)} as read: the Jacobian of a one-step map, held
/// as jacobian({q_j+1, p_j+1}, {q_j, p_j}) (a shape computes it from the relations that define the
/// step); `to` and `from` the names above and below, in order.
GiNaC::ex jacobian_of(const std::vector<GiNaC::symbol>& to, const std::vector<GiNaC::symbol>& from);
/// Whether `e` is a held Jacobian; its names above and below.
bool is_jacobian(const GiNaC::ex& e);
std::pair<std::vector<GiNaC::symbol>, std::vector<GiNaC::symbol>> jacobian_names(const GiNaC::ex& e);

/// \sum_{j=a}^{b} s as read: sum(s, j, a, b).
bool is_sum(const GiNaC::ex& e);

/// The reader's name of a symbol node: q_\ell is "q_l", {\Phi}_3 "Phi_3", \tilde H "tilde(H)";
/// throws tex_error when the node is not one name.
std::string symbol_name(const tex_node& node);

/// One side of an equation (no relation in it) read. Throws tex_error naming the construct.
GiNaC::ex read_math(const tex_list& side, const tex_declarations& declared, tex_symbols& symbols);

/// A TeX fragment (a claims file's '$\omega h$', 'q_{j+1}'), its macros `macros` expanded, read as
/// one side. Throws tex_error.
GiNaC::ex read_tex(const std::string& tex, const tex_declarations& declared, tex_symbols& symbols, const class tex_macros* macros = nullptr);

/// The canonical text of an expression: its normal form as (expanded numerator)/(expanded
/// denominator), each a sum of monomials with symbols in name order and terms in a fixed order, and
/// a matrix entry by entry. GiNaC's own printing orders terms by symbol serial numbers, which
/// depend on what a process created first; reports must not.
std::string canonical_text(const GiNaC::ex& e);

/// The same expression in TeX, for a reader (a report's "printed X, should be Y"): the same normal
/// form and order, a quotient as \frac, Greek names as their macros, a derivative's name
/// (d^6q/dt^5) as its fraction.
std::string canonical_tex(const GiNaC::ex& e);

}  // namespace simpson::verify

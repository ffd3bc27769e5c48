#pragma once
// The reader of a document's math (tex_math.hpp): the tree read into GiNaC, one member per
// construct, a node none takes refused, named. Its members are defined in tex_math.cpp (sums,
// products, atoms, numbers, names, applications) and tex_math_operators.cpp (fractions, derivatives,
// scripts, delimiters, environments, operators, sums and integrals).

#include "tex_math_parts.hpp"

#include <simpson/verify/tex_math.hpp>
#include <simpson/verify/tex_tree.hpp>

#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <vector>

namespace simpson::verify::tex_reading {

class reader {
 public:
  reader(const tex_declarations& declared, tex_symbols& symbols) : declared_(declared), symbols_(symbols) {}

  GiNaC::ex whole(const tex_list& list);

 private:
  struct cursor {
    const tex_list* list;
    std::size_t k;
    void skip() {
      while (k < list->size() && ((*list)[k].kind == tex_node_kind::label || ((*list)[k].kind == tex_node_kind::group && (*list)[k].children.empty()))) ++k;
    }
    bool done() {
      skip();
      return k >= list->size();
    }
    const tex_node& node() {
      skip();
      return (*list)[k];
    }
    const tex_node* next_after() {  // the node after the current one
      skip();
      std::size_t j = k + 1;
      while (j < list->size() && (*list)[j].kind == tex_node_kind::label) ++j;
      return j < list->size() ? &(*list)[j] : nullptr;
    }
  };

  static bool is_atom(const tex_node& n, const std::string& text);

  /// A closing atom (or one carrying scripts, \Big)^2) of `closers`.
  static bool closes(const tex_node& n, const std::vector<std::string>& closers);

  static bool ends_term(cursor& c, const std::vector<std::string>& closers);

  // sum := [+-] term {+- term}
  GiNaC::ex sum(cursor& c, const std::vector<std::string>& closers);

  // term := factor {[\cdot \times * /] factor}
  GiNaC::ex term(cursor& c, const std::vector<std::string>& closers);

  GiNaC::ex factor(cursor& c, const std::vector<std::string>& closers);

  GiNaC::ex primary(cursor& c, const std::vector<std::string>& closers);

  GiNaC::ex atom(cursor& c, const std::vector<std::string>& closers);

  /// Digits (and a decimal point between digits): an exact number; a superscript on its last digit
  /// is on the number (12^2).
  GiNaC::ex number(cursor& c);

  GiNaC::ex whole_node(const tex_node& n);

  /// After an opening atom: the expression to its closing one (which may carry a superscript:
  /// \Big( ... \Big)^2 squares the whole).
  GiNaC::ex parenthesised(cursor& c, const tex_node& open);

  /// The arguments of an application: after '(' (an atom) up to its ')', split at commas, or a
  /// \left( ... \right); and a power on its closing delimiter (V(x)^2 squares the application).
  struct application {
    GiNaC::exvector args;
    std::optional<GiNaC::ex> power;
  };
  application arguments_and_power(cursor& c);

  GiNaC::exvector arguments(cursor& c);

  GiNaC::ex raised(const GiNaC::ex& e, const std::optional<GiNaC::ex>& power);

  /// base^exponent, an exponent whose numerator or denominator exceeds 1000 refused: exact arithmetic
  /// on 9^{9^9} would take what no formula of a derivation needs.
  GiNaC::ex power_of(const GiNaC::ex& base, const GiNaC::ex& exponent);

  static bool opens_application(const tex_node* n);

  /// A name: a symbol, or a declared function applied to what follows in parentheses.
  GiNaC::ex named(cursor& c, const std::string& name, int derivative = 0);

  // --- functions of several arguments (tex_math_functions.cpp)

  /// The arguments of the function `name` as applied, refused when it declares another number of
  /// variables.
  GiNaC::exvector checked(const std::string& name, GiNaC::exvector args, const tex_node& at);

  /// The function `name` written alone stands at its declared variables; refused when it declares
  /// none (what it is applied to is not written).
  GiNaC::exvector at_variables(const std::string& name, const tex_node& at);

  /// The slot of the variable `by` among the function's declared variables (rac{\partial L}{\partial
  /// \dot q}: "dq/dt", the second); refused when it declares none, or not that one.
  std::size_t slot_of(const std::string& of, const std::string& by, const tex_node& at);

  /// The partial derivative of the function `of` by its slots (0-based, repeated for a higher one),
  /// at `args`: GiNaC's D[...](of)(args).
  static GiNaC::ex by_slots(const std::string& of, const std::vector<std::size_t>& slots, const GiNaC::exvector& args);

  /// The derivative of the function `of` by the variables `by` (each with its order), at what
  /// follows in parentheses or else at its variables.
  GiNaC::ex partial_of(cursor& c, const std::string& of, const std::vector<std::pair<std::string, int>>& by, const tex_node& at);

  /// D_1 L_d(a, b), D_2 D_1 L_d(a, b): a derivative by slot, when what D_k is written before is a
  /// declared function; none otherwise.
  std::optional<GiNaC::ex> slot_operator(cursor& c);

  /// \partial L_h / \partial \psi_l: the derivative in slanted form, refused when more factors follow
  /// it (whether they divide or multiply is not written).
  GiNaC::ex slanted_derivative(cursor& c, const std::vector<std::string>& closers);

  /// rac{d}{dt} X: the derivative of X along a trajectory (X's states and their derivatives in t
  /// are the trajectory's; its other symbols are constants, each one declared), X the parenthesised
  /// group after it, or else the product written after it, as for \sin.
  GiNaC::ex derivative_operator(cursor& c, const std::vector<std::string>& closers, const std::string& by, int order, bool partial,
                                const tex_node& at);
  GiNaC::ex along_trajectory(const GiNaC::ex& e, const std::string& by, const tex_node& at);

  // --- fractions and derivatives

  GiNaC::ex fraction(cursor& c, const std::vector<std::string>& closers = {});

  /// \frac{d^k X}{d y^k}, {\rm d}, \mathrm d, \partial: the derivative, or none when the fraction
  /// is not one.
  std::optional<GiNaC::ex> leibniz(cursor& c, const std::vector<std::string>& closers);

  /// \frac{\partial(q_{j+1}, p_{j+1})}{\partial(q_j, p_j)}: the held Jacobian (jacobian_of); none
  /// when neither part is a parenthesised list.
  std::optional<GiNaC::ex> jacobian(const tex_node& n, const tex_list& top, const tex_list& bottom, const differential& dt, const differential& db);

  // --- scripts

  GiNaC::ex scripts(cursor& c, const std::vector<std::string>& closers);

  static std::optional<int> parenthesised_order(const tex_list& sup);  // ^{(3)}

  // --- delimiters, matrices

  GiNaC::ex delimited(const tex_node& n);

  GiNaC::ex environment(const tex_node& n);

  // --- operators

  /// {\rm O}(h^k), \mathcal O(h^k), O(h^k): GiNaC's order term.
  std::optional<GiNaC::ex> order_term(cursor& c);

  /// \det, \operatorname{tr}, \mathrm{tr}, {\rm det}: of the factor that follows.
  std::optional<GiNaC::ex> named_operator(cursor& c, const std::vector<std::string>& closers);

  GiNaC::ex op(cursor& c, const std::vector<std::string>& closers);

  /// What an operator written without parentheses applies to: the parenthesised group after it
  /// alone, or else the product written after it up to +, -, a relation, an explicit product or the
  /// next operator; a parenthesis inside that product or a '/' after it refused.
  /// What an operator applies to; `differentiates` for d/dt and \partial (a product with a velocity in
  /// it is differentiated whole), not for \sin and the like.
  GiNaC::ex operand(cursor& c, const std::vector<std::string>& closers, const std::string& name, bool differentiates = false);

  /// \sin ... 	anh (and \operatorname{sin}): the function of that name applied to x; none for
  /// another name.
  static std::optional<GiNaC::ex> known_function(const std::string& name, const GiNaC::ex& x);
  static bool is_known_function(const std::string& name);

  /// \sum_{j=a}^{b} s: the summand is the rest of the term.
  GiNaC::ex sum_of(cursor& c, const std::vector<std::string>& closers);

  /// \int_a^b f \, dx: held (an integrand written in the state and its derivative must not be
  /// taken for a constant of x).
  GiNaC::ex integral(cursor& c, const std::vector<std::string>& closers);

  const tex_declarations& declared_;
  tex_symbols& symbols_;
};

}  // namespace simpson::verify::tex_reading

// The proof shapes of claims files, by name, and the checks of a record's arguments before
// anything runs: see proof_shapes.hpp and docs/claims-file.md. The shapes themselves are in
// shapes_*.cpp (shape_support.hpp).

#include <simpson/shapes/proof_shapes.hpp>

#include <simpson/prove/printed_check_support.hpp>
#include <simpson/shapes/shape_support.hpp>

#include <simpson/verify/formula_reference.hpp>
#include <simpson/verify/prose_span.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <set>
#include <utility>

namespace simpson::verify::detail {
namespace {

using GiNaC::ex;

/// What every shape takes besides its own arguments: definitions, and the sentence that states the
/// claim in words (its hole {property} must affirm `property`, or deny it: "not symplectic").
const std::vector<shape_parameter> common_parameters{
    {"where", argument_kind::definitions, false, "displays 'x = ...' whose definitions are put in the other formulas"},
    {"entries", argument_kind::definitions, false,
     "two matrices: one printed with a symbol for each entry (Phi = (alpha beta; gamma delta)), then the matrix whose entries they name"},
    {"says", argument_kind::word, false, "the sentence that states the claim, a pattern with the hole {property}"},
    {"property", argument_kind::word, false, "the word the sentence's hole must say (or deny: 'not ...')"}};

/// The scheme and the equation a series shape expands on: what truncation and stated-order share.
std::vector<shape_parameter> with_series(std::vector<shape_parameter> parameters) {
  for (shape_parameter p : std::vector<shape_parameter>{
           {"scheme", argument_kind::formula, true, "the scheme's expression (= 0) in three consecutive states"},
           {"sequence", argument_kind::symbols, true, "the three states q_{j-1}, q_j, q_{j+1}", 3},
           {"step", argument_kind::symbols, true, "the step h", 1},
           {"frequency", argument_kind::formula, true, "omega of q'' = -omega^2 q"},
           {"scale", argument_kind::formula, false, "a factor the text divides the scheme by ('the scheme divided by m'), free of the states"}}) {
    if (p.name == "scale") p.free_of = "sequence";
    parameters.push_back(std::move(p));
  }
  return parameters;
}

/// What the invariance shapes share besides the printed formula they judge: the quadratic form, the
/// map it is invariant under, the state and the form's coefficients.
std::vector<shape_parameter> with_invariance(shape_parameter printed) {
  return {std::move(printed),
          {"form", argument_kind::formula, true, "the quadratic form of the state, its coefficients the unknowns"},
          {"map", argument_kind::matrix, true, "the one-step map"},
          {"state", argument_kind::symbols, true, "the state's symbols, in the map's order", 0, "map"},
          {"unknowns", argument_kind::symbols, true, "the form's coefficients: the system's unknowns (as many as the y_i y_j for its determinant)"}};
}

/// The printed conditions a shape puts in, each solved for one symbol of `solve_for`, in order.
std::vector<shape_parameter> with_conditions(std::vector<shape_parameter> parameters) {
  parameters.push_back({"conditions", argument_kind::equations, true, "printed equations a = b (alpha delta - beta gamma = 1), put in in order"});
  parameters.push_back({"solve_for", argument_kind::symbols, true, "the symbol each condition is solved for (linear in it)", 0, "conditions"});
  return parameters;
}

/// A sentence's pattern that must hold the hole {name} (an optional argument when not `required`).
shape_parameter pattern_with_hole(std::string name, std::string meaning, std::string hole, bool required = true) {
  shape_parameter p{std::move(name), argument_kind::word, required, std::move(meaning)};
  p.hole = std::move(hole);
  return p;
}

std::vector<shape_parameter> with_where(std::vector<shape_parameter> parameters) {
  parameters.insert(parameters.end(), common_parameters.begin(), common_parameters.end());
  return parameters;
}

}  // namespace

const std::map<std::string, proof_shape>& proof_shapes() {
  static const std::map<std::string, proof_shape> shapes = [] {
    std::map<std::string, proof_shape> all;
    const auto add = [&](proof_shape s) { all.emplace(s.name, std::move(s)); };
    add({"identity", "lhs = rhs, the definitions put in", "rhs",
         with_where({{"lhs", argument_kind::formula, true, "a formula"}, {"rhs", argument_kind::formula, true, "the formula it equals"}}),
         identity_shape});
    add({"derivative", "d function / d variable = printed, the definitions put in", "printed",
         with_where({{"function", argument_kind::formula, true, "the formula differentiated"},
                     {"variable", argument_kind::symbols, true, "the symbol it is differentiated by", 1},
                     {"printed", argument_kind::formula, true, "the printed derivative"},
                     {"arguments", argument_kind::symbols, false, "the function's arguments, when the printed derivative is taken at others", 0, "",
                      false, {}, "", "", "at"},
                     {"at", argument_kind::symbols, false, "the values of the arguments in the printed derivative (q_j, q_{j+1} for q_l, q_r)", 0,
                      "arguments", false, {}, "", "", "arguments"}}),
         derivative_shape});
    add({"equal-sides", "every side of each printed equation is equal to its first, the definitions put in", "equations",
         with_where({{"equations", argument_kind::equations, true,
                      "printed equations 'a = b = ...', each read whole (a chain's first side, a symbol nothing defines, names what it defines)"}}),
         equal_sides_shape});
    add({"solves", "the equation (= 0) holds with the unknown replaced by the printed solution, the definitions put in", "solution",
         with_where({{"equation", argument_kind::formula, true, "the equation's side that is 0"},
                     {"unknown", argument_kind::symbols, true, "the symbol it is solved for", 1},
                     {"solution", argument_kind::formula, true, "the printed solution"}}),
         solves_shape});
    add({"determinant", "det matrix = equals", "equals",
         with_where({{"matrix", argument_kind::matrix, true, "a square matrix"}, {"equals", argument_kind::formula, true, "its determinant"}}),
         determinant_shape});
    add({"symplectic", "matrix^T J matrix = J, J = [[0, I], [-I, 0]]", "matrix",
         with_where({{"matrix", argument_kind::matrix, true, "a one-step map of (q, p)"}}), symplectic_shape});
    add({"linear", "the sentence's {linearity} (linear, or not linear) is what the expression is in the variables: e = sum of v_i e(unit v_i)", "expression",
         with_where({{"expression", argument_kind::formula, true, "the printed expression"},
                     {"variables", argument_kind::symbols, true, "the variables it is linear in, or not"},
                     pattern_with_hole("sentence", "the sentence's pattern: the hole {linearity}, 'linear' or 'not linear'", "linearity"),
                     {"positive", argument_kind::symbols, false,
                      "the symbol the sentence's condition makes positive ('if h > 0'): a wording erratum then says what holds, that "
                      "for it > 0 the expression is not its value at 0",
                      1}}),
         linear_shape});
    add({"conserved", "function(map y) = function(y), y the state", "function",
         with_where({{"map", argument_kind::matrix, true, "a one-step map"},
                     {"function", argument_kind::formula, true, "a function of the state"},
                     {"state", argument_kind::symbols, true, "the state's symbols, in the map's order", 0, "map"},
                     {"keep", argument_kind::symbols, false,
                      "a state symbol whose square's coefficient a correction keeps as printed (the first of the state when left out)", 1, "",
                      false, {}, "state"}}),
         conserved_shape});
    add({"proportional", "printed = c of, c free of the state and nonzero", "printed",
         with_where({{"printed", argument_kind::formula, true, "a function of the state"},
                     {"of", argument_kind::formula, true, "the function it is a constant multiple of"},
                     {"state", argument_kind::symbols, true, "the symbols c must be free of"}}),
         proportional_shape});
    add({"invariance-system", "the printed system's rows are the coefficients of y_i y_j (i <= j, in the state's order) in form(map y) - form(y)",
         "system",
         with_where(with_invariance({"system", argument_kind::formula, true, "the printed system: a column with a row for each y_i y_j, linear in the unknowns"})),
         invariance_system_shape});
    add({"invariance-determinant", "printed = det of the system form(map y) = form(y) asks of the form's coefficients (the rows as invariance-system derives them)",
         "printed", with_where(with_invariance({"printed", argument_kind::formula, true, "the printed determinant"})), invariance_determinant_shape});
    add({"invariance-singular", "det of the printed system's coefficients is 0 once the printed conditions are put in (each solved for its symbol)",
         "conditions", with_where(with_conditions(with_invariance({"system", argument_kind::formula, true, "the printed system: a column linear in the unknowns"}))),
         invariance_singular_shape});
    {
      std::vector<shape_parameter> kernel = with_conditions(with_invariance({"printed", argument_kind::formula, true, "the printed form whose coefficients span the kernel"}));
      kernel.push_back({"system", argument_kind::formula, true, "the printed system: a column linear in the unknowns"});
      kernel.push_back({"obtains", argument_kind::equations, false, "printed equations in the unknowns that every solution satisfies (eta = 0)"});
      add({"invariance-kernel",
           "once the printed conditions are put in, the printed form's coefficients span the kernel of the printed system (rank n - 1), and each 'obtains' holds there",
           "printed", with_where(std::move(kernel)), invariance_kernel_shape});
    }
    add({"euler-lagrange", "printed = 0 is D_2 L(q_{j-1}, q_j) + D_1 L(q_j, q_{j+1}) = 0, up to a factor free of the states", "printed",
         with_where({{"lagrangian", argument_kind::formula, true, "the discrete Lagrangian L(q_0, q_1)"},
                     {"nodes", argument_kind::symbols, true, "its two arguments", 2},
                     {"sequence", argument_kind::symbols, true, "three consecutive states", 3},
                     {"printed", argument_kind::formula, true, "the printed equation's side that is 0"}}),
         euler_lagrange_shape});
    add({"explicit-map", "the sentence's {kind} (explicit or implicit) is what the printed map is: explicit when every entry is a polynomial in the step",
         "map",
         with_where({{"map", argument_kind::matrix, true, "the printed one-step map"},
                     {"step", argument_kind::symbols, true, "the step h", 1},
                     {"positive", argument_kind::symbols, false, "symbols positive besides the step (m, omega), for the denominators' signs"},
                     pattern_with_hole("sentence", "the sentence's pattern: the hole {kind}, 'explicit' or 'implicit'", "kind")}),
         explicit_map_shape});
    add({"explicit-scheme", "the sentence's {kind} (explicit or implicit) is what the scheme is for the document's functions left general: explicit when it "
                            "gives its next state in closed form (linear in it, and never inside an application of a function such as V')",
         "scheme",
         with_where({{"scheme", argument_kind::formula, true, "the scheme's expression (= 0) in consecutive states, its functions (V) uninterpreted"},
                     {"sequence", argument_kind::symbols, true, "its states, the last the one a step computes (q_{j+1})"},
                     pattern_with_hole("sentence", "the sentence's pattern: the hole {kind}, 'explicit' or 'implicit'", "kind")}),
         explicit_scheme_shape});
    add({"discrete-momenta", "every side of each printed equation equals its first once p_j = -D_1 L(q_j, q_{j+1}) and p_{j+1} = D_2 L(q_j, q_{j+1}) are put in",
         "equations",
         with_where({{"equations", argument_kind::equations, true, "the printed system: equations in the states and the momenta of one step"},
                     {"lagrangian", argument_kind::formula, true, "the discrete Lagrangian L(q_0, q_1)"},
                     {"nodes", argument_kind::symbols, true, "its two arguments", 2},
                     {"at", argument_kind::symbols, true, "the two states of the step, q_j and q_{j+1}", 2},
                     {"momenta", argument_kind::symbols, true, "the momenta at them, p_j and p_{j+1}", 2}}),
         discrete_momenta_shape});
    add({"stationary", "the printed equation (= 0) is d function / d variable = 0, up to a factor free of the unknowns", "printed",
         with_where({{"printed", argument_kind::formula, true, "the printed equation's side that is 0"},
                     {"function", argument_kind::formula, true, "the function made stationary (a discrete Lagrangian)"},
                     {"variable", argument_kind::symbols, true, "the variable it is stationary in (an internal node)", 1},
                     {"unknowns", argument_kind::symbols, true, "the states the factor must be free of"}}),
         stationary_shape});
    add({"stability-interval", "the printed 0 < variable < c is the first band where the map (det 1), or the three-term scheme (reversible), is power-bounded",
         "condition",
         with_where({{"map", argument_kind::matrix, false, "a 2 x 2 one-step map with det 1", 2},
                     {"scheme", argument_kind::formula, false,
                      "instead of a map: a linear three-term scheme (= 0) whose q_{j+1} and q_{j-1} coefficients are equal", 0, "", false, {}, "",
                      "map"},
                     {"sequence", argument_kind::symbols, false, "the scheme's three states q_{j-1}, q_j, q_{j+1}", 3, "", false, {}, "", "",
                      "scheme"},
                     {"variable", argument_kind::formula, true, "the variable of the condition, a product of positive symbols", 0, "", true},
                     {"condition", argument_kind::condition, true, "the printed condition 0 < variable < c"}}),
         stability_interval_shape});
    add({"discrete-map", "map is the one-step map of the discrete Lagrangian (internal nodes eliminated), p_0 = -D_1 L, p_1 = D_2 L", "map",
         with_where({{"map", argument_kind::matrix, true, "the printed one-step map of (q_0, p_0)", 2},
                     {"lagrangian", argument_kind::formula, true, "the discrete Lagrangian L(q_0, q_1), quadratic"},
                     {"nodes", argument_kind::symbols, true, "its end nodes q_0, q_1", 2},
                     {"momenta", argument_kind::symbols, true, "the momenta p_0, p_1", 2},
                     {"internal", argument_kind::symbols, false, "its internal nodes, eliminated by their equations"},
                     {"order", argument_kind::word, false, "the printed map's state order: 'q p' (the default) or 'p q'", 0, "", false, {"q p", "p q"}}}),
         discrete_map_shape});
    add({"truncation", "the scheme on the exact solution of q'' = -omega^2 q is the printed series, to its printed order", "printed",
         with_where(with_series({{"printed", argument_kind::formula, true, "the printed truncation error, with its order term O(h^N)"}})),
         truncation_shape});
    add({"consistency", "each printed relation of the scheme, on smooth states x_{j+k} = x(t + k h), is h^p times a multiple of its printed differential equation",
         "scheme",
         with_where({{"scheme", argument_kind::equations, true, "the scheme's printed relations 'a = b' (or 'a = 0')"},
                     {"equation", argument_kind::equations, true, "the printed differential equations, one per relation, in order"},
                     {"step", argument_kind::symbols, true, "the step h", 1},
                     {"index", argument_kind::word, true, "the index of the states, 'j' for x_j, x_{j+1}, x_{j-1}"},
                     pattern_with_hole("sentence", "optionally, a sentence stating the order, with the hole {order}", "order", false)}),
         consistency_shape});
    add({"taylor-expansion", "each printed expansion x_{j+k} = ... + O(h^N) is the Taylor polynomial of x(t_j + k h) through h^(N-1)", "expansions",
         with_where({{"expansions", argument_kind::equations, true, "the printed expansions 'x_{j+k} = x_j + ... + O(h^N)'"},
                     {"step", argument_kind::symbols, true, "the step h", 1},
                     {"index", argument_kind::word, true, "the index of the states, 'j' for x_j, x_{j+1}, x_{j-1}"}}),
         taylor_expansion_shape});
    add({"stated-order", "the order a sentence states ({order} in its pattern) is the scheme's order on q'' = -omega^2 q", "scheme",
         with_where(with_series({pattern_with_hole("sentence", "the sentence's pattern, with the hole {order}", "order")})),
         stated_order_shape});
    add({"map-order", "the order a sentence states ({order} in its pattern) is the printed one-step map's on q'' = -omega^2 q: its local error against the exact flow is O(h^(order+1))",
         "map",
         with_where({{"map", argument_kind::matrix, true, "the printed one-step map", 2},
                     {"mass", argument_kind::formula, true, "m of q' = p/m"},
                     {"frequency", argument_kind::formula, true, "omega of q'' = -omega^2 q"},
                     {"step", argument_kind::symbols, true, "the step h", 1},
                     {"order", argument_kind::word, false, "the printed map's state order: 'q p' (the default) or 'p q'", 0, "", false, {"q p", "p q"}},
                     pattern_with_hole("sentence", "the sentence's pattern, with the hole {order}", "order")}),
         map_order_shape});
    add({"quadrature-exactness", "the degree of exactness a sentence states ({degree}) is the printed rule's, for the printed integral it approximates", "rule",
         with_where({{"rule", argument_kind::formula, true, "the printed rule, a combination of the function's values"},
                     {"integral", argument_kind::formula, true, "the printed integral it approximates, \\int_a^b f(x) \\dd x"},
                     {"function", argument_kind::symbols, true, "the function integrated (psi)", 1},
                     pattern_with_hole("sentence", "the sentence's pattern, with the hole {degree} (a number: 'degree three'; or a bound: 'smaller or equal to 1')",
                                       "degree")}),
         quadrature_exactness_shape});
    add({"discrete-lagrangian", "the printed discrete Lagrangian is the printed rule applied to the printed action integral along the interpolant the definitions give",
         "printed",
         with_where({{"printed", argument_kind::formula, true, "the printed discrete Lagrangian"},
                     {"integral", argument_kind::formula, true, "the action integral of one interval, \\int_a^b f \\dd t, f written in the state and its derivative"},
                     {"rule", argument_kind::formula, true, "the printed rule: an equation \\int_{a0}^{b0} psi(x) \\dd x = (or \\simeq) a combination of psi's values"},
                     {"function", argument_kind::symbols, true, "the rule's function (psi)", 1},
                     {"state", argument_kind::symbols, true, "the state q, a function the definitions give (q(t) = ...)", 1}}),
         discrete_lagrangian_shape});
    add({"sum-range", "the printed sum runs over the elements of the printed interval, from the first (starting at its start) to the last (ending at its end)", "sum",
         with_where({{"sum", argument_kind::formula, false, "the printed sum \\sum_{j=a}^{b}", 0, "", false, {}, "", "sentence"},
                     pattern_with_hole("sentence", "instead of a printed sum: a sentence stating its range, with the holes {from} and {to} (TeX: '$1$', '$N - 1$')",
                                       "from", false),
                     {"index", argument_kind::word, false, "the sum's index, with a sentence: 'j'", 0, "", false, {}, "", "", "sentence"},
                     {"element", argument_kind::symbols, true, "the summand's first and last nodes, x_j and x_{j+1}", 2},
                     {"node", argument_kind::formula, true, "the printed time of node j, t_j = j h"},
                     {"range", argument_kind::condition, true, "the printed interval a <= t <= b"}}),
         sum_range_shape});
    add({"emerging-condition",
         "the printed condition 0 < variable < c follows from the printed formula as the text says (c its first pole): only when the scheme's stable set "
         "for variable > 0 is (0, c)",
         "condition",
         with_where({{"condition", argument_kind::condition, true, "the printed condition 0 < variable < c"},
                     {"formula", argument_kind::formula, true, "the formula it is said to emerge from (its denominator's first positive root)"},
                     {"variable", argument_kind::formula, true, "the condition's variable, a product of positive symbols", 0, "", true},
                     {"scheme", argument_kind::formula, true, "the linear three-term scheme (= 0) whose stability the condition states"},
                     {"sequence", argument_kind::symbols, true, "its three states q_{j-1}, q_j, q_{j+1}", 3},
                     pattern_with_hole("sentence", "the sentence that says the condition emerges, with the hole {emerges}", "emerges")}),
         emerging_condition_shape});
    add({"known-method",
         "the printed one-step map is a named partitioned Runge-Kutta method's on q'' = -omega^2 q, and the text, presenting the method as its own, names it",
         "map",
         with_where({{"map", argument_kind::matrix, true, "the printed 2 x 2 one-step map", 2},
                     {"state", argument_kind::symbols, true, "the map's state, in its order ('p', 'q')", 2},
                     {"position", argument_kind::symbols, true, "which of the state is the position q", 1, "", false, {}, "state"},
                     {"step", argument_kind::symbols, true, "the step h", 1},
                     {"frequency", argument_kind::formula, true, "omega"},
                     {"mass", argument_kind::formula, true, "the mass m"},
                     {"tableau_position", argument_kind::matrix, true, "the method's s x s tableau for the position (Lobatto IIIA)"},
                     {"tableau_momentum", argument_kind::matrix, true, "its s x s tableau for the momentum (Lobatto IIIB)"},
                     {"weights", argument_kind::formula, true, "its weights, a 1 x s row"},
                     {"method", argument_kind::word, true, "the method's name, in words ('the 3-stage Lobatto IIIA-IIIB pair')"},
                     {"names", argument_kind::words, true, "words whose presence in the prose names it ('Lobatto')"},
                     pattern_with_hole("sentence", "the sentence presenting the method as the text's own, with the hole {novelty}", "novelty")}),
         known_method_shape});
    add({"spelling", "every word of the document's prose is in Hunspell's en_US dictionary or the record's vocabulary (its names and terms of art)", "",
         {{"vocabulary", argument_kind::words, false, "words the dictionary lacks that the document spells right: names, terms of art ('symplectic')"},
          {"from", argument_kind::word, false, "where the prose checked starts: words the source prints ('Abstract'); the body's start without it"}},
         spelling_shape});
    add({"citations", "every \\cite key of the document has its entry in the document's bibliography; unverifiable when one has none", "", {},
         citations_shape});
    add({"sign-on-interval", "expression has the stated sign on the printed interval 0 < variable < c", "expression",
         with_where({{"expression", argument_kind::formula, true, "a function of the variable alone once scaled"},
                     {"variable", argument_kind::formula, true, "the variable of the condition, a product of positive symbols", 0, "", true},
                     {"condition", argument_kind::condition, true, "the printed interval 0 < variable < c"},
                     {"sign", argument_kind::word, false, "positive or negative, when no sentence states it", 0, "", false, {"positive", "negative"}, "", "sentence"},
                     pattern_with_hole("sentence", "the sentence that states the sign, with the hole {sign}: '... is {sign} for'", "sign", false)}),
         sign_on_interval_shape});
    add({"sign-iff", "expression has the stated sign if and only if 0 < variable < c: on the printed interval, and nowhere else for variable > 0",
         "expression",
         with_where({{"expression", argument_kind::formula, true, "a function of the variable alone once scaled"},
                     {"variable", argument_kind::formula, true, "the variable of the condition, a product of positive symbols", 0, "", true},
                     {"condition", argument_kind::condition, true, "the printed interval 0 < variable < c"},
                     {"sign", argument_kind::word, false, "positive or negative, when no sentence states it", 0, "", false, {"positive", "negative"}, "", "sentence"},
                     pattern_with_hole("sentence", "the sentence that states the sign, with the hole {sign}: '... is {sign} if and only if'", "sign", false)}),
         sign_iff_shape});
    add({"factor-signs", "each factor of the printed product, and the product, have the signs a sentence states on the printed interval 0 < variable < c",
         "expression",
         with_where({{"expression", argument_kind::formula, true, "the printed product: its sums are its factors, the rest one prefactor"},
                     {"variable", argument_kind::formula, true, "the variable of the condition, a product of positive symbols", 0, "", true},
                     {"condition", argument_kind::condition, true, "the printed interval 0 < variable < c"},
                     pattern_with_hole("sentence", "the sentence's pattern: the hole {sign} (the factors' sign), optionally {relation} (the product's, to 0)",
                                       "sign")}),
         factor_signs_shape});
    add({"characteristic", "the printed polynomial in the root is the scheme at (1, r, r^2), up to a factor free of r; unprinted coefficients solved for",
         "printed",
         with_where({{"printed", argument_kind::formula, true, "the printed polynomial (its side that is 0), of degree at most 2 in the root"},
                     {"scheme", argument_kind::formula, true, "a linear three-term scheme (= 0)"},
                     {"sequence", argument_kind::symbols, true, "its three states q_{j-1}, q_j, q_{j+1}", 3},
                     {"root", argument_kind::symbols, true, "the root r: q_{j-1} = 1, q_j = r, q_{j+1} = r^2", 1},
                     {"unprinted", argument_kind::symbols, false, "coefficients the text names but does not print (c), each one whole coefficient"}}),
         characteristic_shape});
    add({"discriminant", "the printed value of the discriminant b^2 - 4ac of the printed polynomial a r^2 + b r + c, its unprinted coefficients solved from the scheme",
         "printed",
         with_where({{"printed", argument_kind::formula, true, "the printed value of the discriminant"},
                     {"polynomial", argument_kind::formula, true, "the printed polynomial in the root (its side that is 0)"},
                     {"definition", argument_kind::formula, false, "the printed definition of the discriminant, b^2 - 4ac, in the polynomial's symbols"},
                     {"scheme", argument_kind::formula, true, "a linear three-term scheme (= 0)"},
                     {"sequence", argument_kind::symbols, true, "the scheme's three states q_{j-1}, q_j, q_{j+1}", 3},
                     {"root", argument_kind::symbols, true, "the polynomial's variable", 1},
                     {"unprinted", argument_kind::symbols, false, "coefficients the text names but does not print, solved from the scheme"}}),
         discriminant_shape});
    add({"characteristic-roots", "what a sentence says of the roots of the scheme's characteristic polynomial on the printed interval: complex or real, their product, stability",
         "scheme",
         with_where({{"scheme", argument_kind::formula, true, "a linear three-term scheme (= 0)"},
                     {"sequence", argument_kind::symbols, true, "its three states q_{j-1}, q_j, q_{j+1}", 3},
                     {"variable", argument_kind::formula, true, "the variable of the condition, a product of positive symbols", 0, "", true},
                     {"condition", argument_kind::condition, true, "the printed interval 0 < variable < c"},
                     pattern_with_hole("sentence", "the sentence's pattern: the hole {roots} (complex conjugate, real), optionally {product} and {conclusion} (stable, unstable)",
                                       "roots")}),
         characteristic_roots_shape});
    add({"unconditional-stability", "what a sentence says of the scheme's stability ({stability}, optionally {qualifier}) against the root condition for every variable > 0",
         "scheme",
         with_where({{"scheme", argument_kind::formula, true, "a linear three-term scheme (= 0) whose first and last coefficients are equal"},
                     {"sequence", argument_kind::symbols, true, "its three states q_{j-1}, q_j, q_{j+1}", 3},
                     {"variable", argument_kind::formula, true, "the variable the scheme's roots depend on, a product of positive symbols", 0, "", true},
                     pattern_with_hole("sentence", "the sentence's pattern: the hole {stability} (stable, linearly stable, conditionally or unconditionally stable, unstable)", "stability"),
                     pattern_with_hole("qualifier", "optionally, a sentence with the hole {qualifier} (unconditionally, conditionally)", "qualifier", false)}),
         unconditional_stability_shape});
    add({"root-criterion", "a stability criterion stated on the roots' modulus, against the root condition on every region of variable > 0", "scheme",
         with_where({{"scheme", argument_kind::formula, true, "a linear three-term scheme (= 0) whose first and last coefficients are equal"},
                     {"sequence", argument_kind::symbols, true, "its three states q_{j-1}, q_j, q_{j+1}", 3},
                     {"variable", argument_kind::formula, true, "the variable the scheme's roots depend on, a product of positive symbols", 0, "", true},
                     pattern_with_hole("sentence", "the sentence's pattern: the hole {modulus} (a bound, optionally with 'simple')", "modulus")}),
         root_criterion_shape});
    return all;
  }();
  return shapes;
}

void check_shape_arguments(const claim_record& record, const std::string& file) {
  const proof_shape& shape = proof_shapes().at(record.shape);
  for (const auto& entry : record.with) {
    const std::string& name = entry.first;  // not a structured binding: clang's C++17 lambdas cannot capture one
    const shape_argument& argument = entry.second;
    const auto it = std::find_if(shape.parameters.begin(), shape.parameters.end(), [&](const shape_parameter& p) { return p.name == name; });
    if (it == shape.parameters.end()) {
      std::string names;
      for (const shape_parameter& p : shape.parameters) names += (names.empty() ? "" : ", ") + p.name;
      throw claims_file_error(file, argument.line, "with." + name, "not an argument of the shape '" + shape.name + "' (" + names + ")");
    }
    const bool list = it->kind == argument_kind::definitions || it->kind == argument_kind::symbols || it->kind == argument_kind::equations ||
                      it->kind == argument_kind::words;
    if (argument.list != list) {
      throw claims_file_error(file, argument.line, "with." + name, list ? "must be an array of strings" : "must be one string (a formula reference)");
    }
    if (list && argument.values.empty()) throw claims_file_error(file, argument.line, "with." + name, "must not be empty");
    if (it->kind == argument_kind::word || it->kind == argument_kind::symbols || it->kind == argument_kind::words) continue;
    for (const std::string& value : argument.values) {  // each a reference that reads ('label#0' does not)
      try {
        parse_reference(value);
      } catch (const std::invalid_argument& e) {
        throw claims_file_error(file, argument.line, "with." + name, e.what());
      }
    }
  }
  for (const shape_parameter& p : shape.parameters) {
    if (p.required && !record.with.count(p.name)) {
      throw claims_file_error(file, record.line, "with." + p.name, "missing: the shape '" + shape.name + "' needs it (" + p.meaning + ")");
    }
  }
  // Alternatives (one of the two) and companions (given exactly with another).
  for (const shape_parameter& p : shape.parameters) {
    const bool given = record.with.count(p.name) > 0;
    if (!p.instead_of.empty()) {
      const bool other = record.with.count(p.instead_of) > 0;
      if (given && other) {
        throw claims_file_error(file, record.with.at(p.name).line, "with." + p.name, "give '" + p.name + "' or '" + p.instead_of + "', not both");
      }
      if (!given && !other) {
        throw claims_file_error(file, record.line, "with." + p.instead_of,
                                "missing: the shape '" + shape.name + "' needs it, or '" + p.name + "' instead (" + p.meaning + ")");
      }
    }
    if (!p.only_with.empty() && given != (record.with.count(p.only_with) > 0)) {
      throw claims_file_error(file, given ? record.with.at(p.name).line : record.with.at(p.only_with).line, "with." + p.name,
                              given ? "given without '" + p.only_with + "'" : "missing: '" + p.only_with + "' needs it (" + p.meaning + ")");
    }
  }
  for (const shape_parameter& p : shape.parameters) {
    const auto it = record.with.find(p.name);
    if (!p.hole.empty() && it != record.with.end() && it->second.values.front().find("{" + p.hole + "}") == std::string::npos) {
      throw claims_file_error(file, it->second.line, "with." + p.name, "the sentence's pattern has no hole {" + p.hole + "}");
    }
    if ((!p.hole.empty() || p.name == "says") && it != record.with.end()) {
      try {
        check_pattern(it->second.values.front());
      } catch (const std::invalid_argument& e) {
        throw claims_file_error(file, it->second.line, "with." + p.name, e.what());
      }
    }
  }
  // The words: a sentence and the property it states, both or neither.
  const auto says = record.with.find("says"), property = record.with.find("property");
  if ((says == record.with.end()) != (property == record.with.end())) {
    const bool has_says = says != record.with.end();
    throw claims_file_error(file, has_says ? says->second.line : property->second.line, has_says ? "with.property" : "with.says",
                            has_says ? "missing: the word the sentence's hole {property} must say" : "missing: the sentence that says the property");
  }
  if (says != record.with.end() && says->second.values.front().find("{property}") == std::string::npos) {
    throw claims_file_error(file, says->second.line, "with.says", "the sentence's pattern has no hole {property}");
  }
}

std::string check_shape_formulas(const claim_record& record, const std::string& file, const tex_document& document,
                                 const claim_declarations& declared) {
  // Read as the shape will read them when it runs (shape_reader): the definitions put in, every
  // symbol declared; what a shape checks only when it runs is checked here, before anything runs.
  // The document's own faults (TeX that does not read) name the document and its line, not the record.
  const shape_call call{record.id, record.statement, record.with, std::make_shared<const claim_declarations>(declared)};
  std::optional<shape_reader> read;
  try {
    read.emplace(call, document);
  } catch (const document_error&) {
    throw;
  } catch (const argument_error& e) {
    throw claims_file_error(file, record.with.at(e.argument).line, "with." + e.argument, e.what());
  } catch (const std::invalid_argument& e) {
    const auto where = record.with.find("where");
    throw claims_file_error(file, where != record.with.end() ? where->second.line : record.line, where != record.with.end() ? "with.where" : "with",
                            e.what());
  }
  const std::set<std::string>& positive = declared.positive;
  const proof_shape& shape = proof_shapes().at(record.shape);
  std::string principal;
  std::map<std::string, unsigned> rows;  // of each matrix argument
  for (const shape_parameter& p : shape.parameters) {
    const auto it = record.with.find(p.name);
    if (it == record.with.end() || p.kind == argument_kind::definitions) continue;  // the definitions: read above
    const std::string field = "with." + p.name;
    const int line = it->second.line;
    try {
      switch (p.kind) {
        case argument_kind::formula:
        case argument_kind::matrix:
        case argument_kind::condition: {
          const referenced_formula f = read->raw(p.name);
          if (p.name == shape.principal) principal = "$" + folded_space(f.tex) + "$ (" + f.locator + ")";
          if (p.kind == argument_kind::matrix) {
            const ex m = read->formula(p.name);
            if (!GiNaC::is_a<GiNaC::matrix>(m) || GiNaC::ex_to<GiNaC::matrix>(m).rows() != GiNaC::ex_to<GiNaC::matrix>(m).cols()) {
              throw claims_file_error(file, line, field, f.locator + " is not a square matrix");
            }
            rows[p.name] = GiNaC::ex_to<GiNaC::matrix>(m).rows();
            if (p.size != 0 && rows[p.name] != p.size) {
              throw claims_file_error(file, line, field, fmt::format("{} is {} x {}, not {} x {}", f.locator, rows[p.name], rows[p.name], p.size, p.size));
            }
          }
          if (!p.free_of.empty() && record.with.count(p.free_of)) {
            const ex value = read->formula(p.name);
            if (GiNaC::normal(value).is_zero()) throw claims_file_error(file, line, field, f.locator + " is 0");
            for (const GiNaC::symbol& s : read->symbols(p.free_of)) {
              if (value.has(s)) {
                throw claims_file_error(file, line, field, f.locator + " depends on " + s.get_name() + ", one of the symbols of '" + p.free_of + "'");
              }
            }
          }
          if (p.kind == argument_kind::condition && f.sides.size() != 3) {
            throw claims_file_error(file, line, field, f.locator + " is not a condition 'a < x < b' (it has " + std::to_string(f.sides.size()) + " sides)");
          }
          if (p.positive && declared.complete) {
            for (const std::string& name : symbol_names(f.value)) {
              if (!positive.count(name)) throw claims_file_error(file, line, field, "the symbol '" + name + "' is not declared positive in [symbols]");
            }
          }
          break;
        }
        case argument_kind::definitions:
        case argument_kind::words: break;
        case argument_kind::equations: {
          std::string shown;
          for (const referenced_formula& f : read->equations(p.name)) {
            if (f.sides.size() < 2) throw claims_file_error(file, line, field, f.locator + " is not an equation 'a = b'");
            shown += (shown.empty() ? "" : "; ") + ("$" + folded_space(f.tex) + "$ (" + f.locator + ")");
          }
          if (p.name == shape.principal) principal = shown;
          break;
        }
        case argument_kind::word:
          if (!p.words.empty() && std::find(p.words.begin(), p.words.end(), it->second.values.front()) == p.words.end()) {
            throw claims_file_error(file, line, field, "'" + it->second.values.front() + "' is not one of: " + fmt::format("{}", fmt::join(p.words, ", ")));
          }
          break;
        case argument_kind::symbols: {
          read->symbols(p.name);  // each one symbol, and declared
          if (p.size != 0 && it->second.values.size() != p.size) {
            throw claims_file_error(file, line, field, fmt::format("{} symbols, not {}", it->second.values.size(), p.size));
          }
          if (!p.same_size_as.empty() && rows.count(p.same_size_as) && it->second.values.size() != rows[p.same_size_as]) {
            throw claims_file_error(file, line, field, fmt::format("{} symbols for the {} rows of '{}'", it->second.values.size(),
                                                                   rows[p.same_size_as], p.same_size_as));
          }
          if (!p.same_size_as.empty() && !rows.count(p.same_size_as) && record.with.count(p.same_size_as) &&
              it->second.values.size() != record.with.at(p.same_size_as).values.size()) {
            throw claims_file_error(file, line, field, fmt::format("{} symbols for the {} of '{}'", it->second.values.size(),
                                                                   record.with.at(p.same_size_as).values.size(), p.same_size_as));
          }
          if (!p.among.empty() && record.with.count(p.among)) {
            const std::vector<GiNaC::symbol> allowed = read->symbols(p.among);
            for (const GiNaC::symbol& s : read->symbols(p.name)) {
              const bool found = std::any_of(allowed.begin(), allowed.end(), [&](const GiNaC::symbol& a) { return a.get_name() == s.get_name(); });
              if (!found) throw claims_file_error(file, line, field, "'" + s.get_name() + "' is not one of the symbols of '" + p.among + "'");
            }
          }
          break;
        }
      }
    } catch (const claims_file_error&) {
      throw;
    } catch (const document_error&) {
      throw;
    } catch (const std::invalid_argument& e) {
      throw claims_file_error(file, line, field, e.what());
    }
  }
  return principal;
}

}  // namespace simpson::verify::detail
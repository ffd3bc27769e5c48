// What a nonlinear derivation prints, read by a rule or refused, never guessed: functions of several
// arguments declared with their variables, their partial derivatives by name and by slot at points,
// slanted derivatives, d/dt along a trajectory, half-index nodes, \operatorname{sin}, and the words
// "for all j" after an equation (tex_math_functions.cpp, tex_names.cpp, tex_document.cpp).

#include <simpson/verify/claim_declarations.hpp>
#include <simpson/verify/paper_source.hpp>
#include <simpson/verify/tex_document.hpp>
#include <simpson/verify/tex_math.hpp>

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace simpson::verify;
using GiNaC::ex;

ex symbol_of(const std::string& name) { return paper_symbols()[name]; }

/// A nonlinear note's declarations: L(q, \dot q), V(q) and L_d(a, b) with their variables, F
/// without; q a state; m, h, a, b, q_l, v_l, t constants.
const tex_declarations& declared() {
  static const tex_declarations d = [] {
    tex_declarations out;
    out.functions = {"L", "V", "L_d", "F", "q"};
    out.symbols = {"q", "m", "h", "a", "b", "q_l", "v_l", "t", "j"};
    for (const char* f : {"L(q, \\dot q)", "V(q)", "L_d(a, b)"}) {
      const function_declaration fd = read_function_declaration(f);
      out.variables[fd.name] = *fd.variables;
    }
    return out;
  }();
  return d;
}

ex reading_of(const std::string& tex) { return read_tex(tex, declared(), paper_symbols()); }
bool equal_values(const ex& a, const ex& b) { return GiNaC::normal(a - b).is_zero(); }
std::string why_refused(const std::string& tex) {
  try {
    reading_of(tex);
  } catch (const tex_error& e) {
    return e.what();
  }
  return "(read)";
}

/// L's partial derivative by its slots at (x, y).
ex partial(const std::string& f, std::initializer_list<int> slots, const ex& x, const ex& y) {
  const GiNaC::symbol a("a_"), b("b_");
  ex e = apply_function(f, {a, b});
  for (const int s : slots) e = e.diff(s == 0 ? a : b);
  return e.subs(GiNaC::lst{a == x, b == y});
}

TEST(TexFunctions, ADeclarationNamesTheVariablesSlotBySlot) {
  const function_declaration l = read_function_declaration("L(q, \\dot q)");
  EXPECT_EQ(l.name, "L");
  ASSERT_TRUE(l.variables);
  EXPECT_EQ(*l.variables, (std::vector<std::string>{"q", "dq/dt"}));
  EXPECT_FALSE(read_function_declaration("V").variables);
  EXPECT_THROW(read_function_declaration("L(q, q)"), std::invalid_argument);      // a variable twice
  EXPECT_THROW(read_function_declaration("L(q + h, v)"), std::invalid_argument);  // not a name
}

TEST(TexFunctions, APartialDerivativeByNameIsBySlotAtThePointsWritten) {
  const ex ql = symbol_of("q_l"), vl = symbol_of("v_l"), q = symbol_of("q"), qdot = symbol_of("dq/dt");
  EXPECT_TRUE(equal_values(reading_of("\\frac{\\partial L}{\\partial \\dot q}(q_l, v_l)"), partial("L", {1}, ql, vl)));
  EXPECT_TRUE(equal_values(reading_of("\\frac{\\partial L}{\\partial q}(q_l, v_l)"), partial("L", {0}, ql, vl)));
  EXPECT_TRUE(equal_values(reading_of("\\frac{\\partial^2 L}{\\partial q \\partial \\dot q}(q_l, v_l)"), partial("L", {0, 1}, ql, vl)));
  EXPECT_TRUE(equal_values(reading_of("\\partial_q L(q_l, v_l)"), partial("L", {0}, ql, vl)));
  EXPECT_TRUE(equal_values(reading_of("\\partial_{\\dot q} L"), partial("L", {1}, q, qdot)));  // alone: at its variables
  EXPECT_TRUE(equal_values(reading_of("\\partial_2 L(q_l, v_l)"), partial("L", {1}, ql, vl)));
  EXPECT_TRUE(equal_values(reading_of("\\partial L / \\partial \\dot q (q_l, v_l)"), partial("L", {1}, ql, vl)));
  // The slot, not the order written: a swapped slot is another function of the points.
  EXPECT_FALSE(equal_values(reading_of("\\frac{\\partial L}{\\partial q}(q_l, v_l)"), partial("L", {1}, ql, vl)));
  EXPECT_FALSE(equal_values(reading_of("\\frac{\\partial L}{\\partial q}(v_l, q_l)"), partial("L", {0}, ql, vl)));
}

TEST(TexFunctions, DkIsTheDerivativeBySlotOfADeclaredFunction) {
  const ex a = symbol_of("a"), b = symbol_of("b"), ql = symbol_of("q_l"), vl = symbol_of("v_l");
  EXPECT_TRUE(equal_values(reading_of("D_2 L_d(q_l, v_l)"), partial("L_d", {1}, ql, vl)));
  EXPECT_TRUE(equal_values(reading_of("D_1L_d(q_l, v_l) + D_2 L_d(q_l, v_l)"), partial("L_d", {0}, ql, vl) + partial("L_d", {1}, ql, vl)));
  EXPECT_TRUE(equal_values(reading_of("D_1 D_2 L_d(q_l, v_l)"), partial("L_d", {0, 1}, ql, vl)));
  EXPECT_TRUE(equal_values(reading_of("\\partial L_d / \\partial a"), partial("L_d", {0}, a, b)));
  // D_2 before what is not a declared function is a name, as before: D_2 times h.
  EXPECT_TRUE(equal_values(reading_of("D_2 h"), symbol_of("D_2") * symbol_of("h")));
}

TEST(TexFunctions, AFunctionWithItsVariablesWrittenAloneStandsAtThem) {
  const ex q = symbol_of("q"), qdot = symbol_of("dq/dt");
  EXPECT_TRUE(equal_values(reading_of("L"), apply_function("L", {q, qdot})));
  EXPECT_TRUE(equal_values(reading_of("V'"), apply_function("V", {q}).diff(GiNaC::ex_to<GiNaC::symbol>(q))));
  // Without declared variables, what it is applied to is not written.
  EXPECT_NE(why_refused("F + 1").find("without its argument"), std::string::npos);
}

TEST(TexFunctions, DerivativeAlongATrajectoryMovesTheStatesOnly) {
  const ex q = symbol_of("q"), qdot = symbol_of("dq/dt"), qddot = symbol_of("d^2q/dt^2"), m = symbol_of("m");
  // d/dt ∂L/∂q̇ = L_{q q̇} q̇ + L_{q̇ q̇} q̈ (the Euler-Lagrange equation's first term).
  EXPECT_TRUE(equal_values(reading_of("\\frac{\\mathrm d}{\\mathrm dt}\\frac{\\partial L}{\\partial\\dot q}"),
                           partial("L", {0, 1}, q, qdot) * qdot + partial("L", {1, 1}, q, qdot) * qddot));
  EXPECT_TRUE(equal_values(reading_of("\\frac{d}{dt}\\left(m \\dot q\\right) + \\frac{d}{dt} V(q)"),
                           m * qddot + apply_function("V", {q}).diff(GiNaC::ex_to<GiNaC::symbol>(q)) * qdot));
  // The operator takes the product after it, up to + or -: its second term is not differentiated.
  EXPECT_TRUE(equal_values(reading_of("\\frac{d}{dt} m \\dot q - m"), m * qddot - m));
}

TEST(TexFunctions, NothingIsGuessed) {
  EXPECT_NE(why_refused("L(q_l)").find("a function of 2 variables (q, dq/dt), applied to 1 argument"), std::string::npos) << why_refused("L(q_l)");
  EXPECT_NE(why_refused("D_2 L_d(q_l)").find("applied to 1 argument"), std::string::npos);
  EXPECT_NE(why_refused("\\frac{\\partial L}{\\partial h}(q_l, v_l)").find("not one of its variables"), std::string::npos);
  EXPECT_NE(why_refused("\\frac{\\partial F}{\\partial a}(a, b)").find("declares no variables"), std::string::npos);
  EXPECT_NE(why_refused("\\partial L / \\partial q \\, m").find("whether they divide or multiply is not written"), std::string::npos);
  EXPECT_NE(why_refused("\\partial L").find("a \\partial outside a derivative"), std::string::npos);
  EXPECT_NE(why_refused("a / \\partial L_d / \\partial a").find("which '/' divides first"), std::string::npos);
  // d/dt of a symbol that is neither a state nor declared: a constant would be a guess.
  EXPECT_NE(why_refused("\\frac{d}{dt} w").find("neither a state nor declared"), std::string::npos) << why_refused("\\frac{d}{dt} w");
  // D_2 declared a symbol: a derivative by slot and a product are both readings.
  tex_declarations with_d = declared();
  with_d.symbols.insert("D_2");
  EXPECT_THROW(read_tex("D_2 L_d(a, b)", with_d, paper_symbols()), tex_error);
}

TEST(TexFunctions, HalfIndexNodesAndKnownOperatorsReadAsPrinted) {
  EXPECT_TRUE(equal_values(reading_of("q_{j+\\frac12} - q_{j+1/2}"), 0));
  EXPECT_TRUE(equal_values(reading_of("q_{j-\\tfrac{1}{2}}"), symbol_of("q_j-1/2")));
  EXPECT_TRUE(equal_values(reading_of("\\operatorname{sin}(a) + \\operatorname{cos} b"), GiNaC::sin(symbol_of("a")) + GiNaC::cos(symbol_of("b"))));
  EXPECT_NE(why_refused("q_{j+\\sqrt2}").find("not a name nor an index"), std::string::npos);
  EXPECT_NE(why_refused("\\operatorname{sgn} a").find("sgn"), std::string::npos);
}

std::vector<tex_equation> equations_in(const std::string& display) {
  const tex_document d(paper_source{"note", display, "", display});
  return equations_of(d.regions().front(), -1);
}

TEST(TexFunctions, ForAllJAfterAnEquationIsItsQuantifierAndOtherWordsAreRefused) {
  for (const char* display : {"\\[ p_j = D_2 L_d(a, b) \\quad \\text{for all } j \\]", "\\[ p_j = D_2 L_d(a, b), \\quad \\text{for every $j$}. \\]",
                              "\\[ p_j = D_2 L_d(a, b) \\quad \\forall j \\]"}) {
    const std::vector<tex_equation> eqs = equations_in(display);
    ASSERT_EQ(eqs.size(), 1u) << display;
    ASSERT_EQ(eqs.front().sides.size(), 2u) << display;
    EXPECT_TRUE(equal_values(read_math(eqs.front().sides[1], declared(), paper_symbols()), partial("L_d", {1}, symbol_of("a"), symbol_of("b")))) << display;
  }
  // Words that are not a quantifier stay, and the reader refuses them.
  const std::vector<tex_equation> eqs = equations_in("\\[ p_j = a \\quad \\text{when } j \\]");
  EXPECT_THROW(read_math(eqs.front().sides[1], declared(), paper_symbols()), tex_error);
}

}  // namespace

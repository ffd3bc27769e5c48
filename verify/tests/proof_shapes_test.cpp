// Proof shapes (proof_shapes.hpp) and what they stand on: a document's macros (tex_macros.hpp),
// formula references (formula_reference.hpp) and our kernel's zero decision (kernel_zero.hpp).
// Each shape is run on a small document where it holds and on one where a weaker check would
// pass a wrong statement; a bad record is named with its line and argument.

#include <simpson/prove/kernel_zero.hpp>
#include <simpson/prove/printed_check_support.hpp>
#include <simpson/shapes/proof_shapes.hpp>

#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/consequences.hpp>
#include <simpson/verify/formula_reference.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/printed_checks.hpp>
#include <simpson/verify/sentence_holes.hpp>
#include <simpson/verify/tex_document.hpp>
#include <simpson/verify/tex_macros.hpp>
#include <simpson/verify/tex_math.hpp>

#include "shape_fixture.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace simpson::verify {
namespace {

using namespace test;  // the shapes' document, its declarations and the fixture (shape_fixture.hpp)

// ---- macros ----

std::string macros_expanded(const std::string& tex, const tex_macros& macros) { return tex_text(expand_all(tex_tokenize(tex), macros)); }

TEST(TexMacros, DefinitionsWithArgumentsExpandAsTeXWould) {
  const tex_macros macros = defined_macros(R"(\newcommand{\om}{\omega} \newcommand\half[1]{\frac{#1}{2}}
\def\sq#1{#1^2} \renewcommand{\om}{\Omega})");
  ASSERT_EQ(macros.all().size(), 3u);
  EXPECT_EQ(macros.find("\\half")->arguments, 1);
  // The arguments' tokens go in as they are, as TeX puts them: \sq x is x^2, \half{\om h} \frac{\Omega h}{2}.
  EXPECT_EQ(macros_expanded(R"(\half{\om h} + \sq x)", macros), R"(\frac{\Omega h}{2} + x^2)");
  EXPECT_EQ(macros_expanded(R"(\omh)", macros), R"(\omh)");  // not \om followed by h
  EXPECT_THROW(macros_expanded(R"(\half)", macros), tex_error);
  EXPECT_THROW(macros_expanded(R"(\a)", defined_macros(R"(\newcommand{\a}{\a x})")), tex_error);
  EXPECT_THROW(defined_macros(R"(\newcommand{\b}[12]{x})"), tex_error);
}

TEST(TexMacros, ADefWithDelimitersExpandsAsTeXDoes) {
  // The paper's own preamble: \def\section*#1{} (a delimited parameter text): \section* then one
  // argument; \section without its * does not match the definition, as TeX says.
  const tex_macros macros = defined_macros(R"(\def\br {\break}
\def\section*#1{} \newcommand{\dd}{{\rm d}} \def\pair(#1,#2){[#1;#2]})");
  ASSERT_EQ(macros.all().size(), 4u);
  EXPECT_EQ(macros.find("\\section")->arguments, 1);
  EXPECT_EQ(macros_expanded(R"(\dd q)", macros), R"({\rm d} q)");
  EXPECT_EQ(macros_expanded(R"(a\section*{x}b)", macros), "ab");
  EXPECT_EQ(macros_expanded(R"(\pair(u,{v,w}))", macros), "[u;v,w]");
  EXPECT_THROW(macros_expanded(R"(\section{x})", macros), tex_error);
  EXPECT_THROW(defined_macros(R"(\def\x*#1)"), tex_error);  // no body
}

TEST(TexMacros, AnOptionalFirstArgumentAndDeclaredOperators) {
  const tex_macros macros = defined_macros(R"(\newcommand{\pd}[2][t]{\frac{\partial #2}{\partial #1}} \DeclareMathOperator{\tr}{tr}
\let\phi\varphi)");
  EXPECT_EQ(macros_expanded(R"(\pd{q} \pd[x]{V})", macros), R"(\frac{\partial q}{\partial t} \frac{\partial V}{\partial x})");
  EXPECT_EQ(macros_expanded(R"(\tr\Phi)", macros), R"(\operatorname{tr}\Phi)");
  EXPECT_EQ(macros_expanded(R"(\phi)", macros), R"(\varphi)");
}

// ---- references ----

const std::string note = R"(\newcommand{\om}{\omega}
\begin{equation}\label{first} a = b + 1, \quad c = 2 \end{equation}
\begin{equation}
x = \frac{\om}{2} \label{end}
\end{equation}
It is stable for $0 < \om h < 2$.
Unlabelled, as the first display after a phrase:
\begin{equation*} y = \om - 1 \end{equation*}
)";

/// What these documents declare: the functions they apply, and q, a state.
const tex_declarations& test_declarations() {
  static const tex_declarations declared{{"V", "W", "q", "varphi_0", "varphi_1"}, {"q"}, {}};
  return declared;
}

// An align environment: each labelled row is a formula of its own, its '&' dropped; a matrix's
// rows inside it are not the environment's.
TEST(FormulaReference, ARowOfAnAlignEnvironment) {
  const tex_document d(document(R"(\begin{align}
x &= a + 1 \label{ax} \\
y &= \begin{pmatrix} a \\ b \end{pmatrix} \label{ay} \\
z &= 3 \nonumber
\end{align})"));
  const tex_declarations& declared = test_declarations();
  const GiNaC::ex a = paper_symbols()["a"], b = paper_symbols()["b"];
  EXPECT_TRUE((read_reference(d, declared, "ax").value - (a + 1)).is_zero());
  EXPECT_TRUE((read_reference(d, declared, "ax:lhs").value - paper_symbols()["x"]).is_zero());
  const referenced_formula y = read_reference(d, declared, "ay");
  ASSERT_TRUE(GiNaC::is_a<GiNaC::matrix>(y.value));
  EXPECT_EQ(GiNaC::ex_to<GiNaC::matrix>(y.value).rows(), 2u);
  EXPECT_EQ(y.line, 3);
}

TEST(FormulaReference, ByLabelEquationSideInlineAndLiteral) {
  const tex_document d(document(note));
  const tex_declarations& declared = test_declarations();
  const GiNaC::ex b = paper_symbols()["b"], omega = paper_symbols()["omega"];
  EXPECT_TRUE((read_reference(d, declared, "first").value - (b + 1)).is_zero());
  EXPECT_TRUE((read_reference(d, declared, "first#2").value - 2).is_zero());
  EXPECT_TRUE((read_reference(d, declared, "first:lhs").value - paper_symbols()["a"]).is_zero());
  EXPECT_TRUE((read_reference(d, declared, "end").value - omega / 2).is_zero()) << "a label at the end of its display";
  EXPECT_EQ(read_reference(d, declared, "end").line, 4);
  EXPECT_EQ(read_reference(d, declared, "inline:stable for").sides.size(), 3u);
  const referenced_formula after = read_reference(d, declared, "after:as the first display after");
  EXPECT_TRUE((after.value - (omega - 1)).is_zero()) << after.tex;
  EXPECT_EQ(after.line, 8);
  EXPECT_THROW(read_reference(d, declared, "after:a phrase the note does not have"), std::invalid_argument);
  EXPECT_THROW(parse_reference("after: "), std::invalid_argument);
  EXPECT_TRUE((read_reference(d, declared, "$\\om + 1$").value - (omega + 1)).is_zero());
  EXPECT_THROW(read_reference(d, declared, "missing"), std::invalid_argument);
  EXPECT_THROW(read_reference(d, declared, "first#3"), std::invalid_argument);
  EXPECT_THROW(read_reference(d, declared, "$\\unknown$"), std::invalid_argument);
  EXPECT_THROW(parse_reference("first#0"), std::invalid_argument);
  // A \label may hold spaces (the paper's own "oscillateur harmonique"), not at its ends.
  EXPECT_EQ(parse_reference("a label").key, "a label");
  EXPECT_THROW(parse_reference(" a label"), std::invalid_argument);
  // The first side of an inline formula.
  EXPECT_TRUE(read_reference(d, declared, "inline:stable for:lhs").value.is_zero());
  const definition x = read_definition(d, declared, "end");
  EXPECT_EQ(x.name.get_name(), "x");
  EXPECT_TRUE((with_definitions(paper_symbols()["x"] * 2, {x}) - omega).is_zero());
}

TEST(FormulaReference, DefinitionsOfAFunctionAndByAChain) {
  const tex_document d(document(R"(\begin{equation}\label{potential energy} V(q) = \frac{k}{2} q^2 \end{equation}
\begin{equation}\label{chain} g = \frac{a + b}{2} = a \end{equation}
\begin{equation}\label{two} V(q) + W(q) = 1 \end{equation})"));
  const tex_declarations& declared = test_declarations();
  const GiNaC::ex k = paper_symbols()["k"], x = paper_symbols()["x"], a = paper_symbols()["a"];
  const definition v = read_definition(d, declared, "potential energy");
  EXPECT_EQ(v.function, "V");
  // V(x) and V'(x) and V''(x) at any argument, and a definition by the last side of a chain.
  const GiNaC::ex applied = read_reference(d, declared, "$V(2 x) + {{\\partial V}\\over{\\partial q}}(x) + {{\\partial^2 V}\\over{\\partial q^2}}(x)$").value;
  EXPECT_TRUE(GiNaC::normal(with_definitions(applied, {v}) - (2 * k * x * x + k * x + k)).is_zero()) << with_definitions(applied, {v});
  EXPECT_TRUE((with_definitions(paper_symbols()["g"], {read_definition(d, declared, "chain")}) - a).is_zero());
  EXPECT_THROW(read_definition(d, declared, "two"), std::invalid_argument);  // its left side is no function of one symbol
}

TEST(FormulaReference, AFunctionDefinedInAnotherVariableAndItsDerivative) {
  // q(t) printed in theta, with t = h theta: read in t (theta = t/h), so q(h) = b and dq/dt = (b - a)/h.
  const tex_document d(document(R"(\newcommand{\dd}{{\rm d}}
\begin{equation}\label{basis} \varphi_0(\theta) = 1 - \theta \,,\,\, \varphi_1(\theta) = \theta \end{equation}
\begin{equation}\label{interp} q(t) = a \, \varphi_0(\theta) + b \, \varphi_1(\theta) \end{equation}
Set $t = h \, \theta$ and $t = 2 \, h \, \theta$.)"));
  const tex_declarations& declared = test_declarations();
  const GiNaC::ex a = paper_symbols()["a"], b = paper_symbols()["b"], h = paper_symbols()["h"], theta = paper_symbols()["theta"];
  std::vector<definition> defs{read_definition(d, declared, "basis#1"), read_definition(d, declared, "basis#2"), read_definition(d, declared, "interp"),
                               read_definition(d, declared, "inline:t = h")};
  const auto value = [&](const std::string& tex, const std::vector<definition>& with) { return with_definitions(read_reference(d, declared, tex).value, with); };
  EXPECT_TRUE(GiNaC::normal(value("$q(h)$", defs) - b).is_zero()) << value("$q(h)$", defs);
  EXPECT_TRUE(GiNaC::normal(value("${{\\dd q}\\over{\\dd t}}(0)$", defs) - (b - a) / h).is_zero()) << value("${{\\dd q}\\over{\\dd t}}(0)$", defs);
  // Without an argument: dq/dt in t, then t = h theta put in (a constant here).
  EXPECT_TRUE(GiNaC::normal(value("${{\\dd q}\\over{\\dd t}}$", defs) - (b - a) / h).is_zero());
  // The change read as printed: t = 2 h theta makes q(h) the value at theta = 1/2.
  defs.back() = read_definition(d, declared, "inline:t = 2");
  EXPECT_TRUE(GiNaC::normal(value("$q(h)$", defs) - (a + b) / 2).is_zero()) << value("$q(h)$", defs);
  // Without it, q's value is in theta, not in t: read as printed it would be constant in t. Refused.
  defs.pop_back();
  try {
    value("$q(h)$", defs);
    ADD_FAILURE() << "q(t) defined in theta alone was read";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("q(t) is defined without t"), std::string::npos) << e.what();
  }
  // sigma = t/h, the other way round, is put in as it is: q(h) = b again.
  const tex_document with_sigma(document(R"(\begin{equation}\label{interp} q(t) = a \, (1 - \sigma) + b \, \sigma \end{equation}
Set $\sigma = t / h$.)"));
  const std::vector<definition> in_sigma{read_definition(with_sigma, declared, "interp"), read_definition(with_sigma, declared, "inline:\\sigma = t")};
  const GiNaC::ex at_h = with_definitions(read_reference(with_sigma, declared, "$q(h)$").value, in_sigma);
  EXPECT_TRUE(GiNaC::normal(at_h - b).is_zero()) << at_h;
}

TEST(FormulaReference, APartialDerivativeOfADefinedSymbol) {
  // g = (a x + b)/h defined: dg/dx is a/h, d^2g/dx^2 is 0; without the definition it stays a symbol.
  const tex_document d(document(R"(\begin{equation}\label{g} g = \frac{a x + b}{h} \end{equation})"));
  const tex_declarations& declared = test_declarations();
  const definition g = read_definition(d, declared, "g");
  const GiNaC::ex a = paper_symbols()["a"], h = paper_symbols()["h"];
  const GiNaC::ex first = read_reference(d, declared, "${{\\partial g}\\over{\\partial x}}$").value;
  EXPECT_TRUE(GiNaC::normal(with_definitions(first, {g}) - a / h).is_zero()) << with_definitions(first, {g});
  EXPECT_TRUE(with_definitions(read_reference(d, declared, "${{\\partial^2 g}\\over{\\partial x^2}}$").value, {g}).is_zero());
  EXPECT_TRUE(GiNaC::is_a<GiNaC::symbol>(with_definitions(first, {})));
}

// ---- our kernel ----

using detail::kernel_decides_zero;
using detail::kernel_decision;

TEST(KernelZero, DecidesIdentitiesAndFindsWhereOneFails) {
  const GiNaC::ex x = paper_symbols()["x"], y = paper_symbols()["y"];
  EXPECT_EQ(kernel_decides_zero(GiNaC::pow(x + y, 2) - x * x - 2 * x * y - y * y).outcome, kernel_decision::result::zero);
  // Written with a removable pole at x = 1, a value of the first grid.
  EXPECT_EQ(kernel_decides_zero((x * x - 1) / (x - 1) * y - (x + 1) * y).outcome, kernel_decision::result::zero);
  // Zero at y = 1 and 2 but not identically: a grid of fewer points than the degree + 1 would pass it.
  const kernel_decision wrong = kernel_decides_zero((y - 1) * (y - 2) * GiNaC::pow(x, 3));
  EXPECT_EQ(wrong.outcome, kernel_decision::result::nonzero);
  EXPECT_NE(wrong.evidence.find("y = 3"), std::string::npos) << wrong.evidence;
  EXPECT_EQ(kernel_decides_zero(GiNaC::matrix{{x - x, 0}, {0, y / y - 1}}).outcome, kernel_decision::result::zero);
  EXPECT_EQ(kernel_decides_zero(GiNaC::sqrt(x) - 1).outcome, kernel_decision::result::not_applicable);
}

// An uninterpreted V: an identity linear in it is decided for V(x) = x^k, k <= 4.
TEST(KernelZero, AnUninterpretedFunctionLinearlyForEachMonomialUpToTheFourth) {
  const GiNaC::ex x = paper_symbols()["x"], y = paper_symbols()["y"];
  const GiNaC::symbol t("t");
  const auto V = [](const GiNaC::ex& at) { return apply_function("V", {at}); };
  // The chain rule, V' at one argument written two ways (GiNaC does not cancel the two as written).
  const GiNaC::ex chain = GiNaC::diff(V(GiNaC::pow(t + 1, 2)), t).subs(t == x) - 2 * (x + 1) * GiNaC::diff(V(t), t).subs(t == x * x + 2 * x + 1);
  const kernel_decision d = kernel_decides_zero(chain);
  EXPECT_EQ(d.outcome, kernel_decision::result::zero) << d.evidence;
  EXPECT_NE(d.evidence.find("every polynomial V of degree <= 4"), std::string::npos) << d.evidence;
  // Additive: true for V of degree <= 1 only, so a kernel that tried V = 1 and V = x alone would pass it.
  const kernel_decision additive = kernel_decides_zero(V(x + y) - V(x) - V(y) + V(0));
  EXPECT_EQ(additive.outcome, kernel_decision::result::nonzero) << additive.evidence;
  EXPECT_NE(additive.evidence.find("V(x) = x^2"), std::string::npos) << additive.evidence;
  // Not linear in V, or two functions: not for our kernel.
  EXPECT_EQ(kernel_decides_zero(V(x) * V(y) - V(y) * V(x) + V(x) * V(x) - x).outcome, kernel_decision::result::not_applicable);
  EXPECT_EQ(kernel_decides_zero(V(x) - apply_function("Q", {x})).outcome, kernel_decision::result::not_applicable);
  EXPECT_EQ(kernel_decides_zero(V(V(x)) - V(x)).outcome, kernel_decision::result::not_applicable);  // V(V(x)): not linear in V
  // GiNaC's own functions are interpreted, so they stay outside our kernel: taken for an uninterpreted
  // V, an odd sin(x + y) + sin(-x - y) would be refuted at V(x) = x^2.
  EXPECT_EQ(kernel_decides_zero(GiNaC::sin(x) - x).outcome, kernel_decision::result::not_applicable);
}

// ---- the shapes, through a claims file: shapes_algebra_test.cpp, shapes_derivation_test.cpp, prose_shapes_test.cpp ----

// A new shape is its file, its list line and its fixture folder (verify/tests/shapes/<shape>/, run
// as shapes.<shape>): a shape without one, or a folder that names no shape, fails here.
TEST(ProofShapes, EachShapeHasItsFixtureFolderAndEachFolderAShape) {
  const std::filesystem::path fixtures = std::filesystem::path(SIMPSON_SOURCE_DIR) / "verify/tests/shapes";
  for (const auto& [name, shape] : detail::proof_shapes()) {
    EXPECT_TRUE(std::filesystem::exists(fixtures / name / "note.tex") && std::filesystem::exists(fixtures / name / "claims.toml"))
        << "the shape '" << name << "' has no fixture folder " << (fixtures / name).string();
  }
  for (const auto& entry : std::filesystem::directory_iterator(fixtures)) {
    if (entry.is_directory()) {
      EXPECT_EQ(detail::proof_shapes().count(entry.path().filename().string()), 1u) << entry.path();
    }
  }
}

// Every hole a shape's pattern names is in the one table the shapes read their words by, and the
// reference generated from it (--list-holes) lists it with the shapes that take it.
TEST(SentenceHoles, EveryHoleAShapeTakesIsInTheTable) {
  const std::string reference = holes_markdown();
  std::size_t holes = 0;
  for (const auto& [name, shape] : detail::proof_shapes()) {
    for (const detail::shape_parameter& p : shape.parameters) {
      if (p.kind != detail::argument_kind::word) continue;
      for (std::size_t at = p.meaning.find('{'); at != std::string::npos; at = p.meaning.find('{', at + 1)) {
        const std::size_t end = p.meaning.find('}', at);
        const std::string hole = p.meaning.substr(at + 1, end - at - 1);
        // A hole's name is two or more lower-case letters (prose_span.hpp): {j+1} is TeX, not a hole.
        if (hole.size() < 2 || !std::all_of(hole.begin(), hole.end(), [](char c) { return c >= 'a' && c <= 'z'; })) continue;
        ++holes;
        EXPECT_NO_THROW(hole_named(hole)) << name << " takes {" << hole << "}";
        EXPECT_NE(reference.find("| `{" + hole + "}` |"), std::string::npos) << hole;
      }
    }
  }
  EXPECT_GT(holes, 10u);
  EXPECT_THROW(hole_named("no-such-hole"), std::logic_error);
  EXPECT_NE(reference.find("`sign-iff`"), std::string::npos) << reference;
}

/// The error a record gives at reading (or at reading its formulas), or "".
std::string error_of(const std::string& shape, const std::string& with, const std::string& extra = "") {
  try {
    claim_book book = read_claim_book(declarations + record("bad", shape, with) + extra, "bad.toml");
    check_claims_file_formulas(book, document(shape_document));
  } catch (const claims_file_error& e) {
    return e.what();
  }
  return "";
}

TEST(ShapeRecords, ADeclaredFunctionIsOneName) {
  const std::string file = "[document]\ntitle = \"x\"\n[symbols]\nreal = ['x']\nfunctions = ['f + g']\n" + record("r", "identity", R"({ lhs = '$x$', rhs = '$x$' })");
  try {
    read_claim_book(file, "bad.toml");
    ADD_FAILURE() << "a function 'f + g' was read";
  } catch (const claims_file_error& e) {
    EXPECT_NE(std::string(e.what()).find("field 'symbols.functions': 'f + g' is not one name"), std::string::npos) << e.what();
  }
}

// One name declared twice with other variables (a second system's Lagrangian): the later one would
// win and the first system's formulas read wrongly; refused, saying so.
TEST(ShapeRecords, AFunctionDeclaredTwiceIsRefused) {
  const std::string file = "[document]\ntitle = \"x\"\n[symbols]\nreal = ['x']\nfunctions = ['L(q, \\dot q)', 'L(\\theta, \\dot\\theta, \\dot\\phi)']\n" +
                           record("r", "identity", R"({ lhs = '$x$', rhs = '$x$' })");
  try {
    read_claim_book(file, "bad.toml");
    ADD_FAILURE() << "L declared twice was read";
  } catch (const claims_file_error& e) {
    EXPECT_NE(std::string(e.what()).find("field 'symbols.functions': 'L(\\theta, \\dot\\theta, \\dot\\phi)' declares L a second time"), std::string::npos)
        << e.what();
  }
}

TEST(ShapeRecords, BadRecordsAreNamedWithTheirLineAndArgument) {
  EXPECT_EQ(error_of("identity", R"({ lhs = "sum", rhs = "expanded" })"), "");
  // A misused argument is bad input before the run, never a harness fault in it: a scale that
  // depends on the states, or is 0 (the shape's own check, reached at run time, was exit 3).
  const std::string series = R"(printed = "trunc", scheme = "sv:lhs", sequence = ['q_{j-1}', 'q_j', 'q_{j+1}'], step = ['h'], frequency = '$\omega$')";
  EXPECT_EQ(error_of("truncation", "{ " + series + R"(, scale = '$m$' })"), "");
  EXPECT_NE(error_of("truncation", "{ " + series + R"(, scale = '$q_j$' })").find("field 'with.scale': the record's TeX 'q_j' depends on q_j"),
            std::string::npos);
  EXPECT_NE(error_of("truncation", "{ " + series + R"(, scale = '$m - m$' })").find("field 'with.scale': the record's TeX 'm - m' is 0"),
            std::string::npos);
  EXPECT_NE(error_of("no-such-shape", "{}").find("field 'shape': no proof shape is named 'no-such-shape'"), std::string::npos);
  EXPECT_NE(error_of("identity", R"({ lhs = "sum" })").find("field 'with.rhs': missing"), std::string::npos);
  EXPECT_NE(error_of("identity", R"({ lhs = "sum", rhs = "expanded", extra = "x" })").find("field 'with.extra': not an argument"),
            std::string::npos);
  EXPECT_NE(error_of("identity", R"({ lhs = ["sum"], rhs = "expanded" })").find("field 'with.lhs': must be one string"), std::string::npos);
  EXPECT_NE(error_of("equal-sides", R"({ equations = "sum" })").find("field 'with.equations': must be an array"), std::string::npos);
  EXPECT_NE(error_of("equal-sides", R"({ equations = ['inline:one side alone'] })").find("field 'with.equations'"), std::string::npos);
  EXPECT_NE(error_of("equal-sides", R"({ equations = ['inline:one side alone'] })").find("is not an equation"), std::string::npos);
  EXPECT_NE(error_of("identity", R"({ lhs = "nolabel", rhs = "expanded" })").find("field 'with.lhs': no \\label{nolabel}"),
            std::string::npos);
  EXPECT_NE(error_of("identity", R"({ lhs = "sum", rhs = '$a +* b$' })").find("field 'with.rhs': "), std::string::npos);
  EXPECT_NE(error_of("identity", R"({ lhs = "sum", rhs = '$z$' })").find("the symbol 'z' is not declared"), std::string::npos);
  // A derivative of something neither declared nor defined: the hint is its definition, not a declaration of dg/dx.
  EXPECT_NE(error_of("identity", R"({ lhs = "sum", rhs = '$\frac{\partial g}{\partial x}$' })")
                .find("the derivative 'dg/dx' of g by x: g is neither declared nor defined; put the label of its definition (g = ...) in 'where'"),
            std::string::npos) << error_of("identity", R"({ lhs = "sum", rhs = '$\frac{\partial g}{\partial x}$' })");
  // Of the wrong kind or size for the shape: found before anything runs, not when the claim runs.
  EXPECT_NE(error_of("determinant", R"({ matrix = "sum", equals = "one" })").find("field 'with.matrix': label sum (line 15) is not a square matrix"),
            std::string::npos);
  EXPECT_NE(error_of("stability-interval", R"({ map = "map", variable = '$\omega h$', condition = "one" })").find("is not a condition"),
            std::string::npos);
  EXPECT_NE(error_of("stability-interval", R"({ map = "map", variable = '$q h$', condition = "inline:Stable for" })")
                .find("field 'with.variable': the symbol 'q' is not declared positive"),
            std::string::npos);
  EXPECT_NE(error_of("symplectic", R"({ matrix = "map", says = 'That map is {property} indeed.' })").find("field 'with.property': missing"),
            std::string::npos);
  EXPECT_NE(error_of("symplectic", R"({ matrix = "map", says = 'That map is symplectic.', property = "symplectic" })")
                .find("field 'with.says': the sentence's pattern has no hole {property}"),
            std::string::npos);
  EXPECT_NE(error_of("conserved", R"({ map = "map", function = "energy", state = ['q', 'p'], keep = ['h'] })")
                .find("field 'with.keep': 'h' is not one of the symbols of 'state'"),
            std::string::npos);
  EXPECT_NE(error_of("conserved", R"({ map = "map", function = "energy", state = ['q', 'p', 'a'] })")
                .find("field 'with.state': 3 symbols for the 2 rows of 'map'"),
            std::string::npos);
  EXPECT_NE(error_of("euler-lagrange", R"({ lagrangian = "ld", nodes = ['q_0'], sequence = ['q_{j-1}', 'q_j', 'q_{j+1}'], printed = "el:lhs" })")
                .find("field 'with.nodes': 1 symbols, not 2"),
            std::string::npos);
  EXPECT_NE(error_of("sign-on-interval", R"({ expression = "inline:Coefficient", variable = '$\omega h$', condition = "inline:positive on", sign = "positve" })")
                .find("field 'with.sign': 'positve' is not one of: positive, negative"),
            std::string::npos);
  // A map or a scheme, not both, not neither; a scheme's sequence only with it.
  EXPECT_NE(error_of("stability-interval", R"({ map = "map", scheme = "sv:lhs", sequence = ['q_{j-1}', 'q_j', 'q_{j+1}'], variable = '$\omega h$', condition = "inline:Stable for" })")
                .find("give 'scheme' or 'map', not both"),
            std::string::npos);
  EXPECT_NE(error_of("stability-interval", R"({ variable = '$\omega h$', condition = "inline:Stable for" })").find("field 'with.map': missing"),
            std::string::npos);
  EXPECT_NE(error_of("stability-interval", R"({ scheme = "sv:lhs", variable = '$\omega h$', condition = "inline:Stable for" })")
                .find("field 'with.sequence': missing"),
            std::string::npos);
  EXPECT_NE(error_of("discrete-map", R"({ map = "map", lagrangian = "ld", nodes = ['q_0', 'q_1'], momenta = ['p_0', 'p_1'], order = "pq" })")
                .find("field 'with.order': 'pq' is not one of: q p, p q"),
            std::string::npos);
  EXPECT_NE(error_of("derivative", R"({ function = "energy", variable = ['q', 'p'], printed = "one" })").find("field 'with.variable': 2 symbols, not 1"),
            std::string::npos);
  EXPECT_NE(error_of("factor-signs", R"({ expression = "disc", condition = "inline:First, on", variable = '$\omega h$', sentence = 'all the factors are negative' })")
                .find("field 'with.sentence': the sentence's pattern has no hole {sign}"),
            std::string::npos);
  EXPECT_NE(error_of("characteristic", R"({ scheme = "sv:lhs", sequence = ['q_{j-1}', 'q_j'], root = ['r'], printed = "inline:Its roots solve:lhs" })")
                .find("field 'with.sequence': 2 symbols, not 3"),
            std::string::npos);
  EXPECT_NE(error_of("derivative", R"({ function = "ld", variable = ['q_1'], printed = "pnext", at = ['q_j', 'q_{j+1}'] })")
                .find("field 'with.arguments': missing: 'at' needs it"),
            std::string::npos);
  EXPECT_NE(error_of("derivative", R"({ function = "ld", variable = ['q_1'], printed = "pnext", arguments = ['q_0', 'q_1'], at = ['q_j'] })")
                .find("field 'with.at': 1 symbols for the 2 of 'arguments'"),
            std::string::npos);
  // A symbol to solve each condition for, and conditions that are equations.
  const std::string invariance = R"(form = 'inline:and a form', map = 'inline:A square map', state = ['q', 'p'], unknowns = ['a', 'b', 'c'], system = "invsys:side2")";
  EXPECT_NE(error_of("invariance-singular", "{ conditions = ['inline:Of unit determinant'], solve_for = ['s', 'w'], " + invariance + " }")
                .find("field 'with.solve_for': 2 symbols for the 1 of 'conditions'"),
            std::string::npos);
  EXPECT_NE(error_of("invariance-singular", "{ conditions = ['inline:a cube'], " + invariance + " }").find("field 'with.solve_for': missing"),
            std::string::npos);
  EXPECT_NE(error_of("invariance-kernel", "{ printed = 'inline:It conserves', conditions = ['inline:one side alone'], solve_for = ['s'], " + invariance + " }")
                .find("field 'with.conditions'"),
            std::string::npos);
  EXPECT_NE(error_of("explicit-map", R"({ map = "map", step = ['h'], sentence = 'leapfrog is an explicit scheme.' })")
                .find("field 'with.sentence': the sentence's pattern has no hole {kind}"),
            std::string::npos);
  EXPECT_NE(error_of("explicit-map", R"({ map = "map", step = ['h', 'm'], sentence = 'leapfrog is an {kind} scheme.' })").find("field 'with.step': 2 symbols, not 1"),
            std::string::npos);
  // A side of a chain by its number, from 1.
  EXPECT_NE(error_of("identity", R"({ lhs = "invsys:side4", rhs = "one" })").find("side 4 is not there (the equation has 3)"), std::string::npos);
  EXPECT_NE(error_of("identity", R"({ lhs = "invsys:side0", rhs = "one" })").find("after ':side' a side number from 1"), std::string::npos);
  // The entries of a generic matrix: two references, the first a matrix of distinct symbols, the
  // second a matrix of its size.
  const std::vector<std::pair<std::string, std::string>> bad_entries{
      {"['map']", "field 'with.entries': 1 references, not 2"},
      {"['map', 'map']", "field 'with.entries': label map (line 6): the entry (1, 1), "},
      {"['inline:a map with a number', 'map']", "the entry (1, 2), 2, is not one symbol"},
      {"['inline:A map of one entry', 'map']", "is 1 x 1 and label map (line 6) is 2 x 2"},
      {"['inline:A generic map', 'one']", "field 'with.entries': label one (line 12) is not a matrix"}};
  for (const auto& [entries, expected] : bad_entries) {
    const std::string error = error_of("proportional", "{ printed = \"energy\", of = 'inline:It conserves', state = ['q', 'p'], entries = " + entries + " }");
    EXPECT_NE(error.find(expected), std::string::npos) << entries << ": " << error;
  }
  const std::string both = error_of("identity", R"({ lhs = "sum", rhs = "expanded" })", "check = \"x\"\n");
  EXPECT_NE(both.find("line"), std::string::npos) << both;
}

// ---- the note of the tests: a derivation the harness has never seen, from its claims file alone ----

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(TrapezoidalNote, EveryVerdictIsTheOneItsClaimsFileExpects) {
  const std::string dir = std::string(SIMPSON_SOURCE_DIR) + "/verify/tests/notes/";
  claim_book book = read_claim_book(file_text(dir + "trapezoidal-note.toml"), "trapezoidal-note.toml");
  const paper_reading reading = read_note(load_document(dir + "trapezoidal-note.tex", book.checked_document()->title));
  check_claims_file_formulas(book, reading.source);
  run_context ctx;
  ctx.paper = &reading;
  ctx.book = &book;
  int errata = 0;
  for (const claim& c : book.claims) {
    const claim_result r = check_claim(c, ctx);
    EXPECT_EQ(r.outcome, c.expected) << c.id << ": " << r.note;
    if (r.outcome == verdict::erratum) {
      ++errata;
      EXPECT_FALSE(r.correction.empty()) << c.id;
    }
  }
  EXPECT_EQ(errata, 6);  // five deliberate errors, and one consequence of the energy's
  EXPECT_EQ(book.find("energy-positive").follows_from, "modified-energy");
  EXPECT_EQ(check_claim(book.find("energy-positive"), ctx).correction,
            "(-h^2*omega^2+2)/(2) is positive for 0 < h*omega < sqrt(2) only, and changes sign there");
  EXPECT_EQ(check_claim(book.find("stability-condition"), ctx).correction, "stable exactly for 0 < h*omega < 2");
  EXPECT_EQ(check_claim(book.find("map-order"), ctx).correction, "the map is of order 2: its local error is O(h^3)");
  EXPECT_EQ(check_claim(book.find("rule-exactness"), ctx).correction,
            "The rule is exact for every polynomial of degree <= 1 and not for degree 2 (the printed words say 'two')");
}

}  // namespace
}  // namespace simpson::verify

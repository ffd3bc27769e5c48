// Proof shapes (proof_shapes.hpp) and what they stand on: a document's macros (tex_macros.hpp),
// formula references (formula_reference.hpp) and our kernel's zero decision (kernel_zero.hpp).
// Each shape is run on a small document where it holds and on one where a weaker check would
// pass a wrong statement; a bad record is named with its line and argument.

#include "kernel_zero.hpp"
#include "printed_check_support.hpp"
#include "proof_shapes.hpp"

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

#include <fstream>
#include <sstream>

namespace simpson::verify {
namespace {

using test::document;
using test::record;
using test::ShapesOnADocument;
using test::shape_document;
using test::declarations;

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
  static const tex_declarations declared{{"V", "W", "q", "varphi_0", "varphi_1"}, {"q"}};
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
  // Without it, q's value is in theta, not in t: q(h) stays a function of theta.
  defs.pop_back();
  EXPECT_TRUE(value("$q(h)$", defs).has(theta));
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

// ---- the shapes, through a claims file ----


// Consequences traced: an erratum's corrected formula put in where another claim reads it. The
// claim that then holds follows from it; a typed link the derivation contradicts is a harness fault.
TEST_F(ShapesOnADocument, ConsequencesAreTracedAndTypedLinksChecked) {
  const std::string records = record("misprint", "identity", R"({ lhs = "sum", rhs = "expanded" })") +
                              record("reads-it", "identity", R"({ lhs = "expanded", rhs = "$(a + b)^2$" })") +
                              record("still-wrong", "identity", R"({ lhs = "expanded", rhs = "$a^3$" })");
  // The document with (expanded) misprinted a^2 + b^2; each record judged as printed, then traced.
  const auto judge = [&](const std::string& file) {
    book_ = read_claim_book(declarations + file, "test.toml");
    std::string text = shape_document;
    text.replace(text.find("t = a^2 + 2 a b + b^2"), 21, "t = a^2 + b^2");
    reading_ = read_note(document(text));
    check_claims_file_formulas(book_, reading_.source);
    run_context ctx;
    ctx.paper = &reading_;
    ctx.book = &book_;
    std::vector<claim_result> results;
    std::vector<const claim*> claims;
    for (const claim& c : book_.claims) {
      claims.push_back(&c);
      results.push_back(check_claim(c, ctx));
    }
    std::vector<const claim_result*> pointers;
    for (const claim_result& r : results) pointers.push_back(&r);
    return std::make_pair(results, trace_consequences(claims, pointers, ctx));
  };
  // 'misprint' is an erratum; 'reads-it' fails as printed and holds with the corrected (expanded);
  // 'still-wrong' does not, and follows from nothing.
  const auto [results, traced] = judge(records);
  EXPECT_EQ(results[0].outcome, verdict::erratum);
  EXPECT_EQ(results[1].outcome, verdict::erratum);
  ASSERT_EQ(traced.size(), 3u);
  EXPECT_FALSE(traced[0]);
  ASSERT_TRUE(traced[1]);
  EXPECT_EQ(traced[1]->cause, "misprint");
  EXPECT_EQ(traced[1]->corrected, std::vector<std::string>{"(expanded)"});
  EXPECT_FALSE(traced[2]);
  // A record that types 'still-wrong' as following from 'misprint': the derivation contradicts it.
  EXPECT_THROW(judge(records + "follows_from = \"misprint\"\n"), std::logic_error);
}

TEST_F(ShapesOnADocument, Identity) {
  const claim_result holds = run("identity", R"({ lhs = "sum", rhs = "expanded" })");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note;
  EXPECT_NE(holds.evidence.at("exact").at("own").get<std::string>().find("holds"), std::string::npos) << holds.evidence.dump();
  EXPECT_FALSE(holds.certificate.empty());
  const claim_result wrong = run("identity", R"({ lhs = "sum", rhs = "$a^2 + b^2$" })");
  EXPECT_EQ(wrong.outcome, verdict::erratum);
  EXPECT_EQ(wrong.correction, "as derived from (sum): ($a^2 + b^2$) = 2*a*b+a^2+b^2");
}

TEST_F(ShapesOnADocument, DeterminantAndSymplectic) {
  EXPECT_EQ(run("determinant", R"({ matrix = "map", equals = "one" })").outcome, verdict::holds);
  EXPECT_EQ(run("symplectic", R"({ matrix = "map" })").outcome, verdict::holds);
  // Psi's (2,1) entry lacks its factor: det = 1 + omega^4 h^4 / 4 (its trace is Phi's, so a check
  // of the trace alone would pass it).
  // Properties of the printed matrix: false, they fail (no corrected matrix), the value in the note.
  const claim_result det = run("determinant", R"({ matrix = "mapwrong", equals = "one" })");
  EXPECT_EQ(det.outcome, verdict::fails);
  EXPECT_TRUE(det.correction.empty());
  EXPECT_NE(det.note.find("det (mapwrong) = "), std::string::npos) << det.note;
  EXPECT_EQ(run("symplectic", R"({ matrix = "mapwrong" })").outcome, verdict::fails);
}

// The words of a sentence against what the shape proves: affirmed, it holds; denied, a wording
// erratum corrected by the fact; words that are neither, text-changed. A shape that ignored the
// words would hold on all three.
TEST_F(ShapesOnADocument, TheSentenceThatSaysIt) {
  const claim_result affirmed = run("symplectic", R"({ matrix = "map", says = 'That map is {property} indeed.', property = "symplectic" })");
  EXPECT_EQ(affirmed.outcome, verdict::holds) << affirmed.note;
  ASSERT_EQ(affirmed.quoted.size(), 1u);
  EXPECT_EQ(affirmed.quoted[0]["words"]["property"], "symplectic");
  const claim_result denied = run("symplectic", R"({ matrix = "map", says = 'This map is {property}, some say.', property = "symplectic" })");
  EXPECT_EQ(denied.outcome, verdict::erratum);
  EXPECT_EQ(denied.correction.rfind("It is symplectic: ", 0), 0u) << denied.correction;
  EXPECT_FALSE(denied.certificate.empty()) << "the fact proved is still certified";
  EXPECT_EQ(run("symplectic", R"({ matrix = "map", says = 'Another map is {property} here.', property = "symplectic" })").outcome,
            verdict::text_changed);
}

TEST_F(ShapesOnADocument, Conserved) {
  EXPECT_EQ(run("conserved", R"({ map = "map", function = "energy", state = ['q', 'p'] })").outcome, verdict::holds);
  // The true energy, which is conserved to O(h^2) only: a sampled or small-h check would pass it.
  const claim_result wrong = run("conserved", R"({ map = "map", function = "energywrong", state = ['q', 'p'] })");
  EXPECT_EQ(wrong.outcome, verdict::erratum);
  EXPECT_NE(wrong.evidence.at("exact").at("own").get<std::string>().find("fails"), std::string::npos) << wrong.evidence.dump();
  // Not conserved: the correction is the map's conserved quadratic form with the printed coefficient
  // of p^2 (keep), i.e. the modified energy "energy", not a restatement of the change in one step.
  const claim_result kept = run("conserved", R"({ map = "map", function = "energywrong", state = ['q', 'p'], keep = ['p'] })");
  EXPECT_EQ(kept.outcome, verdict::erratum);
  EXPECT_EQ(kept.correction.rfind("the quadratic form (map) conserves, with the coefficient of p^2 that (energywrong) prints: ", 0), 0u)
      << kept.correction;
  const GiNaC::ex m = paper_symbols()["m"], w = paper_symbols()["omega"], h = paper_symbols()["h"], q = paper_symbols()["q"],
                  p = paper_symbols()["p"];
  EXPECT_EQ(kept.evidence.at("corrected").at("conserved_form").get<std::string>(),
            detail::text_of(GiNaC::normal(p * p / (2 * m) + m * w * w / 2 * (1 - w * w * h * h / 4) * q * q))) << kept.evidence.dump();
  // Left out, keep is the first of the state: q^2's coefficient kept, p^2's modified.
  EXPECT_EQ(wrong.evidence.at("corrected").at("conserved_form").get<std::string>(),
            detail::text_of(GiNaC::normal(p * p / (2 * m * (1 - w * w * h * h / 4)) + m * w * w / 2 * q * q))) << wrong.evidence.dump();
  // A map with det != 1 conserves no quadratic form: no correction, the claim fails.
  EXPECT_EQ(run("conserved", R"({ map = "mapwrong", function = "energy", state = ['q', 'p'] })").outcome, verdict::fails);
}

// H = c K for the symbols of a generic matrix named for the entries of `map` (Section 7's Q_c of
// Phi, as H_d's record reads it): K = -h H, c = -1/h, free of the state.
TEST_F(ShapesOnADocument, Proportional) {
  const std::string entries = R"(entries = ['inline:A generic map', 'map'])";
  const claim_result holds = run("proportional", R"({ printed = "energy", of = 'inline:It conserves', state = ['q', 'p'], )" + entries + " }");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  const GiNaC::ex h = paper_symbols()["h"];
  EXPECT_EQ(holds.evidence.at("exact").at("factor").get<std::string>(), detail::text_of(GiNaC::normal(-1 / h)));
  EXPECT_NE(holds.evidence.at("exact").at("own").get<std::string>().find("holds"), std::string::npos) << holds.evidence.dump();
  EXPECT_FALSE(holds.certificate.empty());
  EXPECT_EQ(holds.printed["formulas"].back()["parsed"].size(), 4u) << holds.printed.dump();
  // z for v in the p^2 coefficient: the q^2 coefficients are in the ratio -1/h, the p^2 ones are
  // not, so a check of one coefficient's ratio (or that the ratio is nonzero) would pass it. The
  // correction keeps the printed p^2 coefficient.
  const claim_result wrong = run("proportional", R"({ printed = "energy", of = 'inline:and not', state = ['q', 'p'], )" + entries + " }");
  EXPECT_EQ(wrong.outcome, verdict::erratum) << wrong.note;
  EXPECT_NE(wrong.evidence.at("exact").at("own").get<std::string>().find("fails: the coefficients of p^2 and q^2"), std::string::npos)
      << wrong.evidence.dump();
  EXPECT_EQ(wrong.correction.rfind("the multiple of (the formula at 'and not') with the coefficient of p^2 that (energy) prints: ", 0), 0u) << wrong.correction;
  const GiNaC::ex m = paper_symbols()["m"], w = paper_symbols()["omega"], q = paper_symbols()["q"], p = paper_symbols()["p"];
  const GiNaC::ex z = 1 - w * w * h * h / 2, c = 1 / (2 * m) / (-z / 2);
  EXPECT_EQ(wrong.evidence.at("corrected").at("multiple").get<std::string>(),
            detail::text_of(GiNaC::normal(c * (-m * w * w * h * (1 - w * w * h * h / 4) * q * q / 2 - z * p * p / 2))))
      << wrong.evidence.dump();
  // Not a polynomial in the state, or nothing in common: no correction, it fails.
  EXPECT_EQ(run("proportional", R"({ printed = "energy", of = '$\frac{1}{p}$', state = ['q', 'p'] })").outcome, verdict::fails);
}

// The rows of a printed system for the coefficients of a conserved form, against
// form(map y) - form(y) (Section 7's Gamma), read from the middle side of "G v = M v = 0". The
// misprint (w^2 - 1)/2 for (s^2 - 1)/2 is Section 7's own: it agrees with the true entry whenever
// w = s, so a check on maps with equal entries there would pass it.
TEST_F(ShapesOnADocument, InvarianceSystem) {
  const std::string rest = R"(form = 'inline:and a form', map = 'inline:A square map', state = ['q', 'p'], unknowns = ['a', 'b', 'c'])";
  const claim_result holds = run("invariance-system", R"({ system = "invsys:side2", )" + rest + " }");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  EXPECT_NE(holds.evidence.at("exact").at("own").get<std::string>().find("holds"), std::string::npos) << holds.evidence.dump();
  EXPECT_FALSE(holds.certificate.empty());
  const claim_result wrong = run("invariance-system", R"({ system = "invsyswrong:side2", )" + rest + " }");
  EXPECT_EQ(wrong.outcome, verdict::erratum) << wrong.note;
  EXPECT_NE(wrong.evidence.at("exact").at("own").get<std::string>().find("fails"), std::string::npos) << wrong.evidence.dump();
  const GiNaC::ex s = paper_symbols()["s"];
  const GiNaC::ex w = paper_symbols()["w"];
  EXPECT_EQ(wrong.correction.rfind("entry (3, 3) is " + detail::text_of(GiNaC::normal((s * s - 1) / 2)) + ", not " +
                                       detail::text_of(GiNaC::normal((w * w - 1) / 2)) + "; as derived from ",
                                   0),
            0u)
      << wrong.correction;
  // In one line: the entry, printed and as it should be.
  EXPECT_EQ(wrong.amendments, (std::vector<amendment>{{"entry (3, 3) of the system's matrix", "\\frac{w^{2}-1}{2}", "\\frac{s^{2}-1}{2}"}}));
  EXPECT_FALSE(wrong.refutation.empty()) << "the printed rows refuted in Coq";
  EXPECT_NE(wrong.certificate.find("under_test_derived"), std::string::npos) << "the derived rows certified: " << wrong.certificate;
  // The last side, 0, is not the system.
  EXPECT_EQ(run("invariance-system", R"({ system = "invsys", )" + rest + " }").outcome, verdict::undecided);
}

// The determinant of the system a form's invariance asks of its coefficients (Section 7's det Gamma),
// from the rows as derived: (us - vw - 1)(1 - u - s + us - vw)(1 + u + s + us - vw)/4. The product
// without its quarter (Section 7's) vanishes exactly where the determinant does, so a check of its
// roots, or of the singular case alone, would pass it.
TEST_F(ShapesOnADocument, InvarianceDeterminant) {
  const std::string rest = R"(form = 'inline:and a form', map = 'inline:A square map', state = ['q', 'p'], unknowns = ['a', 'b', 'c'])";
  const claim_result holds = run("invariance-determinant", R"({ printed = 'inline:Its determinant is', )" + rest + " }");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  EXPECT_NE(holds.evidence.at("exact").at("own").get<std::string>().find("holds"), std::string::npos) << holds.evidence.dump();
  EXPECT_FALSE(holds.certificate.empty());
  const claim_result wrong = run("invariance-determinant", R"({ printed = 'inline:without the quarter', )" + rest + " }");
  EXPECT_EQ(wrong.outcome, verdict::erratum) << wrong.note;
  EXPECT_NE(wrong.evidence.at("exact").at("own").get<std::string>().find("fails"), std::string::npos) << wrong.evidence.dump();
  EXPECT_EQ(wrong.correction, "as derived: det = " + detail::text_of(GiNaC::numeric(1, 4)) +
                                  " × $(u s - v w - 1) (1 - u - s + u s - v w) (1 + u + s + u s - v w)$ (as printed)");
  EXPECT_EQ(wrong.amendments, (std::vector<amendment>{{"the printed determinant", "(u s - v w - 1) (1 - u - s + u s - v w) (1 + u + s + u s - v w)",
                                                       "\\frac{1}{4} \\times \\text{the printed}"}}));
  EXPECT_FALSE(wrong.refutation.empty());
  EXPECT_NE(wrong.certificate.find("under_test_derived"), std::string::npos) << wrong.certificate;
  // A form with two coefficients for three monomials: no square system, no determinant.
  EXPECT_EQ(run("invariance-determinant", R"({ printed = 'inline:Its determinant is', form = 'inline:and a form', map = 'inline:A square map', state = ['q', 'p'], unknowns = ['a', 'b'] })").outcome,
            verdict::undecided);
}

// "det G vanishes when us - vw = 1", for the printed system's determinant. The misprinted system
// (invsyswrong) is not singular there, though the printed product D, which has the factor
// us - vw - 1, vanishes: a check of the printed product would pass it.
TEST_F(ShapesOnADocument, InvarianceSingular) {
  const std::string rest = R"(form = 'inline:and a form', map = 'inline:A square map', state = ['q', 'p'], unknowns = ['a', 'b', 'c'])";
  const std::string unit = R"(conditions = ['inline:Of unit determinant'], solve_for = ['s'], )";
  const claim_result holds = run("invariance-singular", R"({ system = "invsys:side2", )" + unit + rest + " }");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  EXPECT_NE(holds.evidence.at("exact").at("own").get<std::string>().find("holds"), std::string::npos) << holds.evidence.dump();
  const GiNaC::ex u = paper_symbols()["u"], v = paper_symbols()["v"], w = paper_symbols()["w"];
  EXPECT_EQ(holds.evidence.at("exact").at("conditions_solved")[0].get<std::string>(), "s = " + detail::text_of(GiNaC::normal((1 + v * w) / u)));
  EXPECT_FALSE(holds.certificate.empty());
  const claim_result wrong = run("invariance-singular", R"({ system = "invsyswrong:side2", )" + unit + rest + " }");
  EXPECT_EQ(wrong.outcome, verdict::erratum) << wrong.note;
  EXPECT_NE(wrong.evidence.at("exact").at("own").get<std::string>().find("fails"), std::string::npos) << wrong.evidence.dump();
  EXPECT_EQ(wrong.correction.rfind("the system as derived (the rows invariance-system derives) is singular there", 0), 0u) << wrong.correction;
  EXPECT_FALSE(wrong.refutation.empty());
  EXPECT_NE(wrong.certificate.find("under_test_derived"), std::string::npos) << wrong.certificate;
  // A condition not linear in the symbol it is solved for: nothing is put in, the shape cannot judge it (undecided, never a finding).
  const claim_result circle = run("invariance-singular", R"({ system = "invsys:side2", conditions = ['inline:on a circle'], solve_for = ['s'], )" + rest + " }");
  EXPECT_EQ(circle.outcome, verdict::undecided);
  EXPECT_NE(circle.note.find("is not linear in s"), std::string::npos) << circle.note;
}

// "When u = s, we find b = 0 and K = w q^2/2 - v p^2/2 is conserved, up to a constant": K's
// coefficients span the kernel of the printed system on u = s, us - vw = 1. The rank-one system
// (invsysrankone) holds them in its kernel too, but its kernel is two-dimensional: a check of the
// kernel membership alone would pass it.
TEST_F(ShapesOnADocument, InvarianceKernel) {
  const std::string rest = R"(form = 'inline:and a form', map = 'inline:A square map', state = ['q', 'p'], unknowns = ['a', 'b', 'c'])";
  const std::string on = R"(printed = 'inline:It conserves', conditions = ['inline:With equal diagonal', 'inline:Of unit determinant'], solve_for = ['s', 'w'], )";
  const claim_result holds = run("invariance-kernel", R"({ system = "invsys:side2", obtains = ['inline:we find'], )" + on + rest + " }");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  EXPECT_NE(holds.evidence.at("exact").at("own").get<std::string>().find("holds"), std::string::npos) << holds.evidence.dump();
  EXPECT_EQ(holds.evidence.at("exact").at("rank").at("printed").get<std::string>(), "n - 1 (GiNaC)") << holds.evidence.dump();
  EXPECT_EQ(holds.evidence.at("exact").at("rank").at("own_minor").get<std::string>().rfind("nonzero", 0), 0u) << holds.evidence.dump();
  EXPECT_FALSE(holds.certificate.empty());
  const claim_result rank_one = run("invariance-kernel", R"({ system = "invsysrankone:side2", )" + on + rest + " }");
  EXPECT_EQ(rank_one.outcome, verdict::erratum) << rank_one.note << rank_one.evidence.dump();
  EXPECT_NE(rank_one.evidence.at("exact").at("own").get<std::string>().find("holds"), std::string::npos) << "in the kernel: " << rank_one.evidence.dump();
  EXPECT_NE(rank_one.note.find("the kernel has dimension 2"), std::string::npos) << rank_one.note;
  EXPECT_NE(rank_one.correction.find("which follows from that system"), std::string::npos) << rank_one.correction;
  // The misprinted system: only 0 in its kernel there; corrected by the derived kernel, certified.
  const claim_result wrong = run("invariance-kernel", R"({ system = "invsyswrong:side2", )" + on + rest + " }");
  EXPECT_EQ(wrong.outcome, verdict::erratum) << wrong.note;
  const GiNaC::ex u = paper_symbols()["u"], v = paper_symbols()["v"];
  EXPECT_NE(wrong.correction.find("a one-dimensional kernel spanned by a = " + detail::text_of(GiNaC::normal((u * u - 1) / v)) + ", b = 0, c = " +
                                  detail::text_of(-v)),
            std::string::npos)
      << wrong.correction;
  EXPECT_FALSE(wrong.refutation.empty());
  EXPECT_NE(wrong.certificate.find("under_test_derived"), std::string::npos) << wrong.certificate;
  // What the text says it obtains must hold there: c = 0 does not, and nothing corrects it.
  const claim_result obtains = run("invariance-kernel", R"({ system = "invsys:side2", obtains = ['inline:not only'], )" + on + rest + " }");
  EXPECT_EQ(obtains.outcome, verdict::fails) << obtains.note;
  EXPECT_NE(obtains.note.find("c = 0 does not hold"), std::string::npos) << obtains.note;
  // A form not linear in its coefficients: no one value of them, undecided (not a harness fault, not a finding).
  const std::string squared_form = R"(form = '$\frac{1}{2} a^2 q^2 + b q p + \frac{1}{2} c p^2$', map = 'inline:A square map', state = ['q', 'p'], unknowns = ['a', 'b', 'c'])";
  EXPECT_EQ(run("invariance-kernel", R"({ system = "invsys:side2", )" + on + squared_form + " }").outcome, verdict::undecided);
  // Not the form for any coefficients.
  const std::string cube = R"(printed = 'inline:a cube', conditions = ['inline:With equal diagonal', 'inline:Of unit determinant'], solve_for = ['s', 'w'], )";
  EXPECT_EQ(run("invariance-kernel", R"({ system = "invsys:side2", )" + cube + rest + " }").outcome, verdict::undecided);
}

TEST_F(ShapesOnADocument, EulerLagrange) {
  const std::string args = R"(lagrangian = "ld", nodes = ['q_0', 'q_1'], sequence = ['q_{j-1}', 'q_j', 'q_{j+1}'])";
  const claim_result holds = run("euler-lagrange", "{ " + args + R"(, printed = "el:lhs" })");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note;
  EXPECT_EQ(holds.evidence.at("exact").at("factor"), "-h");
  // q_{j+1} for q_j in the force: the same terms, one index off.
  const claim_result wrong = run("euler-lagrange", "{ " + args + R"(, printed = "elwrong:lhs" })");
  EXPECT_EQ(wrong.outcome, verdict::erratum);
  EXPECT_NE(wrong.correction.find("= 0"), std::string::npos);
}

TEST_F(ShapesOnADocument, StabilityInterval) {
  const std::string args = R"(map = "map", variable = '$\omega h$')";
  const claim_result holds = run("stability-interval", "{ " + args + R"(, condition = "inline:Stable for" })");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  // Coq is told det = 1 as written (a d - b c) and trace^2 - 4 < 0 on the printed band, in x = (omega h)^2.
  ASSERT_EQ(holds.certificate_lemmas.size(), 2u) << holds.certificate_missing;
  EXPECT_NE(holds.certificate_lemmas[0].find("_det"), std::string::npos);
  EXPECT_NE(holds.certificate_lemmas[1].find("_stable_band"), std::string::npos);
  EXPECT_NE(holds.certificate.find("0 < (((-1) * x) + 4)"), std::string::npos) << holds.certificate;
  // 2 sqrt(2) is Simpson's bound, not this map's; 1 is inside the band but not its end (a check
  // that the printed interval is stable would pass it). The certificate states the correction's
  // band, (0, 2), never the printed one.
  for (const std::string phrase : {"Also stable for", "And for"}) {
    const claim_result wrong = run("stability-interval", "{ " + args + ", condition = \"inline:" + phrase + "\" }");
    EXPECT_EQ(wrong.outcome, verdict::erratum) << phrase;
    EXPECT_NE(wrong.correction.find("0 < h*omega < 2"), std::string::npos) << wrong.correction;
    ASSERT_EQ(wrong.certificate_lemmas.size(), 2u) << wrong.certificate_missing;
    EXPECT_NE(wrong.certificate_lemmas[1].find("_first_band"), std::string::npos);
    EXPECT_NE(wrong.certificate.find("0 < (((-1) * x) + 4)"), std::string::npos) << wrong.certificate;
  }
  const claim_result not_det_one = run("stability-interval", R"({ map = "mapwrong", variable = '$\omega h$', condition = "inline:Stable for" })");
  EXPECT_EQ(not_det_one.outcome, verdict::undecided);
}

TEST_F(ShapesOnADocument, DiscreteMap) {
  const std::string ends = R"(nodes = ['q_0', 'q_1'], momenta = ['p_0', 'p_1'])";
  const claim_result holds = run("discrete-map", "{ map = \"map\", lagrangian = \"ld\", " + ends + " }");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  // The same map printed in (p, q): it holds with order "p q" only, and the (q, p) map does not.
  const claim_result pq = run("discrete-map", "{ map = \"mappq\", lagrangian = \"ld\", order = \"p q\", " + ends + " }");
  EXPECT_EQ(pq.outcome, verdict::holds) << pq.note << pq.evidence.dump();
  EXPECT_EQ(run("discrete-map", "{ map = \"mappq\", lagrangian = \"ld\", " + ends + " }").outcome, verdict::erratum);
  EXPECT_EQ(run("discrete-map", "{ map = \"map\", lagrangian = \"ld\", order = \"p q\", " + ends + " }").outcome, verdict::erratum);
  const claim_result wrong = run("discrete-map", "{ map = \"mapwrong\", lagrangian = \"ld\", " + ends + " }");
  EXPECT_EQ(wrong.outcome, verdict::erratum);
  EXPECT_NE(wrong.correction.find("[(h^3*m*omega^4-4*h*m*omega^2)/(4), "), std::string::npos) << wrong.correction;
  // An internal node, eliminated by its equation: the free particle's map. Taking q_m for a
  // constant instead would leave it in the map.
  const claim_result internal = run("discrete-map", "{ map = \"free\", lagrangian = \"ldm\", internal = ['q_m'], " + ends + " }");
  EXPECT_EQ(internal.outcome, verdict::holds) << internal.note << internal.evidence.dump();
  EXPECT_EQ(run("discrete-map", "{ map = \"free\", lagrangian = \"ldm\", " + ends + " }").outcome, verdict::undecided);
}

TEST_F(ShapesOnADocument, Truncation) {
  const std::string args = R"(scheme = "sv:lhs", sequence = ['q_{j-1}', 'q_j', 'q_{j+1}'], step = ['h'], frequency = '$\omega$')";
  const claim_result holds = run("truncation", "{ printed = \"trunc\", " + args + " }");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  EXPECT_EQ(holds.evidence.at("exact").at("leading_power"), 2);
  const claim_result wrong = run("truncation", "{ printed = \"truncwrong\", " + args + " }");
  EXPECT_EQ(wrong.outcome, verdict::erratum);
  EXPECT_EQ(wrong.correction, "as derived: (h^2*omega^4*q_j)/(12) + O(h^4)");
  // An order claimed without its leading term: a check of the printed terms alone (none) would pass.
  EXPECT_EQ(run("truncation", "{ printed = \"truncshort\", " + args + " }").outcome, verdict::erratum);
  // Our kernel confirms each: the printed terms, or GiNaC's series and that the printed terms differ.
  EXPECT_EQ(holds.evidence.at("exact").at("own").get<std::string>().rfind("holds: ", 0), 0u) << holds.evidence.dump();
  EXPECT_NE(wrong.evidence.at("exact").at("own").get<std::string>().find("printed terms differ"), std::string::npos) << wrong.evidence.dump();
  EXPECT_EQ(wrong.evidence.at("exact").at("own").get<std::string>().rfind("fails: ", 0), 0u) << wrong.evidence.dump();
  // The identity our kernel decided is the Coq certificate: the scheme on the Taylor polynomials is
  // the printed terms plus h^4 times the remainder.
  EXPECT_FALSE(holds.certificate.empty()) << holds.certificate_missing;
  EXPECT_EQ(holds.certificate_lemmas.size(), 1u);
}

TEST_F(ShapesOnADocument, TruncationOfASchemeWithADeepPole) {
  // A scheme with h^-6 in it: the solution's Taylor polynomials through h^(N+2) (enough for h^-2)
  // cancel every term through h^2 and would pass "0 + O(h^2)"; the term that remains, -omega^6/360
  // q_j, comes from h^6 of cos, which the degree read from the tree's denominators (6) keeps.
  const std::string args = R"(scheme = "steep:lhs", sequence = ['q_{j-1}', 'q_j', 'q_{j+1}'], step = ['h'], frequency = '$\omega$')";
  const claim_result r = run("truncation", "{ printed = \"steepzero\", " + args + " }");
  EXPECT_EQ(r.outcome, verdict::erratum) << r.note << r.evidence.dump();
  EXPECT_EQ(r.correction, "as derived: (-omega^6*q_j)/(360) + O(h^2)");
  EXPECT_EQ(r.evidence.at("exact").at("taylor_degree"), 7);
}

TEST_F(ShapesOnADocument, StatedOrder) {
  const std::string args = R"(scheme = "sv:lhs", sequence = ['q_{j-1}', 'q_j', 'q_{j+1}'], step = ['h'], frequency = '$\omega$')";
  const claim_result holds = run("stated-order", "{ sentence = 'The same scheme is of {order} order', " + args + " }");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  ASSERT_FALSE(holds.quoted.empty());
  EXPECT_EQ(holds.quoted[0]["words"]["order"], "second");
  // "fourth": the words parse, and only the computed order refutes them.
  const claim_result wrong = run("stated-order", "{ sentence = 'This scheme is of {order} order', " + args + " }");
  EXPECT_EQ(wrong.outcome, verdict::erratum);
  EXPECT_EQ(wrong.correction, "the scheme is of order 2");
  EXPECT_EQ(holds.evidence.at("exact").at("own").get<std::string>().rfind("holds: ", 0), 0u) << holds.evidence.dump();
  EXPECT_EQ(run("stated-order", "{ sentence = 'A sentence the document does not have, of {order} order', " + args + " }").outcome,
            verdict::text_changed);
}

TEST_F(ShapesOnADocument, EqualSides) {
  const std::string where = R"(where = ["phis#1", "phis#2", "linear", 'inline:t = h \, \theta'])";
  const claim_result holds = run("equal-sides", "{ equations = ['inline:q(0) = a', 'inline:q(h) = b', 'slope'], " + where + " }");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  // g names what the chain defines: not compared; the three other sides are, against dq/dt(0).
  EXPECT_EQ(holds.evidence.at("exact").at("sides").size(), 4u) << holds.evidence.dump();
  EXPECT_EQ(holds.evidence.at("exact").at("own").get<std::string>().rfind("holds", 0), 0u) << holds.evidence.dump();
  EXPECT_FALSE(holds.certificate.empty());
  // A wrong node; and a wrong middle side whose chain's first and last sides agree (a check of the
  // ends alone would pass it).
  const claim_result node = run("equal-sides", "{ equations = ['inline:q(h) = a'], " + where + " }");
  EXPECT_EQ(node.outcome, verdict::erratum);
  EXPECT_EQ(node.correction, "as derived from the definitions: q(h) = b, not a");
  const claim_result middle = run("equal-sides", "{ equations = ['slopemiddle'], " + where + " }");
  EXPECT_EQ(middle.outcome, verdict::erratum) << middle.evidence.dump();
  EXPECT_NE(middle.correction.find("not \\frac{b - a}{2 h}"), std::string::npos) << middle.correction;
  // The change of variable is needed: without it q's value stays in theta.
  EXPECT_EQ(run("equal-sides", R"({ equations = ['inline:q(h) = b'], where = ["phis#1", "phis#2", "linear"] })").outcome, verdict::erratum);
}

TEST_F(ShapesOnADocument, QuadratureExactness) {
  const auto on = [&](const std::string& rule, const std::string& sentence) {
    return run("quadrature-exactness", "{ rule = \"" + rule + "\", integral = \"" + rule + ":lhs\", function = ['\\psi'], sentence = '" + sentence + "' }");
  };
  const claim_result holds = on("trapezoid", "Trapezoids are exact for polynomials of degree {degree}.");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  EXPECT_EQ(holds.evidence.at("exact").at("exact_up_to_degree"), 1);
  EXPECT_EQ(holds.evidence.at("exact").at("monomials").size(), 3u);  // degrees 0 and 1 exact, 2 not
  EXPECT_EQ(on("trapezoid", "Trapezoids are exact for polynomials of degree at most {degree}.").outcome, verdict::holds);
  const claim_result two = on("trapezoid", "Trapezoids, some say, are exact for polynomials of degree {degree}.");
  EXPECT_EQ(two.outcome, verdict::erratum);
  EXPECT_EQ(two.correction, "The rule is exact for every polynomial of degree <= 1 and not for degree 2 (the printed words say 'two')");
  // The stated degree is the sharp one: exact for degree 0 is true but not what the rule does (a check
  // of the stated degree alone would pass it).
  EXPECT_EQ(on("trapezoid", "Trapezoids, said loosely, are exact for polynomials of degree {degree}.").outcome, verdict::erratum);
  // Over [0, h], the limits symbolic: the midpoint rule is exact through degree 1.
  const claim_result midpoint = on("midpoint", "Trapezoids are exact for polynomials of degree {degree}.");
  EXPECT_EQ(midpoint.outcome, verdict::holds) << midpoint.note << midpoint.evidence.dump();
  EXPECT_EQ(midpoint.evidence.at("exact").at("monomials")[1]["rule"], "(h^2)/(2)");
}

TEST_F(ShapesOnADocument, DiscreteLagrangian) {
  // The action of one step along the affine interpolant, by the trapezoidal rule (on [0, 1], its
  // nodes mapped to 0 and h) and by the midpoint rule (printed on [0, h]): each gives its own L,
  // and V stays uninterpreted (our kernel: every polynomial V of degree <= 4).
  const auto by = [&](const std::string& rule, const std::string& printed) {
    return run("discrete-lagrangian", "{ printed = \"" + printed + "\", integral = 'inline:One step', rule = \"" + rule +
                                          "\", function = ['\\psi'], state = ['q'], where = [\"phis#1\", \"phis#2\", \"linear\", 'inline:t = h \\, \\theta'] }");
  };
  const claim_result trapezoid = by("trapezoid", "ltrap");
  EXPECT_EQ(trapezoid.outcome, verdict::holds) << trapezoid.note << trapezoid.evidence.dump();
  EXPECT_NE(trapezoid.evidence.at("exact").at("own").get<std::string>().find("every polynomial V"), std::string::npos) << trapezoid.evidence.dump();
  EXPECT_FALSE(trapezoid.certificate.empty());
  EXPECT_EQ(by("midpoint", "lmid").outcome, verdict::holds);
  // The rule is read: each L against the other rule is an erratum, corrected by the derived one.
  const claim_result crossed = by("trapezoid", "lmid");
  EXPECT_EQ(crossed.outcome, verdict::erratum);
  EXPECT_NE(crossed.correction.find("as derived: (lmid) = "), std::string::npos) << crossed.correction;
  EXPECT_EQ(by("midpoint", "ltrap").outcome, verdict::erratum);
}

TEST_F(ShapesOnADocument, Consistency) {
  const std::string on = R"(step = ['h'], index = "j")";
  const claim_result holds = run("consistency", R"({ scheme = ["sv"], equation = ["ode"], )" + on + " }");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  EXPECT_EQ(holds.evidence.at("exact").at("own").get<std::string>().rfind("holds", 0), 0u) << holds.evidence.dump();
  const claim_result wrong = run("consistency", R"({ scheme = ["sv"], equation = ["odewrong"], )" + on + " }");
  EXPECT_EQ(wrong.outcome, verdict::erratum);
  EXPECT_EQ(wrong.correction, "as derived: label sv is consistent with omega^2*q+d^2q/dt^2 = 0") << wrong.correction;
  // A first-order system, each relation against its own equation, in order; swapped, neither
  // relation's leading term is a multiple of the equation it is paired with.
  EXPECT_EQ(run("consistency", R"({ scheme = ["euler#1", "euler#2"], equation = ["hamilton#1", "hamilton#2"], )" + on + " }").outcome, verdict::holds);
  EXPECT_EQ(run("consistency", R"({ scheme = ["euler#1", "euler#2"], equation = ["hamilton#2", "hamilton#1"], )" + on + " }").outcome, verdict::erratum);
  // The order a sentence states: the first term beyond the leading one (h^2 for a symmetric stencil,
  // expanded about its centre).
  const claim_result second = run("consistency", R"({ scheme = ["sv"], equation = ["ode"], )" + on +
                                                     R"(, sentence = 'Leapfrog discretizes the equation to {order} order.' })");
  EXPECT_EQ(second.outcome, verdict::holds) << second.evidence.dump();
  EXPECT_EQ(second.evidence.at("exact").at("order"), "2");
  const claim_result fourth = run("consistency", R"({ scheme = ["sv"], equation = ["ode"], )" + on +
                                                     R"(, sentence = 'Leapfrog, loosely, discretizes it to {order} order.' })");
  EXPECT_EQ(fourth.outcome, verdict::erratum);
  EXPECT_EQ(fourth.correction, "as derived: a discretization of order 2");
  // With V uninterpreted: our kernel for V(x) = x^k, k = 0..4.
  const claim_result general = run("consistency", R"({ scheme = ["el"], equation = ['$m {{\dd^2 q}\over{\dd t^2}} + m \omega^2 q = 0$'], )" + on + " }");
  EXPECT_EQ(general.outcome, verdict::holds) << general.evidence.dump();
}

TEST_F(ShapesOnADocument, SumRange) {
  const auto over = [&](const std::string& sum) {
    return run("sum-range", "{ sum = \"" + sum + R"(", element = ['q_j', 'q_{j+1}'], node = 'inline:t_j = j', range = 'inline:For $0', where = ['inline:h = \frac'] })");
  };
  const claim_result holds = over("action");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  EXPECT_EQ(holds.evidence.at("exact").at("own").get<std::string>().rfind("holds", 0), 0u) << holds.evidence.dump();
  const claim_result shorter = over("actionshort");
  EXPECT_EQ(shorter.outcome, verdict::erratum);
  EXPECT_EQ(shorter.correction, "S = \\sum_{j=0}^{N-1} L_d(q_j, q_{j+1}): the elements of [0, T] are j = 0, ..., N-1: N terms");
  // In one line: the printed range and the derived one, nothing else.
  EXPECT_EQ(shorter.amendments, (std::vector<amendment>{{"the sum's range", "\\sum_{j=1}^{N-1}", "\\sum_{j=0}^{N-1}"}}));
  EXPECT_TRUE(holds.amendments.empty());
  // The upper bound too: a check of the first element alone would pass it.
  EXPECT_EQ(over("actionlong").outcome, verdict::erratum);
}

TEST_F(ShapesOnADocument, UnconditionalStability) {
  const auto judge = [&](const std::string& scheme, const std::string& sentence, const std::string& qualifier) {
    return run("unconditional-stability", "{ scheme = \"" + scheme + R"(:lhs", sequence = ['q_{j-1}', 'q_j', 'q_{j+1}'], variable = '$\omega h$', sentence = ')" +
                                              sentence + "'" + (qualifier.empty() ? "" : ", qualifier = '" + qualifier + "'") + " }");
  };
  const claim_result average = judge("average", "The average scheme is {stability}.", "Averaging is an {qualifier} stable method.");
  EXPECT_EQ(average.outcome, verdict::holds) << average.note << average.evidence.dump();
  EXPECT_FALSE(average.certificate.empty());
  EXPECT_EQ(judge("average", "The average scheme is {stability}.", "").outcome, verdict::holds);
  // The words: "conditionally" of a scheme stable for every step.
  EXPECT_EQ(judge("average", "The average scheme is {stability}.", "Averaging, some say, is a {qualifier} stable method.").outcome, verdict::erratum);
  // Leapfrog is stable for omega h < 2 only: a check at one step (or on (0, 2)) would pass it.
  const claim_result leapfrog = judge("sv", "The leapfrog scheme is {stability}.", "Leapfrog is an {qualifier} stable method.");
  EXPECT_EQ(leapfrog.outcome, verdict::erratum);
  EXPECT_NE(leapfrog.correction.find("changes sign at h*omega = 2"), std::string::npos) << leapfrog.correction;
  // "conditionally stable" in the hole itself: leapfrog's band (0, 2) holds it, with its Coq lemma;
  // of a scheme stable for every step it is an erratum.
  const claim_result conditional = judge("sv", "Leapfrog, with a small step, is {stability}.", "");
  EXPECT_EQ(conditional.outcome, verdict::holds) << conditional.note << conditional.evidence.dump();
  EXPECT_FALSE(conditional.certificate.empty());
  EXPECT_NE(conditional.evidence.at("exact").at("computed").get<std::string>().find("stable (negative) exactly for h*omega in (0, 2)"), std::string::npos)
      << conditional.evidence.dump();
  EXPECT_EQ(judge("average", "Averaging, loosely, is {stability}.", "").outcome, verdict::erratum);
  // q'' = +omega^2 q discretised: real roots rho, 1/rho for every step. "Conditionally stable" needs a
  // band where the discriminant is negative: a shape that took "not for every step" for "conditionally"
  // would pass it.
  const claim_result antidamped = judge("antidamped", "Antidamping, with a small step, is {stability}.", "");
  EXPECT_EQ(antidamped.outcome, verdict::erratum);
  EXPECT_NE(antidamped.correction.find("is stable for no h*omega > 0"), std::string::npos) << antidamped.correction;
  EXPECT_EQ(judge("antidamped", "Antidamping is {stability}.", "").outcome, verdict::holds);
}

TEST_F(ShapesOnADocument, TaylorExpansion) {
  const claim_result holds = run("taylor-expansion", R"({ expansions = ["taylorup"], step = ['h'], index = "j" })");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  EXPECT_EQ(holds.evidence.at("exact").at("own").get<std::string>().rfind("holds", 0), 0u) << holds.evidence.dump();
  // The h^2 term's sign: a comparison through h alone would pass it.
  const claim_result wrong = run("taylor-expansion", R"({ expansions = ["taylorup", "taylorwrong"], step = ['h'], index = "j" })");
  EXPECT_EQ(wrong.outcome, verdict::erratum);
  // The correction names the wrong term, printed and as it should be: the one term that is wrong.
  EXPECT_EQ(wrong.correction, "in q_{j-1} = ... + O(h^3): its h^2 term is printed (-d^2q/dt^2*h^2)/(2), should be (d^2q/dt^2*h^2)/(2)");
  // In one line, in TeX: the term whole (a sign is not one symbol for another).
  EXPECT_EQ(wrong.amendments, (std::vector<amendment>{{"the $h^2$ term of $q_{j-1}$", "\\frac{-\\frac{d^{2}q}{dt^{2}} h^{2}}{2}",
                                                       "\\frac{\\frac{d^{2}q}{dt^{2}} h^{2}}{2}"}}));
  EXPECT_TRUE(holds.amendments.empty());
}

// The one line of a misprinted derivative's order (Section 5's d^6q/dt^5 for d^6q/dt^6): the one
// symbol, in the two expansions it is misprinted in; the two amendments are equal, so the report
// says it once, "twice".
TEST_F(ShapesOnADocument, TaylorExpansionMisprintedOrderInOneLine) {
  const claim_result wrong = run("taylor-expansion", R"({ expansions = ["taylorup3", "taylordown3"], step = ['h'], index = "j" })");
  ASSERT_EQ(wrong.outcome, verdict::erratum) << wrong.note << wrong.evidence.dump();
  ASSERT_EQ(wrong.amendments.size(), 2u);
  EXPECT_EQ(wrong.amendments[0].printed, "\\frac{d^{3}q}{dt^{2}}");
  EXPECT_EQ(wrong.amendments[0].should_be, "\\frac{d^{3}q}{dt^{3}}");
  EXPECT_EQ(wrong.amendments[1].printed, wrong.amendments[0].printed);
  EXPECT_EQ(wrong.amendments[1].where, "the $h^3$ term of $q_{j-1}$");
}

TEST_F(ShapesOnADocument, IdentityWithAFunctionDefined) {
  // V(q) = k q^2/2 put in F = -V'(x): -k x. Without the definition V' stays uninterpreted.
  const claim_result holds = run("identity", R"({ lhs = "force", rhs = '$-k x$', where = ["potential energy"] })");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  EXPECT_EQ(run("identity", R"({ lhs = "force", rhs = '$-2 k x$', where = ["potential energy"] })").outcome, verdict::erratum);
  EXPECT_EQ(run("identity", R"({ lhs = "force", rhs = '$-k x$' })").outcome, verdict::erratum);
}

TEST_F(ShapesOnADocument, Derivative) {
  const claim_result holds = run("derivative", R"({ function = "potential energy", variable = ['q'], printed = '$k q$' })");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  const claim_result wrong = run("derivative", R"({ function = "potential energy", variable = ['q'], printed = '$k q^2$' })");
  EXPECT_EQ(wrong.outcome, verdict::erratum);
  EXPECT_EQ(wrong.correction, "as derived: d(potential energy)/dq = k*q");
  // V uninterpreted: the chain rule, in both kernels (ours for every polynomial V of degree <= 4).
  const claim_result chain =
      run("derivative", R"({ function = '$V(q^2 + q)$', variable = ['q'], printed = '$(2 q + 1) {{\partial V}\over{\partial q}}((q + 1) q)$' })");
  EXPECT_EQ(chain.outcome, verdict::holds) << chain.note << chain.evidence.dump();
  EXPECT_NE(chain.evidence.at("exact").at("own").get<std::string>().find("every polynomial V"), std::string::npos) << chain.evidence.dump();
  EXPECT_EQ(run("derivative", R"({ function = '$V(q^2 + q)$', variable = ['q'], printed = '$2 q {{\partial V}\over{\partial q}}((q + 1) q)$' })").outcome,
            verdict::erratum);
  // Taken where it is undefined: d/dx of 1/(x - k) at x = k. It fails, where GiNaC's evaluation threw.
  const claim_result pole = run("derivative", R"({ function = '$\frac{1}{x - k}$', variable = ['x'], printed = '$0$', arguments = ['x'], at = ['k'] })");
  EXPECT_EQ(pole.outcome, verdict::fails) << pole.evidence.dump();
  EXPECT_NE(pole.note.find("is undefined: the denominator"), std::string::npos) << pole.note;
  // Taken at other arguments: dL_d/dq_1 at (q_0, q_1) = (q_j, q_{j+1}) is (pnext). Without them the
  // derivative is in q_0, q_1 and differs; swapped, it is dL_d/dq_1 at (q_{j+1}, q_j), which differs too.
  const std::string at = R"(function = "ld", variable = ['q_1'], printed = "pnext", arguments = ['q_0', 'q_1'])";
  const claim_result taken_at = run("derivative", "{ " + at + R"(, at = ['q_j', 'q_{j+1}'] })");
  EXPECT_EQ(taken_at.outcome, verdict::holds) << taken_at.note << taken_at.evidence.dump();
  EXPECT_NE(taken_at.evidence.at("exact").at("statement").get<std::string>().find("at q_0 = q_j, q_1 = q_j+1"), std::string::npos)
      << taken_at.evidence.dump();
  EXPECT_EQ(run("derivative", R"({ function = "ld", variable = ['q_1'], printed = "pnext" })").outcome, verdict::erratum);
  EXPECT_EQ(run("derivative", "{ " + at + R"(, at = ['q_{j+1}', 'q_j'] })").outcome, verdict::erratum);
}

// A system in the states and momenta of one step, the momenta p_j = -D_1 L_d(q_j, q_{j+1}) and
// p_{j+1} = D_2 L_d(q_j, q_{j+1}) of the trapezoidal (ld). The midpoint rule's system (momsysmid,
// Section 2's) shares its first relation, and p_{j+1} alone: a check of either would pass it.
TEST_F(ShapesOnADocument, DiscreteMomenta) {
  const std::string rest = R"(lagrangian = "ld", nodes = ['q_0', 'q_1'], at = ['q_j', 'q_{j+1}'])";
  const claim_result holds = run("discrete-momenta", R"({ equations = ["momsys#1", "momsys#2"], momenta = ['p_j', 'p_{j+1}'], )" + rest + " }");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  EXPECT_NE(holds.evidence.at("exact").at("own").get<std::string>().find("holds"), std::string::npos) << holds.evidence.dump();
  EXPECT_NE(holds.evidence.at("exact").at("statement").get<std::string>().find("with p_j = -D_1 L(q_j, q_j+1) = "), std::string::npos) << holds.evidence.dump();
  EXPECT_EQ(holds.certificate_lemmas.size(), 2u) << holds.certificate;
  const claim_result midpoint = run("discrete-momenta", R"({ equations = ["momsysmid#1", "momsysmid#2"], momenta = ['p_j', 'p_{j+1}'], )" + rest + " }");
  EXPECT_EQ(midpoint.outcome, verdict::erratum) << midpoint.note;
  EXPECT_NE(midpoint.evidence.at("exact").at("own").get<std::string>().find("fails"), std::string::npos) << midpoint.evidence.dump();
  EXPECT_EQ(midpoint.correction.find("; "), std::string::npos) << "the second relation alone: " << midpoint.correction;
  // The momenta swapped (p_j = D_2 L): the first relation changes sign.
  EXPECT_EQ(run("discrete-momenta", R"({ equations = ["momsys#1"], momenta = ['p_{j+1}', 'p_j'], )" + rest + " }").outcome, verdict::erratum);
}

// "an explicit scheme", as the field defines it: on a linear problem, a one-step map polynomial in
// the step. Newmark's map (the trapezoidal rule) has denominators with no real root, so the check
// that held before (a map regular for every h) called it explicit too: it must not.
TEST_F(ShapesOnADocument, ExplicitMap) {
  const auto with = [](const std::string& map, const std::string& sentence) {
    return "{ map = \"" + map + "\", step = ['h'], positive = ['m', '\\omega'], sentence = '" + sentence + "' }";
  };
  const claim_result leapfrog = run("explicit-map", with("map", "Written as (\\ref{map}), leapfrog is an {kind} scheme."));
  EXPECT_EQ(leapfrog.outcome, verdict::holds) << leapfrog.note << leapfrog.evidence.dump();
  EXPECT_EQ(leapfrog.evidence.at("exact").at("own").get<std::string>().rfind("holds", 0), 0u) << leapfrog.evidence.dump();
  const claim_result newmark = run("explicit-map", with("newmarkmap", "Written as (\\ref{newmarkmap}), the trapezoidal rule is an {kind} scheme."));
  EXPECT_EQ(newmark.outcome, verdict::erratum) << newmark.note;
  EXPECT_EQ(newmark.evidence.at("exact").at("own").get<std::string>().rfind("fails", 0), 0u) << newmark.evidence.dump();
  EXPECT_EQ(newmark.correction.rfind("The scheme is implicit as a method: the entries of (newmarkmap) have the denominator h^2*omega^2+4 (up to factors "
                                     "free of h)", 0),
            0u)
      << newmark.correction;
  EXPECT_EQ(newmark.note.rfind("Wording: the map is in closed form and regular", 0), 0u) << newmark.note;
  // 4 + h^2 omega^2 once: m (4 + h^2 omega^2) is the same denominator up to a factor free of h.
  EXPECT_EQ(newmark.certificate_lemmas.size(), 1u) << newmark.certificate_missing << newmark.certificate;
  const claim_result said_implicit = run("explicit-map", with("newmarkmap", "Said otherwise, the trapezoidal rule is an {kind} scheme."));
  EXPECT_EQ(said_implicit.outcome, verdict::holds) << said_implicit.note;
  // A denominator that vanishes at h = 2/omega: implicit, and not regular either (no wording excuse).
  const claim_result singular = run("explicit-map", with("singularmap", "Written as (\\ref{singularmap}), the backward rule is an {kind} scheme."));
  EXPECT_EQ(singular.outcome, verdict::erratum);
  EXPECT_EQ(singular.note, "");
  EXPECT_EQ(singular.evidence.at("exact").at("regular").get<std::string>().rfind("not shown", 0), 0u) << singular.evidence.dump();
}

// The order of a printed map: its local error against the exact flow, entry by entry. The sheared
// map has the flow's trace and determinant through h^5 (its off-diagonal entries are the flow's
// Taylor polynomials divided and multiplied by 1 + omega^2 h^2), so a check of its eigenvalues, or of
// its trace against 2 cos(omega h), would call it fourth order; its (1,2) entry is wrong at h^3.
TEST_F(ShapesOnADocument, MapOrder) {
  const auto with = [](const std::string& map, const std::string& sentence, const std::string& order = "q p") {
    return "{ map = \"" + map + "\", order = \"" + order + "\", mass = '$m$', frequency = '$\\omega$', step = ['h'], sentence = '" + sentence + "' }";
  };
  const claim_result leapfrog = run("map-order", with("map", "Leapfrog, (\\ref{map}), is {order} order accurate for state and momentum."));
  EXPECT_EQ(leapfrog.outcome, verdict::holds) << leapfrog.note << leapfrog.evidence.dump();
  EXPECT_EQ(leapfrog.evidence.at("exact").at("lowest_power"), 3) << leapfrog.evidence.dump();
  EXPECT_EQ(leapfrog.evidence.at("exact").at("own").get<std::string>().rfind("holds", 0), 0u) << leapfrog.evidence.dump();
  // A lemma for each entry that differs from the flow's Taylor polynomial of degree 3: the diagonal
  // 1 - omega^2 h^2/2 is that polynomial.
  EXPECT_EQ(leapfrog.certificate_lemmas.size(), 2u) << leapfrog.certificate_missing;
  const claim_result twin = run("map-order", with("mappq", "Its twin (\\ref{mappq}) is {order} order accurate too.", "p q"));
  EXPECT_EQ(twin.outcome, verdict::holds) << twin.note << twin.evidence.dump();
  // The same map read in the wrong state order: its (1,2) entry h/m against -m omega sin(omega h).
  const claim_result swapped = run("map-order", with("mappq", "Its twin (\\ref{mappq}) is {order} order accurate too."));
  EXPECT_EQ(swapped.outcome, verdict::erratum) << swapped.evidence.dump();
  const claim_result third = run("map-order", with("map", "Leapfrog, once more, is {order} order accurate."));
  EXPECT_EQ(third.outcome, verdict::erratum);
  EXPECT_EQ(third.correction, "the map is of order 2: its local error is O(h^3)");
  const claim_result sheared = run("map-order", with("shearedmap", "Sheared, (\\ref{shearedmap}) is {order} order accurate."));
  EXPECT_EQ(sheared.outcome, verdict::erratum) << sheared.evidence.dump();
  EXPECT_EQ(sheared.correction, "the map is of order 2: its local error is O(h^3)");
  EXPECT_EQ(sheared.evidence.at("exact").at("own").get<std::string>().rfind("fails", 0), 0u) << sheared.evidence.dump();
  EXPECT_EQ(run("map-order", with("map", "A sentence the document does not have, {order} order accurate.")).outcome, verdict::text_changed);
}

// "not linear", judged of the printed expression: e = q_0 e(1, 0) + q_1 e(0, 1) identically. The
// squared node is homogeneous of degree 1 (Euler's identity holds), so a check of homogeneity, or of
// e(2 q) = 2 e(q), would call it linear: it is not.
TEST_F(ShapesOnADocument, Linear) {
  const auto with = [](const std::string& expression, const std::string& sentence) {
    return "{ expression = \"" + expression + "\", variables = ['q_0', 'q_1'], sentence = '" + sentence + "' }";
  };
  const claim_result said_not = run("linear", with("midnode", "This node is {linearity} in the ends."));
  EXPECT_EQ(said_not.outcome, verdict::erratum) << said_not.note << said_not.evidence.dump();
  EXPECT_EQ(said_not.correction.rfind("(midnode) is linear in q_0, q_1: ", 0), 0u) << said_not.correction;
  EXPECT_NE(said_not.evidence.at("exact").at("own").get<std::string>().find("holds"), std::string::npos) << said_not.evidence.dump();
  EXPECT_FALSE(said_not.certificate.empty()) << "the linear identity, in Coq";
  EXPECT_EQ(run("linear", with("midnode", "That node is {linearity} in the ends.")).outcome, verdict::holds);
  const claim_result squared = run("linear", with("squarenode", "Squared, the node is {linearity} in the ends."));
  EXPECT_EQ(squared.outcome, verdict::erratum) << squared.note;
  EXPECT_EQ(squared.correction.rfind("(squarenode) is not linear in q_0, q_1: ", 0), 0u) << squared.correction;
  EXPECT_NE(squared.evidence.at("exact").at("own").get<std::string>().find("fails"), std::string::npos) << squared.evidence.dump();
  EXPECT_FALSE(squared.refutation.empty()) << "not linear, refuted in Coq";
  EXPECT_EQ(run("linear", with("squarenode", "This node is {linearity} in the ends.")).outcome, verdict::holds);
  // A pole where one variable is 0 (q_1/q_0): not linear, judged, not a harness fault.
  const claim_result ratio = run("linear", "{ expression = '$\\frac{q_1}{q_0}$', variables = ['q_0', 'q_1'], sentence = 'This node is {linearity} in the ends.' }");
  EXPECT_EQ(ratio.outcome, verdict::holds) << ratio.note << ratio.evidence.dump();
  EXPECT_NE(ratio.note.find("it has no value at q_1 = 1, the others 0"), std::string::npos) << ratio.note;
}

TEST_F(ShapesOnADocument, AFunctionTheFileDeclares) {
  // f is declared a function: f(q^2) is applied, its derivative the chain rule's.
  const claim_result chain = run("derivative", R"({ function = '$f(q^2)$', variable = ['q'], printed = '$2 q {{\partial f}\over{\partial q}}(q^2)$' })");
  EXPECT_EQ(chain.outcome, verdict::holds) << chain.note << chain.evidence.dump();
  EXPECT_EQ(run("derivative", R"({ function = '$f(q^2)$', variable = ['q'], printed = '$q {{\partial f}\over{\partial q}}(q^2)$' })").outcome,
            verdict::erratum);
}

TEST_F(ShapesOnADocument, Stationary) {
  // dL/dq_m = (2m/h)(2 q_m - q_0 - q_1): the printed equation up to the factor -2m/h, free of the states.
  const std::string args = R"(function = "ldm", variable = ['q_m'], unknowns = ['q_0', 'q_m', 'q_1'])";
  const claim_result holds = run("stationary", "{ printed = \"internal:lhs\", " + args + " }");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  EXPECT_EQ(holds.evidence.at("exact").at("factor"), "(-2*m)/(h)");
  const claim_result wrong = run("stationary", "{ printed = \"internalwrong:lhs\", " + args + " }");
  EXPECT_EQ(wrong.outcome, verdict::erratum);
  // Corrected by the derived equation: a ratio that holds a state is no factor.
  EXPECT_EQ(wrong.correction, "as derived: (-2*m*q_0-2*m*q_1+4*m*q_m)/(h) = 0") << wrong.correction;
}

TEST_F(ShapesOnADocument, Solves) {
  EXPECT_EQ(run("solves", R"({ equation = "balance:lhs", unknown = ['q'], solution = '$\frac{2}{k}$' })").outcome, verdict::holds);
  const claim_result wrong = run("solves", R"({ equation = "balance:lhs", unknown = ['q'], solution = '$\frac{1}{k}$' })");
  EXPECT_EQ(wrong.outcome, verdict::erratum);
  EXPECT_EQ(wrong.correction, "as derived from (balance, left side): q = (2)/(k)");
  // Not linear in the unknown: no solution to correct it with, so a wrong one fails.
  EXPECT_EQ(run("solves", R"({ equation = "square:lhs", unknown = ['q'], solution = '$2$' })").outcome, verdict::holds);
  EXPECT_EQ(run("solves", R"({ equation = "square:lhs", unknown = ['q'], solution = '$3$' })").outcome, verdict::fails);
  // Undefined at the solution, as written: it fails, where GiNaC's evaluation threw (a harness fault,
  // exit 3). (x^2 - 1)/(x - 1) - 2 is x - 1 in normal form, 0 at x = 1: a check of the normal form
  // would pass it.
  const claim_result removable = run("solves", R"({ equation = "removable:lhs", unknown = ['x'], solution = '$1$' })");
  EXPECT_EQ(removable.outcome, verdict::fails) << removable.evidence.dump();
  EXPECT_EQ(removable.note, "As printed: (removable, left side) at x = ($1$) is undefined: the denominator x-1 is 0 there.");
  EXPECT_EQ(run("solves", R"({ equation = "removable:lhs", unknown = ['x'], solution = '$2$' })").outcome, verdict::fails);  // 1, not 0
  EXPECT_EQ(run("solves", R"({ equation = "pole:lhs", unknown = ['x'], solution = '$1$' })").outcome, verdict::fails);
}

TEST_F(ShapesOnADocument, SignOnInterval) {
  const std::string args = R"(expression = "inline:Coefficient", variable = '$\omega h$')";
  const claim_result holds = run("sign-on-interval", "{ " + args + R"(, condition = "inline:positive on", sign = "positive" })");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  // Positive at the interval's midpoint and at its start, but not beyond omega h = 2: a check at a
  // point inside would pass it.
  const claim_result wide = run("sign-on-interval", "{ " + args + R"(, condition = "inline:the wide", sign = "positive" })");
  EXPECT_EQ(wide.outcome, verdict::erratum);
  EXPECT_EQ(wide.correction, "(-h^2*omega^2+4)/(4) is positive for 0 < h*omega < 2 only, and changes sign there");
  // Coq: the sign on the printed interval when it holds, on the correction's (0, 2) when not.
  ASSERT_EQ(holds.certificate_lemmas.size(), 1u) << holds.certificate_missing;
  EXPECT_NE(holds.certificate_lemmas[0].find("_sign"), std::string::npos);
  ASSERT_EQ(wide.certificate_lemmas.size(), 1u) << wide.certificate_missing;
  EXPECT_NE(wide.certificate_lemmas[0].find("_sign_before_root"), std::string::npos);
  EXPECT_NE(wide.certificate.find("0 < (((-1) * x) + 4)"), std::string::npos) << wide.certificate;
  EXPECT_EQ(run("sign-on-interval", "{ " + args + R"(, condition = "inline:positive on", sign = "negative" })").outcome, verdict::erratum);
  // The sign read from the sentence that states it, not typed: the document's word decides. Printed
  // "negative", the same record is an erratum; printed "nonnegative" (no word the hole reads), it
  // is text-changed, never a guess.
  const std::string said = "{ " + args + R"(, condition = "inline:positive on", sentence = 'Coefficient $1 - \frac{\om^2 h^2}{4}$ {sign} on' })";
  EXPECT_EQ(run("sign-on-interval", said).outcome, verdict::holds);
  std::string negative = shape_document;
  negative.replace(negative.find("$ positive on"), 13, "$ negative on");
  EXPECT_EQ(run("sign-on-interval", "{ " + args + R"(, condition = "inline:negative on", sentence = 'Coefficient $1 - \frac{\om^2 h^2}{4}$ {sign} on' })", negative).outcome,
            verdict::erratum);
  std::string unread = shape_document;
  unread.replace(unread.find("$ positive on"), 13, "$ nonnegative on");
  EXPECT_EQ(run("sign-on-interval", "{ " + args + R"(, condition = "inline:nonnegative on", sentence = 'Coefficient $1 - \frac{\om^2 h^2}{4}$ {sign} on' })", unread).outcome,
            verdict::text_changed);
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

// The characteristic polynomial of (sv), r^2 - (2 - omega^2 h^2) r + 1 times 1/h^2: the printed one
// with c unprinted holds, and c = 1 is solved for. A misprinted middle coefficient is an erratum (a
// check of the leading coefficient alone, or one that solved every coefficient, would pass it), and
// so is a printed c that is not 1.
TEST_F(ShapesOnADocument, Characteristic) {
  const std::string scheme = R"(scheme = "sv:lhs", sequence = ['q_{j-1}', 'q_j', 'q_{j+1}'], root = ['r'])";
  const claim_result holds = run("characteristic", "{ " + scheme + R"(, printed = "inline:Its roots solve:lhs", unprinted = ['c'] })");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  EXPECT_EQ(holds.note, "Not printed, solved from the scheme: c = 1, the printed r^2 coefficient.");
  EXPECT_NE(holds.evidence.at("exact").at("own").get<std::string>().find("holds"), std::string::npos) << holds.evidence.dump();
  EXPECT_FALSE(holds.certificate.empty());
  const claim_result misprinted = run("characteristic", "{ " + scheme + R"(, printed = "inline:Misprinted:lhs", unprinted = ['c'] })");
  EXPECT_EQ(misprinted.outcome, verdict::erratum);
  EXPECT_EQ(misprinted.correction, "as derived from (sv, left side), scaled to the printed r^2 coefficient: (1) r^2 + (h^2*omega^2-2) r + (1)");
  EXPECT_EQ(run("characteristic", "{ " + scheme + R"(, printed = "inline:With the constant:lhs" })").outcome, verdict::erratum);
  // c named unprinted but printed as a number: not one whole coefficient of the polynomial.
  const claim_result no_hole = run("characteristic", "{ " + scheme + R"(, printed = "inline:With the constant:lhs", unprinted = ['c'] })");
  EXPECT_EQ(no_hole.outcome, verdict::undecided);
  EXPECT_NE(no_hole.note.find("The unprinted c is not one whole coefficient"), std::string::npos) << no_hole.note;
  // Not a three-term scheme in the sequence given.
  EXPECT_EQ(run("characteristic", R"({ scheme = "sv:lhs", sequence = ['q_0', 'q_j', 'q_1'], root = ['r'], printed = "inline:Its roots solve:lhs", unprinted = ['c'] })").outcome,
            verdict::undecided);
}

// The signs of a printed product's factors on a printed interval, against a sentence. Q's two factors
// are negative on (0, 2) and Q > 0: holds. P's prefactor omega^2 h^2/36 is positive: "all the
// factors are negative" is then a wording erratum, the product's sign being right. On (0, 3) a factor
// changes sign at omega h = 2: a check at a point inside (omega h = 1.5) would pass it.
// Delta = b^2 - 4ac of the printed a r^2 + b r + c, a and b as printed, c solved from the scheme
// 2 q_{j+1} - 3 q_j + q_{j-1} = 0: c = 1, Delta = 1. The scheme is not reversible, so a shape that
// took c = a (the roots' product 1, true of the paper's scheme) would find -7, the wrong value the
// document also prints.
TEST_F(ShapesOnADocument, Discriminant) {
  const std::string common = R"(polynomial = "inline:Written:lhs", scheme = "damped:lhs", sequence = ['q_{j-1}', 'q_j', 'q_{j+1}'], root = ['r'], unprinted = ['c'], where = ['inline:with $a =', 'inline:and $b ='])";
  const claim_result holds = run("discriminant", R"({ printed = 'inline:is $\Delta = 1', definition = "inline:its discriminant", )" + common + " }");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  EXPECT_NE(holds.note.find("solved from the scheme: c = 1"), std::string::npos) << holds.note;
  EXPECT_TRUE(holds.certificate.empty()) << "both sides are the number 1: no Coq lemma 1 = 1";
  const claim_result wrong = run("discriminant", R"({ printed = 'inline:not $\Delta', definition = "inline:its discriminant", )" + common + " }");
  EXPECT_EQ(wrong.outcome, verdict::erratum) << wrong.note;
  EXPECT_NE(wrong.evidence.at("exact").at("own").get<std::string>().find("fails"), std::string::npos) << wrong.evidence.dump();
  EXPECT_EQ(wrong.correction, "as derived: (the formula at 'its discriminant') = 1");
  // The printed definition is read: b^2 - 2ac is not the polynomial's discriminant, whatever value follows.
  const claim_result misdefined = run("discriminant", R"({ printed = 'inline:is $\Delta = 1', definition = "inline:misdefined", )" + common + " }");
  EXPECT_EQ(misdefined.outcome, verdict::erratum) << misdefined.note;
  EXPECT_EQ(misdefined.correction.rfind("the discriminant of (the formula at 'Written', left side) is ", 0), 0u) << misdefined.correction;
  // Without a printed definition: b^2 - 4ac of the printed polynomial.
  EXPECT_EQ(run("discriminant", R"({ printed = 'inline:is $\Delta = 1', )" + common + " }").outcome, verdict::holds);
}

TEST_F(ShapesOnADocument, FactorSigns) {
  const auto with = [](const std::string& expression, const std::string& condition, const std::string& sentence) {
    return "{ expression = \"" + expression + "\", condition = \"inline:" + condition + "\", variable = '$\\omega h$', sentence = '" + sentence + "' }";
  };
  const claim_result holds = run("factor-signs", with("disc2", "Then, on", "Then, on $0 < \\om h < 2$ all the factors of $Q$ are {sign} and $Q {relation}$."));
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  ASSERT_EQ(holds.certificate_lemmas.size(), 2u) << holds.certificate_missing;
  const claim_result wording = run("factor-signs", with("disc", "First, on", "First, on $0 < \\om h < 2$ all the factors of $P$ are {sign} and $P {relation}$."));
  EXPECT_EQ(wording.outcome, verdict::erratum);
  EXPECT_EQ(wording.note.rfind("Wording:", 0), 0u) << wording.note;
  EXPECT_EQ(wording.correction, "As proved: on 0 < h*omega < 2: (h^2*omega^2)/(36) positive, h^2*omega^2-4 negative, h^2*omega^2-9 negative; the product is positive");
  ASSERT_EQ(wording.certificate_lemmas.size(), 3u) << wording.certificate_missing;
  const claim_result positive = run("factor-signs", with("disc", "Last, on", "Last, on $0 < \\om h < 2$ all the factors of $P$ are {sign} and $P {relation}$."));
  EXPECT_EQ(positive.outcome, verdict::erratum);
  EXPECT_EQ(positive.note.find("Wording:"), std::string::npos) << positive.note;
  const claim_result wide = run("factor-signs", with("disc2", "Wide, on", "Wide, on $0 < \\om h < 3$ all the factors of $Q$ are {sign} and $Q {relation}$."));
  EXPECT_EQ(wide.outcome, verdict::erratum);
  EXPECT_NE(wide.correction.find("h^2*omega^2-4 of no one sign"), std::string::npos) << wide.correction;
}

// The roots of (sv)'s characteristic polynomial r^2 - (2 - omega^2 h^2) r + 1: its discriminant
// omega^2 h^2 (omega^2 h^2 - 4) is negative on (0, 2), so two complex conjugate roots of product 1,
// stable. On (0, 3) it changes sign at omega h = 2: a check at a point inside would pass the words.
// Real roots, or a product of 2, are the words' errata.
TEST_F(ShapesOnADocument, CharacteristicRoots) {
  const auto with = [](const std::string& phrase) {
    return "{ scheme = \"sv:lhs\", sequence = ['q_{j-1}', 'q_j', 'q_{j+1}'], variable = '$\\omega h$', condition = \"inline:" + phrase +
           "\", sentence = '" + phrase + " on $0 < \\om h < {end}$ the equation has two {roots} roots, of product {product}, and the scheme is {conclusion}.' }";
  };
  const claim_result holds = run("characteristic-roots", with("Narrow:"));
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  EXPECT_EQ(holds.note, "Proved in both kernels on the whole interval (no sample): on 0 < h*omega < 2 the discriminant is negative: the roots are "
                        "complex conjugate, their product 1, and the scheme is stable.");
  // Coq: the discriminant's sign on the band; the product P0 = 1 * P2 is one expression once GiNaC
  // has evaluated it here (P0 and P2 are both 1/h^2), so it is named as not stated.
  ASSERT_EQ(holds.certificate_lemmas.size(), 1u) << holds.certificate_missing << holds.certificate;
  EXPECT_NE(holds.certificate_lemmas[0].find("_discriminant"), std::string::npos);
  const claim_result wide = run("characteristic-roots", with("Wide:"));
  EXPECT_EQ(wide.outcome, verdict::erratum);
  EXPECT_NE(wide.correction.find("of both signs"), std::string::npos) << wide.correction;
  EXPECT_EQ(run("characteristic-roots", with("Real:")).outcome, verdict::erratum);
  EXPECT_EQ(run("characteristic-roots", with("Double:")).outcome, verdict::erratum);
}

// A criterion stated on the roots' modulus, against the root condition on every region of omega h > 0
// for (sv): a simple conjugate pair of modulus 1 on (0, 2), a double root -1 at 2, real roots beyond.
// "at most 1" alone calls the double root stable (linear growth): a check of the open regions alone
// would pass it.
TEST_F(ShapesOnADocument, RootCriterion) {
  const auto with = [](const std::string& which) {
    return "{ scheme = \"sv:lhs\", sequence = ['q_{j-1}', 'q_j', 'q_{j+1}'], variable = '$\\omega h$', sentence = 'Criterion " + which +
           ": the scheme is stable when the roots are of modulus {modulus}.' }";
  };
  const claim_result holds = run("root-criterion", with("two"));
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  ASSERT_EQ(holds.certificate_lemmas.size(), 1u) << holds.certificate_missing << holds.certificate;  // the band; reversible is X = X here
  EXPECT_NE(holds.certificate_lemmas[0].find("_stable_band_1"), std::string::npos);
  const claim_result smaller = run("root-criterion", with("one"));
  EXPECT_EQ(smaller.outcome, verdict::erratum);
  EXPECT_NE(smaller.correction.find("for h*omega in (0, 2)"), std::string::npos) << smaller.correction;
  EXPECT_EQ(run("root-criterion", with("three")).outcome, verdict::erratum);
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

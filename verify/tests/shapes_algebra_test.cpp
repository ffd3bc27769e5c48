// The proof shapes of identities, a form's invariance, stability intervals, discrete maps and
// series (proof_shapes.hpp), each run on the shapes' test document (shape_fixture.hpp) where it holds
// and where a weaker check would pass a wrong statement; consequences traced through them.

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

#include <fstream>
#include <sstream>

namespace simpson::verify {
namespace {

using namespace test;  // the shapes' document, its declarations and the fixture (shape_fixture.hpp)

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
    return std::make_pair(results, trace_consequences(claims, pointers, ctx, check_claim));
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
                                  " × $(u s - v w - 1) (1 - u - s + u s - v w) (1 + u + s + u s - v w)$ (as printed): a constant factor, the same zeros");
  EXPECT_EQ(wrong.amendments, (std::vector<amendment>{{"the printed determinant, off by a constant factor (its zeros the same)",
                                                       "(u s - v w - 1) (1 - u - s + u s - v w) (1 + u + s + u s - v w)",
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
  // The misprinted system: the conclusion (the system as derived is singular there) holds, and only
  // its derivation from the printed system fails: it holds, with a derivation-gap remark (before: an
  // erratum on a true conclusion).
  const claim_result wrong = run("invariance-singular", R"({ system = "invsyswrong:side2", )" + unit + rest + " }");
  EXPECT_EQ(wrong.outcome, verdict::holds) << wrong.note;
  EXPECT_EQ(wrong.remark_kind, finding::derivation_gap);
  // The remark names the gap: the printed entries that differ from the derived ones, no more.
  EXPECT_NE(wrong.remark.find("The printed derivation fails only through the printed system's entry ("), std::string::npos) << wrong.remark;
  EXPECT_NE(wrong.remark.find("alone, its 8 other entries as derived; the conclusion holds of the system as derived"), std::string::npos) << wrong.remark;
  EXPECT_NE(wrong.evidence.at("exact").at("printed_system").at("own").get<std::string>().find("fails"), std::string::npos) << wrong.evidence.dump();
  EXPECT_NE(wrong.evidence.at("exact").at("own").get<std::string>().find("holds"), std::string::npos) << wrong.evidence.dump();
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
  // The rank-one system holds K's coefficients in a two-dimensional kernel: the conclusion (K
  // conserved, up to a constant) holds of the system as derived, its derivation from the printed one
  // fails: it holds, with that remark.
  const claim_result rank_one = run("invariance-kernel", R"({ system = "invsysrankone:side2", )" + on + rest + " }");
  EXPECT_EQ(rank_one.outcome, verdict::holds) << rank_one.note << rank_one.evidence.dump();
  EXPECT_EQ(rank_one.remark_kind, finding::derivation_gap);
  EXPECT_NE(rank_one.remark.find("the kernel has dimension 2"), std::string::npos) << rank_one.remark;
  EXPECT_NE(rank_one.remark.find("which follows from that system"), std::string::npos) << rank_one.remark;
  // The misprinted system: only 0 in its kernel there; the conclusion holds of the derived kernel
  // (certified), the derivation from the printed system fails.
  const claim_result wrong = run("invariance-kernel", R"({ system = "invsyswrong:side2", )" + on + rest + " }");
  EXPECT_EQ(wrong.outcome, verdict::holds) << wrong.note;
  const GiNaC::ex u = paper_symbols()["u"], v = paper_symbols()["v"];
  EXPECT_NE(wrong.remark.find("a one-dimensional kernel spanned by a = " + detail::text_of(GiNaC::normal((u * u - 1) / v)) + ", b = 0, c = " +
                              detail::text_of(-v)),
            std::string::npos)
      << wrong.remark;
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
  // A map whose determinant is not 1 is not symplectic, and the report says so: its premise fails
  // (before: "undecided within the enclosure budget").
  const claim_result not_det_one = run("stability-interval", R"({ map = "mapwrong", variable = '$\omega h$', condition = "inline:Stable for" })");
  EXPECT_EQ(not_det_one.outcome, verdict::fails);
  EXPECT_NE(not_det_one.note.find("is not symplectic: its determinant is"), std::string::npos) << not_det_one.note;
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

}  // namespace
}  // namespace simpson::verify

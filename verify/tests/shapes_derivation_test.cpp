// The proof shapes of derivations, quadrature, sums, stability words, explicitness, orders,
// linearity, signs and characteristic polynomials (proof_shapes.hpp), each run on the shapes' test
// document (shape_fixture.hpp) where it holds and where a weaker check would pass a wrong statement.

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
  // The change of variable is needed: without it q's value is in theta, not t, and would read as
  // constant in t (a false erratum): refused, naming the definition.
  try {
    run("equal-sides", R"({ equations = ['inline:q(h) = b'], where = ["phis#1", "phis#2", "linear"] })");
    ADD_FAILURE() << "q(t) defined in theta alone was read";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("field 'with.where': label linear (line 53): q(t) is defined without t"), std::string::npos) << e.what();
  }
}

TEST_F(ShapesOnADocument, QuadratureExactness) {
  const auto on = [&](const std::string& rule, const std::string& sentence) {
    return run("quadrature-exactness", "{ rule = \"" + rule + "\", integral = \"" + rule + ":lhs\", function = ['\\psi'], sentence = '" + sentence + "' }");
  };
  const claim_result holds = on("trapezoid", "Trapezoids are exact for polynomials of degree {degree}.");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  EXPECT_EQ(holds.evidence.at("exact").at("exact_up_to_degree"), 1);
  EXPECT_EQ(holds.evidence.at("exact").at("monomials").size(), 3u);  // degrees 0 and 1 exact, 2 not
  EXPECT_EQ(on("trapezoid", "Trapezoids are, at best, exact for polynomials of degree at most {degree}.").outcome, verdict::holds);
  // A pattern that matches two sentences of the document (before the sentence above read "at best"
  // this one matched it too) is refused, never read as its first.
  const claim_result two_sentences = on("trapezoid", "exact for polynomials of degree {degree}.");
  EXPECT_EQ(two_sentences.outcome, verdict::text_changed);
  EXPECT_NE(two_sentences.note.find("matches 4 spans"), std::string::npos) << two_sentences.note;
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

// "an explicit scheme", as the field reads it of a scheme on a linear problem whose map the text
// gives (docs/findings.md, the policy): the next state in closed form for every step. Leapfrog's map
// is a polynomial in h: explicit outright. The trapezoidal rule's map, written out, is in closed form
// and regular for every h > 0: it holds, with the wording remark that a denominator in h makes it
// implicit as a method (before: an erratum). A denominator that vanishes at h = 2/omega: explicit
// only where it does not, an erratum.
TEST_F(ShapesOnADocument, ExplicitMap) {
  const auto with = [](const std::string& map, const std::string& sentence) {
    return "{ map = \"" + map + "\", step = ['h'], positive = ['m', '\\omega'], sentence = '" + sentence + "' }";
  };
  const claim_result leapfrog = run("explicit-map", with("map", "Written as (\\ref{map}), leapfrog is an {kind} scheme."));
  EXPECT_EQ(leapfrog.outcome, verdict::holds) << leapfrog.note << leapfrog.evidence.dump();
  EXPECT_TRUE(leapfrog.remark.empty()) << leapfrog.remark;
  EXPECT_EQ(leapfrog.evidence.at("exact").at("own").get<std::string>().rfind("holds", 0), 0u) << leapfrog.evidence.dump();
  const claim_result newmark = run("explicit-map", with("newmarkmap", "Written as (\\ref{newmarkmap}), the trapezoidal rule is an {kind} scheme."));
  EXPECT_EQ(newmark.outcome, verdict::holds) << newmark.note;
  EXPECT_EQ(newmark.remark_kind, finding::wording);
  EXPECT_NE(newmark.remark.find("In the usual sense the scheme is implicit: the entries are rational in h, with the denominator h^2*omega^2+4 (up to factors free of h)"), std::string::npos)
      << newmark.remark;
  EXPECT_EQ(newmark.evidence.at("exact").at("own").get<std::string>().rfind("holds at m = 1, omega = 1: ", 0), 0u) << newmark.evidence.dump();
  // 4 + h^2 omega^2 once: m (4 + h^2 omega^2) is the same denominator up to a factor free of h.
  EXPECT_EQ(newmark.certificate_lemmas.size(), 1u) << newmark.certificate_missing << newmark.certificate;
  const claim_result said_implicit = run("explicit-map", with("newmarkmap", "Said otherwise, the trapezoidal rule is an {kind} scheme."));
  EXPECT_EQ(said_implicit.outcome, verdict::holds) << said_implicit.note;
  EXPECT_TRUE(said_implicit.remark.empty());
  // Leapfrog said implicit: false, its map a polynomial in h.
  EXPECT_EQ(run("explicit-map", with("map", "Said otherwise, leapfrog is an {kind} scheme.")).outcome, verdict::erratum);
  // A denominator that vanishes at h = 2/omega: not in closed form there (our kernel's Sturm root).
  const claim_result singular = run("explicit-map", with("singularmap", "Written as (\\ref{singularmap}), the backward rule is an {kind} scheme."));
  EXPECT_EQ(singular.outcome, verdict::erratum);
  EXPECT_NE(singular.correction.find("is not in closed form for every h > 0"), std::string::npos) << singular.correction;
  EXPECT_EQ(singular.evidence.at("exact").at("own").get<std::string>().rfind("fails", 0), 0u) << singular.evidence.dump();
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

// "linear" as the field reads it (docs/findings.md): of an equation or a curve, affine, e = e(0) +
// sum q_i (e(unit q_i) - e(0)); of a map or a form (sense = "homogeneous"), additive and homogeneous.
// The squared node is homogeneous of degree 1 (Euler's identity holds), so a check of homogeneity, or
// of e(2 q) = 2 e(q), would call it linear: it is not, in either sense.
TEST_F(ShapesOnADocument, Linear) {
  const auto with = [](const std::string& expression, const std::string& sentence, const std::string& more = "") {
    return "{ expression = \"" + expression + "\", variables = ['q_0', 'q_1'], sentence = '" + sentence + "'" + more + " }";
  };
  const claim_result said_not = run("linear", with("midnode", "This node is {linearity} in the ends."));
  EXPECT_EQ(said_not.outcome, verdict::erratum) << said_not.note << said_not.evidence.dump();
  EXPECT_EQ(said_not.correction.rfind("(midnode) is affine in q_0, q_1: ", 0), 0u) << said_not.correction;
  EXPECT_NE(said_not.evidence.at("exact").at("own").get<std::string>().find("fails (it is affine)"), std::string::npos) << said_not.evidence.dump();
  EXPECT_FALSE(said_not.certificate.empty()) << "the linear identity, in Coq";
  EXPECT_EQ(run("linear", with("midnode", "That node is {linearity} in the ends.")).outcome, verdict::holds);
  const claim_result squared = run("linear", with("squarenode", "Squared, the node is {linearity} in the ends."));
  EXPECT_EQ(squared.outcome, verdict::erratum) << squared.note;
  // The words are false under every reading: no meaning of "linear" holds of a square over a sum.
  EXPECT_EQ(squared.note, "As printed, the sentence says 'linear'.");
  EXPECT_EQ(squared.correction.rfind("(squarenode) is not affine in q_0, q_1: ", 0), 0u) << squared.correction;
  EXPECT_NE(squared.evidence.at("exact").at("own").get<std::string>().find("fails"), std::string::npos) << squared.evidence.dump();
  EXPECT_FALSE(squared.refutation.empty()) << "not linear, refuted in Coq";
  EXPECT_EQ(run("linear", with("squarenode", "Squared, the node is {linearity} in the ends.", ", sense = \"homogeneous\"")).outcome, verdict::erratum);
  EXPECT_EQ(run("linear", with("squarenode", "This node is {linearity} in the ends.")).outcome, verdict::holds);
  // An equation in q_1 with a constant term is linear in q_1 as the field says it (affine; before: an
  // erratum, read strictly); of a map, with sense = "homogeneous", it is not.
  const std::string shifted = "{ expression = '$q_1 - 2 q_0 + 1$', variables = ['q_1'], sentence = 'Squared, the node is {linearity} in the ends.'";
  EXPECT_EQ(run("linear", shifted + " }").outcome, verdict::holds);
  EXPECT_EQ(run("linear", shifted + ", sense = \"homogeneous\" }").outcome, verdict::erratum);
  // A pole at the origin (q_1/q_0): judged from the point of ones, not affine; not a harness fault.
  const claim_result ratio = run("linear", "{ expression = '$\\frac{q_1}{q_0}$', variables = ['q_0', 'q_1'], sentence = 'This node is {linearity} in the ends.' }");
  EXPECT_EQ(ratio.outcome, verdict::holds) << ratio.note << ratio.evidence.dump();
  EXPECT_NE(ratio.note.find("is not affine in q_0, q_1: it differs from"), std::string::npos) << ratio.note;
  // Homogeneous: its value at q_0 = 1, q_1 = 0 is 0, at q_1 = 1 a pole: not linear there either.
  const claim_result ratio_map = run("linear", "{ expression = '$\\frac{q_1}{q_0}$', variables = ['q_0', 'q_1'], sentence = 'This node is {linearity} in the ends.', sense = \"homogeneous\" }");
  EXPECT_EQ(ratio_map.outcome, verdict::holds) << ratio_map.note;
  EXPECT_NE(ratio_map.note.find("it has no value at q_1 = 1, the others 0"), std::string::npos) << ratio_map.note;
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
  // Corrected by the derived equation (a ratio that holds a state is no factor), scaled to agree
  // with as many printed coefficients as it can: the wrong one named, with the right one.
  EXPECT_EQ(wrong.correction,
            "as derived, with the printed coefficients where they are right: -2*q_m+q_0+q_1 = 0 (the coefficient of q_m: printed -1, derived -2)")
      << wrong.correction;
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
  // Only the prefactor is positive, and the product's stated sign holds: "all the factors" can only
  // be the sums; as an expert reads it, it holds, with a wording remark.
  const claim_result wording = run("factor-signs", with("disc", "First, on", "First, on $0 < \\om h < 2$ all the factors of $P$ are {sign} and $P {relation}$."));
  EXPECT_EQ(wording.outcome, verdict::holds);
  EXPECT_EQ(wording.remark_kind, finding::wording);
  EXPECT_NE(wording.remark.find("As proved: on 0 < h*omega < 2: (h^2*omega^2)/(36) positive, h^2*omega^2-4 negative, h^2*omega^2-9 negative; the product is positive"),
            std::string::npos)
      << wording.remark;
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
  // "Smaller than 1": read literally a sufficient condition no step meets (the roots' product is 1),
  // read as meant the root condition without its clause on simple roots, which the stable roots are:
  // it holds, with a wording remark (the policy). "At most 1" alone calls the double root stable: an
  // erratum under every reading.
  const claim_result smaller = run("root-criterion", with("one"));
  EXPECT_EQ(smaller.outcome, verdict::holds);
  EXPECT_EQ(smaller.remark_kind, finding::wording);
  EXPECT_NE(smaller.remark.find("stable for h*omega in (0, 2)"), std::string::npos) << smaller.remark;
  EXPECT_EQ(run("root-criterion", with("three")).outcome, verdict::erratum);
}

}  // namespace
}  // namespace simpson::verify

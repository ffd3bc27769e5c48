// The prose claims quote the sentence they judge from the paper's source and parse the words that
// carry the claim: a copy of the paper whose sentence changed flips the verdict (the new words are
// judged) or flags it (text-changed: the sentence is gone, or its words no longer parse).

#include <simpson/verify/table1_reader.hpp>
#include <simpson/verify/ledger.hpp>
#include "embedded_reading.hpp"
#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/printed_checks.hpp>
#include <simpson/verify/prose_span.hpp>
#include <simpson/verify/quoted_words.hpp>
#include <simpson/verify/table1_conventions.hpp>
#include <simpson/verify/tex_math.hpp>

#include <boost/math/constants/constants.hpp>
#include <fmt/format.h>

#include <gtest/gtest.h>

namespace simpson::verify {
namespace {

paper_source text_source(const std::string& text) { return {"test", text, "", text}; }

TEST(ProseSpan, MatchesAcrossLineBreaksAndTakesTheHolesWords) {
  const paper_source paper = text_source("First.\nThe quadrature formula (\\ref{simpson})  is accurate up to\n polynomials of degree three. Then");
  const auto span = find_prose(paper, "The quadrature formula (\\ref{simpson}) is accurate up to polynomials of degree {degree}.");
  ASSERT_TRUE(span.has_value());
  EXPECT_EQ(span->line, 2);
  EXPECT_EQ(span->holes.at("degree"), "three");
  EXPECT_EQ(span->text, "The quadrature formula (\\ref{simpson}) is accurate up to polynomials of degree three.");
}

TEST(ProseSpan, ASentenceThatIsGoneIsNotFound) {
  const paper_source paper = text_source("The quadrature formula is exact.");
  EXPECT_FALSE(find_prose(paper, "accurate up to polynomials of degree {degree}.").has_value());
}

TEST(ProseSpan, TexGroupsAreTextAndAPatternMustStartWithWords) {
  const paper_source paper = text_source("that $ \\, {\\rm det} \\, \\Phi_3 = 1 \\, $ and in consequence the scheme is symplectic.");
  const auto span = find_prose(paper, "$ \\, {\\rm det} \\, \\Phi_3 = 1 \\, $ and in consequence the scheme is {property}.");
  ASSERT_TRUE(span.has_value());
  EXPECT_EQ(span->holes.at("property"), "symplectic");
  EXPECT_THROW(find_prose(paper, "{property} is"), std::logic_error);
}

TEST(ProseSpan, AHoleTakesProseOnlyNeverADisplayOrAParagraphBreak) {
  // The first "is" starts a span whose hole would take the display and the sentence after it; the
  // hole stays in the prose, so the span is the second sentence's. Before this rule the first "is"
  // matched, with a hole of 60 characters of math.
  const paper_source paper = text_source("The node is\n\\begin{equation}\nq_m = q\n\\end{equation}\nThe ratio is not linear in q.");
  const auto span = find_prose(paper, "is {linearity} in q.");
  ASSERT_TRUE(span.has_value());
  EXPECT_EQ(span->holes.at("linearity"), "not linear");
  EXPECT_EQ(span->line, 5);
  for (const char* between : {"\\[ x \\]", "$$ x $$", "\n\n", "\n  \n"}) {
    const paper_source broken = text_source(std::string("It is stable") + between + "for all h.");
    EXPECT_FALSE(find_prose(broken, "is {property} for all h.").has_value()) << between;
  }
  EXPECT_TRUE(find_prose(text_source("It is stable\n for all h."), "is {property} for all h.").has_value());  // a line break is not a paragraph's
  EXPECT_FALSE(find_prose(text_source("It is for all h."), "is {property} for all h.").has_value());  // a hole stands for words
}

TEST(ProseSpan, APatternThatMatchesTwoSpansIsRefusedNamingBoth) {
  // Which sentence is judged is never guessed: a pattern with holes that matches twice says where.
  const paper_source paper = text_source("The map is linear in q.\nThe ratio is not linear in q.");
  const auto span = find_prose(paper, "is {linearity} in q.");
  ASSERT_TRUE(span.has_value());
  EXPECT_EQ(span->also_at, std::vector<int>{2});
  try {
    (void)quote_sentence(paper, "is {linearity} in q.", nullptr);
    ADD_FAILURE() << "an ambiguous pattern was quoted";
  } catch (const text_changed& e) {
    EXPECT_NE(std::string(e.what()).find("matches 2 spans (lines 1, 2)"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(find_prose(paper, "The ratio is {linearity} in q.")->also_at.empty());
  // Words without a hole are the same words wherever they stand: not ambiguous.
  EXPECT_TRUE(find_prose(paper, "in q.")->also_at.empty());
}

TEST(ProseSpan, PlainWordsDropsMathMarkupAndSpacing) {
  EXPECT_EQ(plain_words("smaller or equal to $ \\, 1 $"), "smaller or equal to 1");
  EXPECT_EQ(plain_words("\\sin \\, \\omega \\, t \\,"), "\\sin \\omega t");
}

/// The words of one hole, parsed through a quoted sentence of a small text.
quoted_sentence sentence(const std::string& words, json& records) {
  static paper_reading reading;
  reading.source = text_source("The words are " + words + " here.");
  run_context ctx;
  ctx.paper = &reading;
  ctx.quotes = &records;
  return quote(ctx, "The words are {words} here.");
}

TEST(QuotedWords, NumbersBoundsAndChoicesParseAndAreRecorded) {
  json records = json::array();
  EXPECT_EQ(sentence("three", records).number("words"), 3);
  EXPECT_EQ(sentence("fourth", records).number("words"), 4);
  EXPECT_EQ(sentence("$ 12 $", records).number("words"), 12);
  const stated_bound b = sentence("smaller or equal to $ \\, 1 $", records).bound("words");
  EXPECT_EQ(b.relation, "<=");
  EXPECT_EQ(b.value, 1);
  EXPECT_TRUE(b.admits(1));
  EXPECT_FALSE(b.admits(2));
  const stated_bound strict = sentence("smaller than 1, simple", records).bound("words");
  EXPECT_EQ(strict.relation, "<");
  EXPECT_EQ(strict.rest, "simple");
  EXPECT_EQ(sentence("Explicit", records).choice("words", {{"explicit", "E"}, {"implicit", "I"}}), "E");
  ASSERT_EQ(records.size(), 6u);
  EXPECT_EQ(records[0]["parsed"]["words"], 3);
  EXPECT_EQ(records[0]["words"]["words"], "three");
}

TEST(QuotedWords, WordsThatDoNotParseAreTextChanged) {
  json records = json::array();
  EXPECT_THROW(sentence("trois", records).number("words"), text_changed);
  EXPECT_THROW(sentence("bigger than", records).bound("words"), text_changed);
  EXPECT_THROW(sentence("semi-explicit", records).choice("words", {{"explicit", "E"}}), text_changed);
  paper_reading empty;
  empty.source = text_source("Nothing of the kind.");
  run_context ctx;
  ctx.paper = &empty;
  EXPECT_THROW(quote(ctx, "The words are {words} here."), text_changed);
}

/// The embedded paper with the first `from` replaced by `to`, read.
paper_reading altered_reading(const std::string& from, const std::string& to) {
  paper_source paper = embedded_paper();
  const std::size_t at = paper.text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) replace_text(paper, at, from.size(), to);
  paper.origin = "altered copy";
  return read_paper(paper);
}

/// One prose sentence of the embedded paper changed: the claim that quotes it gets `expected`.
struct sentence_change {
  std::string claim;
  std::string from, to;  // in the paper's source, first occurrence
  verdict expected;
};

std::ostream& operator<<(std::ostream& out, const sentence_change& a) { return out << a.claim << ": '" << a.from << "' -> '" << a.to << "'"; }

class ChangedSentence : public testing::TestWithParam<sentence_change> {};

TEST_P(ChangedSentence, FlipsOrFlagsTheClaimThatQuotesIt) {
  const sentence_change& a = GetParam();
  const paper_reading reading = altered_reading(a.from, a.to);
  const claim& c = paper_book().find(a.claim);
  const run_context ctx{{precision::parse("double"), precision::parse("rational")}, 20230830, 2, &reading};
  const claim_result r = check_claim(c, ctx);
  EXPECT_EQ(to_string(r.outcome), to_string(a.expected)) << r.note << " " << r.evidence.dump().substr(0, 600);
  EXPECT_NE(r.outcome, c.expected) << "an altered sentence left " << a.claim << " as expected";
  ASSERT_FALSE(r.quoted.empty());
  if (r.outcome == verdict::text_changed) {
    EXPECT_TRUE(r.evidence.contains("text_changed"));
  }
}

INSTANTIATE_TEST_SUITE_P(
    Paper, ChangedSentence,
    testing::Values(
        sentence_change{"simpson-exactness", "polynomials of  degree three", "polynomials of degree five", verdict::erratum},
        sentence_change{"simpson-exactness", "polynomials of  degree three", "polynomials of degree trois", verdict::text_changed},
        sentence_change{"midpoint-exactness", "smaller or equal to $ \\, 1 $", "smaller or equal to $ \\, 2 $", verdict::erratum},
        // "at most 1" without simple roots calls the double root at 2 sqrt(2) stable: false under every reading.
        sentence_change{"root-modulus-criterion", "of modulus smaller than 1", "of modulus smaller or equal to 1", verdict::erratum},
        sentence_change{"root-modulus-criterion", "The scheme is stable when the roots", "The scheme is stable if the roots",
                   verdict::text_changed},
        // The abbreviated action named: false under every reading (Maupertuis's name alone holds, with a remark).
        sentence_change{"maupertuis-naming", "Maupertuis's stationary-action", "Maupertuis's abbreviated-action", verdict::erratum},
        sentence_change{"internal-equation-second-order", "a second order discretization", "a fourth order discretization",
                        verdict::erratum},
        sentence_change{"classical-consistency", "is clearly consistent with", "is clearly not consistent with", verdict::erratum},
        sentence_change{"hamilton-consistency", "These relations are consistent", "These relations are inconsistent", verdict::erratum},
        sentence_change{"newmark-det", "(\\ref{systeme-symplectique-ordre-2}) is symplectic", "(\\ref{systeme-symplectique-ordre-2}) is not symplectic",
                        verdict::erratum},
        sentence_change{"newmark-energy", "is conserved: we have", "is not conserved: we have", verdict::erratum},
        sentence_change{"scheme-consistency", "(\\ref{schema-ordre-3}) is consistent with", "(\\ref{schema-ordre-3}) is not consistent with",
                        verdict::erratum},
        // Of the interpolating curve, of degree 2 in t when h > 0: "linear" is false (an affine curve).
        sentence_change{"qm-not-affine", "is not linear if", "is linear if", verdict::erratum},
        sentence_change{"fourth-order-truncation", "(\\ref{schema-ordre-3}) is fourth order", "(\\ref{schema-ordre-3}) is second order",
                   verdict::erratum},
        sentence_change{"roots-product-one", "is equal to 1 and the scheme", "is equal to 2 and the scheme", verdict::erratum},
        sentence_change{"phi3-symplectic", "in consequence the scheme is symplectic", "in consequence the scheme is not symplectic",
                   verdict::erratum},
        sentence_change{"newmark-unconditional-stability", "particular inconditionally stable", "particular conditionally stable",
                   verdict::erratum},
        sentence_change{"newmark-identification", "version of the\nNewmark scheme", "version of the\nVerlet scheme", verdict::text_changed},
        sentence_change{"conclusion-conditionally-stable", "symplectic, conditionnally stable and", "symplectic, unconditionally stable and", verdict::erratum},
        sentence_change{"conclusion-symplectic", "The method is symplectic, conditionnally", "The method is not symplectic, conditionnally", verdict::erratum},
        sentence_change{"conclusion-fourth-order", "is fourth order accurate for state", "is third order accurate for state", verdict::erratum},
        sentence_change{"table-orders", "$ 1.27  \\,\\, 10^{-1} $  & 2", "$ 1.27  \\,\\, 10^{-1} $  & 3", verdict::fails},
        sentence_change{"table-conservation", "$ 1.49 \\,\\, 10^{-13} $   & exact", "$ 1.49 \\,\\, 10^{-13} $   & 4", verdict::fails},
        sentence_change{"table-values", "$ 4.11  \\,\\, 10^{-4} $", "$ 4.11  \\,\\, 10^{-x} $", verdict::text_changed},
        // An "exact" row printed far above round-off (0.17, 0.50, 1.49): judged by its printed values.
        sentence_change{"table-conservation", "$ 1.70 \\,\\, 10^{-13} $ &   $ 4.97 \\,\\, 10^{-14} $  & $ 1.49 \\,\\, 10^{-13} $",
                        "$ 1.70 \\,\\, 10^{-1} $ &   $ 5.0 \\,\\, 10^{-1} $  & $ 1.49 \\,\\, 10^{0} $", verdict::fails},
        // The Simpson state row printed with ratios of 4 (order 2) under its order cell 4.
        sentence_change{"table-orders", "$ 2.55 \\,\\, 10^{-5} $   & $ 1.60 \\,\\, 10^{-6} $",
                        "$ 1.03 \\,\\, 10^{-4} $   & $ 2.57 \\,\\, 10^{-5} $", verdict::fails},
        // "Unconditionally stable" is false: the scheme is stable on two bands only (a plain "stable"
        // holds, read as the field reads it, with a remark).
        sentence_change{"abstract-stable", "It is a stable,", "It is a unconditionally stable,", verdict::erratum},  // (the pattern keeps its "a")
        // "It is a stable, explicit ... scheme": Section 6's wording (phi3-explicit); "implicit" holds.
        sentence_change{"abstract-explicit", "explicit, and  symplectic", "explicit for nonlinear problems too, and symplectic", verdict::erratum},
        sentence_change{"experiment-conventions", "p(t) = m \\, \\omega \\, \\cos", "p(t) = m \\, \\cos", verdict::fails}));

// "All the factors ... are negative" (and Delta < 0, in the same sentence): consistent only when "all
// the factors" are the binomials (the prefactor is positive), which are negative, and Delta < 0,
// proved: it holds, with a wording remark (before: an erratum). Printed "positive", or with a factor
// (8 - omega^2 h^2), the substance is false too: an erratum, no remark.
TEST(ChangedSentence, TheDiscriminantsFactorsHoldAsAnExpertReadsThemAndFailWhenChanged) {
  const run_context printed{{precision::parse("double")}, 20230830, 2, &embedded_reading()};
  const claim_result as_printed = check_claim(paper_book().find("discriminant-negative"), printed);
  EXPECT_EQ(as_printed.outcome, verdict::holds);
  EXPECT_EQ(as_printed.remark_kind, finding::wording);
  EXPECT_EQ(as_printed.remark.rfind("'All the factors' can only be the factors that are sums", 0), 0u) << as_printed.remark;
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"are negative", "are positive"},
                                 std::pair<std::string, std::string>{"(\\omega^2 \\, h^2 - 8 )", "(8 - \\omega^2 \\, h^2)"}}) {
    const paper_reading reading = altered_reading(from, to);
    const claim_result r = check_claim(paper_book().find("discriminant-negative"), run_context{{precision::parse("double")}, 20230830, 2, &reading});
    EXPECT_EQ(r.outcome, verdict::erratum) << to;
    EXPECT_TRUE(r.remark.empty()) << to << ": " << r.remark;
  }
}

// The verdicts a word decides say so, in their note and evidence, printed and with the word changed:
// the computation beside them is the same whatever the word.
TEST(ChangedSentence, AWordDecidedVerdictSaysItIsLexical) {
  const std::vector<std::pair<std::string, std::pair<std::string, std::string>>> claims{
      {"abstract-explicit", {"explicit, and  symplectic", "explicit for nonlinear problems too, and symplectic"}},
      {"nonlinear-internal-node", {"is not possible in that case", "is possible in that case"}},
      {"maupertuis-naming", {"the Maupertuis's stationary-action principle", "the Hamilton's stationary-action principle"}}};
  for (const auto& [id, change] : claims) {
    const claim_result printed = check_claim(paper_book().find(id), run_context{{precision::parse("double")}, 20230830, 2, &embedded_reading()});
    EXPECT_EQ(printed.note.rfind("Lexical: decided by the word", 0), 0u) << id << ": " << printed.note;
    EXPECT_TRUE(printed.evidence.contains("lexical")) << id;
    const paper_reading reading = altered_reading(change.first, change.second);
    const claim_result changed = check_claim(paper_book().find(id), run_context{{precision::parse("double")}, 20230830, 2, &reading});
    // The word moves the verdict, or the remark (nonlinear-internal-node: "not possible" holds as
    // meant, with a remark; "possible" holds plainly).
    EXPECT_TRUE(changed.outcome != printed.outcome || changed.remark != printed.remark) << id << ": " << changed.note;
    EXPECT_EQ(changed.note.rfind("Lexical: decided by the word", 0), 0u) << id << ": " << changed.note;
  }
}

// "Maupertuis's stationary-action principle": Maupertuis's name on what is Hamilton's principle (the
// field often gives his name to any least-action principle) holds with a naming remark; "Hamilton's"
// holds plainly; the abbreviated action named is an erratum (the ChangedSentence case above).
TEST(ChangedSentence, MaupertuisNameOnHamiltonsPrincipleIsANamingRemark) {
  const run_context ctx{{precision::parse("double")}, 20230830, 2, &embedded_reading()};
  const claim_result printed = check_claim(paper_book().find("maupertuis-naming"), ctx);
  EXPECT_EQ(printed.outcome, verdict::holds) << printed.note;
  EXPECT_EQ(printed.remark_kind, finding::naming);
  EXPECT_NE(printed.remark.find("strictly Hamilton's"), std::string::npos) << printed.remark;
  const paper_reading reading = altered_reading("Maupertuis's stationary-action", "Hamilton's stationary-action");
  const claim_result hamilton = check_claim(paper_book().find("maupertuis-naming"), run_context{{precision::parse("double")}, 20230830, 2, &reading});
  EXPECT_EQ(hamilton.outcome, verdict::holds) << hamilton.note;
  EXPECT_TRUE(hamilton.remark.empty()) << hamilton.remark;
}

// The referee's cases (docs/findings.md, the policy): a sentence true as an expert reads it holds,
// with a remark at most. "This interpolation is not linear if h > 0" is said of the curve t -> q(t),
// of degree 2 when h > 0 (before: an erratum on q_m's linearity in q_l, q_r, which the sentence does
// not assert); "an explicit scheme" of Phi_3, in closed form for every h > 0, holds with the remark
// that as a method it is implicit (before: an erratum on a definition of the harness's own).
TEST(ChangedSentence, TheReferesReadingsHoldWithARemark) {
  const run_context ctx{{precision::parse("double")}, 20230830, 2, &embedded_reading()};
  const claim_result affine = check_claim(paper_book().find("qm-not-affine"), ctx);
  EXPECT_EQ(affine.outcome, verdict::holds) << affine.note;
  EXPECT_EQ(affine.remark_kind, finding::wording) << affine.remark;  // affine for some data: q_l + q_r = 0
  EXPECT_NE(affine.note.find("At h = 0 it is affine: the condition h > 0 is what makes it not affine"), std::string::npos) << affine.note;
  // With the harmonic q_m printed as the midpoint, the curve is affine for every h: "not linear" is false.
  const paper_reading midpoint = altered_reading("q_m = {{1}\\over{1-{{\\omega^2 \\, h^2}\\over{8}}}} \\, {{q_\\ell + q_r}\\over2} .", "q_m = {{q_\\ell + q_r}\\over2} .");
  EXPECT_EQ(check_claim(paper_book().find("qm-not-affine"), run_context{{precision::parse("double")}, 20230830, 2, &midpoint}).outcome, verdict::erratum);
  const claim_result explicit_map = check_claim(paper_book().find("phi3-explicit"), ctx);
  EXPECT_EQ(explicit_map.outcome, verdict::holds);
  EXPECT_EQ(explicit_map.remark_kind, finding::wording);
  EXPECT_NE(explicit_map.remark.find("the denominator h^2*omega^2+24 (up to factors free of h)"), std::string::npos) << explicit_map.remark;
  EXPECT_NE(explicit_map.remark.find("In the usual sense the scheme is implicit"), std::string::npos) << explicit_map.remark;
  EXPECT_TRUE(explicit_map.correction.empty()) << explicit_map.correction;
  // "Stable when the roots are of modulus smaller than 1": read literally a true sufficient condition,
  // read as meant (at most 1) the root condition without simple roots, which the roots are: it holds,
  // with a wording remark (before: an erratum).
  const claim_result modulus = check_claim(paper_book().find("root-modulus-criterion"), ctx);
  EXPECT_EQ(modulus.outcome, verdict::holds);
  EXPECT_EQ(modulus.remark_kind, finding::wording);
  EXPECT_NE(modulus.remark.find("'smaller than 1' should read 'at most 1, those of modulus 1 simple' (the root condition)"), std::string::npos)
      << modulus.remark;
  EXPECT_NE(modulus.remark.find("stable for h*omega in (0, 2 sqrt(2)) and (2 sqrt(3), 2 sqrt(6))"), std::string::npos) << modulus.remark;
}

// The abstract's "approximate energy": H_d = H + m omega^6 h^4 q^2/(72 (8 - omega^2 h^2)) holds as
// printed; with H_d's 1/24 printed 1/25 it does not (an erratum, the derived right side its correction).
TEST(ChangedFormula, TheApproximateEnergyIsTheEnergyPlusAnOrderFourTerm) {
  const run_context printed_ctx{{precision::parse("double")}, 20230830, 2, &embedded_reading()};
  EXPECT_EQ(check_claim(paper_book().find("approximate-energy"), printed_ctx).outcome, verdict::holds);
  EXPECT_EQ(check_claim(paper_book().find("approximate-energy-sign"), printed_ctx).outcome, verdict::holds);
  const paper_reading reading = altered_reading("\\Big(1 - {{\\omega^2 \\, h^2}\\over24} \\Big) \\, q^2", "\\Big(1 - {{\\omega^2 \\, h^2}\\over25} \\Big) \\, q^2");
  const claim_result r = check_claim(paper_book().find("approximate-energy"), run_context{{precision::parse("double")}, 20230830, 2, &reading});
  EXPECT_EQ(r.outcome, verdict::erratum) << r.note;
}

TEST(ChangedSentence, ExplicitForNonlinearProblemsIsStillAnErratum) {
  // "nonlinear" is not a restriction to linear problems: the words are wrong in substance, not wording.
  const paper_reading reading = altered_reading("explicit, and  symplectic", "explicit for nonlinear problems too, and symplectic");
  const claim_result r = check_claim(paper_book().find("abstract-explicit"), run_context{{precision::parse("double")}, 20230830, 2, &reading});
  EXPECT_EQ(r.outcome, verdict::erratum);
  EXPECT_EQ(r.evidence.at("stated").at("qualified"), false);
  EXPECT_TRUE(r.remark.empty());
  // As printed (explicit for the harmonic oscillator, read in context): it holds, with Section 6's
  // wording remark (before: an erratum).
  const claim_result printed = check_claim(paper_book().find("abstract-explicit"), run_context{{precision::parse("double")}, 20230830, 2, &embedded_reading()});
  EXPECT_EQ(printed.outcome, verdict::holds);
  EXPECT_EQ(printed.remark_kind, finding::wording);
  EXPECT_NE(printed.remark.find("Explicit for the harmonic oscillator, to which the sentence before limits it"), std::string::npos) << printed.remark;
  EXPECT_EQ(paper_book().find("abstract-explicit").follows_from, "phi3-explicit");
  // "It" is the scheme the sentence before makes explicit for the harmonic oscillator; made explicit
  // for general systems instead, "explicit" is false in substance too.
  const paper_reading general = altered_reading("is explicited for an elementary harmonic oscillator", "is explicited for general dynamical systems");
  const claim_result unqualified = check_claim(paper_book().find("abstract-explicit"), run_context{{precision::parse("double")}, 20230830, 2, &general});
  EXPECT_EQ(unqualified.outcome, verdict::erratum);
  EXPECT_TRUE(unqualified.remark.empty());
  // "linear" inside "nonlinear" is no limit to linear problems (a substring match took it for one).
  const paper_reading nonlinear = altered_reading("is explicited for an elementary harmonic oscillator", "is explicited for nonlinear systems");
  const claim_result extended = check_claim(paper_book().find("abstract-explicit"), run_context{{precision::parse("double")}, 20230830, 2, &nonlinear});
  EXPECT_EQ(extended.outcome, verdict::erratum);
  // The scope is what the verdict rests on: the quote records what the check made of it.
  bool scope_parsed = false;
  for (const json& q : printed.quoted) scope_parsed = scope_parsed || q.value("parsed", json::object()).contains("scope");
  EXPECT_TRUE(scope_parsed) << printed.quoted.dump();
}

// "an explicit scheme" of Phi_3: explicit on this linear problem (its one denominator positive for
// every h > 0: Coq checks the sign; our kernel finds no positive root), with the remark that a
// denominator in h is what solving the step equation leaves. Stated "implicit", it holds plainly.
TEST(ChangedSentence, ExplicitIsJudgedAsTheFieldDefinesIt) {
  const claim_result printed = check_claim(paper_book().find("phi3-explicit"), run_context{{precision::parse("double")}, 20230830, 2, &embedded_reading()});
  EXPECT_EQ(printed.outcome, verdict::holds);
  const GiNaC::ex w = paper_symbols()["omega"], h = paper_symbols()["h"];
  EXPECT_NE(printed.remark.find(canonical_text(h * h * w * w + 24)), std::string::npos) << printed.remark;
  EXPECT_EQ(printed.evidence.at("exact").at("own").get<std::string>().rfind("holds at m = 1, omega = 1: ", 0), 0u) << printed.evidence.dump();
  EXPECT_FALSE(printed.certificate.empty()) << "the denominators' signs, in Coq";
  const paper_reading implicit = altered_reading("is an explicit scheme.", "is an implicit scheme.");
  const claim_result said_implicit = check_claim(paper_book().find("phi3-explicit"), run_context{{precision::parse("double")}, 20230830, 2, &implicit});
  EXPECT_EQ(said_implicit.outcome, verdict::holds);
  EXPECT_TRUE(said_implicit.remark.empty());
}

TEST(ChangedTable, TableOneIsJudgedAsPrinted) {
  // table-values already fails as printed: a changed entry shows in its evidence, read from the copy.
  const paper_reading reading = altered_reading("$ 4.11  \\,\\, 10^{-4} $", "$ 4.11  \\,\\, 10^{-3} $");
  const claim_result r = check_claim(paper_book().find("table-values"), run_context{{precision::parse("double")}, 20230830, 2, &reading});
  EXPECT_EQ(r.evidence.at("numeric").at("rows")[3]["published_N_10_20_40"][0], "4.11e-03");
  EXPECT_NE(r.note.find("Symplectic Simpson state 0.997-9.84x ours"), std::string::npos) << r.note;
}

// Section 8's stated conventions are judged by the experiment they state: as printed they do not
// reproduce Table 1 and another exact solution does (an erratum, naming the simplest); with a table no convention
// reproduces, the stated pair is not supported either (fails). The same sentence in both copies.
TEST(ChangedTable, TheStatedConventionsAreJudgedByWhetherTheyReproduceTheTable) {
  const claim_result printed = check_claim(paper_book().find("experiment-conventions"), run_context{{precision::parse("double")}, 20230830, 2, &embedded_reading()});
  EXPECT_EQ(printed.outcome, verdict::erratum);
  EXPECT_NE(printed.correction.find("released from rest at q₀ = π/2, p₀ = 0, m = 1"), std::string::npos) << printed.correction;
  // The stated pair is what the search starts from: the quote records q and p as read.
  ASSERT_FALSE(printed.quoted.empty());
  EXPECT_EQ(printed.quoted[0].at("parsed").value("q_exact", ""), "sin(omega*t)") << printed.quoted.dump();
  EXPECT_EQ(printed.quoted[0].at("parsed").value("p_exact", ""), "cos(omega*t)*m*omega") << printed.quoted.dump();
  const paper_reading reading = altered_reading("$ 4.11  \\,\\, 10^{-4} $", "$ 4.11  \\,\\, 10^{-3} $");
  const claim_result changed = check_claim(paper_book().find("experiment-conventions"), run_context{{precision::parse("double")}, 20230830, 2, &reading});
  EXPECT_EQ(changed.outcome, verdict::fails) << changed.note;
}

/// The embedded paper with Table 1 as `computed` gives it, each entry printed with three digits in the
/// paper's own format ("$ d.dd \,\, 10^{e} $"); an "exact" row keeps its round-off values.
paper_source with_table(const std::vector<computed_entry>& computed, paper_source paper = embedded_paper()) {
  std::size_t at = paper.text.find("Newmark & momentum &");
  const printed_table1 printed = read_table1(embedded_paper());
  for (std::size_t k = 0; k < computed.size(); ++k) {
    at = paper.text.find('$', at);
    const std::size_t end = paper.text.find('$', at + 1) + 1;
    if (printed.orders[k / 3] != "exact") {
      const double v = computed[k].value;
      const int exponent = static_cast<int>(std::floor(std::log10(v)));
      replace_text(paper, at, end - at, fmt::format("$ {:.2f} \\,\\, 10^{{{}}} $", v / std::pow(10.0, exponent), exponent));
    }
    at = paper.text.find('$', at + 1) + 1;
  }
  paper.origin = "altered copy";
  return paper;
}

/// The embedded paper stating q(t) = cos ωt and p(t) = -m ω sin ωt: another consistent solution.
paper_source stating_a_cosine(paper_source paper = embedded_paper()) {
  const std::string printed = "q(t) = \\sin \\, \\omega \\, t \\, $ and $ \\, p(t) = m \\, \\omega \\, \\cos \\, \\omega \\, t $";
  const std::size_t at = paper.text.find(printed);
  if (at == std::string::npos) throw std::logic_error("the stated solution's sentence is not in the embedded paper");
  replace_text(paper, at, printed.size(), "q(t) = \\cos \\, \\omega \\, t \\, $ and $ \\, p(t) = - m \\, \\omega \\, \\sin \\, \\omega \\, t $");
  paper.origin = "altered copy";
  return paper;
}

// The stated solution is read, not typed: a copy stating another consistent solution, q = cos ωt
// with p = -m ω sin ωt, is searched from it (a check that expects the printed sin fails it without
// a search). On the printed table it does not reproduce the entries (an erratum naming the simplest
// start, as for the sin); on a table computed from it (m = 1, released from rest at q₀ = 1) it holds.
TEST(ChangedTable, AnotherConsistentStatedSolutionIsSearchedNotFailed) {
  const paper_reading cosine = read_paper(stating_a_cosine());
  const claim_result on_printed = check_claim(paper_book().find("experiment-conventions"), run_context{{precision::parse("double")}, 20230830, 2, &cosine});
  EXPECT_EQ(on_printed.outcome, verdict::erratum) << on_printed.note;
  EXPECT_NE(on_printed.correction.find("q(t) = cos(ωt) with m = 1 reproduces"), std::string::npos) << on_printed.correction;
  const double half_pi = boost::math::constants::half_pi<double>();
  const paper_reading computed_from_it =
      read_paper(stating_a_cosine(with_table(table1_under(table1_stated_conventions(), {{"m", 1}, {"amplitude", 1}, {"phase", half_pi}}))));
  const claim_result holds = check_claim(paper_book().find("experiment-conventions"), run_context{{precision::parse("double")}, 20230830, 2, &computed_from_it});
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  // The sin the paper prints, on that table: not reproduced.
  const paper_reading sine = read_paper(with_table(table1_under(table1_stated_conventions(), {{"m", 1}, {"amplitude", 1}, {"phase", half_pi}})));
  EXPECT_NE(check_claim(paper_book().find("experiment-conventions"), run_context{{precision::parse("double")}, 20230830, 2, &sine}).outcome,
            verdict::holds);
  // A pair that is no one solution is what fails: p printed +m ω sin ωt for q = cos ωt.
  paper_source wrong = stating_a_cosine();
  const std::size_t minus = wrong.text.find("p(t) = - m");
  replace_text(wrong, minus, 10, "p(t) = m");
  const paper_reading inconsistent = read_paper(wrong);
  EXPECT_EQ(check_claim(paper_book().find("experiment-conventions"), run_context{{precision::parse("double")}, 20230830, 2, &inconsistent}).outcome,
            verdict::fails);
}

// A copy whose Table 1 was computed from rest at q₀ = π/4 with m = 2 (the stated discrete
// conventions), each entry printed with three digits in the paper's own format: table-values names
// exactly that start, every entry reproduced, and decides it by enclosures too.
TEST(ChangedTable, ATableComputedWithSimpleValuesIsExplainedByThem) {
  const double pi = boost::math::constants::pi<double>();
  const paper_reading reading = read_paper(with_table(table1_under(table1_stated_conventions(), {{"m", 2}, {"amplitude", pi / 4}, {"phase", pi / 2}})));
  const claim_result r = check_claim(paper_book().find("table-values"), run_context{{precision::parse("double")}, 20230830, 2, &reading});
  // The numbers right, their description not: holds with a wording remark (experiment-conventions
  // is the finding).
  EXPECT_EQ(r.outcome, verdict::holds) << r.note;
  EXPECT_EQ(r.remark_kind, finding::wording) << r.remark;
  EXPECT_NE(r.remark.find("Every entry within its printed digits: The oscillator released from rest at q₀ = π/4, "
                          "p₀ = 0, m = 2 (q(t) = π/4 cos ωt), under the stated discrete conventions, reproduces within their printed digits 18 of the 18 informative "
                          "entries (the 6 others, of the rows printed as exact, are at round-off level, as ours are)"),
            std::string::npos)
      << r.remark;
  EXPECT_EQ(r.evidence.at("simplest").at("enclosed").at("reproduced"), "24 of 24") << r.evidence.at("simplest").dump();
  // table-roundoff proves its bound on that orbit, not on a typed one: m = 2, from rest at q₀ = π/4,
  // in a box 9/8 of its amplitudes, rounded up in eighths (|q| ≤ 1, |p| ≤ 89/8).
  const claim_result roundoff = check_claim(paper_book().find("table-roundoff"), run_context{{precision::parse("double")}, 20230830, 2, &reading});
  EXPECT_EQ(roundoff.outcome, verdict::holds) << roundoff.note;
  EXPECT_NE(roundoff.note.find("released from rest at q₀ = π/4, p₀ = 0, m = 2"), std::string::npos) << roundoff.note;
  const std::string method = roundoff.evidence.at("floating").at("method");
  EXPECT_NE(method.find("m = 2,"), std::string::npos) << method;
  EXPECT_NE(method.find("|p| ≤ 89/8, |q| ≤ 1;"), std::string::npos) << method;
}

TEST(ChangedTable, AnEntryIsJudgedToTheDigitsItIsPrintedWith) {
  // "4.2 10^{-4}" has two significant digits: its interval is 4.2e-4 ± 0.05e-4, and ours (4.18e-4) is
  // inside; printed "4.11" (three digits, ± 0.005e-4) it is not.
  const paper_reading reading = altered_reading("$ 4.11  \\,\\, 10^{-4} $", "$ 4.2 \\,\\, 10^{-4} $");
  const claim_result r = check_claim(paper_book().find("table-values"), run_context{{precision::parse("double")}, 20230830, 2, &reading});
  const json& entry = r.evidence.at("search").at("stated").at("entries")[9];
  EXPECT_EQ(entry["row"], "Symplectic Simpson state");
  EXPECT_EQ(entry["printed"], "4.2e-04");
  EXPECT_EQ(entry["reproduced"], true) << entry.dump();
}

// newmark-identification judges the printed Φ (matrice-symplectique-ordre-2), not the core's
// newmark_map: a copy with Φ's (1,2) entry printed −mω²h/2 is not Newmark's β = 1/4, γ = 1/2 map
// (fails), while our core still is (which the claim used to compare alone).
TEST(ChangedFormula, NewmarksIdentificationJudgesThePrintedMatrix) {
  const claim_result printed = check_claim(paper_book().find("newmark-identification"), run_context{{precision::parse("double")}, 20230830, 2, &embedded_reading()});
  EXPECT_EQ(printed.outcome, verdict::holds) << printed.note;
  const paper_reading reading = altered_reading("& - m \\, \\omega^2 \\, h \\\\", "& - m \\, \\omega^2 \\, {h \\over 2} \\\\");
  const claim_result r = check_claim(paper_book().find("newmark-identification"), run_context{{precision::parse("double")}, 20230830, 2, &reading});
  EXPECT_EQ(r.outcome, verdict::fails) << r.note;
  EXPECT_NE(r.note.find("printed Phi − derived"), std::string::npos) << r.note;
}

TEST(ChangedFormula, TheContractionConstantFollowsThePrintedInternalEquation) {
  // (equation-milieu-intervalle) with 2/h^2 for 4/h^2: the pendulum's contraction bound moves from
  // omega h < 2 sqrt(2) to omega h < 2, no longer the stability bound.
  const paper_reading reading = altered_reading("m\\, {{4}\\over{h^2}} \\, \\big( q_\\ell -2", "m\\, {{2}\\over{h^2}} \\, \\big( q_\\ell -2");
  const run_context ctx{{precision::parse("double")}, 20230830, 2, &reading};
  const claim_result r = check_claim(paper_book().find("nonlinear-internal-node"), ctx);
  EXPECT_EQ(r.evidence.at("exact").at("pendulum_contraction_constant"), "(h^2*omega^2)/(4)");
  EXPECT_EQ(r.evidence.at("exact").at("same_bound"), false);
  const claim_result printed = check_claim(paper_book().find("nonlinear-internal-node"), run_context{{precision::parse("double")}, 20230830, 2, &embedded_reading()});
  EXPECT_EQ(printed.evidence.at("exact").at("same_bound"), true);
}

}  // namespace
}  // namespace simpson::verify

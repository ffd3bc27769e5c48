// The shapes that judge what a text says about itself and its place: its spelling, its citations,
// a condition it says emerges from a formula, and a method it presents as its own that is a known
// one; and the prose's words they read (prose_words.hpp). Each on a small document where it holds
// and on one where a weaker check would pass.

#include "shape_fixture.hpp"
#include <simpson/verify/readable_math.hpp>

#include <simpson/verify/prose_words.hpp>
#include <simpson/verify/tex_document.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace simpson::verify {
namespace {

using test::document;
using test::ShapesOnADocument;
using test::shape_document;

std::vector<std::string> words_of(const std::string& text, const std::string& from = {}) {
  const paper_source source = document(text);
  std::vector<std::string> out;
  for (const prose_word& w : prose_words(source, tex_document(source), from)) out.push_back(w.word);
  return out;
}

TEST(ProseWords, AreWhatAReaderReadsBetweenTheFormulas) {
  // Math, a label, a citation and a comment are not prose; an accent is its letter; an ending glued
  // to a number is not a word; an emphasis's argument is prose.
  const std::vector<std::string> words =
      words_of("\\begin{document}\nThe step $h_{teh}$ is \\emph{smal} \\cite{Ar74} in Math\\'ematiques\\label{recieve} since the 1950's % misspeled\n"
               "and the 6th time, \\[ x = \\mathrm{wrng} \\] Fran\\c{c}ois's.\n\\end{document}\nafter");
  EXPECT_EQ(words, (std::vector<std::string>{"The", "step", "is", "smal", "in", "Mathématiques", "since", "the", "and", "the", "time", "François's"}));
  // From where the record says the prose starts; a start the source does not print is bad input.
  EXPECT_EQ(words_of("Title words. Abstract Here it starts.", "Abstract"), (std::vector<std::string>{"Abstract", "Here", "it", "starts"}));
  EXPECT_THROW(words_of("No such start.", "Abstract"), std::invalid_argument);
}

// A finding's words show the math as a reader writes it: Greek names as letters, powers as
// superscripts, square roots as √, products by juxtaposition; a word that only starts with a Greek
// name, and TeX between $...$, are left as they are.
TEST(ReadableMath, TheCanonicalTextsOperatorsAsAReaderWritesThem) {
  EXPECT_EQ(readable_math("h^2*omega^2-8"), "h²ω²-8");
  EXPECT_EQ(readable_math("h*omega in (0, 2 sqrt(2)) and (2 sqrt(3), 2 sqrt(6))"), "hω in (0, 2√2) and (2√3, 2√6)");
  EXPECT_EQ(readable_math("12*3 between the betas"), "12·3 between the betas");
  EXPECT_EQ(readable_math("at $\\omega^{2} h$ the omega"), "at $\\omega^{2} h$ the ω");
}

const std::string prose_declarations = R"(
[document]
title = "Prose under test"
[symbols]
real = ['x']
)";

/// The verdict of a record on a document that declares only x: the prose's shapes read no formula.
class ProseOfADocument : public test::RecordOnADocument {
 protected:
  claim_result run(const std::string& shape, const std::string& with, const std::string& text) {
    return run_declared(prose_declarations, shape, with, text);
  }
};

TEST_F(ProseOfADocument, SpellingFindsEachSlipOnceWithTheDictionarysSuggestion) {
  const std::string text = "\\title{Prose under test}\nThe scheme is symplectic and inconditionally stable; the scheme is mutiple times "
                           "inconditionally stable, as $x_{mutiple}$ says \\cite{Smth99}.\n";
  const claim_result slips = run("spelling", "{ vocabulary = ['symplectic'] }", text);
  ASSERT_EQ(slips.outcome, verdict::erratum) << slips.note << slips.evidence.dump();
  ASSERT_EQ(slips.amendments.size(), 2u) << slips.evidence.dump();
  EXPECT_EQ(slips.amendments[0].printed, "inconditionally");
  EXPECT_EQ(slips.amendments[0].should_be, "unconditionally");
  EXPECT_EQ(slips.amendments[1].printed, "mutiple");
  EXPECT_EQ(slips.amendments[1].should_be, "multiple");
  // The word of art, without the vocabulary, is a slip too: the vocabulary is what keeps it out.
  EXPECT_EQ(run("spelling", "{ from = 'Prose' }", text).amendments.size(), 3u);
  const claim_result clean = run("spelling", "{ vocabulary = ['symplectic'] }", "\\title{Prose under test}\nThe scheme is symplectic and stable.\n");
  EXPECT_EQ(clean.outcome, verdict::holds) << clean.evidence.dump();
}

// A phrase of the record's takes over a misspelled word where it is printed, and a misuse of real
// words (which the dictionary passes) is a slip only where the prose prints its phrase.
TEST_F(ProseOfADocument, SpellingReadsTheRecordsPhrases) {
  const std::string text = "\\title{Prose under test}\nThe map is explicited here. To explicit the map is easy; it is explicited at the relation "
                           "$(1)$, and it can we written.\n";
  const std::string with = "{ suggestions = ['explicited: made explicit', 'explicited at the relation: given explicitly by relation'], "
                           "misused = ['To explicit: To make explicit', 'can we written: can be written', 'and explicit: and make explicit'] }";
  const claim_result slips = run("spelling", with, text);
  ASSERT_EQ(slips.outcome, verdict::erratum) << slips.evidence.dump();
  ASSERT_EQ(slips.amendments.size(), 4u) << slips.evidence.dump();
  EXPECT_EQ(slips.amendments[0].printed, "explicited");
  EXPECT_EQ(slips.amendments[0].should_be, "made explicit");
  EXPECT_EQ(slips.amendments[1].printed, "explicited at the relation");
  EXPECT_EQ(slips.amendments[1].should_be, "given explicitly by relation");
  EXPECT_EQ(slips.amendments[2].printed, "To explicit");
  EXPECT_EQ(slips.amendments[3].printed, "can we written");
  EXPECT_EQ(slips.evidence.at("prose").at("misused").size(), 2u) << "'and explicit' is not printed: no slip";
  // Without the phrases the dictionary passes the real words, and every "explicited" takes one replacement.
  const claim_result words_only = run("spelling", "{ suggestions = ['explicited: made explicit'] }", text);
  ASSERT_EQ(words_only.amendments.size(), 1u) << words_only.evidence.dump();
  EXPECT_EQ(words_only.amendments[0].where, "line 2") << "two on one line: the line once";
  // The misuse corrected, the words as English uses them: it holds.
  const claim_result clean = run("spelling", with, "\\title{Prose under test}\nTo make explicit the map, it can be written.\n");
  EXPECT_EQ(clean.outcome, verdict::holds) << clean.evidence.dump();
  // A phrase without its replacement is refused when the claims file is read.
  EXPECT_THROW(run("spelling", "{ misused = ['To explicit'] }", text), claims_file_error);
}

TEST_F(ProseOfADocument, CitationsWithoutTheirEntriesAreUnverifiableOnce) {
  const std::string cited = "\\title{Prose under test}\nAs shown \\cite{Ar74,Ne59} and again \\cite{Ar74}.\n";
  const claim_result missing = run("citations", "{}", cited);
  EXPECT_EQ(missing.outcome, verdict::unverifiable) << missing.note;
  EXPECT_EQ(missing.evidence.at("citations").at("unresolved"), (json{"Ar74", "Ne59"}));
  // One entry missing is enough; both there, the citations resolve.
  EXPECT_EQ(run("citations", "{}", cited + "\\begin{thebibliography}{9}\\bibitem{Ar74} Arnold.\\end{thebibliography}\n").outcome, verdict::unverifiable);
  EXPECT_EQ(run("citations", "{}", cited + "\\begin{thebibliography}{9}\\bibitem{Ar74} Arnold. \\bibitem{Ne59} Newmark.\\end{thebibliography}\n").outcome,
            verdict::holds);
}

// "A stability condition is naturally emerging" after a formula with a pole: the pole bounds
// stability only when the scheme's stable set is the band it ends. Leapfrog (sv) is stable on
// (0, 2) alone: a pole at 2 ends it; the node's pole at 2 sqrt(2) does not, though the condition
// 0 < omega h < 2 sqrt(2) is that pole (a check of the pole alone would pass it); a bound that is
// not the pole is an erratum.
TEST_F(ShapesOnADocument, EmergingCondition) {
  const std::string text = shape_document + "\\begin{equation}\\label{poletwo} y = \\frac{1}{1 - \\frac{\\om^2 h^2}{4}} \\end{equation}\n"
                                            "A stability condition is naturally emerging: see.\n";
  const auto judge = [&](const std::string& formula, const std::string& condition, const std::string& scheme) {
    return run("emerging-condition", "{ formula = \"" + formula + "\", condition = '" + condition + "', scheme = \"" + scheme +
                                         R"(:lhs", sequence = ['q_{j-1}', 'q_j', 'q_{j+1}'], variable = '$\omega h$', sentence = 'A stability condition is {emerges}:' })",
               text);
  };
  const claim_result holds = judge("poletwo", "inline:Stable for", "sv");
  EXPECT_EQ(holds.outcome, verdict::holds) << holds.note << holds.evidence.dump();
  const claim_result gap = judge("midnode", "inline:Also stable for", "sv");
  EXPECT_EQ(gap.outcome, verdict::erratum) << gap.note;
  EXPECT_NE(gap.note.find("not the end of the stable band"), std::string::npos) << gap.note;
  ASSERT_EQ(gap.amendments.size(), 1u);
  EXPECT_EQ(gap.amendments[0].printed, "naturally emerging (from the pole of midnode)");
  // Stable for every step (average): a pole bounds nothing.
  EXPECT_EQ(judge("poletwo", "inline:Stable for", "average").outcome, verdict::erratum);
  const claim_result not_the_pole = judge("midnode", "inline:Stable for", "sv");
  EXPECT_EQ(not_the_pole.outcome, verdict::erratum);
  EXPECT_NE(not_the_pole.note.find("is not where (midnode) has its first pole"), std::string::npos) << not_the_pole.note;
  // A scheme read as 0 (its last side, not its left one) is no three-term scheme: undecided, not a fault.
  EXPECT_EQ(run("emerging-condition", R"({ formula = "poletwo", condition = 'inline:Stable for', scheme = "sv", sequence = ['q_{j-1}', 'q_j', 'q_{j+1}'], )"
                                      R"(variable = '$\omega h$', sentence = 'A stability condition is {emerges}:' })",
                text)
                .outcome,
            verdict::undecided);
}

// Leapfrog's map (map, in (q, p)) is the 2-stage Lobatto IIIA-IIIB pair's on the oscillator: a text
// that presents it as new without naming it holds, with a naming remark (a known method left
// unnamed is no falsehood: the policy); naming it, no remark; another map (or another tableau) is not
// that method, and nothing is remarked.
TEST_F(ShapesOnADocument, KnownMethod) {
  const std::string presented = shape_document + "We propose a new integrator for the time integration of oscillators.\n";
  const auto judge = [&](const std::string& map, const std::string& tableau_position, const std::string& text) {
    return run("known-method", "{ map = \"" + map + "\", state = ['q', 'p'], position = ['q'], step = ['h'], frequency = '$\\omega$', mass = '$m$', "
                                                    "tableau_position = '" + tableau_position + R"(', )" +
                                   R"(tableau_momentum = '$\begin{pmatrix} \frac{1}{2} & 0 \\ \frac{1}{2} & 0 \end{pmatrix}$', )"
                                   R"(weights = '$\begin{pmatrix} \frac{1}{2} & \frac{1}{2} \end{pmatrix}$', method = "the 2-stage Lobatto IIIA-IIIB pair", )"
                                   R"(names = ["Lobatto", "Verlet"], sentence = 'We propose a {novelty} for the time integration of' })",
               text);
  };
  const std::string lobatto_a = R"($\begin{pmatrix} 0 & 0 \\ \frac{1}{2} & \frac{1}{2} \end{pmatrix}$)";
  const claim_result unnamed = judge("map", lobatto_a, presented);
  EXPECT_EQ(unnamed.outcome, verdict::holds) << unnamed.note << unnamed.evidence.dump();
  EXPECT_EQ(unnamed.remark_kind, finding::naming);
  EXPECT_NE(unnamed.remark.find("Known prior work, never named: the method is the 2-stage Lobatto IIIA-IIIB pair. Proved here on this problem "
                                 "only: the printed map (map) is that method's on q'' = -omega^2 q, entry by entry. The text never names it"),
            std::string::npos)
      << unnamed.remark;
  ASSERT_EQ(unnamed.amendments.size(), 1u);
  EXPECT_EQ(unnamed.amendments[0].printed, "new integrator");
  EXPECT_FALSE(unnamed.certificate.empty()) << "the maps' equality certified entry by entry";
  const claim_result named = judge("map", lobatto_a, presented + "It is the Verlet scheme.\n");
  EXPECT_EQ(named.outcome, verdict::holds);
  EXPECT_TRUE(named.remark.empty()) << named.remark;
  // Psi's (2,1) entry lacks its factor: not the pair's map, nothing to name.
  const claim_result other = judge("mapwrong", lobatto_a, presented);
  EXPECT_EQ(other.outcome, verdict::holds);
  EXPECT_TRUE(other.remark.empty()) << other.remark;
  // Lobatto IIIB's tableau for q too: another method, another map.
  EXPECT_TRUE(judge("map", R"($\begin{pmatrix} \frac{1}{2} & 0 \\ \frac{1}{2} & 0 \end{pmatrix}$)", presented).remark.empty());
}

}  // namespace
}  // namespace simpson::verify

// The paper as printed: its formulas are read from the LaTeX source and proved against the derived
// ones in GiNaC; a coefficient changed in the text changes the matching verdict.

#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/enclosure_decision.hpp>
#include <simpson/verify/formula_reference.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/paper_provenance.hpp>
#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/printed_checks.hpp>
#include <simpson/verify/run.hpp>

#include "altered_paper.hpp"
#include "check_registry.hpp"

#include <gtest/gtest.h>

namespace simpson::verify {
namespace {

/// The embedded text with `from` replaced by `to` in the display after `\label{label}` (or after the
/// anchor): comments keep an older Φ₃, so the replacement is made where the reader looks.
verdict verdict_of(const std::string& id, const paper_reading& paper) {
  const run_context ctx{{precision::parse("double"), precision::parse("rational")}, 20230830, 2, &paper};
  return check_claim(paper_book().find(id), ctx).outcome;
}

TEST(PaperReading, EveryFormulaOfTheEmbeddedPaperParsesAndKeepsItsVerdict) {
  const paper_reading paper = read_paper(embedded_paper());
  EXPECT_EQ(paper.formulas.size(), printed_formula_locations().size());
  std::size_t read = 0;
  for (const claim& c : paper_book().claims) {
    if (!reads_printed_formula(c)) continue;
    ++read;
    const claim_result r = check_claim(c, run_context{{precision::parse("double"), precision::parse("rational")}, 20230830, 2, &paper});
    EXPECT_EQ(r.outcome, c.expected) << c.id << ": " << r.note;
    EXPECT_FALSE(r.printed.is_null()) << c.id;
    if (std::holds_alternative<shape_decider>(c.decided_by)) {
      // A proof shape: both kernels decided on the printed formula. A claim that holds, each proved
      // it; an erratum's identity each found false ("fails: lhs − rhs = ..."), or each proved the
      // facts the erratum rests on ("holds: 2 expansions differ ..."); never "not applicable".
      for (const char* kernel : {"own", "ginac"}) {
        const std::string said = r.evidence.at("exact")[kernel].get<std::string>();
        const bool decided = said.rfind("holds", 0) == 0 || (c.expected != verdict::holds && said.rfind("fails", 0) == 0);
        EXPECT_TRUE(decided) << c.id << " " << kernel << ": " << said;
      }
    } else {
      EXPECT_TRUE(r.evidence.at("kernels").at("ginac").at("derived_holds").get<bool>()) << c.id;
    }
  }
  EXPECT_EQ(read, printed_formula_claim_count(paper_book().claims));
  EXPECT_GE(read, 30u);  // every claim whose statement is a formula
  for (const char* id : {"phi3-det", "discriminant-factorization", "hd-invariance", "truncation-1440", "gamma-system",
                         "gamma-determinant", "taylor-display", "classical-action-range", "simpson-action-range",
                         "derivation-phi3", "lh-dqm", "internal-equation", "simpson-lagrangian", "classical-euler-lagrange"}) {
    EXPECT_TRUE(reads_printed_formula(paper_book().find(id))) << id;
  }
  EXPECT_EQ(paper.at("Phi3").source.line, 488);
}

TEST(PaperReading, DisplaysSplitIntoTheirEquations) {
  const paper_reading paper = read_paper(embedded_paper());
  const tex_document document = read_document(embedded_paper());
  const tex_declarations& declared = paper_book().declarations->reading;
  // Two equations separated by "\,,\,\," and an array's rows, the spacing row dropped.
  const referenced_formula gear = read_reference(document, declared, "derivees-gear#2");
  EXPECT_EQ(gear.tex.find("g_r"), 0u) << gear.tex;
  EXPECT_NE(read_reference(document, declared, "after:at the precise points#2").tex.find("q_{j-1}"), std::string::npos);
  EXPECT_EQ(canonical_text(paper.at("stabilite").sides.back()), "2*sqrt(2)");
  // The printed misprint stays visible in the parsed side.
  EXPECT_NE(canonical_text(read_reference(document, declared, "after:at the precise points").value).find("d^6q/dt^5"), std::string::npos);
  EXPECT_TRUE(is_sum(read_reference(document, declared, "after:can be defined according to").value));
}

struct alteration {
  const char* where;
  const char* from;
  const char* to;
  std::vector<std::string> claims;  // each must stop holding
};

TEST(PaperReading, AChangedCoefficientInTheTextChangesTheVerdict) {
  const std::vector<alteration> alterations{
      {"\\label{Phi3}", "{11\\over24}", "{11\\over23}", {"phi3-elimination", "phi3-det", "hd-invariance"}},
      {"can be factorized", "\\over576}", "\\over575}", {"discriminant-factorization"}},
      {"\\label{hamiltonien-discret}", "\\over12} \\Big)", "\\over13} \\Big)", {"hd-invariance", "hd-proportional"}},
      // Phi_3's (2,1) entry is Q_c's gamma (the entries of the printed generic Phi): its 1 - x/8 made
      // 1 - x/9 moves Q_c's p^2 term alone.
      {"\\label{Phi3}", "\\over8}}\\big)", "\\over9}}\\big)", {"hd-proportional", "hd-invariance", "phi3-det"}},
      {"\\label{qm-oscillateur-harmonique}", "{{q_\\ell + q_r}\\over2}", "{{q_\\ell + q_r}\\over3}", {"qm-harmonic"}},
      {"\\label{Lagrangien-reduit}", "{{22-h^2", "{{21-h^2", {"reduced-lagrangian"}},
      {"We observe that $ \\, g_r", "-2 \\,  q_m", "-3 \\,  q_m", {"gr-minus-gl"}},
      {"{{\\partial L_h}\\over{\\partial q_m}} =  {{h}", "{{8\\, m}\\over{h}} \\,  g_\\ell", "{{7\\, m}\\over{h}} \\,  g_\\ell", {"lh-dqm"}},
      // V'(q_m) put in as printed: a q_m that does not solve the harmonic internal equation.
      {"\\label{oscillateur harmonique}", "{1\\over2} \\, m", "{1\\over3} \\, m", {"qm-harmonic", "reduced-lagrangian"}},
      {"one obtains without difficulty", "{1\\over1440}", "{1\\over1441}", {"truncation-1440"}},
      {"one obtains without difficulty", "h^4", "h^3", {"truncation-1440"}},
      // ω⁴ → ω⁶ in p_r: invisible once m = ω = 1, caught with every symbol free.
      {"\\label{moment-ordre-3}", "\\omega^4}\\over48}", "\\omega^6}\\over48}", {"momentum-order-3"}},
      {"\\label{derivees-gear}", "-3 \\, q_\\ell", "-2 \\, q_\\ell", {"gear-derivatives"}},
      {"\\label{LLhh}", "4 \\, V(q_m)", "3 \\, V(q_m)", {"simpson-lagrangian"}},
      {"\\label{lagrangien-discret}", "{{m\\,h}\\over2}", "{{m\\,h}\\over3}", {"classical-euler-lagrange"}},
      {"\\label{schema-ordre-deux}", "{1\\over2} \\, \\Big[", "{1\\over3} \\, \\Big[", {"classical-euler-lagrange"}},
      {"\\label{equation-milieu-intervalle}", "{{4}\\over{h^2}}", "{{3}\\over{h^2}}", {"internal-equation"}},
      // The truncation error and its order are the printed scheme's (the paper: "the order of
      // truncation of the scheme (schema-ordre-3)"), so a misprinted scheme takes them along.
      {"\\label{schema-ordre-3}", "22 \\, q_j", "21 \\, q_j", {"scheme-order-3", "truncation-1440", "fourth-order-truncation"}},
      {"\\label{matrice-symplectique-ordre-2}", "- m \\, \\omega^2 \\, h", "- m \\, \\omega^2 \\, h^2", {"newmark-matrix", "newmark-det"}},
      // The band every "under the stability condition" judges is read: 2 sqrt(3) covers the unstable gap
      // (8, 12), where Delta > 0 and the roots are real.
      {"\\label{stabilite}", "2 \\, \\sqrt{2}", "2 \\, \\sqrt{3}", {"stability-condition", "discriminant-negative", "roots-product-one"}},
      // The characteristic polynomial's printed coefficients, each against the scheme: a (whose value
      // also sets the scale the unprinted c is solved with), and b.
      {"with $\\, a = 1", "\\over24}", "\\over12}", {"characteristic-equation"}},
      {"b = -{1\\over24}", "48 - 22", "48 - 21", {"characteristic-equation"}},
      {"We have also", "4 \\, \\theta - 3", "4 \\, \\theta - 2", {"interpolant-derivative"}},
      {"\\label{fonctions-de-base}", "4 \\, \\theta", "3 \\, \\theta", {"interpolant-nodal"}},
      // The change of variable t = h theta is read: t = 2 h theta moves every node but 0.
      {"With $ \\, t = h", "t = h", "t = 2 \\, h", {"interpolant-nodal", "interpolant-derivative", "gear-derivatives", "centred-derivative"}},
      {"Then $ \\, q(0)", "q({{h}\\over2}) =  q_m", "q({{h}\\over2}) =  q_r", {"interpolant-nodal"}},
      // A middle side of a chain: g_m = dq/dt(h/2) = (g_l + g_r)/2 = ..., its 1/2 made 1/3.
      {"\\label{derivee-centree}", "{1\\over2} \\, (g_\\ell", "{1\\over3} \\, (g_\\ell", {"centred-derivative"}},
      // The rules are read as printed: a midpoint at 1/3 is exact for constants only; a Simpson
      // weight 3 for 4 is not even that. And the stated degree is read from the words.
      {"method studied previously", "\\psi \\big( {1\\over2} \\big)", "\\psi \\big( {1\\over3} \\big)", {"midpoint-exactness"}},
      {"\\label{simpson}", "4 \\, \\psi", "3 \\, \\psi", {"simpson-exactness", "simpson-lagrangian"}},
      // L_h is the printed rule applied to the printed action integral: its kinetic m/2 made m/3.
      {"L_h (q_\\ell ,\\, q_m ,\\, q_r) \\simeq", "{m\\over2}", "{m\\over3}", {"simpson-lagrangian"}},
      {"is accurate up to polynomials", "degree three", "degree two", {"simpson-exactness"}},
      // Consistency is judged against the printed differential equations: 2 m q'' + V' is not the
      // scheme's limit, nor is dq/dt = p/(2m).
      {"\\label{oscillateur-nonlineaire}", "m \\, {{\\dd^2 q}", "2 \\, m \\, {{\\dd^2 q}", {"classical-consistency"}},
      {"first order Hamilton version", "{{p}\\over{m}}", "{{p}\\over{2 \\, m}}", {"hamilton-consistency"}},
      {"It is easy to verify that when", "is linearly stable", "is linearly unstable", {"newmark-unconditional-stability"}},
      {"We have put in evidence", "a second order", "a fourth order", {"internal-equation-second-order"}},
      {"Due to the relations", "-{{4}\\over{h}}", "{{4}\\over{h}}", {"gear-partials"}},
      {"a conserved quadratic form", "\\gamma \\, p^2", "\\delta \\, p^2", {"conserved-form", "hd-proportional"}},
  };
  for (const alteration& a : alterations) {
    const paper_reading paper = read_paper(altered(a.where, a.from, a.to));
    for (const std::string& id : a.claims) {
      const verdict v = verdict_of(id, paper);
      EXPECT_TRUE(v == verdict::erratum || v == verdict::fails) << a.where << ": " << id << " still " << to_string(v);
    }
  }
}

// A narrower printed band, 0 < omega h < 2: no longer the stability condition, but the sentences that
// judge the band (all factors negative, Delta < 0, complex roots, stable) still hold on it, and their
// evidence names the band read.
TEST(PaperReading, TheStabilityBandIsReadFromTheDisplay) {
  const paper_reading paper = read_paper(altered("\\label{stabilite}", "2 \\, \\sqrt{2}", "2"));
  EXPECT_NE(verdict_of("stability-condition", paper), verdict::holds);
  EXPECT_EQ(verdict_of("discriminant-negative", paper), verdict::holds);  // with its wording remark: the prefactor is positive, as on (0, 8)
  EXPECT_EQ(verdict_of("roots-product-one", paper), verdict::holds);
  const run_context ctx{{precision::parse("double")}, 20230830, 2, &paper};
  const claim_result r = check_claim(paper_book().find("discriminant-negative"), ctx);
  EXPECT_EQ(r.evidence.at("exact").at("statement"), "the factors of (the display after 'can be factorized') on 0 < h*omega < 2") << r.evidence.at("exact").dump();
  // Printed as 0 < omega h < pi: no rational band, so the signs on it are not decided (our kernel
  // compares ends exactly).
  const paper_reading irrational = read_paper(altered("\\label{stabilite}", "2 \\, \\sqrt{2}", "\\pi"));
  EXPECT_EQ(verdict_of("discriminant-negative", irrational), verdict::undecided);
  EXPECT_EQ(verdict_of("roots-product-one", irrational), verdict::undecided);
}

TEST(PaperReading, AnErratumOfAFormulaIsCorrectedByTheDerivedOne) {
  const paper_reading paper = read_paper(altered("\\label{qm-oscillateur-harmonique}", "{{q_\\ell + q_r}\\over2}", "{{q_\\ell + q_r}\\over3}"));
  const run_context ctx{{precision::parse("double")}, 20230830, 2, &paper};
  const claim_result r = check_claim(paper_book().find("qm-harmonic"), ctx);
  EXPECT_EQ(r.outcome, verdict::erratum);
  EXPECT_NE(r.correction.find("as derived"), std::string::npos) << r.correction;
  EXPECT_EQ(r.printed["formulas"][0]["label"], "label qm-oscillateur-harmonique");
}

/// The embedded text with the errata corrected as the ledger derives them.
paper_source corrected_copy() {
  paper_source p = embedded_paper();
  const auto replace_after = [&p](const std::string& after, const std::string& from, const std::string& to, int times) {
    std::size_t at = p.text.find(after);
    for (int k = 0; k < times; ++k) {
      at = p.text.find(from, at);
      ASSERT_NE(at, std::string::npos) << from;
      replace_text(p, at, from.size(), to);
    }
  };
  replace_after("the following homogeneous linear system", "{{\\gamma^2-1}\\over2}", "{{\\delta^2-1}\\over2}", 1);
  replace_after("{\\rm det} \\, \\Gamma =", "\\Gamma =", "\\Gamma = {1\\over4} \\,", 1);
  replace_after("at the precise points", "{{\\dd^6 q}\\over{\\dd t^5}}", "{{\\dd^6 q}\\over{\\dd t^6}}", 2);
  replace_after("can be defined according to", "\\sum_{j=1}", "\\sum_{j=0}", 1);
  replace_after("\\label{SSdd}", "\\sum_{j=1}", "\\sum_{j=0}", 1);
  p.origin = "corrected copy";
  return p;
}

TEST(PaperReading, ACopyWithTheErrataCorrectedMakesThemHold) {
  const paper_reading paper = read_paper(corrected_copy());
  for (const char* id : {"gamma-system", "gamma-determinant", "taylor-display", "classical-action-range", "simpson-action-range"}) {
    const claim_result r = check_claim(paper_book().find(id), run_context{{precision::parse("double")}, 20230830, 2, &paper});
    EXPECT_EQ(r.outcome, verdict::holds) << id << ": " << r.note;
    EXPECT_TRUE(r.correction.empty()) << id;
  }
  // The claims that depend on det Gamma still hold with the factor 1/4, and so does the conserved
  // form read from the corrected Gamma.
  EXPECT_EQ(verdict_of("gamma-singular", paper), verdict::holds);
  EXPECT_EQ(verdict_of("conserved-form", paper), verdict::holds);
}

const claim_record& record_of(const std::string& id) {
  for (const claim_record& r : paper_book().records) {
    if (r.id == id) return r;
  }
  throw std::invalid_argument("no record " + id);
}

TEST(PaperReading, KernelsThatDisagreeOnTheDerivedStatementAreItsOwnVerdict) {
  const paper_reading paper = read_paper(embedded_paper());
  claim broken = paper_book().find("derivation-phi3");
  detail::registered_check pretending = *detail::registered_checks().find("derivation-phi3");
  pretending.check = [](const run_context&) {  // our kernel, pretending not to prove the derivation
    detail::decider_evidence e;
    e.own = detail::answer::fails;
    e.if_false = verdict::fails;
    return e;
  };
  broken.check = detail::claim_check_of(detail::bespoke_judge(record_of("derivation-phi3"), pretending, paper_book().declarations), broken.id, broken.statement);
  const claim_result r = check_claim(broken, run_context{{precision::parse("double")}, 20230830, 2, &paper});
  EXPECT_EQ(r.outcome, verdict::kernels_disagree);
  EXPECT_NE(r.note.find("derivation-phi3"), std::string::npos) << r.note;
  EXPECT_EQ(to_string(r.outcome), "kernels-disagree");
}

TEST(PaperReading, AClaimNoEnclosureDecidesIsUndecidedWithItsEnclosureNamed) {
  const paper_reading paper = read_paper(embedded_paper());
  claim wide = paper_book().find("phi3-det");
  wide.check = detail::claim_check_of(
      [](const run_context&) -> detail::decider_evidence {
        throw enclosure_undecided("phi3-det: the residual's enclosure 0 ± 3e-20 decides nothing at 640 digits, the run's budget");
      },
      wide.id, wide.statement);
  const claim_result r = check_claim(wide, run_context{{precision::parse("double")}, 20230830, 2, &paper});
  EXPECT_EQ(r.outcome, verdict::undecided);
  EXPECT_EQ(to_string(r.outcome), "undecided");
  EXPECT_NE(r.evidence.value("undecided", std::string()).find("0 ± 3e-20"), std::string::npos) << r.evidence.dump();
  EXPECT_NE(r.note.find("--enclosure-budget"), std::string::npos) << r.note;
}

TEST(PaperReading, BadSourcesAreNamedWithLabelLineAndToken) {
  paper_source p = embedded_paper();
  replace_text(p, p.text.find("\\label{stabilite}"), 17, "\\label{stability}");
  try {
    read_paper(p);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no \\label{stabilite}"), std::string::npos) << e.what();
  }
  // A label only a shape record reads: named with the record's line and argument, before anything runs.
  paper_source renamed = embedded_paper();
  replace_text(renamed, renamed.text.find("\\label{moment-ordre-3}"), 22, "\\label{moment-order-3}");
  try {
    claim_book book = paper_book();
    check_claims_file_formulas(book, renamed);
    ADD_FAILURE();
  } catch (const claims_file_error& e) {
    EXPECT_NE(std::string(e.what()).find("field 'with.printed': no \\label{moment-ordre-3}"), std::string::npos) << e.what();
  }
  const paper_source q = altered("\\label{Phi3}", "{11\\over24}", "{11\\over24} \\unknowncommand");
  try {
    read_paper(q);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    // The document's own fault: its line (the command's, in the display of label Phi3), not a claims file's.
    EXPECT_NE(what.find("document 'altered copy', label Phi3, line 490: the command \\unknowncommand"), std::string::npos) << what;
    EXPECT_EQ(what.find("claims file"), std::string::npos) << what;
  }
  EXPECT_THROW(load_paper("/no/such/paper.tex"), std::invalid_argument);
}

// GiNaC makes a denominator's leading coefficient positive in its own order of the symbols, which
// follows the order they were made in, so one quotient could print as a/b in one run and (-a)/(-b) in
// another (a report's text then changed between runs). The text's denominator starts with a positive
// term whatever the signs GiNaC chose.
TEST(TexMath, AQuotientPrintsOneWayWhateverTheSignsGiNaCChose) {
  tex_symbols s;
  const GiNaC::ex h = s["h"], w = s["omega"], q = s["q"];
  for (const GiNaC::ex& e : {1 / (1 - h), (q - h) / (w * w * h * h - 8), (h - q) / (8 - w * w * h * h), -q / (h * h - 24 * w)}) {
    const std::string text = canonical_text(e);
    EXPECT_EQ(canonical_text(GiNaC::numer(GiNaC::normal(e)) * -1 / (GiNaC::denom(GiNaC::normal(e)) * -1)), text);
    const std::size_t over = text.find(")/(");
    ASSERT_NE(over, std::string::npos) << text;
    EXPECT_NE(text[over + 3], '-') << text;
  }
  EXPECT_EQ(canonical_text((q - h) / (w * w * h * h - 8)), canonical_text((h - q) / (8 - w * w * h * h)));
}

TEST(TexMath, ReadsWhatThePaperPrints) {
  tex_symbols& s = paper_symbols();
  const tex_document paper = read_document(embedded_paper());
  const tex_declarations& declared = paper_book().declarations->reading;
  const auto read = [&](const std::string& tex) { return read_tex(tex, declared, s, &paper.macros()); };
  const GiNaC::ex h = s["h"], w = s["omega"];
  EXPECT_TRUE((read("{{\\omega^2 \\, h^2}\\over576}") - w * w * h * h / 576).is_zero());
  EXPECT_TRUE((read("h^24") - h * h * 4).is_zero());  // TeX's one-token script
  EXPECT_TRUE((read("\\frac{1}{2} \\big( h + 1 \\big)") - (h + 1) / 2).is_zero());
  EXPECT_TRUE((read("q_\\ell - q_r") - (s["q_l"] - s["q_r"])).is_zero());
  EXPECT_THROW(read("h + \\foo"), tex_error);
  // A derivative with the paper's \dd, with \partial, and with what \dd expands to ({\rm d}, \mathrm{d}):
  // the derivative of V at x each time, not a product of symbols named V and q.
  const GiNaC::symbol t("t");
  const GiNaC::ex v_prime = GiNaC::diff(apply_function("V", {t}), t).subs(t == s["x"]);
  for (const char* tex : {"{{\\dd V}\\over{\\dd q}}(x)", "{{\\partial V}\\over{\\partial q}}(x)", "{{{\\rm d} V}\\over{{\\rm d} q}}(x)",
                          "{{\\mathrm{d} V}\\over{\\mathrm{d} q}}(x)"}) {
    EXPECT_TRUE((read(tex) - v_prime).is_zero()) << tex << ": " << read(tex);
  }
}


// Provenance: the text read names its edition and hash; its citations are unresolved without a
// bibliography, and a \bibitem resolves its key.
TEST(Provenance, TheEditionTheHashAndTheUnresolvedCitationsAreRead) {
  const paper_source paper = embedded_paper();
  const paper_provenance p = read_provenance(paper);
  EXPECT_EQ(p.title, "A variational symplectic scheme based on Simpson's quadrature");
  EXPECT_EQ(p.edition, "Edition 22 June 2024.");
  EXPECT_GT(p.edition_line, 0);
  EXPECT_EQ(p.sha256, paper.sha256);
  EXPECT_FALSE(p.bibliography);
  EXPECT_EQ(p.unresolved.size(), 13u);
  EXPECT_NE(std::find(p.unresolved.begin(), p.unresolved.end(), "KMOW00"), p.unresolved.end());
  paper_source with_bibliography = paper;
  replace_text(with_bibliography, with_bibliography.text.size(), 0, "\\begin{thebibliography}{9}\n\\bibitem{KMOW00} C. Kane et al.\n\\end{thebibliography}\n");
  const paper_provenance resolved = read_provenance(with_bibliography);
  EXPECT_TRUE(resolved.bibliography);
  EXPECT_EQ(resolved.unresolved.size(), 12u);
  EXPECT_EQ(std::find(resolved.unresolved.begin(), resolved.unresolved.end(), "KMOW00"), resolved.unresolved.end());
}

// The attribution a quoted sentence makes: the \cite keys of its whole sentence, before and after the
// quoted words ("Kane et al.}" does not end the sentence); the sentences around it are not its.
TEST(Provenance, TheCitationsOfAQuotedSentenceAreThoseOfItsSentence) {
  const paper_source paper = embedded_paper();
  EXPECT_EQ(citations_in_sentence(paper, 220, "the discrete flow (\\ref{systeme-symplectique-ordre-2}) is symplectic as observed by"),
            (std::vector<std::string>{"SS92"}));
  EXPECT_EQ(citations_in_sentence(paper, 223, "the numerical scheme (\\ref{systeme-symplectique-ordre-2}) is one particular"),
            (std::vector<std::string>{"KMOW00", "Ne59"}));
  EXPECT_TRUE(citations_in_sentence(paper, 226, "the discrete Hamiltonian").empty());
  EXPECT_TRUE(citations_in_sentence(paper, 220, "words the paper does not have").empty());
}

// The earlier Phi_3 the source keeps commented out is read and checked like the live one: its
// (2,1) entry h/(m(1 - omega^2 h^2/8)) makes det Phi_3 != 1, so phi3-det fails on it. Without the
// comment there is no earlier text.
TEST(Provenance, TheEarlierPhi3InTheCommentsIsCheckedAndIsNotSymplectic) {
  const paper_source paper = embedded_paper();
  const std::vector<earlier_display> earlier = commented_displays(paper);
  ASSERT_EQ(earlier.size(), 1u);
  EXPECT_EQ(earlier[0].label, "Phi3");
  EXPECT_NE(earlier[0].tex.find("{{1}\\over{1 - {{\\omega^2   h^2}\\over8}}} \\, {{h}\\over{m}}"), std::string::npos) << earlier[0].tex;
  const paper_reading before = read_paper(with_earlier_display(paper, earlier[0]));
  EXPECT_EQ(verdict_of("phi3-det", before), verdict::fails);
  EXPECT_EQ(verdict_of("phi3-det", read_paper(paper)), verdict::holds);
  paper_source uncommented = paper;
  const std::size_t at = uncommented.raw.find("%\\moneq \\label{Phi3}");
  ASSERT_NE(at, std::string::npos);
  uncommented.raw.replace(at, 1, "%%");  // a remark ("%%"), no longer an earlier display
  EXPECT_TRUE(commented_displays(uncommented).empty());
}

}  // namespace
}  // namespace simpson::verify

// Checking many Coq files with few coqc processes (verify/base/coq_batch.hpp).

#include <simpson/verify/coq_batch.hpp>

#include <simpson/verify/command.hpp>

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace simpson::verify {
namespace {

const std::string reals = "Require Import Reals Lra.\nOpen Scope R_scope.\n";

coq_document lemma(const std::string& name, const std::string& statement) {
  return {name, reals + "Ltac close := lra.\nLemma same_name : " + statement + ".\nProof. close. Qed.\n"};
}

TEST(CoqBatch, RequiresAreHoistedAndEachFileBecomesAModule) {
  const std::string file = coq_modules_file({lemma("a", "1 < 2"), lemma("b", "2 < 3")});
  // One Require of the libraries, before any module; each module imports them again.
  EXPECT_EQ(file.find("Require Reals Lra."), file.rfind("Require Reals Lra.")) << file;
  EXPECT_LT(file.find("Require Reals Lra."), file.find("Module Cert_a."));
  EXPECT_EQ(file.find("Require Import"), std::string::npos) << file;
  EXPECT_NE(file.find("Module Cert_a.\nImport Reals Lra.\n"), std::string::npos) << file;
  EXPECT_NE(file.find("End Cert_b."), std::string::npos);
  // From … Require Import keeps its prefix.
  const std::string gappa = coq_modules_file({{"g", "From Gappa Require Import Gappa_tactic.\nGoal True. exact I. Qed.\n"}});
  EXPECT_NE(gappa.find("From Gappa Require Gappa_tactic."), std::string::npos) << gappa;
  EXPECT_NE(gappa.find("Import Gappa_tactic."), std::string::npos) << gappa;
}

TEST(CoqBatch, NamesMustBeIdentifiersAndDistinct) {
  EXPECT_THROW(coq_modules_file({{"phi3-det", "Goal True. exact I. Qed."}}), std::invalid_argument);
  EXPECT_THROW(coq_modules_file({lemma("a", "1 < 2"), lemma("a", "2 < 3")}), std::invalid_argument);
}

TEST(CoqBatch, OneProcessAcceptsFilesThatShareNamesAndNamesTheRejectedOne) {
  if (!program_on_path("coqc")) GTEST_SKIP() << "coqc not found: nothing checked";
  // The same lemma and tactic names in every file: concatenated without modules, coqc would reject
  // the second file's lemma as already defined.
  const std::vector<coq_document> documents{lemma("first", "1 < 2"), lemma("wrong", "3 < 2"), lemma("third", "0 < 1"),
                                            lemma("fourth", "2 < 5")};
  for (const unsigned jobs : {1u, 2u}) {
    const std::vector<coq_verdict> verdicts = check_with_coqc(documents, jobs);
    ASSERT_EQ(verdicts.size(), 4u);
    EXPECT_TRUE(verdicts[0].accepted) << verdicts[0].message;
    EXPECT_FALSE(verdicts[1].accepted);
    EXPECT_NE(verdicts[1].message.find("Error"), std::string::npos) << verdicts[1].message;
    EXPECT_TRUE(verdicts[2].accepted) << verdicts[2].message;
    EXPECT_TRUE(verdicts[3].accepted) << verdicts[3].message;
  }
  EXPECT_TRUE(check_with_coqc({}, 2).empty());
}

}  // namespace
}  // namespace simpson::verify

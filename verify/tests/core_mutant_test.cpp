// Our core bound to the print, shown by mutation: this test is linked with core_formulas.cpp
// compiled against a core header with one coefficient changed (verify/tests/CMakeLists.txt,
// simpson_core_mutant), so the book's instantiation of that core formula is the mutant's. Every
// record of the paper that binds the mutated function then no longer has its expected verdict, and
// its note names the core formula: the claim that binds the formula to the print catches the
// change itself, not only the experiments downstream.

#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/printed_checks.hpp>

#include <gtest/gtest.h>

#include <string>

#ifndef SIMPSON_MUTATED_FUNCTION
#error "SIMPSON_MUTATED_FUNCTION: the core function the mutated header implements"
#endif

namespace simpson::verify {
namespace {

TEST(CoreMutant, EveryRecordBindingTheMutatedFormulaChangesItsVerdictAndNamesIt) {
  const std::string function = SIMPSON_MUTATED_FUNCTION;
  claim_book book = paper_book();
  const paper_reading reading = read_paper(embedded_paper());
  check_claims_file_formulas(book, reading.source);
  run_context ctx;
  ctx.paper = &reading;
  ctx.book = &book;
  int binding = 0;
  for (const claim_record& r : book.records) {
    bool binds = false;
    for (const core_binding& b : r.core) binds = binds || b.function == function;
    if (!binds) continue;
    ++binding;
    const claim_result result = check_claim(book.find(r.id), ctx);
    EXPECT_NE(result.outcome, book.find(r.id).expected) << r.id << ": the mutant of " << function << " went unnoticed: " << result.note;
    EXPECT_NE(result.note.find("the core's " + function + " is not"), std::string::npos) << r.id << ": " << result.note;
  }
  EXPECT_GT(binding, 0) << "no record of the paper binds " << function;
}

}  // namespace
}  // namespace simpson::verify

#pragma once
// What the paper prints for a claim, taken from the source the run read: the TeX of the formulas
// the claim read from that file (with its line numbers), or, for a claim typed from the prose, the
// ledger's wording. The report's "Printed:" lines and the JUnit messages use this, so that a run
// with --paper quotes the file given, not the embedded text.

#include <simpson/verify/run.hpp>

#include <string>

namespace simpson::verify {

struct printed_statement {
  std::string text;    // the TeX, formulas joined by " ; ", or the typed statement
  std::string source;  // "embedded, line 532" / "paper.tex, lines 488, 490" / "typed from the prose"
  bool read = false;   // formulas read from the paper's source
  bool quoted = false; // prose quoted from the paper's source (both false: typed into the ledger)
};

printed_statement printed_of(const claim_outcome& o);

}  // namespace simpson::verify

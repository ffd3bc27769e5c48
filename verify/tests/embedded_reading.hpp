#pragma once
// The embedded paper read with its book's declarations, once per test process: what a run of the
// paper scene passes to every claim (run_context::paper). A claim is never run without its document.

#include <simpson/verify/ledger.hpp>
#include <simpson/verify/paper_source.hpp>

namespace simpson::verify {

inline const paper_reading& embedded_reading() {
  static const paper_reading reading = read_paper(embedded_paper());
  return reading;
}

}  // namespace simpson::verify

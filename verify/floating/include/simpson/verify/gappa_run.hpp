#pragma once
// Gappa run on a round-off problem (gappa_script.hpp), its bound exported to Coq and checked by
// coqc (Debian's gappa and libcoq-gappa, scripts/install-deps):
//   1. Gappa is asked for enclosures of the two errors and of every intermediate;
//   2. every intermediate must lie below the format's largest finite number (Gappa's formats have
//      no overflow), or the bound is `unproved` with the intermediate that may overflow;
//   3. the bounds found (the larger end of each enclosure) are stated in a second script, proved by
//      Gappa again and exported with gappa -Bcoq;
//   4. coqc checks that Coq proof (Gappa's Coq library).
// A missing gappa gives `skipped` (never a pass); a missing coqc leaves the bound Gappa's alone,
// said so.

#include <simpson/verify/gappa_script.hpp>

#include <string>

namespace simpson::verify {

enum class proof_status { proved, unproved, skipped };

struct roundoff_proof {
  proof_status status = proof_status::skipped;
  std::string reason;          // why unproved or skipped: Gappa's own words, or the intermediate that may overflow
  claimed_bounds bounds;       // when proved: |error in p| ≤ bounds.p, |error in q| ≤ bounds.q
  std::string script;          // the script that states and proves the bounds
  std::string certificate;     // its Coq proof (gappa -Bcoq), when proved
  std::string coq;             // "checked", "rejected: …", or "not checked: coqc not found"
  std::string coq_version;     // coqc's, when checked
};

/// Runs the four steps; with check_with_coqc false the certificate is produced but not checked.
roundoff_proof prove_roundoff(const roundoff_problem& problem, bool check_with_coqc = true);

/// coqc on a Coq file's text (written to a temporary directory as <module>.v): "checked",
/// "rejected: <coqc's first lines>", or "not checked: coqc not found".
std::string coqc_check(const std::string& text, const std::string& module);

/// A number Gappa prints ("-825b-62", "1", "0", "3b2"), exactly; throws std::invalid_argument otherwise.
rational parse_gappa_number(const std::string& text);

}  // namespace simpson::verify

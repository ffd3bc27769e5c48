#pragma once
// Provenance: the text a run checked (title, edition line, SHA-256), the citations it cannot resolve
// (the source carries no bibliography) with the claims whose quoted sentences make them, and the
// earlier text the source keeps in its comments, checked like the live text: every claim of the run
// that reads a display the comments hold an earlier version of is judged again on that version, and
// each verdict that differs is a finding about the earlier text.

#include <simpson/verify/claim.hpp>
#include <simpson/verify/paper_reading.hpp>

namespace simpson::verify {

/// A claim the run checked: its quoted sentences (the claim's "quoted" records), so that a cited
/// sentence names its claim, and its verdict on the live text.
struct checked_claim {
  std::string id;
  json quoted;
  verdict live;
};

/// report.json's "provenance": {title, edition, edition_line, sha256, source, citations{...},
/// earlier_text[...]}. The earlier text is judged for the claims of `checked` only, each against
/// the verdict the run gave it (a claim the run did not ask for is not computed for it); a run
/// without claims leaves it out ("earlier_text_checked" false).
json provenance_json(const paper_reading& paper, const run_context& ctx, const std::vector<checked_claim>& checked);

}  // namespace simpson::verify

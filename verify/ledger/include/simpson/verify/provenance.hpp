#pragma once
// Provenance: the text a run checked (title, edition line, SHA-256), the citations it cannot resolve
// (the source carries no bibliography) with the claims whose quoted sentences make them, and the
// earlier text the source keeps in its comments, checked like the live text: every claim that reads
// a display the comments hold an earlier version of is judged again on that version, and each
// verdict that differs is a finding about the earlier text.

#include <simpson/verify/claim.hpp>
#include <simpson/verify/paper_reading.hpp>

namespace simpson::verify {

/// report.json's "provenance": {title, edition, edition_line, sha256, source, citations{...},
/// earlier_text[...]}. `quoted_by_claim` holds each checked claim's quoted sentences (id -> the
/// claim's "quoted" records), so that a cited sentence names its claim. The earlier text is checked
/// only `with_earlier_text` (a run without claims leaves it out: "earlier_text_checked" false).
json provenance_json(const paper_reading& paper, const run_context& ctx, const std::vector<std::pair<std::string, json>>& quoted_by_claim,
                     bool with_earlier_text = true);

}  // namespace simpson::verify

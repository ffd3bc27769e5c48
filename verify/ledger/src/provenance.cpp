// Provenance: see provenance.hpp.

#include <simpson/verify/provenance.hpp>

#include <simpson/verify/ledger.hpp>
#include <simpson/verify/paper_provenance.hpp>
#include <simpson/verify/printed_checks.hpp>

#include <set>
#include <stdexcept>

namespace simpson::verify {
namespace {

/// The earlier displays of the source's comments, each with the claims that read its label judged on
/// the live text and on the earlier one.
json earlier_text_json(const paper_reading& live, const run_context& ctx) {
  json out = json::array();
  for (const earlier_display& d : commented_displays(live.source)) {
    json entry = {{"label", d.label}, {"line", d.line}, {"tex", folded_space(d.tex)}};
    paper_reading earlier;
    try {
      earlier = read_paper(with_earlier_display(live.source, d));
    } catch (const std::invalid_argument& e) {
      entry["reads"] = false;
      entry["error"] = e.what();
      out.push_back(entry);
      continue;
    }
    entry["reads"] = true;
    json claims = json::array();
    run_context on_live = ctx, on_earlier = ctx;
    on_live.paper = &live;
    on_live.quotes = nullptr;
    on_earlier.paper = &earlier;
    on_earlier.quotes = nullptr;
    for (const std::string& id : claims_reading_formula(d.label)) {
      const claim& c = find_claim(id);
      const claim_result now = check_claim(c, on_live), before = check_claim(c, on_earlier);
      json row = {{"claim", id}, {"live", to_string(now.outcome)}, {"earlier", to_string(before.outcome)},
                  {"differs", now.outcome != before.outcome}};
      if (now.outcome != before.outcome) {
        row["earlier_note"] = before.note;
        if (!before.correction.empty()) row["earlier_correction"] = before.correction;
      }
      claims.push_back(row);
    }
    entry["claims"] = claims;
    out.push_back(entry);
  }
  return out;
}

}  // namespace

json provenance_json(const paper_reading& paper, const run_context& ctx, const std::vector<std::pair<std::string, json>>& quoted_by_claim,
                     bool with_earlier_text) {
  const paper_provenance p = read_provenance(paper.source);
  json uses = json::array();
  for (const citation_use& c : p.citations) uses.push_back({{"key", c.key}, {"line", c.line}});
  // The claims whose quoted sentence cites: their attribution cannot be checked without the bibliography.
  json attributed = json::array();
  const std::set<std::string> unresolved(p.unresolved.begin(), p.unresolved.end());
  for (const auto& [id, quoted] : quoted_by_claim) {
    std::set<std::string> keys;
    for (const json& q : quoted) {
      if (!q.value("found", false)) continue;
      for (const std::string& key : citations_in_sentence(paper.source, q.value("line", 0), q.value("text", ""))) {
        if (unresolved.count(key)) keys.insert(key);
      }
    }
    if (!keys.empty()) attributed.push_back({{"claim", id}, {"keys", std::vector<std::string>(keys.begin(), keys.end())}});
  }
  return {{"source", paper.origin},
          {"title", p.title},
          {"edition", p.edition},
          {"edition_line", p.edition_line},
          {"sha256", p.sha256},
          {"citations", {{"uses", uses},
                         {"bibliography", p.bibliography},
                         {"unresolved", p.unresolved},
                         {"claims_citing_unresolved", attributed}}},
          {"earlier_text_checked", with_earlier_text},
          {"earlier_text", with_earlier_text ? earlier_text_json(paper, ctx) : json::array()}};
}

}  // namespace simpson::verify

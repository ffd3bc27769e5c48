// Provenance: see provenance.hpp.

#include <simpson/verify/provenance.hpp>

#include <simpson/verify/claim_book.hpp>
#include <simpson/verify/paper_provenance.hpp>

#include <algorithm>
#include <set>
#include <stdexcept>

namespace simpson::verify {
namespace {

/// The earlier displays of the source's comments, each with the run's claims that read its label:
/// their verdict on the live text (the run's) and on the earlier one.
json earlier_text_json(const paper_reading& live, const run_context& ctx, const std::vector<checked_claim>& checked) {
  json out = json::array();
  for (const earlier_display& d : commented_displays(live.source)) {
    json entry = {{"label", d.label}, {"line", d.line}, {"tex", folded_space(d.tex)}};
    paper_reading earlier;
    try {
      earlier = read_paper(with_earlier_display(live.source, d), ctx.book->declarations->reading, ctx.book->formulas);
    } catch (const std::invalid_argument& e) {
      entry["reads"] = false;
      entry["error"] = e.what();
      out.push_back(entry);
      continue;
    }
    entry["reads"] = true;
    json claims = json::array();
    run_context on_earlier = ctx;
    on_earlier.paper = &earlier;
    on_earlier.quotes = nullptr;
    for (const std::string& id : claims_reading_formula(*ctx.book, d.label)) {
      const auto it = std::find_if(checked.begin(), checked.end(), [&](const checked_claim& c) { return c.id == id; });
      if (it == checked.end()) continue;
      const verdict now = it->live;
      const claim_result before = check_claim(ctx.book->find(id), on_earlier);
      json row = {{"claim", id}, {"live", to_string(now)}, {"earlier", to_string(before.outcome)},
                  {"differs", now != before.outcome}};
      if (now != before.outcome) {
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

json provenance_json(const paper_reading& paper, const run_context& ctx, const std::vector<checked_claim>& checked) {
  if (ctx.book == nullptr) throw std::logic_error("provenance_json: the run's book is not given");
  const paper_provenance p = read_provenance(paper.source);
  json uses = json::array();
  for (const citation_use& c : p.citations) uses.push_back({{"key", c.key}, {"line", c.line}});
  // The claims whose quoted sentence cites: their attribution cannot be checked without the bibliography.
  json attributed = json::array();
  const std::set<std::string> unresolved(p.unresolved.begin(), p.unresolved.end());
  for (const checked_claim& c : checked) {
    std::set<std::string> keys;
    for (const json& q : c.quoted) {
      if (!q.value("found", false)) continue;
      for (const std::string& key : citations_in_sentence(paper.source, q.value("line", 0), q.value("text", ""))) {
        if (unresolved.count(key)) keys.insert(key);
      }
    }
    if (!keys.empty()) attributed.push_back({{"claim", c.id}, {"keys", std::vector<std::string>(keys.begin(), keys.end())}});
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
          {"earlier_text_checked", !checked.empty()},
          {"earlier_text", checked.empty() ? json::array() : earlier_text_json(paper, ctx, checked)}};
}

}  // namespace simpson::verify

// The referee's summary of report.md: the headline in a referee's words, each distinct finding in
// one line, ordered by consequence, with what follows from it, then the remarks on claims that hold;
// and the provenance of the text checked (its edition, citations and earlier text).
#include "report_parts.hpp"

#include <simpson/verify/markdown_text.hpp>
#include <simpson/verify/report.hpp>
#include <simpson/verify/report_html.hpp>

#include <fmt/format.h>

#include <string>
#include <vector>

namespace simpson::verify {

namespace {

/// Words with $…$ spans of TeX, in Markdown.
std::string words_with_math(const std::string& text) {
  std::string out;
  std::size_t at = 0;
  bool math = false;
  for (std::size_t dollar; (dollar = text.find('$', at)) != std::string::npos; at = dollar + 1, math = !math) {
    const std::string piece = text.substr(at, dollar - at);
    out += math ? markdown_code(piece) : markdown_escaped(piece);
  }
  return out + (math ? markdown_code(text.substr(at)) : markdown_escaped(text.substr(at)));
}

/// One side of an amendment in Markdown: TeX as code (report.html renders it), words as a quote with
/// their $…$ spans as TeX.
std::string amendment_side(const std::string& text, bool tex) {
  return tex ? markdown_code(text) : "“" + words_with_math(text) + "”";
}

/// A finding's one line: "where: printed X, should be Y", the same change at several places said once
/// with its count ("twice: in ...; in ...").
}  // namespace

std::string report_parts::amendments_markdown(const std::vector<amendment>& amendments) {
  std::vector<std::string> lines;
  std::vector<bool> said(amendments.size(), false);
  for (std::size_t k = 0; k < amendments.size(); ++k) {
    if (said[k]) continue;
    const amendment& a = amendments[k];
    std::vector<std::string> places{words_with_math(a.where)};
    for (std::size_t l = k + 1; l < amendments.size(); ++l) {
      const amendment& b = amendments[l];
      if (!said[l] && b.printed == a.printed && b.should_be == a.should_be && b.tex == a.tex) {
        said[l] = true;
        places.push_back(words_with_math(b.where));
      }
    }
    std::string where = places.front();
    for (std::size_t l = 1; l < places.size(); ++l) where += (l + 1 == places.size() ? " and " : ", ") + places[l];
    if (places.size() > 1) where += places.size() == 2 ? " (twice)" : fmt::format(" ({} times)", places.size());
    lines.push_back(fmt::format("{}: printed {}, should be {}", where, amendment_side(a.printed, a.tex), amendment_side(a.should_be, a.tex)));
  }
  return report_parts::join(lines, "; ");
}

/// The first sentence of a note (up to ". "), for a one-line statement.
std::string report_parts::first_sentence(const std::string& text) {
  const std::size_t end = text.find(". ");
  return end == std::string::npos ? text : text.substr(0, end + 1);
}

/// What a referee reads first: the findings about the paper in a referee's words (substantive
/// errors, typographical slips, statements false as worded, remarks), then each distinct finding,
/// ordered by consequence, each in one line with the claims that follow from it, then the remarks on
/// claims that hold.
std::string report_parts::referee_summary_markdown(const run_record& r) {
  const report_parts::verdict_counts c = report_parts::count_verdicts(r);
  if (r.outcomes.empty()) return {};
  const std::string the = r.of_the_paper ? "paper" : "document";
  std::string md = "## Referee's summary\n\n";
  md += "**" + markdown_escaped(findings_headline(r)) + "**";
  if (c.harness + c.beyond > 0) {
    md += fmt::format(" The other {} claims are {} (not counted here).", c.harness + c.beyond,
                      c.beyond == 0    ? fmt::format("the harness's own statements", c.harness)
                      : c.harness == 0 ? fmt::format("claims beyond the {}", the)
                                       : fmt::format("{} beyond the {} and {} the harness's own statements", c.beyond, the, c.harness));
  }
  md += " A finding is false as printed under every reasonable reading, its correction proved; a remark is said of a claim that holds "
        "as an expert reads it (classes: docs/findings.md).\n\n";
  if (c.distinct + c.consequences + c.source_findings == 0 && c.remarks == 0 && c.prose_slips == 0) {
    return md + (r.run_scene.selection.empty()
                     ? fmt::format("No finding: every claim of the {} checked holds as printed.\n\n", the)
                     : fmt::format("No finding among the {} claim{} of this selection; the {}'s other claims were not run.\n\n", r.outcomes.size(),
                                   r.outcomes.size() == 1 ? "" : "s", the));
  }
  // Ordered by consequence: a substantive error that others follow from first, then the other
  // substantive errors, an inconsistency that changes no conclusion, a slip that breaks a derivation, derivation gaps, wording and naming, what
  // cannot be verified, the typographical slips that break nothing, the prose's spelling; the
  // ledger's order within each.
  const auto follows = [&](const claim& k) {
    std::vector<std::string> out;
    for (const claim_outcome& other : r.outcomes) {
      if (cause_of(other) == k.id && (is_finding(other.result.outcome) || !other.result.remark.empty())) {
        out.push_back("`" + other.checked->id + "`" + (is_finding(other.result.outcome) ? "" : " (holds, with a remark)"));
      }
    }
    return out;
  };
  const auto rank = [&](const claim_outcome& o) {
    const bool consequential = !follows(*o.checked).empty();
    const finding kind = report_parts::finding_of(o);
    if (kind == finding::prose) return 8;
    if (o.checked->typographical || o.result.constant_factor) return consequential ? 3 : 7;
    switch (kind) {
      case finding::erratum: return !o.conclusions_standing.empty() ? 2 : consequential ? 0 : 1;
      case finding::derivation_gap: return 4;
      case finding::wording:
      case finding::naming: return 5;
      case finding::unverifiable: return 6;
      default: return 7;
    }
  };
  if (c.distinct + c.source_findings > 0 || c.prose_slips > 0) {
    md += "Findings, ordered by consequence: substantive errors first (those that others follow from before the rest), then inconsistencies that change no "
          "conclusion, slips that break a derivation, derivation gaps, wording and naming, what cannot be verified, typographical and constant-factor slips, and the prose's spelling.\n\n";
  }
  for (int level = 0; level <= 8; ++level) {
    for (const claim_outcome& o : r.outcomes) {
      const claim& k = *o.checked;
      if (k.origin != claim_origin::paper || !is_finding(o.result.outcome) || !cause_of(o).empty() || rank(o) != level) continue;
      const std::vector<std::string> consequences = follows(k);
      const std::string what = !o.result.amendments.empty()   ? amendments_markdown(o.result.amendments)
                               : !o.result.correction.empty() ? markdown_escaped(o.result.correction)
                                                              : markdown_escaped(first_sentence(o.result.note));
      const bool stops = !what.empty() && what.back() == '.';
      const finding kind = report_parts::finding_of(o);
      const std::string label = o.result.reads_whole_text                  ? "a check of the source, " + to_string(kind)
                                : o.checked->typographical                    ? to_string(kind) + ", typographical"
                                : kind == finding::erratum && o.result.constant_factor ? std::string("erratum, a constant factor, zeros unchanged")
                                : kind == finding::erratum && !o.conclusions_standing.empty()
                                    ? "an inconsistency that changes no conclusion (" + report_parts::join(o.conclusions_standing, ", ") + " hold)"
                                : kind == finding::erratum                             ? std::string("substantive error")
                                                           : to_string(kind);
      md += fmt::format("- **`{}`** (§{}, {}): {}{}{}\n", k.id, markdown_escaped(k.section), label, what, stops || consequences.empty() ? "" : ".",
                        consequences.empty() ? "" : fmt::format(" Following from it: {}.", report_parts::join(consequences, ", ")));
    }
  }
  if (c.remarks > 0) {
    md += c.linked_remarks == 0 ? fmt::format("\nRemarks on claims that hold ({}), not findings:\n\n", c.remarks)
                                : fmt::format("\nRemarks on claims that hold ({}, {} of them following the finding or remark of the claim they "
                                              "link to), not findings:\n\n",
                                              c.remarks, c.linked_remarks);
    for (const claim_outcome& o : r.outcomes) {
      if (o.checked->origin != claim_origin::paper || !meaning(o.result.outcome).affirms || o.result.remark.empty()) continue;
      md += fmt::format("- **`{}`** (§{}, {}{}): {}\n", o.checked->id, markdown_escaped(o.checked->section), to_string(o.result.remark_kind),
                        cause_of(o).empty() ? "" : "; linked to `" + cause_of(o) + "`", markdown_escaped(o.result.remark));
    }
  }
  return md + "\n";
}

constexpr const char* earlier_text_heading = "Earlier text in the source's comments";

/// The text checked, as the source prints it; its citations; where its earlier text's verdicts are.
std::string report_parts::provenance_markdown(const run_record& r) {
  const json& p = r.provenance;
  if (!p.is_object()) return {};
  std::string md = fmt::format("Text checked: *{}* ({}), {}, SHA-256 `{}`.", markdown_escaped(p.value("title", "")),
                               markdown_escaped(p.value("source", "")),
                               p.value("edition_line", 0) > 0
                                   ? fmt::format("whose source prints “{}” (line {})", markdown_escaped(p.value("edition", "")), p.value("edition_line", 0))
                                   : std::string("whose source prints no edition line"),
                               p.value("sha256", ""));
  const json& citations = p["citations"];
  const std::size_t uses = citations["uses"].size(), unresolved = citations["unresolved"].size();
  if (unresolved > 0) {
    std::vector<std::string> claims;
    for (const json& c : citations["claims_citing_unresolved"]) claims.push_back("`" + c["claim"].get<std::string>() + "`");
    md += fmt::format(" Its {} citations ({} distinct keys) are unresolved: the source carries {}, so no attribution "
                      "(to {}) can be checked{}.", uses, unresolved, citations["bibliography"].get<bool>() ? "no entry for them" : "no bibliography",
                      report_parts::join(citations["unresolved"].get<std::vector<std::string>>(), ", "),
                      claims.empty() ? std::string() : "; the claims whose quoted sentence cites: " + report_parts::join(claims, ", "));
  }
  md += "\n\n";
  if (p["earlier_text"].is_array() && !p["earlier_text"].empty()) {  // the verdicts on it at the end: no verdict on the paper
    md += fmt::format("Earlier text kept in the source's comments ({} display{}) is checked like the live text: "
                      "[its verdicts](#{}), at the end of this report, judge drafts, not the paper.\n\n",
                      p["earlier_text"].size(), p["earlier_text"].size() == 1 ? "" : "s", heading_slug(earlier_text_heading));
  }
  return md;
}

/// The earlier text the source keeps in its comments, checked like the live text: the last section
/// before the evidence (drafts, not the paper: no verdict of the run).
std::string report_parts::earlier_text_markdown(const run_record& r) {
  const json& p = r.provenance;
  if (!p.is_object() || !p["earlier_text"].is_array() || p["earlier_text"].empty()) return {};
  std::string md = fmt::format("\n## {}\n\nDisplays the source keeps in its comments, checked like the live text: "
                               "drafts the authors set aside, not claims of the paper.\n\n", earlier_text_heading);
  for (const json& e : p["earlier_text"]) {
    md += fmt::format("- ({}) commented out at line {}: ", markdown_escaped(e["label"].get<std::string>()), e["line"].get<int>());
    if (!e["reads"].get<bool>()) {
      md += "does not parse: " + markdown_escaped(e.value("error", "")) + "\n";
      continue;
    }
    std::vector<std::string> rows;
    for (const json& c : e["claims"]) {
      rows.push_back(fmt::format(fmt::runtime(c["differs"].get<bool>() ? "`{}` {} on the live text, **{}** on the earlier one" : "`{}` {} on both"),
                                 c["claim"].get<std::string>(), c["live"].get<std::string>(), c["earlier"].get<std::string>()));
    }
    md += (rows.empty() ? std::string("no claim of this run reads it") : report_parts::join(rows, "; ")) + "\n";
  }
  md += "\n";
  return md;
}

}  // namespace simpson::verify

#include "report_parts.hpp"

#include <simpson/verify/report.hpp>
#include <simpson/verify/report_directory.hpp>

#include <simpson/verify/certify.hpp>
#include <simpson/verify/junit.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/markdown_text.hpp>
#include <simpson/verify/printed_statement.hpp>
#include <simpson/verify/report_html.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace simpson::verify {

namespace {

/// "Numeric recheck decided by interval enclosures …": which enclosure decided the claim, at which
/// digits; empty when the claim has no numeric recheck.
std::string enclosure_markdown(const json& evidence) {
  if (!evidence.contains("numeric") || !evidence["numeric"].is_object()) return "";
  const json& numeric = evidence["numeric"];
  if (!numeric.contains("enclosure")) {
    return numeric.contains("decided_by") ? "Numeric recheck decided by " + markdown_escaped(numeric["decided_by"].get<std::string>()) + ".\n\n" : "";
  }
  const json& e = numeric["enclosure"];
  return fmt::format("Numeric recheck decided by interval enclosures (MPFI, outward rounding from the exact inputs): **{}** at {} "
                     "samples, {} digits (from {}, budget {}); widest: {}.\n\n",
                     e["decision"].get<std::string>(), e["samples"].get<unsigned>(), e["decided_at_digits"].get<unsigned>(),
                     e["first_digits"].get<unsigned>(), e["budget_digits"].get<unsigned>(),
                     markdown_escaped(e["widest_enclosure"].get<std::string>()));
}

/// How many characters of a display's TeX the claims table shows.
constexpr std::size_t said_cut = 140;

/// The paper's own words for a claim, for the claims table: the first sentence it quoted, or the
/// display its record names (else the first it read; its TeX, cut), with the line; a typed claim's
/// record statement.
std::string what_the_paper_says(const claim_outcome& o) {
  if (!o.result.quoted.empty() && o.result.quoted.front().value("found", false)) {
    const json& q = o.result.quoted.front();
    return "“" + markdown_cell(q.value("text", "")) + "” (line " + std::to_string(q.value("line", 0)) + ")";
  }
  if (o.result.printed.is_object() && o.result.printed.contains("formulas") && !o.result.printed["formulas"].empty()) {
    // The display the record names (its `equation`) when the claim read it, else the first read: a
    // claim that compares two displays is about the one its record names.
    const json& formulas = o.result.printed["formulas"];
    const json* named = &formulas.front();
    for (const json& candidate : formulas) {
      if (candidate.value("label", "") == "label " + o.checked->equation) {
        named = &candidate;
        break;
      }
    }
    const json& f = *named;
    std::string tex = f.value("tex", "");
    if (tex.size() > said_cut) {
      std::size_t cut = said_cut;
      while (cut > 0 && (static_cast<unsigned char>(tex[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
      tex = tex.substr(0, cut) + " …";
    }
    std::string cell;  // a | would end the table's cell even inside a code span: GFM takes \| there
    for (const char ch : tex) cell += ch == '|' ? std::string("\\|") : std::string(1, ch);
    return "`" + cell + "` (line " + std::to_string(f.value("line", 0)) + ")";
  }
  return "*" + markdown_cell(o.checked->statement) + "*";
}

}  // namespace

namespace {

/// The claims' Coq certificates in one paragraph: how many exported, how many checked by coqc and in how long.
std::string coq_markdown(const run_record& r) {
  const report_parts::verdict_counts c = report_parts::count_verdicts(r);
  if (r.outcomes.empty()) return "";
  std::string version;
  for (const claim_outcome& o : r.outcomes) {
    const json coq = o.result.evidence.value("coq", json::object());
    if (coq.value("status", "") == "checked") version = coq.value("coq_version", "");
  }
  std::string md = fmt::format(
      "Coq certificates: **{} of {} claims** export one (certificates/*.v, printed from the expressions GiNaC decided: "
      "identities proved by `field` over Coq's reals, signs on a band by `nra` on their factors, and an erratum's "
      "printed identity as its negation at a counterexample point, in `_refuted.v`); **{} checked by coqc{}**{}.\n\n",
      c.coq_exported, r.outcomes.size(), c.coq_checked, version.empty() ? "" : " " + version,
      c.coq_checked ? std::string(" (coqc's time: timing.md)")
                    : std::string(" (these are exported, not checked: run with `--certify`, or `make certify`, to check them)"));
  md += "Each claim's certificate, or why it has none: the section Coq certificates, before the evidence.\n\n";
  return md;
}

/// Each claim's certificate: its file and lemmas, or why there is none.
std::string coq_table_markdown(const run_record& r) {
  if (r.outcomes.empty()) return "";
  std::string md = "\n## Coq certificates\n\n| claim | coq | certificate, or why none |\n|---|---|---|\n";
  for (const claim_outcome& o : r.outcomes) {
    const json coq = o.result.evidence.value("coq", json::object());
    const auto file_text = [](const json& on, const char* what) {
      const std::size_t lemmas = on.value("lemmas", json::array()).size();
      return fmt::format("[{0}]({0}), {1} {2}{3}", on["file"].get<std::string>(), lemmas, what, lemmas == 1 ? "" : "s");
    };
    std::string detail = coq.contains("file") ? file_text(coq, "lemma") : markdown_escaped(coq.value("reason", ""));
    if (coq.contains("refutation")) detail += "; printed statement refuted: " + file_text(coq["refutation"], "negation");
    md += fmt::format("| [{}](#{}) | {} | {} |\n", o.checked->id, heading_slug(o.checked->id), coq.value("status", "not recorded"), detail);
  }
  return md;
}

/// Where a claim sits: its section, and for a claim the text does not make (beyond the paper, or the
/// harness's own) that first, so that a reader scanning a section does not take it for the section's.
std::string place_of(const claim& c, const std::string& mark) {
  if (c.origin == claim_origin::paper || c.section == to_string(c.origin)) return mark + c.section;
  return to_string(c.origin) + ", about " + mark + c.section;
}

/// A sentence a claim quotes: where, the words as printed, and what was parsed from each hole.
std::string quoted_markdown(const json& q) {
  if (!q.value("found", false)) {
    return fmt::format("Quoted from the paper ({}): **not found**; the ledger looks for {}\n\n", markdown_escaped(q["source"].get<std::string>()),
                       markdown_code(q["pattern"].get<std::string>()));
  }
  std::string md = fmt::format("Quoted from the paper ({}, line {}):\n\n> {}\n\n", markdown_escaped(q["source"].get<std::string>()),
                               q["line"].get<int>(), markdown_escaped(q["text"].get<std::string>()));
  for (const auto& [hole, words] : q["words"].items()) {
    const json& parsed = q["parsed"];
    md += fmt::format("- {}: “{}” → {}\n", markdown_escaped(hole), markdown_escaped(words.get<std::string>()),
                      parsed.contains(hole) ? markdown_code(parsed[hole].is_string() ? parsed[hole].get<std::string>() : parsed[hole].dump())
                                            : std::string("not read by the check"));
  }
  return md + "\n";
}

/// An erratum or a failure in report.md: its heading, the verdict line (Markdown, none for an
/// erratum), what the paper prints (the TeX read as code, or the typed wording), the correction and
/// the note where there are, and a link to its evidence.
std::string finding_markdown(const claim_outcome& o, const std::string& verdict_line) {
  const claim& c = *o.checked;
  const printed_statement printed = printed_of(o);
  std::string md = fmt::format("### {} (§{}, {})\n\n", c.id, c.section, markdown_escaped(c.equation));
  if (!verdict_line.empty()) md += "- Verdict: " + verdict_line + "\n";
  md += fmt::format("- Printed ({}): {}\n", markdown_escaped(printed.source),
                    printed.read ? markdown_code(printed.text) : printed.quoted ? "“" + markdown_escaped(printed.text) + "”" : markdown_escaped(printed.text));
  if (!o.result.amendments.empty()) md += "- In one line: " + report_parts::amendments_markdown(o.result.amendments) + "\n";
  if (!o.result.correction.empty()) md += "- Corrected: " + markdown_escaped(o.result.correction) + "\n";
  if (!o.result.note.empty()) md += "- Note: " + markdown_escaped(o.result.note) + "\n";
  return md + fmt::format("- Evidence: [{}](#{})\n\n", c.id, heading_slug(c.id));
}

}  // namespace

std::string report_markdown(const run_record& r) { return report_markdown(r, report_parts::all_plots_drawn(r)); }

namespace {

/// report.md's part on the run: its summary and expectation lines, what the claims read, the Coq
/// certificates, the environment, the seed and precisions, the document's provenance, the verdicts.
std::string run_markdown(const run_record& r) {
  std::string md;
  md += fmt::format("## The run\n\n**{}**\n\n{}\n\n", markdown_escaped(summary_line(r)), markdown_escaped(expectation_line(r)));
  {
    const report_parts::verdict_counts c = report_parts::count_verdicts(r);
    const std::string source = r.of_the_paper ? "the paper" : "the document";
    md += fmt::format("{} of {} claims read their formula from {}'s LaTeX source ({}) and prove it in GiNaC against "
                      "the derived one, beside our own kernel; {} quote the prose sentence they judge from that source{} and parse "
                      "the words that carry the claim from it (a sentence gone, or words that no longer parse, give "
                      "**text-changed**);{} {} {} no words of {} ({}).\n\n",
                      c.machine_read, r.outcomes.size(), source, markdown_escaped(r.paper_origin), c.quoted,
                      c.read_and_quoted ? fmt::format(" ({} of them also read a formula)", c.read_and_quoted) : "",
                      c.whole_text == 0 ? std::string()
                                        : fmt::format(" {} read{} the source's text as a whole (its spelling, its citations);", c.whole_text,
                                                      c.whole_text == 1 ? "s" : ""),
                      c.typed,
                      c.typed == 1 ? "quotes" : "quote", source,
                      r.of_the_paper ? "the harness's own lemmas and findings" : "statements typed in the claims file");
  }
  md += coq_markdown(r);
  md += r.run_scene.timing ? "Run times: [timing.md](timing.md). " : "Not timed (--no-timing). ";
  md += "The tool's version and commit, the machine, the command line and the SHA-256 of the scene and the " +
        std::string(r.of_the_paper ? "paper" : "document") + " are in "
        "report.json (`environment`).\n\n";
  md += fmt::format("Seed {} · {} random samples per numeric recheck and precision · precisions: {} · interval enclosures from "
                    "40 digits, doubled up to {}\n\n", r.run_scene.seed,
                    r.run_scene.samples, report_parts::join(report_parts::precision_names(r.run_scene.precisions), ", "), r.run_scene.enclosure_budget_digits);
  md += report_parts::provenance_markdown(r);
  std::vector<std::string> legend;  // verdict.hpp's table, in its order
  for (const verdict_meaning& m : verdict_meanings) legend.push_back(fmt::format("**{}** ({})", m.name, m.legend));
  md += "Verdicts: " + report_parts::join(legend, ", ") + ".\n\n";

  return md;
}

/// report.md's table of the claims, one row each.
std::string claims_table_markdown(const run_record& r) {
  std::string md;
  {
    const std::string the = r.of_the_paper ? "paper" : "document";
    md += fmt::format("## Claims\n\nStatement: *read* when its formulas are read from the {0}'s source and proved in both kernels "
                      "(our kernel and GiNaC), *quoted* when its prose sentence is quoted from the source and its words parsed, *typed* when "
                      "it quotes nothing of the {0}. The {0} says: the sentence quoted, or the first display read (its TeX, cut at "
                      "{1} characters), with its line; for a typed claim, its record's statement.\n\n"
                      "| id | § | equation | statement | the {0} says | verdict | {2} | methods |\n|---|---|---|---|---|---|---|---|\n",
                      the, said_cut, r.validation ? "to hold" : "expected");
  }
  for (const claim_outcome& o : r.outcomes) {
    const claim& c = *o.checked;
    const std::string verdict_text = "**" + to_string(o.result.outcome) + "**" +
                                     (outcome_as_expected(o) ? "" : r.validation ? " **(does not hold)**" : " **(unexpected)**");
    md += fmt::format("| [{}](#{}) | {} | {} | {} | {} | {} | {} | {} |\n", c.id, heading_slug(c.id), place_of(c, ""), markdown_cell(c.equation),
                      !o.result.printed.is_null() ? "read" : !o.result.quoted.empty() ? "quoted" : "typed", what_the_paper_says(o),
                      verdict_text, to_string(o.expected), report_parts::join(c.methods, ", ") + (o.result.printed.is_null() ? "" : ", GiNaC"));
  }

  return md;
}

/// report.md's errata, unverifiable claims, fixes and failures (the verdict table's rows).
std::string findings_markdown(const run_record& r) {
  std::string md;
  // The claims of one verdict, each with its printed and corrected statements.
  const auto section_of = [&](verdict v) {
    std::string out;
    for (const claim_outcome& o : r.outcomes) {
      if (o.result.outcome == v) out += finding_markdown(o, "");
    }
    return out.empty() ? std::string("None in this run.\n\n") : out;
  };
  md += "\n## Errata\n\n" + section_of(verdict::erratum);
  md += "## Unverifiable\n\nClaims about material the source does not carry (a figure, a reference): no verdict on the words is "
        "possible; what the harness computed beside them is context.\n\n" + section_of(verdict::unverifiable);

  // Fixes, changes and failures as the verdict table judges them (verdict_table.hpp): its row's words.
  const std::vector<verdict_row> rows = verdict_table(r);
  std::string fixes;
  for (std::size_t k = 0; k < r.outcomes.size(); ++k) {
    const claim_outcome& o = r.outcomes[k];
    if (!o.fixed) continue;
    fixes += fmt::format("- **{}** (§{}): recorded as {}, now **holds**{}.\n", o.checked->id, o.checked->section, recorded_as(o),
                         o.fix_accepted ? " (accepted: --accept-fixes)" : ": a change of the paper; the exit code is 1 unless --accept-fixes accepts fixes");
  }
  if (!fixes.empty()) md += "## Fixed\n\nFindings and remarks of the record that the checked text no longer has, its own words or formula changed.\n\n" + fixes + "\n";
  md += "## Failures\n\n";
  bool any_failure = false;
  for (std::size_t k = 0; k < r.outcomes.size(); ++k) {
    const claim_outcome& o = r.outcomes[k];
    const verdict_row& row = rows[k];
    const bool listed = row.state == verdict_row::status::error || row.state == verdict_row::status::expected_failure ||
                        (row.state == verdict_row::status::failed && row.type != "fixed");
    if (!listed) continue;  // fixes are listed above
    any_failure = true;
    const std::string why = row.message + (row.state == verdict_row::status::expected_failure ? " (the exit code is 0)" : " (the exit code is 1)");
    md += finding_markdown(o, "**" + row.verdict + "**, " + markdown_escaped(why));
  }
  for (const section_result& section : r.sections) {
    for (const expectation& e : section.expectations) {
      if (e.holds) continue;
      any_failure = true;
      md += fmt::format("- **expectation {}.{}** failed (the exit code is 1): {} Predicted: {}. Observed: {}.\n\n", section.name, e.key,
                        markdown_escaped(e.statement), markdown_escaped(e.predicted), markdown_escaped(e.observed));
    }
  }
  if (!any_failure) md += "None in this run.\n\n";

  return md;
}

/// report.md's notes on claims that hold, and Φ₃ at the paper's configuration (the paper only).
std::string notes_markdown(const run_record& r) {
  std::string md;
  md += "## Notes on claims that hold\n\n";
  bool any_note = false;
  for (const claim_outcome& o : r.outcomes) {
    if (!meaning(o.result.outcome).affirms || o.result.note.empty()) continue;
    any_note = true;
    md += fmt::format("- **[{}](#{})**: {}\n", o.checked->id, heading_slug(o.checked->id), markdown_escaped(o.result.note));
  }
  if (!any_note) md += "None in this run.\n";
  if (r.paper_configuration.is_object()) {  // none for a document other than the paper
    md += "\n## Φ₃ at the paper's configuration\n\n";
    md += markdown_escaped(r.paper_configuration.value("parameters", "")) + "\n\n";
    md += "| precision | epsilon | α = δ | β | γ | det Φ₃ − 1 | Δ | H_d(Φ₃y) − H_d(y) |\n|---|---|---|---|---|---|---|---|\n";
    for (const json& row : r.paper_configuration["rows"]) {
      md += "|";
      for (const char* key : {"precision", "epsilon", "alpha_equals_delta", "beta", "gamma", "det_minus_one", "discriminant",
                              "hd_change_one_step"}) {
        md += " " + markdown_cell(row[key].get<std::string>()) + " |";
      }
      md += "\n";
    }
  }

  return md;
}

/// report.md's experiments: each section's Markdown, and the plots not drawn.
std::string experiments_markdown(const run_record& r, const plot_outcome& plots) {
  std::string md;
  if (!r.sections.empty()) {
    md += "\n# Experiments\n\n";
    std::vector<std::string> names;
    for (const section_result& section : r.sections) names.push_back(section.name);
    md += "Sections computed for this scene: " + report_parts::join(names, ", ") +
          ". Data files (CSV, .dat) and gnuplot scripts (.gp) are beside this report; each plot is an SVG and a PNG.\n\n";
    for (const section_result& section : r.sections) md += section_markdown(section);
    if (!plots.failures.empty()) {
      md += "**Plots not drawn:** " + report_parts::join(plots.failures, "; ") + "\n\n";
    }
  }

  return md;
}

/// report.md's evidence of one claim: what was read, what each kernel proved, the words quoted, the
/// correction and note, the enclosures and the evidence as JSON.
std::string evidence_markdown(const run_record& r, const claim_outcome& o) {
  std::string md;
  const claim& c = *o.checked;
  md += fmt::format("### {}\n\n{}, {} — **{}** (expected {})\n\n> {}\n\n", c.id, place_of(c, "§"), markdown_escaped(c.equation),
                    to_string(o.result.outcome), to_string(o.expected), markdown_escaped(c.statement));
  if (!o.result.printed.is_null()) {
    md += fmt::format("Read from the paper ({}):\n\n", markdown_escaped(o.result.printed["source"].get<std::string>()));
    for (const json& f : o.result.printed["formulas"]) {
      // A definition a proof shape puts in has no TeX or parse of its own here (its display is listed).
      std::vector<std::string> sides;
      if (f.contains("parsed")) {
        for (const json& side : f["parsed"]) sides.push_back(markdown_code(side.get<std::string>()));
      }
      md += fmt::format("- {} (line {}){}{}\n", markdown_escaped(f["label"].get<std::string>()), f["line"].get<int>(),
                        f.contains("tex") ? ": " + markdown_code(f["tex"].get<std::string>()) : std::string(),
                        sides.empty() ? std::string() : "\n  - parsed: " + report_parts::join(sides, " and "));
    }
    md += "\n";
  }
  if (!o.result.printed.is_null() && o.result.evidence.contains("kernels")) {
    const json& kernels = o.result.evidence["kernels"];
    md += fmt::format("What each kernel proved:\n\n- ours: {} ({})\n- GiNaC, printed side: {}\n- GiNaC, derived side: {}\n\n",
                      kernels["own"]["derived_holds"].get<bool>() ? "the derived statement" : "not the derived statement",
                      markdown_escaped(kernels["own"]["statement"].get<std::string>()),
                      markdown_escaped(kernels["ginac"]["printed"].get<std::string>()),
                      markdown_escaped(kernels["ginac"]["derived"].get<std::string>()));
  }
  // A proof shape's identity: both kernels on the statement as read (shape_support.hpp).
  const json& exact = o.result.evidence.contains("exact") ? o.result.evidence["exact"] : json();
  if (!o.result.printed.is_null() && exact.is_object() && exact.contains("own") && exact.contains("ginac") && exact.contains("statement")) {
    md += fmt::format("What each kernel proved, of {}:\n\n- ours: {}\n- GiNaC: {}\n\n", markdown_escaped(exact["statement"].get<std::string>()),
                      markdown_escaped(exact["own"].get<std::string>()), markdown_escaped(exact["ginac"].get<std::string>()));
  }
  for (const json& q : o.result.quoted) md += quoted_markdown(q);
  if (o.result.printed.is_null() && o.result.quoted.empty()) md += r.of_the_paper ? "Statement typed into the ledger: it quotes no words of the paper.\n\n"
                        : "Statement typed in the claims file: it quotes no words of the document.\n\n";
  if (!o.result.correction.empty()) md += "Corrected: " + markdown_escaped(o.result.correction) + "\n\n";
  if (!o.result.note.empty()) md += "Note: " + markdown_escaped(o.result.note) + "\n\n";
  md += enclosure_markdown(o.result.evidence);
  md += "```json\n" + o.result.evidence.dump(2) + "\n```\n\n";
  return md;
}

}  // namespace

std::string report_markdown(const run_record& r, const plot_outcome& plots) {
  std::string md;
  md += fmt::format("# simpson-verify report: scene `{}`{}\n\n", r.run_scene.name,
                    r.run_scene.selection.empty() ? "" : ": " + r.run_scene.selection);
  if (!r.run_scene.description.empty()) md += markdown_escaped(r.run_scene.description) + "\n\n";
  if (!r.run_scene.selection.empty()) {
    md += fmt::format("**A selection**: {}. This report judges only what was selected; the scene's other claims and sections were "
                      "not run, and nothing here speaks for them.\n\n",
                      markdown_escaped(r.run_scene.selection));
  }
  md += report_parts::referee_summary_markdown(r);
  md += run_markdown(r);
  md += claims_table_markdown(r);
  md += findings_markdown(r);
  md += notes_markdown(r);
  md += experiments_markdown(r, plots);
  md += coq_table_markdown(r);
  md += report_parts::earlier_text_markdown(r);
  md += "\n## Evidence\n\n";
  for (const claim_outcome& o : r.outcomes) md += evidence_markdown(r, o);
  return md;
}

namespace {

/// The sections' files that hold run times (`timing`) or those that do not, in section order.
std::vector<std::string> section_file_names(const run_record& r, const plot_outcome& plots, bool timing) {
  std::vector<std::string> names;
  for (const section_result& section : r.sections) {
    for (const data_file& f : section_files(section)) {
      if (f.timing == timing) names.push_back(f.name);
    }
    for (const plot_spec& plot : section_plots(section)) {
      if (plot.timing != timing) continue;
      names.push_back(plot.name + ".gp");
      if (std::find(plots.drawn.begin(), plots.drawn.end(), plot.name) != plots.drawn.end()) {
        names.push_back(plot.name + ".svg");
        names.push_back(plot.name + ".png");
      }
    }
  }
  return names;
}

}  // namespace

std::vector<std::string> report_file_names(const run_record& r, const plot_outcome& plots) {
  std::vector<std::string> names{"report.json", "report.md", "report.html", "report.junit.xml"};
  for (std::string& name : section_file_names(r, plots, false)) names.push_back(std::move(name));
  for (const claim_outcome& o : r.outcomes) {
    for (const certificate_document& d : certificate_documents(o)) names.push_back(d.file);
  }
  for (std::string& name : katex_file_names()) names.push_back(std::move(name));
  return names;
}

std::vector<std::string> timing_file_names(const run_record& r, const plot_outcome& plots) {
  if (!r.run_scene.timing) return {};
  std::vector<std::string> names{"timing.json", "timing.md", "timing.html"};
  for (std::string& name : section_file_names(r, plots, true)) names.push_back(std::move(name));
  return names;
}

plot_outcome write_report_files(const std::filesystem::path& dir, const run_record& r) {
  return write_report_directory(dir, r.sections, [&](const plot_outcome& plots) {
    report_documents docs{report_json(r, plots), report_markdown(r, plots), "simpson-verify report: scene " + r.run_scene.name,
                          report_junit(r), json(), "", {}};
    for (const claim_outcome& o : r.outcomes) {
      for (const certificate_document& d : certificate_documents(o)) docs.extra_files.emplace_back(d.file, *d.text);
    }
    if (r.run_scene.timing) {
      docs.timing = timing_json(r);
      docs.timing_markdown = timing_markdown(r, plots);
    }
    return docs;
  });
}

}  // namespace simpson::verify

#include "report_parts.hpp"

#include <simpson/verify/claim_reads.hpp>

#include <simpson/verify/report.hpp>
#include <simpson/verify/report_directory.hpp>

#include <simpson/verify/certify.hpp>
#include <simpson/verify/junit.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/markdown_text.hpp>
#include <simpson/verify/printed_statement.hpp>
#include <simpson/verify/report_html.hpp>
#include <simpson/verify/verdict_table.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace simpson::verify {

namespace {

/// The speed figures: the headline claims (their records say `headline = true`) in GiNaC (with the derivation
/// they share) and every claim in both kernels (exact proofs and numeric rechecks together).
struct speed_figures {
  double headline = 0, claims_total = 0;
  std::vector<std::string> headline_ids;
};

speed_figures speed_of(const run_record& r) {
  speed_figures s;
  s.headline = r.ginac_derivation_seconds;
  for (const claim_outcome& o : r.outcomes) {
    s.claims_total += o.seconds;
    const std::string& id = o.checked->id;
    if (!o.result.printed.is_null() && o.checked->headline) {
      s.headline += o.result.printed_seconds;
      s.headline_ids.push_back(id);
    }
  }
  return s;
}

}  // namespace

plot_outcome report_parts::all_plots_drawn(const run_record& r) {
  plot_outcome p;
  for (const section_result& section : r.sections) {
    for (const plot_spec& plot : section_plots(section)) p.drawn.push_back(plot.name);
  }
  return p;
}

json report_json(const run_record& r) { return report_json(r, report_parts::all_plots_drawn(r)); }

namespace {

json amendments_json(const std::vector<amendment>& amendments) {
  json out = json::array();
  for (const amendment& a : amendments) {
    out.push_back({{"where", a.where}, {"printed", a.printed}, {"should_be", a.should_be}, {"notation", a.tex ? "tex" : "words"}});
  }
  return out;
}

/// The verdict table (verdict_table.hpp): every claim and expectation in one list, each with the
/// one rule's status; a row whose status is "failed" or "error" is what makes the exit code non-zero.
json verdicts_json(const run_record& r) {
  json rows = json::array();
  for (const verdict_row& row : verdict_table(r)) {
    json entry{{"name", row.name},         {"kind", row.expectation ? "expectation" : "claim"}, {"suite", row.suite},
               {"verdict", row.verdict},   {"expected", row.expected},
               {"status", to_string(row.state)}};
    if (!row.type.empty()) entry["type"] = row.type;
    if (!row.message.empty()) entry["message"] = row.message;
    rows.push_back(std::move(entry));
  }
  return rows;
}

}  // namespace

json report_json(const run_record& r, const plot_outcome& plots) {
  json claims = json::array();
  for (const claim_outcome& o : r.outcomes) {
    const claim& c = *o.checked;
    json entry{{"id", c.id},
               {"section", c.section},
               {"equation", c.equation},
               {"statement", c.statement},
               {"methods", c.methods},
               {"verdict", to_string(o.result.outcome)},
               {"expected", to_string(o.expected)},
               {"as_expected", outcome_as_expected(o)},
               {"origin", to_string(c.origin)},
               {"finding", to_string(report_parts::finding_of(o))}};
    if (!cause_of(o).empty()) entry["follows_from"] = cause_of(o);
    if (!o.result.remark.empty()) entry["remark"] = {{"class", to_string(o.result.remark_kind)}, {"text", o.result.remark}};
    if (o.expected_remark != finding::none) entry["expected_remark"] = to_string(o.expected_remark);
    if (!o.content_changed.empty()) entry["content_changed"] = o.content_changed;
    if (o.fixed) entry["fixed"] = true;
    if (!o.changed.empty()) entry["changed"] = {{"why", o.changed}, {"cause", o.changed_cause}};
    if (const std::string reads = reads_digest(o.result.printed, o.result.quoted); !reads.empty()) entry["reads"] = reads;
    if (c.typographical) entry["typographical"] = true;
    if (o.result.constant_factor) entry["constant_factor"] = true;
    if (!o.conclusions_standing.empty()) entry["conclusions_standing"] = o.conclusions_standing;
    if (!o.result.correction.empty()) entry["correction"] = o.result.correction;
    if (!o.result.amendments.empty()) entry["amendments"] = amendments_json(o.result.amendments);
    if (!o.result.note.empty()) entry["note"] = o.result.note;
    if (!o.result.printed.is_null()) entry["printed"] = o.result.printed;
    if (!o.result.quoted.empty()) entry["quoted"] = o.result.quoted;
    entry["evidence"] = o.result.evidence;
    claims.push_back(std::move(entry));
  }
  json experiments = json::object(), plot_list = json::array();
  for (const section_result& section : r.sections) {
    experiments[section.name] = section_json(section);
    for (const plot_spec& plot : section_plots(section)) {
      const bool drawn = std::find(plots.drawn.begin(), plots.drawn.end(), plot.name) != plots.drawn.end();
      plot_list.push_back({{"name", plot.name},
                           {"section", section.name},
                           {"caption", plot.caption},
                           {"script", plot.name + ".gp"},
                           {"run_times", plot.timing},
                           {"files", drawn ? json::array({plot.name + ".svg", plot.name + ".png"}) : json::array()}});
    }
  }
  return json{{"schema_version", report_schema_version},
              {"tool", "simpson-verify"},
              {"scene", r.run_scene.name},
              {"description", r.run_scene.description},
              {"seed", r.run_scene.seed},
              {"samples", r.run_scene.samples},
              {"enclosure_budget_digits", r.run_scene.enclosure_budget_digits},
              {"precisions", report_parts::precision_names(r.run_scene.precisions)},
              {"paper", r.paper_origin},
              {"overrides", r.run_scene.overrides},
              {"summary", summary_json(r)},
              {"all_as_expected", run_exit_code(r) == 0},
              {"verdicts", verdicts_json(r)},
              {"claims", claims},
              {"experiments", experiments},
              {"plots", plot_list},
              {"plots_not_drawn", plots.failures},
              {"files", report_file_names(r, plots)},
              {"timing_files", timing_file_names(r, plots)},
              {"paper_configuration", r.paper_configuration},
              {"provenance", r.provenance},
              {"environment", r.environment}};
}

json timing_json(const run_record& r) {
  json claims = json::object(), ginac = json::object(), sections = json::object(), tables = json::object();
  for (const claim_outcome& o : r.outcomes) {
    claims[o.checked->id] = o.seconds;
    if (!o.result.printed.is_null()) ginac[o.checked->id] = o.result.printed_seconds;
  }
  for (std::size_t k = 0; k < r.sections.size(); ++k) {
    sections[r.sections[k].name] = r.section_seconds[k];
    const json section_tables = section_timing_json(r.sections[k]);
    if (!section_tables.empty()) tables[r.sections[k].name] = section_tables;
  }
  const speed_figures speed = speed_of(r);
  return json{{"tool", "simpson-verify"},
              {"scene", r.run_scene.name},
              {"timestamp_utc", r.environment.value("timestamp_utc", "")},
              {"unit", "seconds"},
              {"total", r.seconds},
              {"claims", claims},
              {"claims_total", speed.claims_total},
              {"coqc_total", r.coq_seconds},
              {"coqc_files", r.coq_documents},
              {"coqc_processes", r.coq_processes},
              {"printed_formulas_in_ginac", ginac},
              {"ginac_derivation", r.ginac_derivation_seconds},
              {"headline_in_ginac", speed.headline},
              {"headline_claims", speed.headline_ids},
              {"sections", sections},
              {"experiments", tables}};
}

std::string timing_markdown(const run_record& r, const plot_outcome& plots) {
  std::string md = fmt::format("# simpson-verify run times: scene `{}`{}\n\n", r.run_scene.name,
                               r.run_scene.selection.empty() ? "" : ": " + r.run_scene.selection);
  const json& env = r.environment;
  md += fmt::format("Run at {} on {} ({}, {} hardware threads), {} {}, built {}. Every other file of the report is the same "
                    "from run to run for the same scene, seed and build; this one and the files it links are not.\n\n",
                    env.value("timestamp_utc", "?"), env.value("cpu", "?"), env.value("os", "?"),
                    env.value("hardware_threads", 0u), env.value("tool", "simpson-verify"), env.value("version", "?"),
                    env.value("flags", "?"));
  md += fmt::format("Total: {:.2f} s. The verdicts and figures: [report.md](report.md).\n\n", r.seconds);
  if (!r.outcomes.empty()) {
    const speed_figures speed = speed_of(r);
    if (machine_read(r) > 0 && !speed.headline_ids.empty()) {  // a note's records name no headline claims
      md += fmt::format("The GiNaC derivation from first principles took {:.2e} s; the headline claims ({}) in GiNaC, with that "
                        "derivation, {:.2e} s.\n\n",
                        r.ginac_derivation_seconds, report_parts::join(speed.headline_ids, ", "), speed.headline);
    }
    md += fmt::format("## Claims\n\nEvery claim in both kernels, numeric rechecks included: {:.2e} s.{}\n\n"
                      "| claim | seconds | of which GiNaC, printed formula |\n|---|---|---|\n",
                      speed.claims_total,
                      r.coq_documents > 0 ? fmt::format(" coqc checked the {} certificate files in {:.1f} s ({} processes side by side).",
                                                        r.coq_documents, r.coq_seconds, r.coq_processes)
                                          : std::string());
    for (const claim_outcome& o : r.outcomes) {
      md += fmt::format("| {} | {:.2e} | {} |\n", o.checked->id, o.seconds,
                        o.result.printed.is_null() ? std::string() : fmt::format("{:.2e}", o.result.printed_seconds));
    }
    md += "\n";
  }
  if (!r.sections.empty()) {
    md += "## Sections\n\n| section | seconds |\n|---|---|\n";
    for (std::size_t k = 0; k < r.sections.size(); ++k) md += fmt::format("| {} | {:.2f} |\n", r.sections[k].name, r.section_seconds[k]);
    md += "\n";
    for (const section_result& section : r.sections) md += section_timing_markdown(section);
    if (!plots.failures.empty()) md += "**Plots not drawn:** " + report_parts::join(plots.failures, "; ") + "\n\n";
  }
  return md;
}

}  // namespace simpson::verify

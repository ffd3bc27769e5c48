// The verdicts of a run counted once, and the summary lines and JSON made of them: see report.hpp
// and report_parts.hpp.

#include "report_parts.hpp"

#include <simpson/verify/certify.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/verdict_table.hpp>

#include <fmt/format.h>

#include <algorithm>

namespace simpson::verify {

namespace report_parts {

std::string join(const std::vector<std::string>& parts, const std::string& separator) {
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : separator) + p;
  return out;
}

std::vector<std::string> precision_names(const std::vector<precision>& precisions) {
  std::vector<std::string> names;
  for (const precision& p : precisions) names.push_back(p.name());
  return names;
}

prose_slips prose_slips_of(const claim_outcome& o) {
  prose_slips out;
  if (!o.result.evidence.contains("prose")) return out;
  const json& prose = o.result.evidence["prose"];
  if (prose.contains("not_in_dictionary")) out.misspelled = prose["not_in_dictionary"].size();
  if (prose.contains("misused")) out.misused = prose["misused"].size();
  return out;
}

std::string prose_slips_words(std::size_t misspelled, std::size_t misused) {
  // "At least": a dictionary and the record's phrases find what they know, not every slip of usage.
  std::string out = fmt::format("{} word{} not English", misspelled, misspelled == 1 ? "" : "s");
  if (misused > 0) out += fmt::format(" and {} phrase{} misused", misused, misused == 1 ? "" : "s");
  return out + ", at least";
}

finding finding_of(const claim_outcome& o) {
  if (!is_finding(o.result.outcome)) return finding::none;
  if (o.result.outcome == o.expected && o.checked->kind != finding::none) return o.checked->kind;
  return o.result.outcome == verdict::unverifiable ? finding::unverifiable : finding::erratum;
}

verdict_counts count_verdicts(const run_record& r) {
  return count_verdicts(r, [](const claim_outcome&) { return true; });
}

verdict_counts count_verdicts(const run_record& r, const std::function<bool(const claim_outcome&)>& keep) {
  verdict_counts c;
  for (const claim_outcome& o : r.outcomes) {
    if (!keep(o)) continue;
    if (o.result.evidence.contains("error")) {  // a harness fault is never counted as a verdict
      ++c.faults;
      continue;
    }
    const bool paper = o.checked->origin == claim_origin::paper;
    const bool source_check = paper && o.result.reads_whole_text;
    (source_check ? c.source_checks : paper ? c.paper : o.checked->origin == claim_origin::beyond ? c.beyond : c.harness) += 1;
    const finding kind = finding_of(o);
    if (source_check && is_finding(o.result.outcome) && kind != finding::prose) {
      ++c.source_findings;
    } else if (paper && is_finding(o.result.outcome) && kind == finding::prose) {
      ++c.prose_claims;
      const prose_slips slips = prose_slips_of(o);
      c.prose_misspelled += slips.misspelled;
      c.prose_misused += slips.misused;
      c.prose_slips += std::max<std::size_t>(1, slips.misspelled + slips.misused);
    } else if (paper && is_finding(o.result.outcome)) {
      if (cause_of(o).empty()) {
        ++c.distinct;
        if (o.checked->typographical) {
          ++c.typographical;
        } else if (o.result.constant_factor) {
          ++c.constant_factor;
        } else if (!o.conclusions_standing.empty()) {
          ++c.inconsistent;
        } else if (kind == finding::unverifiable) {
          ++c.unverifiable_findings;
        } else if (remark_class(kind)) {
          ++c.wording;
        } else {
          ++c.substantive;
        }
      } else {
        ++c.consequences;
      }
    }
    c.errata_following += o.result.outcome == verdict::erratum && !cause_of(o).empty();
    c.prose_errata += paper && o.result.outcome == verdict::erratum && kind == finding::prose;
    const bool remark = paper && meaning(o.result.outcome).affirms && !o.result.remark.empty();
    c.remarks += remark;
    c.linked_remarks += remark && !cause_of(o).empty();
    ++c.of[static_cast<std::size_t>(o.result.outcome)];
    c.machine_read += !o.result.printed.is_null();
    c.quoted += !o.result.quoted.empty();  // a claim may read a formula and quote its sentence: counted in both
    c.whole_text += o.result.reads_whole_text;
    c.typed += o.result.printed.is_null() && o.result.quoted.empty() && !o.result.reads_whole_text;
    c.read_and_quoted += !o.result.printed.is_null() && !o.result.quoted.empty();
    c.coq_exported += !certificate_documents(o).empty();
    c.coq_checked += o.result.evidence.contains("coq") && o.result.evidence["coq"].value("status", "") == "checked";
    if (o.fixed) c.fixed.push_back(o.checked->id);
    if (!o.changed.empty()) {
      c.changed.push_back(o.checked->id + (o.changed_cause.empty() ? "" : " from " + o.changed_cause));
    } else if (o.fixed && !outcome_as_expected(o)) {
      c.fixes_not_accepted.push_back(o.checked->id);
    } else if (!outcome_as_expected(o)) {
      c.unexpected.push_back(o.checked->id);
    }
  }
  return c;
}

expectation_counts count_expectations(const run_record& r) {
  expectation_counts e;
  for (const section_result& section : r.sections) e.total += section.expectations.size();
  e.failed = failed_expectations(r);
  return e;
}

}  // namespace report_parts

namespace {

/// The spelling checks' errata in words: "1 spelling erratum (6 words not English, at least)".
std::string spelling_words(const report_parts::verdict_counts& c) {
  return fmt::format("{} spelling errat{} ({})", c.prose_errata, c.prose_errata == 1 ? "um" : "a",
                     report_parts::prose_slips_words(c.prose_misspelled, c.prose_misused));
}

/// Each verdict's count in its words (verdict.hpp's table): those always shown, then the others met.
std::string counted_words(const report_parts::verdict_counts& c, bool only_met = false) {
  std::vector<std::string> counted;
  for (const verdict_meaning& m : verdict_meanings) {
    // A spelling check's erratum judges the source's words, not a statement: named apart, after the errata.
    const std::size_t spelling = m.value == verdict::erratum ? c.prose_errata : 0;
    const std::size_t n = c.count(m.value) - spelling;
    if ((only_met || !m.always_counted) && n == 0) continue;
    std::string words = fmt::format(fmt::runtime(n == 1 ? m.counted_as_one : m.counted_as), n);
    if (m.affirms && c.remarks > 0) words += fmt::format(" ({} with a remark)", c.remarks);
    if (m.value == verdict::erratum && c.errata_following > 0) words += fmt::format(" ({} following from another's)", c.errata_following);
    counted.push_back(words);
    if (spelling > 0) counted.push_back(spelling_words(c));
  }
  if (c.faults) counted.push_back(fmt::format("{} without a verdict (a harness fault: the check threw)", c.faults));
  return report_parts::join(counted, ", ");
}

/// A check of the source by its id and verdict: "prose-spelling erratum (6 words not English, at least)",
/// "bibliography unverifiable (its material absent from the supplied source)".
std::string source_check_words(const claim_outcome& o) {
  const std::string& id = o.checked->id;
  if (o.result.evidence.contains("error")) return id + " without a verdict (a harness fault)";
  const report_parts::prose_slips slips = report_parts::prose_slips_of(o);
  switch (o.result.outcome) {
    case verdict::holds: return id + " holds";
    case verdict::erratum:
      return report_parts::finding_of(o) == finding::prose ? fmt::format("{} erratum ({})", id, report_parts::prose_slips_words(slips.misspelled, slips.misused))
                                                        : id + " erratum";
    case verdict::unverifiable: return id + " unverifiable (its material absent from the supplied source)";
    default: return id + " " + to_string(o.result.outcome);
  }
}

}  // namespace

std::string summary_line(const run_record& r) {
  const report_parts::verdict_counts c = report_parts::count_verdicts(r);
  const report_parts::expectation_counts e = report_parts::count_expectations(r);
  const std::vector<std::string> rejected = rejected_certificates(r);
  // What makes the exit code 1, each named: the line says "as expected" only when it is 0.
  std::vector<std::string> problems;
  if (!c.unexpected.empty()) {
    problems.push_back(r.validation ? fmt::format("{} not holding ({})", c.unexpected.size(), report_parts::join(c.unexpected, ", "))
                                    : fmt::format("{} not as expected ({})", c.unexpected.size(), report_parts::join(c.unexpected, ", ")));
  }
  if (!c.changed.empty()) {
    problems.push_back(fmt::format("{} changed by what {} read{} ({}: recorded as a finding or a remark, now holding without it, not a fix)",
                                   c.changed.size(), c.changed.size() == 1 ? "it" : "they", c.changed.size() == 1 ? "s" : "",
                                   report_parts::join(c.changed, ", ")));
  }
  if (!c.fixes_not_accepted.empty()) {
    problems.push_back(fmt::format("{} fixed ({}: recorded as a finding, now holds; --accept-fixes accepts a fix)", c.fixes_not_accepted.size(),
                                   report_parts::join(c.fixes_not_accepted, ", ")));
  }
  if (!e.failed.empty()) {
    problems.push_back(fmt::format("{} expectation{} failed ({})", e.failed.size(), e.failed.size() == 1 ? "" : "s", report_parts::join(e.failed, ", ")));
  }
  if (!rejected.empty()) {
    problems.push_back(fmt::format("coqc rejected {} certificate{} ({})", rejected.size(), rejected.size() == 1 ? "" : "s", report_parts::join(rejected, ", ")));
  }
  const std::string expectations =
      e.total == 0 ? std::string()
                   : fmt::format("; {} expectation{} of the experiments: {} hold{}", e.total, e.total == 1 ? "" : "s", e.total - e.failed.size(),
                                 e.failed.empty() ? "" : fmt::format(", {} failed", e.failed.size()));
  const std::string ending = c.faults           ? std::string("no verdict on the run: a harness fault")
                             : !problems.empty() ? report_parts::join(problems, "; ")
                             : r.validation      ? std::string(e.total == 0 ? "every claim holds" : "every claim and expectation holds")
                             : !c.fixed.empty()  ? fmt::format("all verdicts as expected, {} fixed, fixes accepted ({})", c.fixed.size(), report_parts::join(c.fixed, ", "))
                                                 : std::string("all verdicts as expected");
  // The records in their groups, each counted apart: the paper's (or the document's) claims, the
  // checks of its source (its spelling, its citations: no statement of the text), the harness's own
  // (beyond the paper, or the reductions every proof uses). One group alone is "N claims: ...".
  const auto source_check = [](const claim_outcome& o) { return o.checked->origin == claim_origin::paper && o.result.reads_whole_text; };
  const auto text_claim = [&](const claim_outcome& o) { return o.checked->origin == claim_origin::paper && !source_check(o); };
  const auto own = [](const claim_outcome& o) { return o.checked->origin != claim_origin::paper; };
  std::size_t claims = 0, checks = 0, owns = 0;
  for (const claim_outcome& o : r.outcomes) (source_check(o) ? checks : text_claim(o) ? claims : owns) += 1;
  const int groups = (claims > 0) + (checks > 0) + (owns > 0);
  if (groups <= 1) {
    return fmt::format("{} {}: {}{}; {}", r.outcomes.size(), r.outcomes.size() == 1 ? "claim" : "claims", counted_words(report_parts::count_verdicts(r)),
                       expectations, ending);
  }
  const std::string whose = r.of_the_paper ? "the paper's" : "the document's";
  std::vector<std::string> parts;
  if (claims > 0) {
    parts.push_back(fmt::format("{} {} claim{}: {}", whose, claims, claims == 1 ? "" : "s", counted_words(report_parts::count_verdicts(r, text_claim))));
  }
  if (checks > 0) {
    std::vector<std::string> each;
    for (const claim_outcome& o : r.outcomes) {
      if (source_check(o)) each.push_back(source_check_words(o));
    }
    parts.push_back(fmt::format("{} check{} of {} source: {}", checks, checks == 1 ? "" : "s", r.of_the_paper ? "its" : "the", report_parts::join(each, ", ")));
  }
  if (owns > 0) {
    // Records not of the text: beyond it (a statement it does not make) and the harness's own (the
    // reductions its proofs use); only the verdicts met ("6 held"), no findings of the text's to count.
    const report_parts::verdict_counts c = report_parts::count_verdicts(r, own);
    std::vector<std::string> whose_own;
    if (c.beyond > 0) whose_own.push_back(fmt::format("{} beyond it", c.beyond));
    if (c.harness > 0) whose_own.push_back(fmt::format("{} the harness's own", c.harness));
    parts.push_back(fmt::format("{} not of the {} ({}): {}", owns, r.of_the_paper ? "paper" : "document", report_parts::join(whose_own, ", "),
                                counted_words(c, true)));
  }
  return fmt::format("{} records: {}{}; {}", r.outcomes.size(), report_parts::join(parts, "; "), expectations, ending);
}

namespace {

/// A validation's exit line: what holds in the document, with no talk of expected verdicts. A claim
/// that holds once another's correction is put in is counted with its cause, never twice.
std::string validation_line(const run_record& r, const report_parts::verdict_counts& c) {
  std::vector<std::string> causes, consequences, undecided, other;
  for (const claim_outcome& o : r.outcomes) {
    if (outcome_as_expected(o)) continue;
    const std::string& id = o.checked->id;
    if (meaning(o.result.outcome).tool_limit) {
      undecided.push_back(id);
    } else if (is_finding(o.result.outcome) && !cause_of(o).empty()) {
      consequences.push_back(id + " (from " + cause_of(o) + ")");
    } else if (is_finding(o.result.outcome)) {
      causes.push_back(id);
    } else {
      other.push_back(id + " (" + to_string(o.result.outcome) + ")");
    }
  }
  std::vector<std::string> parts;
  if (!causes.empty()) {
    parts.push_back(fmt::format("{} claim{} {} not hold as written ({})", causes.size(), causes.size() == 1 ? "" : "s",
                                causes.size() == 1 ? "does" : "do", report_parts::join(causes, ", ")));
  }
  if (!consequences.empty()) {
    parts.push_back(fmt::format("{} follow{} from another's correction ({})", consequences.size(), consequences.size() == 1 ? "s" : "",
                                report_parts::join(consequences, ", ")));
  }
  if (!undecided.empty()) {
    parts.push_back(fmt::format("{} could not be decided ({}: the tool's limits, not findings)", undecided.size(), report_parts::join(undecided, ", ")));
  }
  if (!other.empty()) parts.push_back(fmt::format("{} changed ({})", other.size(), report_parts::join(other, ", ")));
  (void)c;
  return report_parts::join(parts, "; ");
}

}  // namespace

std::string expectation_line(const run_record& r) {
  const std::vector<std::string> failed = failed_expectations(r);
  if (r.outcomes.empty() && failed.empty()) return "No claim in this run.";
  const report_parts::verdict_counts c = report_parts::count_verdicts(r);
  std::vector<std::string> expected_failures;
  for (const verdict_row& row : verdict_table(r)) {
    if (row.state == verdict_row::status::expected_failure) expected_failures.push_back(row.name);
  }
  const int code = run_exit_code(r);
  if (code == 3) return "Exit code 3: a check threw (a bug in the harness); see Failures.";
  // What the expected verdicts are: the paper's, as the ledger judges it, or a claims file's for its document.
  const bool document = !r.of_the_paper;
  const std::string judgment = document ? "the claims file's expected verdicts for its document" : "the ledger's recorded judgment of the printed paper";
  const std::string changed = document ? "the document" : "the paper";
  const bool rejected = !rejected_certificates(r).empty();
  if (r.validation) {  // no expected verdicts: the document's claims are to hold
    if (code == 0) return fmt::format("Exit code 0: every claim of the {} holds.", r.of_the_paper ? "paper" : "document");
    std::string why = validation_line(r, c);
    if (rejected) why += (why.empty() ? "" : "; ") + std::string("coqc rejected a certificate");
    if (!failed.empty()) {
      why += (why.empty() ? "" : "; ") + fmt::format("{} expectation{} of the experiments failed ({})", failed.size(), failed.size() == 1 ? "" : "s",
                                                     report_parts::join(failed, ", "));
    }
    return "Exit code 1: " + why + "; see Failures.";
  }
  if (code != 0) {
    std::string why;
    if (!c.unexpected.empty()) {
      why = fmt::format("{} verdict{} differ{} from the expected one ({}): either {} or the harness changed", c.unexpected.size(),
                        c.unexpected.size() == 1 ? "" : "s", c.unexpected.size() == 1 ? "s" : "", judgment, changed);
    }
    if (!c.changed.empty()) {
      why += (why.empty() ? "" : "; ") + fmt::format("{} claim{} recorded as a finding or a remark now hold{} because a premise {} read{} changed "
                                                     "({}): a consequence, not a fix, which --accept-fixes does not pass",
                                                     c.changed.size(), c.changed.size() == 1 ? "" : "s", c.changed.size() == 1 ? "s" : "",
                                                     c.changed.size() == 1 ? "it" : "they", c.changed.size() == 1 ? "s" : "", report_parts::join(c.changed, ", "));
    }
    if (!c.fixes_not_accepted.empty()) {
      why += (why.empty() ? "" : "; ") + fmt::format("{} finding{} of the record now hold{} ({}): a fix of {}, which a guard reports as a "
                                                     "change (--accept-fixes accepts fixes); see Fixed",
                                                     c.fixes_not_accepted.size(), c.fixes_not_accepted.size() == 1 ? "" : "s",
                                                     c.fixes_not_accepted.size() == 1 ? "s" : "", report_parts::join(c.fixes_not_accepted, ", "), changed);
    }
    if (rejected) why += (why.empty() ? "" : "; ") + std::string("coqc rejected a certificate");
    if (!failed.empty()) {
      why += (why.empty() ? "" : "; ") + fmt::format("{} expectation{} of the experiments failed ({})", failed.size(), failed.size() == 1 ? "" : "s",
                                                     report_parts::join(failed, ", "));
    }
    return "Exit code 1: " + why + "; see Failures.";
  }
  std::string line = fmt::format("Exit code 0: every verdict is the expected one, {} (a regression check: a difference would "
                                 "mean that {} or the harness changed), not a validation",
                                 judgment, changed);
  std::vector<std::string> findings;
  const std::size_t errata = c.count(verdict::erratum) - c.prose_errata;
  if (errata > 0) findings.push_back(fmt::format("{} {} (false as printed, a correction proved)", errata, errata == 1 ? "erratum" : "errata"));
  if (c.prose_errata > 0) findings.push_back(spelling_words(c));
  if (!expected_failures.empty()) {
    findings.push_back(fmt::format("{} expected failure{} ({}: not reproduced, no correction found)", expected_failures.size(),
                                   expected_failures.size() == 1 ? "" : "s", report_parts::join(expected_failures, ", ")));
  }
  if (findings.empty()) return line + ".";
  const std::size_t expected_findings = errata + c.prose_errata + expected_failures.size();
  return line + ": " + report_parts::join(findings, " and ") + (expected_findings == 1 ? " is an expected verdict." : " are expected verdicts.");
}

namespace {

/// The paper's headline results (records with `headline = true`) that were run, each with its verdict.
std::vector<std::pair<std::string, verdict>> headline_results(const run_record& r) {
  std::vector<std::pair<std::string, verdict>> out;
  for (const claim_outcome& o : r.outcomes) {
    if (o.checked->origin == claim_origin::paper && o.checked->headline && !o.threw) out.emplace_back(o.checked->id, o.result.outcome);
  }
  return out;
}

json headline_claims_json(const run_record& r) {
  json out = json::array();
  for (const auto& [id, v] : headline_results(r)) out.push_back({{"id", id}, {"verdict", to_string(v)}});
  return out;
}

}  // namespace

json summary_json(const run_record& r) {
  const report_parts::verdict_counts c = report_parts::count_verdicts(r);
  json out = {{"line", summary_line(r)},     {"expectation", expectation_line(r)}, {"headline", findings_headline(r)}, {"claims", r.outcomes.size()},
              {"harness_faults", c.faults},
              {"paper_claims", c.paper},     {"source_checks", c.source_checks}, {"beyond_claims", c.beyond},   {"harness_claims", c.harness},
              {"distinct_findings", c.distinct}, {"substantive_findings", c.substantive}, {"constant_factor_findings", c.constant_factor},
              {"inconsistent_findings", c.inconsistent},
              {"headline_claims", headline_claims_json(r)}, {"typographical_findings", c.typographical},
              {"wording_findings", c.wording}, {"unverifiable_findings", c.unverifiable_findings}, {"consequences", c.consequences},
              {"remarks", c.remarks},
              {"spelling_slips", c.prose_slips},
              {"machine_read", c.machine_read}, {"quoted", c.quoted}, {"whole_text", c.whole_text}, {"typed", c.typed},
              {"coq_exported", c.coq_exported}, {"coq_checked", c.coq_checked},
              {"unexpected", c.unexpected}, {"failed_expectations", failed_expectations(r)},
              {"expectations", report_parts::count_expectations(r).total},
              {"fixed", c.fixed},
              {"changed", c.changed},
              {"fixes_accepted", r.run_scene.accept_fixes},
              {"exit_code", run_exit_code(r)},
              {"mode", r.validation ? "validation" : "regression"}};
  for (const verdict_meaning& m : verdict_meanings) out[m.count_key] = c.count(m.value);
  return out;
}

/// The findings in a referee's words: first whether the headline results hold, then how many
/// substantive errors (and where), constant-factor slips (zeros unchanged), typographical slips,
/// statements false as worded, claims the supplied source cannot show, and remarks on claims that
/// hold, the spelling apart; the claims that follow from a finding counted with it.
std::string findings_headline(const run_record& r) {
  const report_parts::verdict_counts c = report_parts::count_verdicts(r);
  const std::string the = r.of_the_paper ? "paper" : "document";
  const auto n = [](std::size_t k, const char* one, const char* many) { return fmt::format("{} {}", k, k == 1 ? one : many); };
  // Each distinct finding's category, and what follows from it.
  std::vector<std::string> substantive, constant_factor, inconsistent, unverifiable;
  std::size_t follows_other = 0;
  for (const claim_outcome& o : r.outcomes) {
    if (o.checked->origin != claim_origin::paper || o.result.reads_whole_text || !is_finding(o.result.outcome) || !cause_of(o).empty()) continue;
    const finding kind = report_parts::finding_of(o);
    std::size_t following = 0;
    for (const claim_outcome& other : r.outcomes) following += cause_of(other) == o.checked->id && is_finding(other.result.outcome);
    const std::string place = fmt::format("§{}, {}", o.checked->section, o.checked->id);
    const std::string and_following = following == 0 ? std::string() : fmt::format(", and {} following from it", n(following, "claim", "claims"));
    const std::vector<std::string>& standing = o.conclusions_standing;
    if (kind == finding::erratum && !o.checked->typographical && o.result.constant_factor) {
      constant_factor.push_back(place + and_following);
    } else if (kind == finding::erratum && !o.checked->typographical && !standing.empty()) {
      const std::string where = o.result.amendments.empty() ? std::string() : ": " + o.result.amendments.front().where;
      inconsistent.push_back(place + where + and_following + "; the conclusions the text draws from those data hold of the printed numbers: " + report_parts::join(standing, ", "));
    } else if (kind == finding::erratum && !o.checked->typographical) {
      const std::string where = o.result.amendments.empty() ? std::string() : ": " + o.result.amendments.front().where;
      substantive.push_back(place + where + and_following);
    } else {
      if (kind == finding::unverifiable) unverifiable.push_back(o.checked->id);
      follows_other += following;
    }
  }
  std::string line = fmt::format("The {}'s {}{}: ", the, n(c.paper, "claim", "claims"),
                                 c.source_checks == 0 ? std::string() : " and " + n(c.source_checks, "check of its source", "checks of its source"));
  const std::vector<std::pair<std::string, verdict>> headline = headline_results(r);
  if (!headline.empty()) {
    std::vector<std::string> held, not_held;
    for (const auto& [id, v] : headline) {
      if (meaning(v).affirms) {
        held.push_back(id);
      } else {
        not_held.push_back(fmt::format("{}: {}", id, to_string(v)));
      }
    }
    line += not_held.empty() ? fmt::format("its {} {} ({}). ", n(headline.size(), "headline result", "headline results"),
                                           headline.size() == 1 ? "holds" : "hold", report_parts::join(held, ", "))
                             : fmt::format("of its {}, {} {}; {}. ", n(headline.size(), "headline result", "headline results"), held.size(),
                                           held.size() == 1 ? "holds" : "hold", report_parts::join(not_held, "; "));
    line += "Findings: ";
  }
  std::string errors = n(c.substantive, "substantive error", "substantive errors");
  if (!substantive.empty()) errors += " (" + report_parts::join(substantive, "; ") + ")";
  std::vector<std::string> parts{errors};
  if (c.inconsistent > 0) {
    parts.push_back(fmt::format("{} ({})",
                                n(c.inconsistent, "inconsistency that changes no conclusion", "inconsistencies that change no conclusion"),
                                report_parts::join(inconsistent, "; ")));
  }
  if (c.constant_factor > 0) {
    parts.push_back(fmt::format("{}, zeros unchanged ({})", n(c.constant_factor, "constant-factor slip", "constant-factor slips"),
                                report_parts::join(constant_factor, "; ")));
  }
  parts.push_back(n(c.typographical, "typographical slip", "typographical slips"));
  if (c.wording > 0) parts.push_back(n(c.wording, "statement false as worded (wording, naming or derivation)", "statements false as worded (wording, naming or derivation)"));
  line += report_parts::join(parts, ", ");
  if (follows_other > 0) line += fmt::format(" ({} following from these)", n(follows_other, "more claim", "more claims"));
  // A remark that follows another claim's finding or remark says so.
  line += fmt::format("; {} on claims that hold", n(c.remarks, "remark", "remarks"));
  if (c.linked_remarks > 0) line += fmt::format(" ({} of them following the finding or remark of another claim)", c.linked_remarks);
  // Prior work the text never names is what a referee asks about first: said here, not only among the remarks.
  for (const claim_outcome& o : r.outcomes) {
    if (o.checked->origin != claim_origin::paper || !meaning(o.result.outcome).affirms || o.result.remark.empty() ||
        !o.result.evidence.contains("prior_work")) {
      continue;
    }
    line += fmt::format(". Prior work the text never names: on this problem its map is exactly {}'s, proved here; beyond it, by the "
                        "literature's construction the remark cites ({})",
                        o.result.evidence["prior_work"].get<std::string>(), o.checked->id);
  }
  // What the supplied copy lacks is a limit of the source, not a defect of the mathematics: said apart.
  if (c.unverifiable_findings > 0) {
    line += fmt::format(". What the supplied source cannot show, its material absent: {}", report_parts::join(unverifiable, ", "));
  }
  // The checks of the source as a whole: what each found, apart from the claims.
  std::vector<std::string> of_source;
  for (const claim_outcome& o : r.outcomes) {
    if (o.checked->origin != claim_origin::paper || !o.result.reads_whole_text) continue;
    const finding kind = report_parts::finding_of(o);
    const report_parts::prose_slips slips = report_parts::prose_slips_of(o);
    of_source.push_back(kind == finding::prose ? fmt::format("{} ({})", o.checked->id, report_parts::prose_slips_words(slips.misspelled, slips.misused))
                        : kind == finding::unverifiable ? o.checked->id + " (unverifiable: its material absent from the supplied source)"
                        : is_finding(o.result.outcome) ? fmt::format("{} ({})", o.checked->id, to_string(o.result.outcome))
                                                       : o.checked->id + " (holds)");
  }
  if (!of_source.empty()) line += ". The source's checks: " + report_parts::join(of_source, ", ");
  return line + ".";
}

std::size_t machine_read(const run_record& r) { return report_parts::count_verdicts(r).machine_read; }

}  // namespace simpson::verify

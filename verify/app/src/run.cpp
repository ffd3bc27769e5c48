#include <simpson/verify/interruption.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/environment.hpp>
#include <simpson/verify/paper_configuration.hpp>
#include <simpson/verify/printed_checks.hpp>
#include <simpson/verify/provenance.hpp>
#include <simpson/verify/quoted_sentence.hpp>
#include <simpson/verify/run.hpp>
#include <simpson/verify/utf8_text.hpp>
#include <simpson/verify/claim_reads.hpp>
#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/formula_reference.hpp>
#include <simpson/verify/run_memo.hpp>

#include <simpson/verify/certify.hpp>
#include <simpson/verify/consequences.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <optional>
#include <set>
#include <cstdlib>
#include <exception>

namespace simpson::verify {

paper_reading read_scene_paper(const scene& s, claim_book& book) {
  if (const claims_document* document = book.checked_document()) {
    // A document other than the paper: its claims read their formulas themselves (proof shapes).
    if (s.paper_file.empty()) throw std::invalid_argument("the claims file checks a document ([document]): give its LaTeX with --paper");
    paper_reading reading = read_note(load_document(s.paper_file, document->title));
    check_claims_file_formulas(book, reading.source);
    return reading;
  }
  paper_reading reading = read_paper(s.paper_file.empty() ? embedded_paper() : load_paper(s.paper_file), book.declarations->reading, book.formulas);
  // What the scene's shape records read, before anything runs: a label or phrase the paper no longer
  // has is bad input, named, not a harness fault in the middle of a run.
  check_claims_file_formulas(book, reading.source, &s.claims);
  return reading;
}

run_record run(const scene& s, const progress_callback& progress,
               const std::function<void(const std::string&, double)>& section_progress, const progress_sink& work, const claim_checker& checker) {
  auto book = std::make_shared<claim_book>(paper_book());
  const paper_reading paper = read_scene_paper(s, *book);
  return run(s, std::move(book), paper, progress, section_progress, work, checker);
}

void apply_baseline(scene& s, const json& baseline, const std::string& name) {
  std::map<std::string, const json*> judged;
  if (!baseline.contains("claims") || !baseline.at("claims").is_array()) throw std::invalid_argument("--baseline '" + name + "': no claims");
  for (const json& c : baseline.at("claims")) judged[c.value("id", "")] = &c;
  for (const std::string& id : s.claims) {
    const auto it = judged.find(id);
    if (it == judged.end()) continue;  // a claim the baseline did not judge keeps its record's expectation
    const json& entry = *it->second;
    const std::string word = entry.value("verdict", "");
    const std::optional<verdict> v = verdict_of_name(word);
    if (!v) throw std::invalid_argument("--baseline '" + name + "': claim " + id + " has no verdict ('" + word + "')");
    // Undecided, unproved, text-changed, kernels-disagree or skipped there: no judgment to keep, so the
    // record's expectation stays (a guard stays red on what it could not decide, and never expects it).
    if (!expectable(*v)) continue;
    s.expected_overrides[id] = *v;
    baseline_claim b;
    if (meaning(*v).corrected) b.correction = entry.value("correction", "");
    if (entry.contains("remark") && entry["remark"].is_object()) {
      const std::string kind = entry["remark"].value("class", "");
      const std::optional<finding> f = finding_of_name(kind);
      if (!f || !remark_class(*f)) throw std::invalid_argument("--baseline '" + name + "': claim " + id + " has a remark of no remark's class ('" + kind + "')");
      b.remark_kind = *f;
      b.remark = entry["remark"].value("text", "");
    }
    b.reads = reads_digest(entry.value("printed", json()), entry.value("quoted", json::array()));
    s.baseline_claims[id] = std::move(b);
  }
  s.baseline = name;
  s.accept_fixes = true;
  s.overrides["baseline"] = name;
}

namespace {

/// The formula references a claim read (its result's printed formulas).
std::set<std::string> references_read(const claim_result& r) {
  std::set<std::string> out;
  if (r.printed.is_object() && r.printed.contains("formulas")) {
    for (const json& f : r.printed["formulas"]) out.insert(f.value("reference", std::string()));
  }
  out.erase("");
  return out;
}

/// A claim recorded as a finding or with a remark that now holds without it, told apart: changed when
/// a claim that reads one of its displays no longer has its recorded verdict (the display changed
/// under both: a premise it reads broke; the first such claim of the run is the cause), or when the
/// text it reads is the text recorded (nothing it reads changed: the harness's judgment did); else
/// fixed, the text it reads changed.
void resolve_fixes(run_record& r, const scene& s) {
  for (claim_outcome& o : r.outcomes) {
    if (!o.fixed) continue;
    const std::set<std::string> mine = references_read(o.result);
    for (const claim_outcome& other : r.outcomes) {
      if (&other == &o || other.fixed || outcome_as_expected(other)) continue;
      for (const std::string& ref : references_read(other.result)) {
        if (!mine.count(ref)) continue;
        o.changed_cause = other.checked->id;
        o.changed = fmt::format("a consequence of {}, which reads the same ({}) and no longer has its recorded verdict: the premise changed, not "
                                "this claim's own text",
                                other.checked->id, ref);
        break;
      }
      if (!o.changed.empty()) break;
    }
    if (o.changed.empty()) {
      const auto from_baseline = s.baseline_claims.find(o.checked->id);
      const std::string recorded = from_baseline != s.baseline_claims.end() ? from_baseline->second.reads : o.checked->expected_reads;
      const std::string now = reads_digest(o.result.printed, o.result.quoted);
      if (!recorded.empty() && recorded == now) {
        o.changed = "nothing it reads changed (the displays and sentences it reads are the recorded ones): the harness's judgment changed, not the "
                    "document";
      }
    }
    if (!o.changed.empty()) {
      o.fixed = false;
      o.fix_accepted = false;
    }
  }
}

/// Each erratum whose record names the conclusions it leaves standing: those claims, when every one of
/// them ran and holds (claim_outcome::conclusions_standing).
void conclusions_standing(run_record& r) {
  for (claim_outcome& o : r.outcomes) {
    const std::vector<std::string>& kept = o.checked->conclusions_kept;
    if (o.result.outcome != verdict::erratum || kept.empty()) continue;
    const bool all_hold = std::all_of(kept.begin(), kept.end(), [&](const std::string& id) {
      const auto at = std::find_if(r.outcomes.begin(), r.outcomes.end(), [&](const claim_outcome& other) { return other.checked->id == id; });
      return at != r.outcomes.end() && meaning(at->result.outcome).affirms;
    });
    if (all_hold) o.conclusions_standing = kept;
  }
}

}  // namespace

std::string text_change(const std::string& what, const std::string& recorded, const std::string& now) {
  const std::size_t k = utf8_first_difference(recorded, now);
  return fmt::format("{} is not the recorded one: recorded '{}', now '{}'", what, utf8_around(recorded, k, 160), utf8_around(now, k, 160));
}

std::string correction_change(const std::string& recorded, const std::string& now) { return text_change("its correction", recorded, now); }

run_record run(const scene& s, std::shared_ptr<const claim_book> book, const paper_reading& paper, const progress_callback& progress,
               const std::function<void(const std::string&, double)>& section_progress, const progress_sink& work, const claim_checker& checker) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  run_record r;
  r.run_scene = s;
  if (!book) throw std::logic_error("run: no book");
  r.book = book;
  r.validation = s.overrides.value("validate", false) || !book->guards;
  r.of_the_paper = book->checked_document() == nullptr;
  r.paper_origin = paper.origin;
  run_memo memo;  // what the run's claims and sections compute once (Table 1's search), gone with the run
  run_context ctx{s.precisions, s.seed, s.samples, &paper};
  ctx.book = book.get();
  ctx.memo = &memo;
  ctx.enclosure_budget_digits = s.enclosure_budget_digits;
  for (std::size_t k = 0; k < s.claims.size(); ++k) {
    throw_if_interrupted();
    const claim& c = book->find(s.claims[k]);
    if (progress) progress(k, s.claims.size(), c, nullptr);
    claim_outcome outcome;
    outcome.checked = &c;
    const auto override_it = s.expected_overrides.find(c.id);
    outcome.expected = override_it == s.expected_overrides.end() ? c.expected : override_it->second;
    const auto claim_start = clock::now();
    try {
      outcome.result = checker ? checker(c, ctx) : check_claim(c, ctx);
    } catch (const interrupted&) {
      throw;
    } catch (const claims_file_error&) {  // an argument only the run could judge: bad input (exit 2), no verdict
      throw;
    } catch (const document_error&) {
      throw;
    } catch (const std::exception& e) {
      outcome.result = claim_result{};
      outcome.result.outcome = verdict::fails;
      outcome.result.evidence["error"] = std::string("the check threw: ") + e.what();
      outcome.threw = true;
      r.internal_errors.push_back(c.id + ": " + e.what());
    }
    outcome.seconds = std::chrono::duration<double>(clock::now() - claim_start).count();
    // What the record (or the baseline) expects beyond the verdict: an erratum's correction, a remark.
    const bool overridden = s.expected_overrides.find(c.id) != s.expected_overrides.end();
    const auto from_baseline = s.baseline_claims.find(c.id);
    const bool baselined = from_baseline != s.baseline_claims.end();
    const std::string recorded = baselined ? from_baseline->second.correction : overridden ? std::string() : c.expected_correction;
    if (baselined) {
      outcome.expected_remark = from_baseline->second.remark_kind;
      outcome.expected_remark_text = from_baseline->second.remark;
    } else if (!overridden && c.expects_remark()) {
      outcome.expected_remark = c.kind;
      outcome.expected_remark_text = c.expected_correction;
    }
    const claim_result& got = outcome.result;
    if (meaning(outcome.expected).corrected && got.outcome == outcome.expected && !recorded.empty() && got.correction != recorded) {
      outcome.content_changed = correction_change(recorded, got.correction);
    }
    if (!r.validation && meaning(got.outcome).affirms && got.outcome == outcome.expected) {
      if (outcome.expected_remark == finding::none && got.remark_kind != finding::none) {
        outcome.content_changed = fmt::format("it holds with a remark the record does not have ({}: {})", to_string(got.remark_kind), got.remark);
      } else if (outcome.expected_remark != finding::none && got.remark_kind != finding::none &&
                 (got.remark_kind != outcome.expected_remark ||
                  (!outcome.expected_remark_text.empty() && got.remark != outcome.expected_remark_text))) {
        outcome.content_changed = got.remark_kind != outcome.expected_remark
                                      ? fmt::format("its remark is of another class: recorded {}, now {}", to_string(outcome.expected_remark),
                                                    to_string(got.remark_kind))
                                      : text_change("its remark", outcome.expected_remark_text, got.remark);
      }
    }
    // A finding or a remark of the record that the claim now holds without: fixed, or changed by a
    // premise (resolve_fixes, once every claim ran). The ledger's expectation, or the baseline's.
    const bool recorded_finding = is_finding(outcome.expected) || outcome.expected_remark != finding::none;
    if (meaning(got.outcome).affirms && got.remark_kind == finding::none && recorded_finding && (!overridden || !s.baseline.empty())) {
      outcome.fixed = true;
      outcome.fix_accepted = s.accept_fixes;
    }
    r.outcomes.push_back(std::move(outcome));
    if (progress) progress(k, s.claims.size(), c, &r.outcomes.back());
  }
  resolve_fixes(r, s);
  conclusions_standing(r);
  // Consequences traced: a claim that does not hold, judged again with an erratum's corrected
  // formulas, that then holds, is counted under that erratum.
  {
    std::vector<const claim*> claims;
    std::vector<const claim_result*> results;
    for (const claim_outcome& o : r.outcomes) {
      claims.push_back(o.checked);
      results.push_back(&o.result);
    }
    const std::vector<std::optional<consequence>> traced =
        trace_consequences(claims, results, ctx, checker ? claim_judge(checker) : claim_judge(check_claim));
    for (std::size_t k = 0; k < traced.size(); ++k) {
      if (!traced[k]) continue;
      claim_outcome& o = r.outcomes[k];
      o.consequence_of = traced[k]->cause;
      const std::string follows = fmt::format("Follows from `{}`: holds once {} is corrected as that claim proves.", traced[k]->cause,
                                              fmt::format("{}", fmt::join(traced[k]->corrected, " and ")));
      o.result.note = o.result.note.empty() ? follows : follows + " " + o.result.note;
    }
  }
  for (const claim_outcome& o : r.outcomes) {
    if (!o.result.printed.is_null()) {
      r.ginac_derivation_seconds = ginac_derivation_seconds();
      break;
    }
  }
  // What text was checked; its earlier text judged again for the claims the run checked.
  {
    std::vector<checked_claim> checked;
    for (const claim_outcome& o : r.outcomes) checked.push_back({o.checked->id, o.result.quoted, o.result.outcome});
    r.provenance = provenance_json(paper, ctx, checked);
  }
  record_certificates(r, false);  // each claim's evidence "coq": exported or why not (checked by --certify)
  // The sections the scene asks for, each run by its registry entry (experiment_section.hpp), with
  // the run's memo, where it reports its work and the run's document.
  const section_inputs inputs{&memo, work, &paper};
  for (const experiment_settings::entry& entry : s.experiments.entries()) {
    throw_if_interrupted();
    const auto section_start = clock::now();
    r.sections.push_back(entry.section->run(entry.settings, inputs));
    r.section_seconds.push_back(std::chrono::duration<double>(clock::now() - section_start).count());
    if (section_progress) section_progress(r.sections.back().name, r.section_seconds.back());
  }
  // Φ₃ at the paper's configuration: the paper's, not a document's that a claims file checks.
  if (r.of_the_paper) r.paper_configuration = paper_configuration(s.precisions);
  r.environment = build_environment(s, paper);
  r.seconds = std::chrono::duration<double>(clock::now() - start).count();
  return r;
}

}  // namespace simpson::verify

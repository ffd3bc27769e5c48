// The run's verdict table (verdict_table.hpp): one rule for every claim and expectation.

#include <simpson/verify/verdict_table.hpp>

#include <fmt/format.h>

#include <algorithm>

namespace simpson::verify {

namespace {

bool certificate_rejected(const claim_outcome& o) {
  const json& evidence = o.result.evidence;
  return evidence.contains("coq") && evidence["coq"].value("status", "") == "failed";
}

}  // namespace

std::string recorded_as(const claim_outcome& o) {
  if (meaning(o.expected).affirms && o.expected_remark != finding::none) return "holds with a remark (" + to_string(o.expected_remark) + ")";
  return to_string(o.expected);
}

verdict_row claim_row(const claim_outcome& o, bool validation) {
  using status = verdict_row::status;
  verdict_row row;
  row.name = o.checked->id;
  row.suite = "claims";
  row.verdict = to_string(o.result.outcome);
  row.expected = to_string(o.expected);
  const auto set = [&](status state, std::string type, std::string message) {
    row.state = state;
    row.type = std::move(type);
    row.message = std::move(message);
  };
  const json& evidence = o.result.evidence;
  const verdict_meaning& met = meaning(o.result.outcome);
  const auto reason = [&]() { return evidence.value(met.reason_key, std::string(met.default_reason)); };
  if (evidence.contains("error")) {
    set(status::error, "internal-error", "internal error (a bug in the harness): " + evidence["error"].get<std::string>());
  } else if (met.met == verdict_meaning::row::not_counted) {
    set(status::skipped, met.name, reason());
  } else if (met.met == verdict_meaning::row::never_expected) {  // the tool's limit or a changed text, not a judgment
    set(status::failed, met.name,
        (validation ? row.verdict + ": " : "verdict " + row.verdict + ", expected " + row.expected + ": ") + reason());
  } else if (!o.changed.empty()) {  // recorded as a finding or a remark, holds now because a premise changed: never a fix
    set(status::failed, "changed",
        fmt::format("changed: recorded as {}, now holds{}: {} (not a fix: --accept-fixes does not pass it)", recorded_as(o),
                    o.result.remark.empty() ? "" : " with another remark", o.changed));
  } else if (o.fixed) {  // a finding or a remark of the record that now holds without it
    if (o.fix_accepted) {
      set(status::passed, "fixed-accepted", "fixed: recorded as " + recorded_as(o) + ", now holds (accepted: --accept-fixes)");
    } else {
      set(status::failed, "fixed", "fixed: recorded as " + recorded_as(o) + ", now holds (--accept-fixes accepts a fix)");
    }
  } else if (!outcome_as_expected(o) && validation) {  // no expected verdicts: the claim is to hold
    if (cause_of(o).empty()) {
      set(status::failed, "does-not-hold", row.verdict + ": the claim does not hold as written");
    } else {
      set(status::failed, "consequence", row.verdict + ": a consequence of " + cause_of(o) + ", which does not hold as written");
    }
  } else if (!o.content_changed.empty()) {  // the expected verdict, but another erratum or remark
    const bool remark = meaning(o.result.outcome).affirms;
    set(status::failed, remark ? "remark-changed" : "erratum-changed", (remark ? "holds, as expected, but " : "erratum, as expected, but ") + o.content_changed);
  } else if (!outcome_as_expected(o)) {
    set(status::failed, "unexpected-verdict", "verdict " + row.verdict + ", expected " + row.expected);
  } else if (certificate_rejected(o)) {
    set(status::failed, "certificate-rejected", "coqc rejected its Coq certificate");
  } else if (meaning(o.result.outcome).expected_failure) {
    set(status::expected_failure, "expected-failure",
        "expected failure: verdict fails, as the ledger expects" + (o.result.note.empty() ? std::string() : ": " + o.result.note));
  }
  return row;
}

verdict_row expectation_row(const section_result& section, const expectation& e) {
  verdict_row row;
  row.name = section.name + "." + e.key;
  row.suite = section.name;
  row.expectation = true;
  row.verdict = e.holds ? "holds" : "fails";
  row.expected = "holds";
  if (!e.holds) {
    row.state = verdict_row::status::failed;
    row.type = "expectation-failed";
    row.message = "the run did not show what was predicted: " + e.statement;
  }
  return row;
}

std::vector<verdict_row> verdict_table(const run_record& r) {
  std::vector<verdict_row> rows;
  for (const claim_outcome& o : r.outcomes) rows.push_back(claim_row(o, r.validation));
  for (const section_result& section : r.sections) {
    for (const expectation& e : section.expectations) rows.push_back(expectation_row(section, e));
  }
  return rows;
}

std::vector<std::string> rejected_certificates(const run_record& r) {
  std::vector<std::string> ids;
  for (const claim_outcome& o : r.outcomes) {
    if (certificate_rejected(o)) ids.push_back(o.checked->id);
  }
  return ids;
}

std::vector<std::string> failed_expectations(const run_record& r) {
  std::vector<std::string> keys;
  for (const verdict_row& row : verdict_table(r)) {
    if (row.expectation && fails_the_run(row)) keys.push_back(row.name);
  }
  return keys;
}

int run_exit_code(const run_record& r) {
  const std::vector<verdict_row> rows = verdict_table(r);
  const auto any = [&](auto&& test) { return std::any_of(rows.begin(), rows.end(), test); };
  if (!r.internal_errors.empty() || any([](const verdict_row& row) { return row.state == verdict_row::status::error; })) return 3;
  return any(fails_the_run) ? 1 : 0;
}

}  // namespace simpson::verify

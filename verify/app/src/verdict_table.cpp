// The run's verdict table (verdict_table.hpp): one rule for every claim and expectation.

#include <simpson/verify/verdict_table.hpp>

#include <algorithm>

namespace simpson::verify {

namespace {

bool certificate_rejected(const claim_outcome& o) {
  const json& evidence = o.result.evidence;
  return evidence.contains("coq") && evidence["coq"].value("status", "") == "failed";
}

}  // namespace

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
  const verdict v = o.result.outcome;
  // A verdict never expected, with its reason: a validation speaks of what holds, not of expectations.
  const auto limit = [&](const char* field, const char* otherwise) {
    return (validation ? row.verdict + ": " : "verdict " + row.verdict + ", expected " + row.expected + ": ") + evidence.value(field, std::string(otherwise));
  };
  if (evidence.contains("error")) {
    set(status::error, "internal-error", "internal error (a bug in the harness): " + evidence["error"].get<std::string>());
  } else if (v == verdict::skipped) {
    set(status::skipped, "skipped", evidence.value("skipped", std::string("the prover is not installed")));
  } else if (v == verdict::undecided) {  // never expected (expectable): the tool's limit, not a judgment
    set(status::failed, "undecided", limit("undecided", "no enclosure decided the claim"));
  } else if (v == verdict::unproved) {
    set(status::failed, "unproved", limit("unproved", "Gappa could not bound the round-off"));
  } else if (v == verdict::text_changed) {
    set(status::failed, "text-changed", limit("text_changed", "the quoted words changed"));
  } else if (o.fixed) {  // a finding of the record that now holds
    if (o.fix_accepted) {
      set(status::passed, "fixed-accepted", "fixed: recorded as " + row.expected + ", now holds (accepted: --accept-fixes)");
    } else {
      set(status::failed, "fixed", "fixed: recorded as " + row.expected + ", now holds (--accept-fixes accepts a fix)");
    }
  } else if (!outcome_as_expected(o) && validation) {  // no expected verdicts: the claim is to hold
    if (cause_of(o).empty()) {
      set(status::failed, "does-not-hold", row.verdict + ": the claim does not hold as written");
    } else {
      set(status::failed, "consequence", row.verdict + ": a consequence of " + cause_of(o) + ", which does not hold as written");
    }
  } else if (!o.content_changed.empty()) {  // the expected erratum, but another one
    set(status::failed, "erratum-changed", "erratum, as expected, but " + o.content_changed);
  } else if (!outcome_as_expected(o)) {
    set(status::failed, "unexpected-verdict", "verdict " + row.verdict + ", expected " + row.expected);
  } else if (certificate_rejected(o)) {
    set(status::failed, "certificate-rejected", "coqc rejected its Coq certificate");
  } else if (v == verdict::fails) {
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

// simpson-verify's lists (cli_commands.hpp): the claims of a book, the scenes, the precisions, the
// sections of the registry and the verdicts' meanings.

#include "cli_commands.hpp"

#include <simpson/precision.hpp>
#include <simpson/verify/experiment_section.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/scene.hpp>
#include <simpson/verify/verdict.hpp>

#include <fmt/core.h>
#include <fmt/format.h>

#include <string>
#include <vector>

namespace simpson::verify {
namespace {

/// What decides a record, as the Markdown list spells it: "shape `identity`", "observes
/// `table1.printed-orders`" or "check `scaling`".
std::string decided_by_markdown(const decider& d) {
  if (const shape_decider* s = std::get_if<shape_decider>(&d)) return "shape `" + s->shape + "`";
  if (const observation_decider* o = std::get_if<observation_decider>(&d)) return "observes `" + o->fact + "`";
  return "check `" + std::get<check_decider>(d).check + "`";
}

}  // namespace

int list_claims(const claim_book& book, const std::string& format) {
  if (format == "json") {
    json out = json::array();
    for (const claim& c : book.claims) {
      json one{{"id", c.id},           {"section", c.section},   {"equation", c.equation}, {"statement", c.statement},
               {"methods", c.methods}, {"check", to_string(c.decided_by)}, {"expected", to_string(c.expected)}};
      if (c.kind != finding::none) one["finding"] = to_string(c.kind);
      if (!c.follows_from.empty()) one["follows_from"] = c.follows_from;
      out.push_back(std::move(one));
    }
    fmt::print("{}\n", out.dump(2));
    return 0;
  }
  if (format == "markdown") {
    // One row per record: what decides it, what it reads, whose it is, what it is expected to be,
    // and the core formulas it binds to the print (docs/ledger.md's list, generated).
    fmt::print("| id | § | decided by | reads | origin | expected | binds our core |\n|---|---|---|---|---|---|---|\n");
    for (const claim_record& r : book.records) {
      const claim& c = book.find(r.id);
      std::vector<std::string> core;
      for (const core_binding& b : r.core) core.push_back("`" + b.function + "`");
      const std::string expected = to_string(c.expected) + (c.follows_from.empty() ? "" : ", follows from `" + c.follows_from + "`");
      fmt::print("| `{}` | {} | {} | {} | {} | {} | {} |\n", c.id, c.section, decided_by_markdown(c.decided_by),
                 c.equation, to_string(c.origin), expected, core.empty() ? "" : fmt::format("{}", fmt::join(core, ", ")));
    }
    return 0;
  }
  for (const claim& c : book.claims) {
    fmt::print("{:<34} §{:<8} {:<8} {}\n", c.id, c.section, to_string(c.expected), c.equation);
  }
  return 0;
}

int list_scenes() {
  for (const auto& [name, text] : embedded_scenes()) {
    const scene s = parse_scene(text, name, paper_book());
    fmt::print("{:<8} {} claims, {} precisions: {}\n", name, s.claims.size(), s.precisions.size(), s.description);
  }
  return 0;
}

int list_precisions() {
  fmt::print("double, long double (or long-double), float128, bin50, bin100, mpfr:D ({} <= D <= {}), rational\n",
             simpson::precision::min_mpfr_digits, simpson::precision::max_mpfr_digits);
  for (const simpson::precision& p : simpson::default_precisions()) fmt::print("{:<12} epsilon {}\n", p.name(), p.epsilon());
  return 0;
}

int list_sections() {
  fmt::print("| section | computes | scene keys | --precisions | --timing-runs | --long |\n|---|---|---|---|---|---|\n");
  for (const experiment_section* section : experiment_sections()) {
    std::vector<std::string> keys;
    for (const std::string& key : section->keys()) keys.push_back("`" + key + "`");
    const char* precisions = section->precisions() == experiment_section::precisions_use::applied   ? "applied"
                             : section->precisions() == experiment_section::precisions_use::refused ? "refused"
                                                                                                     : "ignored";
    fmt::print("| `{}` | {} | {} | {} | {} | {} |\n", section->name(), section->summary(), fmt::join(keys, ", "), precisions,
               section->times_runs() ? "yes" : "", section->runs_long() ? "yes" : "");
  }
  return 0;
}

int list_verdicts() {
  fmt::print("| verdict | means | a finding | a record may expect it | carries | a run's row | met as expected, in JUnit | summary | "
             "report.json counts |\n|---|---|---|---|---|---|---|---|---|\n");
  for (const verdict_meaning& m : verdict_meanings) {
    const char* row = m.met == verdict_meaning::row::as_judged        ? "compared with the expected verdict"
                      : m.met == verdict_meaning::row::never_expected ? "fails, whatever was expected"
                                                                       : "neither passes nor fails";
    const char* carries = m.affirms ? "a remark, when it says more or less than holds" : m.corrected ? "the proved correction" : "";
    const std::string junit = !m.expectable        ? std::string()
                              : m.expected_failure ? std::string("an expected failure")
                              : *m.passed_words    ? fmt::format("passed: “{}”", m.passed_words)
                                                   : std::string("passed");
    fmt::print("| `{}` | {} | {} | {} | {} | {} | {} | {} | `summary.{}` |\n", m.name, m.legend, m.finding ? "yes" : "", m.expectable ? "yes" : "", carries, row,
               junit, fmt::format(fmt::runtime(m.counted_as), "N"), m.count_key);
  }
  return 0;
}

}  // namespace simpson::verify

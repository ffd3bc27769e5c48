#include <simpson/verify/sentence_holes.hpp>
#include <simpson/verify/ledger.hpp>

#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/tex_math.hpp>
#include <simpson/verify/formula_reference.hpp>
#include <simpson/verify/tex_document.hpp>
#include <simpson/verify/quoted_words.hpp>

#include <simpson/shapes/proof_shapes.hpp>

#include "bespoke/bespoke_checks.hpp"
#include "check_registry.hpp"
#include "claim_support.hpp"
#include "core_bindings.hpp"
#include "derivation_support.hpp"
#include "embedded_claims.hpp"
#include "published_facts.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <set>
#include <stdexcept>

namespace simpson::verify {

std::string embedded_claims_text() { return detail::embedded_claims_bytes(); }

namespace detail {

const check_registry& registered_checks() {
  static const check_registry checks = [] {
    check_registry all;
    add_scaling_lemma_check(all);
    add_abstract_checks(all);
    add_section2_checks(all);
    add_section5_checks(all);
    add_section6_7_checks(all);
    add_convention_checks(all);
    add_figure1_check(all);
    add_nonlinear_internal_node_check(all);
    add_roundoff_checks(all);
    add_peer_checks(all);
    add_shear_checks(all);
    add_beyond_checks(all);
    add_beyond_ndof_checks(all);
    add_family_checks(all);
    return all;
  }();
  return checks;
}

}  // namespace detail

namespace {

/// The labels of the displays a shape record reads (its formula, matrix, condition and definition
/// arguments that name a \label).
std::vector<std::string> labels_read(const claim_record& r) {
  std::vector<std::string> labels;
  if (r.shape.empty()) return labels;
  for (const detail::shape_parameter& p : detail::proof_shapes().at(r.shape).parameters) {
    const auto it = r.with.find(p.name);
    if (it == r.with.end() || p.kind == detail::argument_kind::word || p.kind == detail::argument_kind::symbols ||
        p.kind == detail::argument_kind::words) {
      continue;
    }
    for (const std::string& value : it->second.values) {
      const formula_reference reference = parse_reference(value);
      if (reference.where == formula_reference::kind::labelled) labels.push_back(reference.key);
    }
  }
  return labels;
}

/// A shape's verdict against the sentence that states it (`says`, `property`): a fact that holds
/// while the words deny it is a wording erratum, corrected by the fact; words that are neither the
/// property nor its denial make the verdict text-changed (quote throws).
detail::decider_evidence as_the_sentence_says(detail::decider_evidence e, const detail::shape_call& call, const run_context& ctx) {
  const auto says = call.with.find("says"), property = call.with.find("property");
  if (says == call.with.end() || property == call.with.end()) return e;
  claim_result& result = e.found;
  const quoted_sentence said = quote(ctx, says->second.values.front());
  const bool affirmed = said.choice("property", affirmed_or_denied(property->second.values.front())) == "affirmed";
  result.evidence["stated"] = affirmed ? property->second.values.front() : "not " + property->second.values.front();
  const json& statement = result.evidence["exact"]["statement"];
  const std::string fact = "It is " + property->second.values.front() + ": " + (statement.is_string() ? statement.get<std::string>() : call.statement);
  bool denied = false;
  e = detail::as_the_words_say(std::move(e), affirmed, fact, &denied);
  if (denied) e.found.note = "Wording: the sentence denies what the formulas it judges prove.";
  return e;
}

/// What decides a record, as evidence: its shape run with its arguments and the file's declarations
/// (then against the sentence that states it), the fact an experiment publishes that it observes, or
/// its bespoke check with its facets; each with our core bound to the print.
detail::judge judge_of(const claim_record& r, const std::shared_ptr<const claim_declarations>& declared) {
  detail::shape_call call{r.id, r.statement, r.with, declared};
  if (!r.shape.empty()) {
    const detail::proof_shape& shape = detail::proof_shapes().at(r.shape);
    return [call, run = shape.run, core = r.core, coq_none = r.coq_none](const run_context& ctx) {
      detail::shape_call with_document = call;
      with_document.corrections = ctx.corrections;
      const auto start = std::chrono::steady_clock::now();
      detail::decider_evidence e = run(with_document, ctx);
      e.found.printed_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();  // GiNaC's and ours
      if (!e.goals && e.found.certificate.empty() && e.found.certificate_missing.empty()) {
        e.found.certificate_missing = detail::without_coq_statement(coq_none);
      }
      return detail::bound_to_core(as_the_sentence_says(std::move(e), with_document, ctx), core, with_document, ctx);
    };
  }
  if (!r.observes.empty()) {
    const auto fact = detail::published_facts().find(r.observes);
    if (fact == detail::published_facts().end()) throw std::logic_error("claims_of: no experiment publishes '" + r.observes + "'");
    return [call, publish = fact->second.publish, core = r.core, coq_none = r.coq_none](const run_context& ctx) {
      detail::shape_call with_document = call;
      with_document.corrections = ctx.corrections;
      return detail::bound_to_core(detail::observed(publish(ctx), coq_none), core, with_document, ctx);
    };
  }
  const detail::registered_check* check = detail::registered_checks().find(r.check);
  if (!check) throw std::logic_error("claims_of: no check is named '" + r.check + "'");
  return detail::bespoke_judge(r, *check, declared);
}

/// The check of a record: what decides it, made a verdict by decide() (decide.hpp), the one place
/// that makes one.
std::function<claim_result(const run_context&)> check_of(const claim_record& r, const std::shared_ptr<const claim_declarations>& declared) {
  return detail::claim_check_of(judge_of(r, declared), r.id, r.statement);
}

std::vector<claim> claims_of(const std::vector<claim_record>& records, const std::shared_ptr<const claim_declarations>& declared) {
  std::vector<claim> out;
  for (const claim_record& r : records) {
    claim c{r.id, r.section, r.equation, r.statement, r.methods, r.expected, check_of(r, declared), r.kind, r.follows_from, r.typographical, r.origin};
    c.decided_by = decider_of(r);
    c.labels_read = labels_read(r);
    c.headline = r.headline;
    c.coq_none = r.coq_none;
    c.expected_correction = meaning(r.expected).corrected ? r.correction : r.remark;
    c.expected_reads = r.reads;
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace

namespace detail {

judge bespoke_judge(const claim_record& r, const registered_check& check,
                    const std::shared_ptr<const claim_declarations>& declared) {
  const shape_call call{r.id, r.statement, r.with, declared};
  return [call, check, core = r.core, coq_none = r.coq_none](const run_context& ctx) {
    shape_call with_document = call;
    with_document.corrections = ctx.corrections;
    return with_facets(bound_to_core(check.check(ctx), core, with_document, ctx), check, call.claim_id, call.statement, coq_none, ctx);
  };
}

}  // namespace detail

claim_book read_claim_book(const std::string& text, const std::string& file) {
  claims_file_contents contents = read_claims_contents(text, file, [](const std::string& field, const std::string& name) {
    if (field == "shape") return detail::proof_shapes().count(name) > 0;
    if (field == "core") return detail::find_core_formula(name) != nullptr;
    if (field == "observes") return detail::published_facts().count(name) > 0;
    return detail::registered_checks().find(name) != nullptr;
  });
  for (const claim_record& r : contents.records) {
    if (!r.shape.empty()) detail::check_shape_arguments(r, file);
  }
  claim_book book;
  book.file = file;
  book.document = contents.document;
  book.declarations = std::make_shared<const claim_declarations>(read_declarations(contents, file));
  book.records = std::move(contents.records);
  book.claims = claims_of(book.records, book.declarations);
  if (!book.document) book.formulas = printed_formula_locations();
  book.sections = experiment_sections();
  book.guards = std::any_of(book.records.begin(), book.records.end(), [](const claim_record& r) { return r.expected_given; });
  return book;
}

std::vector<claim_record> read_claims_with_known_checks(const std::string& text, const std::string& file) {
  return read_claim_book(text, file).records;
}

const claim_book& paper_book() {
  static const claim_book book = [] {
    claim_book read;
    try {
      read = read_claim_book(embedded_claims_text(), "claims/paper.toml");
    } catch (const claims_file_error& e) {
      throw std::logic_error(std::string("the embedded claims file does not read: ") + e.what());  // a harness fault
    }
    // Every registered check (its facets with it) is named by some record: one no record names is
    // dead code.
    std::set<std::string> named, observed;
    for (const claim_record& r : read.records) {
      named.insert(r.check);
      observed.insert(r.observes);
    }
    for (const auto& [name, check] : detail::registered_checks().all()) {
      if (!named.count(name)) throw std::logic_error("check '" + name + "' is registered but no record of claims/paper.toml names it");
    }
    for (const auto& [name, fact] : detail::published_facts()) {
      if (!observed.count(name)) throw std::logic_error("fact '" + name + "' is published but no record of claims/paper.toml observes it");
    }
    return read;
  }();
  return book;
}

const claim& claim_book::find(const std::string& id) const {
  for (const claim& c : claims) {
    if (c.id == id) return c;
  }
  throw std::invalid_argument("unknown claim id '" + id + "' (see --list-claims)");
}

void check_claims_file_formulas(claim_book& book, const paper_source& source, const std::vector<std::string>* only) {
  const tex_document document = read_document(source, book.checked_document() ? "document" : "paper");
  for (const claim_record& r : book.records) {
    if (only && std::find(only->begin(), only->end(), r.id) == only->end()) continue;
    if (r.shape.empty()) {
      detail::check_core_bindings(r, book.file, document, *book.declarations);
      continue;
    }
    const std::string printed = detail::check_shape_formulas(r, book.file, document, *book.declarations);
    detail::check_core_bindings(r, book.file, document, *book.declarations);
    if (!r.statement.empty()) continue;
    // A record without a statement: the reports, and its shape's notes, show the TeX it reads.
    claim_record stated = r;
    stated.statement = printed;
    for (claim& c : book.claims) {
      if (c.id != r.id) continue;
      c.statement = printed;
      c.check = check_of(stated, book.declarations);
    }
  }
}

paper_reading read_paper(const paper_source& paper) { return read_paper(paper, paper_book().declarations->reading, printed_formula_locations()); }

std::vector<std::string> required_claim_ids() {
  std::vector<std::string> out;
  for (const claim& c : paper_book().claims) {
    if (c.headline) out.push_back(c.id);
  }
  return out;
}

}  // namespace simpson::verify

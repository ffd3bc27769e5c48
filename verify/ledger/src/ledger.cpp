#include <simpson/verify/sentence_holes.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/printed_checks.hpp>

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

#include <fmt/format.h>
#include <fmt/ranges.h>

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

book_deciders paper_deciders() {
  book_deciders deciders;
  deciders.knows = [](const std::string& field, const std::string& name) {
    if (field == "core") return detail::find_core_formula(name) != nullptr;
    if (field == "observes") return detail::published_facts().count(name) > 0;
    return field == "check" && detail::registered_checks().find(name) != nullptr;
  };
  deciders.judge = [](const claim_record& r, const std::shared_ptr<const claim_declarations>& declared) -> detail::judge {
    const detail::shape_call call{r.id, r.statement, r.with, declared};
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
  };
  deciders.bind_core = detail::bound_to_core;
  deciders.check_core = detail::check_core_bindings;
  deciders.formulas_read = formulas_its_check_reads;
  return deciders;
}

namespace {

/// No stand-ins: a document other than the paper is judged by what it prints. A bespoke check proves
/// the paper's own statements (on the paper, or an edited copy of it); a published fact is of the
/// harness's experiment, so a document's record observes it only with a `core` binding that proves
/// the document's printed scheme is the experiment's. Throws claims_file_error naming the record.
void only_what_the_document_prints(const claim_book& book) {
  for (const claim_record& r : book.records) {
    if (!r.check.empty()) {
      throw claims_file_error(book.file, r.line, "check",
                              fmt::format("'{}' is one of the paper's bespoke proofs: it judges the paper or an edited copy of it, not this "
                                          "[document]; decide record '{}' by a proof shape on the document's own formulas",
                                          r.check, r.id));
    }
    if (r.observes.empty()) continue;
    const std::vector<std::string>& schemes = detail::published_facts().at(r.observes).schemes;
    const bool bound = std::any_of(r.core.begin(), r.core.end(), [&](const core_binding& b) {
      return std::find(schemes.begin(), schemes.end(), b.function) != schemes.end();
    });
    if (bound) continue;
    throw claims_file_error(
        book.file, r.line, "observes",
        schemes.empty()
            ? fmt::format("'{}' is a fact of the harness's own experiment, and no formula of our core is that experiment's scheme yet: "
                          "record '{}' cannot show that the document's printed scheme is the one the experiment runs",
                          r.observes, r.id)
            : fmt::format("'{}' is a fact of the harness's own experiment: on a [document], record '{}' observes it only with a core "
                          "binding of the document's printed scheme to the experiment's (core = {{ function = \"{}\", formula = ... }}; "
                          "the functions: {})",
                          r.observes, r.id, schemes.front(), fmt::join(schemes, ", ")));
  }
}

}  // namespace

claim_book read_claim_book(const std::string& text, const std::string& file) {
  claim_book book = read_claim_book(text, file, paper_deciders());
  if (book.document) {
    only_what_the_document_prints(book);
  } else {
    book.formulas = printed_formula_locations();
  }
  book.sections = experiment_sections();
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

paper_reading read_paper(const paper_source& paper) { return read_paper(paper, paper_book().declarations->reading, printed_formula_locations()); }

std::vector<std::string> required_claim_ids() {
  std::vector<std::string> out;
  for (const claim& c : paper_book().claims) {
    if (c.headline) out.push_back(c.id);
  }
  return out;
}

}  // namespace simpson::verify

#include <simpson/verify/ledger.hpp>

#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/tex_math.hpp>
#include <simpson/verify/formula_reference.hpp>
#include <simpson/verify/tex_macros.hpp>
#include <simpson/verify/quoted_words.hpp>

#include "check_registry.hpp"
#include "claim_support.hpp"
#include "proof_shapes.hpp"
#include "printed_check_support.hpp"
#include "bespoke/bespoke_checks.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <set>
#include <stdexcept>

namespace simpson::verify {

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
    add_section8_9_checks(all);
    add_roundoff_checks(all);
    add_peer_checks(all);
    add_shear_checks(all);
    add_beyond_checks(all);
    add_beyond_ndof_checks(all);
    add_beyond_fpu_checks(all);
    add_family_checks(all);
    return all;
  }();
  return checks;
}

}  // namespace detail

namespace {

/// The document of the claims file installed, if it declares one (use_claims_file).
std::optional<claims_document>& installed_document_storage() {
  static std::optional<claims_document> document;
  return document;
}

/// The labels of the displays a shape record reads (its formula, matrix, condition and definition
/// arguments that name a \label).
std::vector<std::string> labels_read(const claim_record& r) {
  std::vector<std::string> labels;
  if (r.shape.empty()) return labels;
  for (const detail::shape_parameter& p : detail::proof_shapes().at(r.shape).parameters) {
    const auto it = r.with.find(p.name);
    if (it == r.with.end() || p.kind == detail::argument_kind::word || p.kind == detail::argument_kind::symbols) continue;
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
claim_result as_the_sentence_says(claim_result result, const detail::shape_call& call, const run_context& ctx) {
  const auto says = call.with.find("says"), property = call.with.find("property");
  if (says == call.with.end() || property == call.with.end()) return result;
  const quoted_sentence said = quote(ctx, says->second.values.front());
  const bool affirmed = said.choice("property", detail::affirmed_or_denied(property->second.values.front())) == "affirmed";
  result.evidence["stated"] = affirmed ? property->second.values.front() : "not " + property->second.values.front();
  const json& statement = result.evidence["exact"]["statement"];
  const std::string fact = "It is " + property->second.values.front() + ": " + (statement.is_string() ? statement.get<std::string>() : call.statement);
  const bool denied = result.outcome == verdict::holds && !affirmed;
  result = detail::as_the_words_say(std::move(result), affirmed, fact);
  if (denied) result.note = "Wording: the sentence denies what the formulas it judges prove.";
  return result;
}

/// The check of a record: its bespoke check, or its shape run with its arguments.
detail::check_function check_of(const claim_record& r) {
  if (!r.shape.empty()) {
    const detail::proof_shape& shape = detail::proof_shapes().at(r.shape);
    detail::shape_call call{r.id, r.statement, r.with, nullptr};
    return [call, run = shape.run](const run_context& ctx) {
      detail::shape_call with_document = call;
      with_document.document = installed_document_storage() ? &*installed_document_storage() : nullptr;
      if (with_document.statement.empty()) with_document.statement = find_claim(call.claim_id).statement;  // the TeX read
      const auto start = std::chrono::steady_clock::now();
      claim_result result = run(with_document, ctx);
      result.printed_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();  // GiNaC's and ours
      return as_the_sentence_says(std::move(result), with_document, ctx);
    };
  }
  const detail::registered_check* check = detail::registered_checks().find(r.check);
  if (!check) throw std::logic_error("claims_of: no check is named '" + r.check + "'");
  return check->check;
}

}  // namespace

std::vector<claim> claims_of(const std::vector<claim_record>& records) {
  std::vector<claim> out;
  for (const claim_record& r : records) {
    claim c{r.id, r.section, r.equation, r.statement, r.methods, r.expected, check_of(r), r.kind, r.follows_from, r.typographical, r.origin};
    c.check_name = r.shape.empty() ? r.check : "shape " + r.shape;
    c.labels_read = labels_read(r);
    c.headline = r.headline;
    c.coq_none = r.coq_none;
    out.push_back(std::move(c));
  }
  return out;
}

claims_file_contents read_claims_with_known_names(const std::string& text, const std::string& file) {
  claims_file_contents contents = read_claims_contents(text, file, [](const std::string& field, const std::string& name) {
    if (field == "shape") return detail::proof_shapes().count(name) > 0;
    return detail::registered_checks().find(name) != nullptr;
  });
  for (const claim_record& r : contents.records) {
    if (!r.shape.empty()) detail::check_shape_arguments(r, file);
  }
  return contents;
}

std::vector<claim_record> read_claims_with_known_checks(const std::string& text, const std::string& file) {
  return read_claims_with_known_names(text, file).records;
}

namespace {

/// The claims of a file given on the command line, once installed (use_claims_file).
std::optional<std::vector<claim>>& installed_claims() {
  static std::optional<std::vector<claim>> claims;
  return claims;
}

/// The records of the file installed, and its name (check_claims_file_formulas).
std::vector<claim_record>& installed_records() {
  static std::vector<claim_record> records;
  return records;
}
std::string& installed_file() {
  static std::string file;
  return file;
}

/// The records of the embedded claims/paper.toml.
const std::vector<claim_record>& embedded_records() {
  static const std::vector<claim_record> records = [] {
    std::vector<claim_record> read;
    try {
      read = read_claims_with_known_checks(embedded_claims_text(), "claims/paper.toml");
    } catch (const claims_file_error& e) {
      throw std::logic_error(std::string("the embedded claims file does not read: ") + e.what());  // a harness fault
    }
    // Every registered check (its facets with it) is named by some record: one no record names is
    // dead code.
    std::set<std::string> named;
    for (const claim_record& r : read) named.insert(r.check);
    for (const auto& [name, check] : detail::registered_checks().all()) {
      if (!named.count(name)) throw std::logic_error("check '" + name + "' is registered but no record of claims/paper.toml names it");
    }
    return read;
  }();
  return records;
}

const std::vector<claim>& embedded_ledger() {
  static const std::vector<claim> claims = claims_of(embedded_records());
  return claims;
}

}  // namespace

const std::vector<claim>& ledger() { return installed_claims() ? *installed_claims() : embedded_ledger(); }

void use_claims_file(const std::string& text, const std::string& file) {
  claims_file_contents contents = read_claims_with_known_names(text, file);
  // The document's functions: applied as f(x) by the reader from now on.
  if (contents.document) {
    for (const std::string& tex : contents.document->functions) {
      GiNaC::ex name;
      try {
        name = parse_tex_math(tex, paper_symbols());
      } catch (const tex_parse_error&) {
      }
      if (!GiNaC::is_a<GiNaC::symbol>(name)) throw claims_file_error(file, contents.document->line, "symbols.functions", "'" + tex + "' is not one name");
      declare_function(GiNaC::ex_to<GiNaC::symbol>(name).get_name());
    }
  }
  installed_claims() = claims_of(contents.records);
  installed_document_storage() = contents.document;
  installed_records() = std::move(contents.records);
  installed_file() = file;
}

const claims_document* installed_document() { return installed_document_storage() ? &*installed_document_storage() : nullptr; }

void check_claims_file_formulas(const paper_source& document, const std::vector<std::string>* only) {
  try {
    defined_macros(document.text);  // a macro definition that does not read: the document is at fault, and named, once
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("paper '" + document.origin + "', " + e.what());
  }
  const bool installed = installed_claims().has_value();
  for (const claim_record& r : installed ? installed_records() : embedded_records()) {
    if (r.shape.empty() || (only && std::find(only->begin(), only->end(), r.id) == only->end())) continue;
    const std::string printed =
        detail::check_shape_formulas(r, installed ? installed_file() : std::string("claims/paper.toml"), document, installed_document());
    if (!r.statement.empty() || !installed_claims()) continue;
    // A record without a statement: the reports show the TeX it reads.
    for (claim& c : *installed_claims()) {
      if (c.id == r.id) c.statement = printed;
    }
  }
}

const claim& find_claim(const std::string& id) {
  for (const claim& c : ledger()) {
    if (c.id == id) return c;
  }
  throw std::invalid_argument("unknown claim id '" + id + "' (see --list-claims)");
}

}  // namespace simpson::verify

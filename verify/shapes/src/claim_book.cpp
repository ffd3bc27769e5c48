#include <simpson/verify/claim_book.hpp>

#include <simpson/prove/printed_check_support.hpp>
#include <simpson/shapes/shape_support.hpp>
#include <simpson/verify/formula_reference.hpp>
#include <simpson/verify/quoted_words.hpp>
#include <simpson/verify/sentence_holes.hpp>
#include <simpson/verify/tex_document.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <exception>
#include <chrono>
#include <set>
#include <stdexcept>

namespace simpson::verify {

namespace {

/// Every record's refusal in one pass (bad input: each one line with its record and line): the one
/// refusal as it was thrown, or all of them, one line each, as one std::invalid_argument.
class refusals {
 public:
  explicit refusals(std::string file) : file_(std::move(file)) {}

  /// Runs `check` for the record `r`; false when it refused (its message kept).
  template <typename F>
  bool check(const claim_record& r, F&& check) {
    try {
      check();
      return true;
    } catch (const std::invalid_argument&) {
      caught_.push_back(std::current_exception());
      records_.push_back(fmt::format("claims file '{}', record '{}' (line {})", file_, r.id, r.line));
      return false;
    }
  }
  void throw_any() const {
    if (caught_.empty()) return;
    if (caught_.size() == 1) std::rethrow_exception(caught_.front());
    std::string lines;
    std::vector<std::string> seen;
    for (std::size_t k = 0; k < caught_.size(); ++k) {
      try {
        std::rethrow_exception(caught_[k]);
      } catch (const std::invalid_argument& refused) {
        // A claims file's own refusal names its line; a formula of the document that does not read
        // names the document's line, once however many records read it (the fault is the TeX's, or
        // the declarations', not a record's); any other is named with its record.
        const std::string what = refused.what();
        const bool named = what.rfind("claims file", 0) == 0 || what.rfind("document '", 0) == 0;
        const std::string line = named ? what : records_[k] + ": " + what;
        if (std::find(seen.begin(), seen.end(), line) != seen.end()) continue;
        seen.push_back(line);
        lines += (lines.empty() ? "" : "\n") + line;
      }
    }
    throw std::invalid_argument(lines);
  }

 private:
  std::string file_;
  std::vector<std::exception_ptr> caught_;
  std::vector<std::string> records_;
};

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
/// (then against the sentence that states it, with the book's bindings judged), or, for a record
/// that names no shape, the book's own decider.
detail::judge judge_of(const claim_record& r, const std::shared_ptr<const claim_declarations>& declared, const book_deciders& deciders) {
  if (r.shape.empty()) {
    if (!deciders.judge) throw std::logic_error("claims_of: record '" + r.id + "' names no shape, and the book has no deciders of its own");
    return deciders.judge(r, declared);
  }
  const detail::shape_call call{r.id, r.statement, r.with, declared};
  const detail::proof_shape& shape = detail::proof_shapes().at(r.shape);
  return [call, run = shape.run, core = r.core, coq_none = r.coq_none, bind = deciders.bind_core, file = r.file, line = r.line](const run_context& ctx) {
    detail::shape_call with_document = call;
    with_document.corrections = ctx.corrections;
    const auto start = std::chrono::steady_clock::now();
    detail::decider_evidence e;
    try {
      e = run(with_document, ctx);
    } catch (const detail::argument_error& error) {
      // An argument the checks before the run could not judge (the shape learns it only as it
      // reads): bad input, named by its field, never a fault of the harness.
      const auto it = call.with.find(error.argument);
      throw claims_file_error(file, it != call.with.end() ? it->second.line : line, "with." + error.argument, error.what());
    }
    e.found.printed_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();  // GiNaC's and ours
    if (!e.goals && e.found.certificate.empty() && e.found.certificate_missing.empty()) {
      e.found.certificate_missing = detail::without_coq_statement(coq_none);
    }
    e = as_the_sentence_says(std::move(e), with_document, ctx);
    return bind ? bind(std::move(e), core, with_document, ctx) : e;
  };
}

/// The check of a record: what decides it, made a verdict by decide() (decide.hpp), the one place
/// that makes one.
std::function<claim_result(const run_context&)> check_of(const claim_record& r, const std::shared_ptr<const claim_declarations>& declared,
                                                         const book_deciders& deciders) {
  return detail::claim_check_of(judge_of(r, declared, deciders), r.id, r.statement);
}

/// A claim that follows from a premise its record calls a typographical slip, and holds as derived
/// where its printed derivation fails only through that premise: its printed conclusion is the
/// corrected premise's, not the printed one's, so the derivation went through the right value and
/// the misprint is the premise's alone, counted there. Its derivation-gap remark becomes a note (no
/// finding, no remark): a gap the text does not have is no verdict it earned.
std::function<claim_result(const run_context&)> through_a_slip(std::function<claim_result(const run_context&)> check, const std::string& slip) {
  return [check = std::move(check), slip](const run_context& ctx) {
    claim_result got = check(ctx);
    if (!meaning(got.outcome).affirms || got.remark_kind != finding::derivation_gap) return got;
    got.note = (got.note.empty() ? std::string() : got.note + " ") + "It holds as printed: its printed conclusion is what the premise corrected by `" + slip +
               "` (a typographical slip) gives, and not what the premise as printed gives, so the derivation went through the right value; "
               "the slip is counted there.";
    got.remark.clear();
    got.remark_kind = finding::none;
    got.amendments.clear();
    return got;
  };
}

std::vector<claim> claims_of(const std::vector<claim_record>& records, const std::shared_ptr<const claim_declarations>& declared,
                             const book_deciders& deciders) {
  std::set<std::string> slips;  // the records that call themselves typographical slips
  for (const claim_record& r : records) {
    if (r.typographical) slips.insert(r.id);
  }
  std::vector<claim> out;
  for (const claim_record& r : records) {
    std::function<claim_result(const run_context&)> check = check_of(r, declared, deciders);
    if (slips.count(r.follows_from) > 0) check = through_a_slip(std::move(check), r.follows_from);
    claim c{r.id, r.section, r.equation, r.statement, r.methods, r.expected, std::move(check), r.kind, r.follows_from, r.typographical, r.origin};
    c.decided_by = decider_of(r);
    c.labels_read = labels_read(r);
    c.headline = r.headline;
    c.conclusions_kept = r.conclusions_kept;
    c.coq_none = r.coq_none;
    c.expected_correction = meaning(r.expected).corrected ? r.correction : r.remark;
    c.expected_reads = r.reads;
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace

claim_book read_claim_book(const std::string& text, const std::string& file, const book_deciders& deciders) {
  claims_file_contents contents = read_claims_contents(text, file, [&deciders](const std::string& field, const std::string& name) {
    if (field == "shape") return detail::proof_shapes().count(name) > 0;
    return deciders.knows && deciders.knows(field, name);
  });
  refusals all(file);
  for (const claim_record& r : contents.records) {
    if (!r.shape.empty()) all.check(r, [&] { detail::check_shape_arguments(r, file); });
  }
  all.throw_any();
  claim_book book;
  book.file = file;
  book.document = contents.document;
  book.declarations = std::make_shared<const claim_declarations>(read_declarations(contents, file));
  book.records = std::move(contents.records);
  book.deciders = deciders;
  book.claims = claims_of(book.records, book.declarations, book.deciders);
  book.guards = std::any_of(book.records.begin(), book.records.end(), [](const claim_record& r) { return r.expected_given; });
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
  const auto check_core = [&](const claim_record& r) {
    if (book.deciders.check_core) book.deciders.check_core(r, book.file, document, *book.declarations);
  };
  refusals all(book.file);
  for (const claim_record& r : book.records) {
    if (only && std::find(only->begin(), only->end(), r.id) == only->end()) continue;
    if (r.shape.empty()) {
      all.check(r, [&] { check_core(r); });
      continue;
    }
    std::string printed;
    if (!all.check(r, [&] {
          printed = detail::check_shape_formulas(r, book.file, document, *book.declarations);
          check_core(r);
        })) {
      continue;
    }
    if (!r.statement.empty()) continue;
    // A record without a statement: the reports, and its shape's notes, show the TeX it reads.
    claim_record stated = r;
    stated.statement = printed;
    for (claim& c : book.claims) {
      if (c.id != r.id) continue;
      c.statement = printed;
      c.check = check_of(stated, book.declarations, book.deciders);
    }
  }
  all.throw_any();
}

std::vector<std::string> claims_reading_formula(const claim_book& book, const std::string& label) {
  std::vector<std::string> ids;
  for (const claim& c : book.claims) {
    std::vector<std::string> names = book.deciders.formulas_read ? book.deciders.formulas_read(c) : std::vector<std::string>{};
    names.insert(names.end(), c.labels_read.begin(), c.labels_read.end());
    for (const std::string& name : names) {
      if (name == label || name.rfind(label + "#", 0) == 0) {
        ids.push_back(c.id);
        break;
      }
    }
  }
  return ids;
}

claim_result check_claim(const claim& c, const run_context& ctx) {
  json quotes = json::array();
  run_context quoting = ctx;
  quoting.quotes = &quotes;
  claim_result result = c.check(quoting);
  result.quoted = std::move(quotes);
  return result;
}

}  // namespace simpson::verify

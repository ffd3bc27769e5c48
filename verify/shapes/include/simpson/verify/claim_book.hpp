#pragma once
// A claims file read into a book of claims, for any document: every checkable statement, in the
// file's order, each claim carrying what it needs to run (its shape's arguments, the file's
// declarations) and made a verdict by decide(). The engine knows its proof shapes; a book adds its
// own deciders (the paper's bespoke checks, our core bound to the print, the facts its experiments
// publish) as a registry passed in (book_deciders), as LLVM lit takes a suite's test formats. A book
// is a value: read once, bound to its document once, and passed to the run; nothing in the process
// remembers which book is "installed".

#include <simpson/prove/decide.hpp>
#include <simpson/shapes/proof_shapes.hpp>
#include <simpson/verify/claim.hpp>
#include <simpson/verify/claim_declarations.hpp>
#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/paper_source.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace simpson::verify {

class experiment_section;  // experiment_section.hpp: a book's sections, which the engine only carries
class tex_document;

/// What a book adds to the proof shapes: its own deciders, by the field of a record that names them.
/// The engine alone (book_deciders{}) knows none: a record naming a `check`, a `core` formula or a
/// fact it `observes` does not read.
struct book_deciders {
  /// Whether `name` names one of the book's deciders for the record's field `field` ("check", "core"
  /// or "observes").
  std::function<bool(const std::string& field, const std::string& name)> knows;
  /// What decides a record that names no shape: its bespoke check with its facets, or the fact it
  /// observes, with its `core` bindings judged.
  std::function<detail::judge(const claim_record&, const std::shared_ptr<const claim_declarations>&)> judge;
  /// A shape's evidence with the record's `core` bindings judged (none: the evidence as it is).
  std::function<detail::decider_evidence(detail::decider_evidence, const std::vector<core_binding>&, const detail::shape_call&,
                                         const run_context&)>
      bind_core;
  /// The record's `core` bindings read from the document before anything runs; throws
  /// claims_file_error naming the field.
  std::function<void(const claim_record&, const std::string& file, const tex_document&, const claim_declarations&)> check_core;
  /// The formulas a claim's own decider reads from the document by name (a bespoke check's printed
  /// facet: labels, or "label#k" for one of a display's equations), beside the labels its shape reads.
  std::function<std::vector<std::string>(const claim&)> formulas_read;
};

/// A claims file read: its records, its [document] and declarations, and its claims, each joined
/// with the shape or the book's decider its record names.
struct claim_book {
  std::string file;                                         // "claims/paper.toml", or the path given
  std::optional<claims_document> document;                  // [document]: a document other than the paper
  std::shared_ptr<const claim_declarations> declarations;   // never null
  std::vector<claim_record> records;
  std::vector<claim> claims;
  book_deciders deciders;  // the book's own, beside the engine's shapes
  /// The formulas its checks read from the document by name (paper_reading::formulas): the paper's
  /// for a book that checks the paper, none for a note's.
  std::vector<formula_location> formulas;
  /// The experiment sections a scene run with this book may ask for, in the order a run computes
  /// them: the registry the app iterates (experiment_section.hpp). None for the engine alone.
  std::vector<const experiment_section*> sections;
  /// Whether any record says what its verdict is expected to be: a guard against regressions. A file
  /// whose records say none validates its document (every claim is to hold).
  bool guards = false;

  /// The claim with this id; throws std::invalid_argument naming the id when there is none.
  const claim& find(const std::string& id) const;
  /// The [document] it checks, when it is a document other than the paper; null otherwise.
  const claims_document* checked_document() const { return document ? &*document : nullptr; }
};

/// Reads a claims file into a book: every record checked (claims_file.hpp), every `shape` one of the
/// engine's with arguments of their kinds, every other decider one `deciders` knows, the declarations
/// read. Throws claims_file_error.
claim_book read_claim_book(const std::string& text, const std::string& file, const book_deciders& deciders);

/// Binds `book` to `document` before anything runs: reads every formula its shape records name
/// (only the claims `only` lists, when given), and their `core` bindings. Throws claims_file_error
/// naming the record's argument when one is missing or uses a symbol the file does not declare, and
/// std::invalid_argument naming the document's line when its TeX does not read. A record without a
/// statement gets the TeX of the formula it judges, with where it was read.
void check_claims_file_formulas(claim_book& book, const paper_source& document, const std::vector<std::string>* only = nullptr);

/// The claims of `book` that read the printed formula `label` (a \label of the document, or one of
/// its equations): their shape's formula arguments, or what their book's decider reads.
std::vector<std::string> claims_reading_formula(const claim_book& book, const std::string& label);

/// Runs the claim's check with the sentences it quotes recorded: its decider's evidence, made a
/// verdict by decide() (decide.hpp).
claim_result check_claim(const claim& c, const run_context& ctx);

}  // namespace simpson::verify

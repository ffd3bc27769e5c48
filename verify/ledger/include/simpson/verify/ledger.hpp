#pragma once
// The claims ledger: a claims file read into a book of claims (every checkable statement, in the
// file's order), each claim carrying what it needs to run (its shape's arguments, the file's
// declarations). The paper's book is claims/paper.toml, compiled in; --claims-file reads another.
// A book is a value: read once, bound to its document once, and passed to the run; nothing in the
// process remembers which book is "installed".

#include <simpson/verify/experiment_section.hpp>
#include <simpson/verify/claim.hpp>
#include <simpson/verify/claim_declarations.hpp>
#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/paper_source.hpp>
#include <simpson/verify/table1_reader.hpp>
#include <simpson/verify/the_paper.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace simpson::verify {

/// A claims file read: its records, its [document] and declarations, and its claims, each joined
/// with the check or shape its record names.
struct claim_book {
  std::string file;                                         // "claims/paper.toml", or the path given
  std::optional<claims_document> document;                  // [document]: a document other than the paper
  std::shared_ptr<const claim_declarations> declarations;   // never null
  std::vector<claim_record> records;
  std::vector<claim> claims;
  /// The formulas its checks read from the document by name (paper_reading::formulas): the paper's
  /// (printed_formula_locations()) for a book that checks the paper, none for a note's.
  std::vector<formula_location> formulas;
  /// The experiment sections a scene run with this book may ask for, in the order a run computes
  /// them: the registry the app iterates (experiment_section.hpp; experiment_sections() below).
  std::vector<const experiment_section*> sections;
  /// Whether any record says what its verdict is expected to be: a guard against regressions. A file
  /// whose records say none validates its document (every claim is to hold).
  bool guards = false;

  /// The claim with this id; throws std::invalid_argument naming the id when there is none.
  const claim& find(const std::string& id) const;
  /// The [document] it checks, when it is a document other than the paper; null otherwise.
  const claims_document* checked_document() const { return document ? &*document : nullptr; }
};

/// Reads a claims file into a book: every record checked (claims_file.hpp), every `check` a
/// registered one, every shape's arguments of their kinds, the declarations read. Throws
/// claims_file_error.
claim_book read_claim_book(const std::string& text, const std::string& file);

/// The text of claims/paper.toml, compiled in.
std::string embedded_claims_text();

/// The paper's book (the embedded claims/paper.toml), read once.
const claim_book& paper_book();

/// The experiment sections a scene may ask for, in the order a run computes them: the registry the
/// app iterates (experiment_section.hpp). Each is stateless; the book's table1 reads the run's paper.
const std::vector<const experiment_section*>& experiment_sections();

/// The records of a claims file whose every `check` is a registered one (read_claims_file).
std::vector<claim_record> read_claims_with_known_checks(const std::string& text, const std::string& file);

/// Binds `book` to `document` before anything runs: reads every formula its shape records name
/// (only the claims `only` lists, when given). Throws claims_file_error naming the record's argument
/// when one is missing or uses a symbol the file does not declare, and std::invalid_argument naming
/// the document's line when its TeX does not read. A record without a statement gets the TeX of the
/// formula it judges, with where it was read.
void check_claims_file_formulas(claim_book& book, const paper_source& document, const std::vector<std::string>* only = nullptr);

/// The ids that every run of the `paper` scene must contain: the headline claims of its records.
std::vector<std::string> required_claim_ids();

/// The formulas of our core that a record may bind to the print (`core = { function = ... }`), as a
/// Markdown table: each one's name, the paper's label it implements, its variables, and the records
/// of `book` that bind it (simpson-verify --list-core).
std::string core_formulas_markdown(const claim_book& book);

/// The facts the experiments publish that a record may observe (`observes = "table1.printed-orders"`),
/// as a Markdown table: each one's name, what it states, and the records of `book` that observe it
/// (simpson-verify --list-facts).
std::string published_facts_markdown(const claim_book& book);

/// The paper read with its book's declarations (claims/paper.toml's [symbols]), as its claims read it.
paper_reading read_paper(const paper_source& paper);

}  // namespace simpson::verify

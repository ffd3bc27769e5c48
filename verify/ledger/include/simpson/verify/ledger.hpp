#pragma once
// The claims ledger: the paper's book. The engine reads a claims file into a book of claims
// (claim_book.hpp); the ledger adds the paper's own deciders (bespoke checks, our core bound to the
// print, the facts its experiments publish), its experiment sections and its formulas. The paper's
// book is claims/paper.toml, compiled in; --claims-file reads another with the same deciders.

#include <simpson/verify/claim_book.hpp>
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

/// The paper's deciders, beside the engine's shapes: its registered (bespoke) checks, our core
/// bound to the print (`core = { function = ... }`), and the facts its experiments publish
/// (`observes`).
book_deciders paper_deciders();

/// Reads a claims file into a book with the paper's deciders (read_claim_book of claim_book.hpp with
/// paper_deciders()), its experiment sections, and the paper's formulas when it checks the paper.
/// Throws claims_file_error.
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

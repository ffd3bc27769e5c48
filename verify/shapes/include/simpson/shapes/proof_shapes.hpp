#pragma once
// Proof shapes: the generic checks a claims-file record names (`shape = "determinant"`), each one
// C++ function with typed arguments read from the record (`with = { matrix = "phi", equals = "$1$" }`).
// A shape reads the formulas it is given from the document's LaTeX (formula_reference.hpp), decides
// its statement in GiNaC's normal form and again in our kernel (kernel_zero.hpp) where the
// statement is an identity, states the goals Coq is to check (coq_export.hpp), and returns its
// evidence: decide() (decide.hpp) makes the verdict of it, holds or erratum with the proved
// correction (docs/claims-file.md lists the shapes).

#include <simpson/prove/decide.hpp>
#include <simpson/verify/claim.hpp>
#include <simpson/verify/claim_declarations.hpp>
#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/tex_document.hpp>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace simpson::verify::detail {

/// What an argument holds: a formula reference ("phi#2", "inline:stable for", "$1$"); one that must
/// be a square matrix once the definitions are put in; a printed condition "a < x < b" (three
/// sides); a word of the record's own, one of a few (a sign: "positive"); a list of definitions
/// (references to displays "x = ..."); a list of symbol names in TeX ('q_0', '\omega'); or a list of
/// equations, each read whole, every side ("a = b = c"); or a list of the record's own words (a
/// vocabulary).
enum class argument_kind { formula, matrix, condition, word, definitions, symbols, equations, words };

struct shape_parameter {
  std::string name;
  argument_kind kind = argument_kind::formula;
  bool required = true;
  std::string meaning;         // for docs and errors
  unsigned size = 0;           // symbols: exactly so many; matrix: so many rows (0: any)
  std::string same_size_as{};  // symbols: as many as the rows of this matrix argument
  bool positive = false;       // formula: every symbol of it declared positive (with a [document])
  std::vector<std::string> words{};  // word: the values it may take (none: any text, such as a sentence's pattern)
  std::string among{};               // symbols: each one of this symbols argument's
  std::string instead_of{};          // given instead of this argument: exactly one of the two (neither `required`)
  std::string only_with{};           // given exactly when this argument is
  std::string hole{};                // word: a sentence's pattern, which must hold the hole {hole}
  std::string free_of{};             // formula: nonzero, and free of this symbols argument's symbols (a scale free of the states)
  bool pairs = false;                // words: each entry 'word: replacement', both non-empty
};

/// One call: the claim's id and statement, its arguments, and its claims file's declarations (they
/// decide what the TeX leaves open; with a [document], every symbol must be declared).
struct shape_call {
  std::string claim_id;
  std::string statement;
  std::map<std::string, shape_argument> with;
  std::shared_ptr<const claim_declarations> declared;
  const formula_corrections* corrections = nullptr;  // the run's, when the claim is judged again with corrected formulas
};

using shape_function = std::function<decider_evidence(const shape_call&, const run_context&)>;

class shape_reader;  // shape_support.hpp

/// What a shape checks of a record once its formulas are read, before anything runs (the notation
/// it reads that the declarations must settle): throws argument_error naming the argument.
using shape_binding = std::function<void(shape_reader&, const shape_call&)>;

struct proof_shape {
  std::string name;
  std::string summary;
  std::string principal;  // the argument whose formula is the printed statement (the reports show its TeX)
  std::vector<shape_parameter> parameters;
  shape_function run;
  shape_binding bind = {};
};

/// Every shape, by name.
const std::map<std::string, proof_shape>& proof_shapes();

/// The record's arguments against its shape's parameters: each required one given, none unknown,
/// each of its kind (one string for a formula, a list otherwise). Throws claims_file_error naming
/// the record's line and the argument ("with.matrix").
void check_shape_arguments(const claim_record& record, const std::string& file);

/// Every formula, definition and symbol a record's arguments name, read from `document`: throws
/// claims_file_error naming the argument's line when one is missing, uses a symbol `declared` does
/// not declare, or is not of its parameter's kind and size (a matrix that is not square, a
/// condition without three sides, a state of another size than its map), and document_error when
/// the document's TeX does not read (the document is at fault, not the record). Returns the TeX of
/// the principal argument's formula, with where it was read: "$...$ (label det, line 12)".
std::string check_shape_formulas(const claim_record& record, const std::string& file, const tex_document& document,
                                 const claim_declarations& declared);

}  // namespace simpson::verify::detail

#pragma once
// The claims ledger: every checkable statement of the paper, in the paper's order.

#include <simpson/verify/claim.hpp>
#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/paper_source.hpp>

#include <string>
#include <vector>

namespace simpson::verify {

/// All claims, built once from the embedded claims/paper.toml and the registered checks; ids are
/// unique and stable.
const std::vector<claim>& ledger();

/// The records of a claims file whose every `check` is a registered one (read_claims_file).
std::vector<claim_record> read_claims_with_known_checks(const std::string& text, const std::string& file);

/// The claims of records, each joined with the check its record names.
std::vector<claim> claims_of(const std::vector<claim_record>& records);

/// From now on ledger() is the claims of this file instead of claims/paper.toml (the CLI's
/// --claims-file, before anything runs). Throws claims_file_error when the file does not read.
void use_claims_file(const std::string& text, const std::string& file);

/// The [document] and [symbols] of the claims file installed, when it checks a document other than
/// the paper; null otherwise.
const claims_document* installed_document();

/// Reads every formula the installed file's shape records name (the embedded claims/paper.toml's
/// when no file is installed; only the claims `only` lists, when given) from `document`, before
/// anything runs: throws claims_file_error naming the record's argument when one is missing, does
/// not parse, or uses a symbol the file does not declare.
void check_claims_file_formulas(const paper_source& document, const std::vector<std::string>* only = nullptr);

/// The claim with this id; throws std::invalid_argument naming the id when there is none.
const claim& find_claim(const std::string& id);

/// The ids that every run of the `paper` scene must contain: the headline claims of its records.
inline const std::vector<std::string>& required_claim_ids() {
  static const std::vector<std::string> ids = [] {
    std::vector<std::string> out;
    for (const claim& c : ledger()) {
      if (c.headline) out.push_back(c.id);
    }
    return out;
  }();
  return ids;
}

}  // namespace simpson::verify

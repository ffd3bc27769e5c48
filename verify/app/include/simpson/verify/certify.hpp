#pragma once
// The claims' Coq certificates: the evidence each claim records about its certificate, and their
// check by coqc (`--certify`, `make certify`). A certificate is printed by the ledger from the
// identities GiNaC proved (coq_export.hpp); here it is only checked and recorded.

#include <simpson/verify/run.hpp>

#include <string>

namespace simpson::verify {

/// The first line of `coqc --version`'s version ("8.16.1"), or empty when coqc is not found.
std::string coqc_version();

/// The report-relative file of a claim's certificate: certificates/<id>.v with '-' as '_' (coqc
/// takes the file's name as a module name, which must be an identifier).
std::string certificate_file(const std::string& claim_id);

/// The report-relative file of the negations of a claim's refuted identities: certificates/<id>_refuted.v.
std::string refutation_file(const std::string& claim_id);

/// One Coq file of a claim: the identities proved, or the refuted ones' negations.
struct certificate_document {
  std::string file;  // report-relative
  const std::string* text;
  const std::vector<std::string>* lemmas;
};

/// A claim's Coq files (none, one or two), in that order.
std::vector<certificate_document> certificate_documents(const claim_outcome& o);

/// Records evidence "coq" for every claim: "not exported" with the reason, or "exported" with the
/// file and its lemmas (and "refutation": the negations' file and lemmas). With `check`, every file
/// of the run is checked by coqc, all in coqc_processes() processes at most (coq_batch.hpp): "checked"
/// with the Coq version, or "failed" with the rejected file and coqc's first lines on it; the wall
/// time, the files and the processes go to r.coq_seconds, coq_documents, coq_processes (timing.json). Throws std::invalid_argument when `check` is asked and coqc
/// is not found. Returns the ids whose certificate coqc rejected.
std::vector<std::string> record_certificates(run_record& r, bool check);

}  // namespace simpson::verify

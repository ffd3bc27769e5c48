#pragma once
// Checking many Coq files with few coqc processes. Each coqc process loads the standard library's
// reals (and Gappa's, Flocq's, Interval's libraries) again, about 0.7 s of a certificate's 0.75 s:
// checked one process each, the paper scene's 43 files took 44 s of coqc. Here the files become the
// modules of one file per process (their Require commands hoisted to the top, so every library loads
// once), and the processes run side by side.

#include <cstddef>
#include <string>
#include <vector>

namespace simpson::verify {

/// One Coq file to check: `name` is its module name (an identifier: the file's name without .v).
struct coq_document {
  std::string name;
  std::string text;
};

/// coqc's verdict on one document: accepted, or rejected with coqc's first lines on it.
struct coq_verdict {
  bool accepted = false;
  std::string message;  // empty when accepted
};

/// The text of one file that holds `documents` as modules `Cert_<name>`: each document's
/// `Require [Import|Export] L.` and `From P Require [Import|Export] L.` lines become one `Require`
/// of every library at the top and an `Import`/`Export` in the document's module, so a library loads
/// once and every module sees what its own file imported. Throws std::invalid_argument when a name
/// is not an identifier or two documents share one.
std::string coq_modules_file(const std::vector<coq_document>& documents);

/// How many coqc processes a check runs side by side by default: the machine's hardware threads
/// (2 when the machine does not say).
unsigned coqc_processes();

/// How many processes check_with_coqc starts for `documents` files and at most `jobs`.
unsigned coqc_processes_for(std::size_t documents, unsigned jobs = coqc_processes());

/// Checks `documents` with coqc, in coqc_processes_for(documents.size(), jobs) processes run side by
/// side (the documents shared out by size, largest first, so the longest proofs land in different
/// processes). A process whose file coqc accepts accepts each of its documents. When coqc rejects a process's file, each of its
/// documents is checked alone, so the verdict names exactly the documents coqc rejects, each with
/// coqc's own message. Throws std::invalid_argument when coqc is not found; interruption
/// (interruption.hpp) is checked before each process starts.
std::vector<coq_verdict> check_with_coqc(const std::vector<coq_document>& documents, unsigned jobs = coqc_processes());

}  // namespace simpson::verify

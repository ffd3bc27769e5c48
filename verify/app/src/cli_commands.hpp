#pragma once
// simpson-verify's commands, each one function: main() parses the command line and dispatches.

#include "cli_options.hpp"

#include <simpson/verify/ledger.hpp>
#include <simpson/verify/run.hpp>

#include <string>

namespace simpson::verify {

/// --list-claims: the book's claims, as text (one line each), json (every field) or markdown (a table).
int list_claims(const claim_book& book, const std::string& format);
/// --list-scenes, --list-precisions.
int list_scenes();
int list_precisions();
/// --list-sections: the registry's sections (a Markdown table, docs/architecture.md's, generated).
int list_sections();
/// --list-verdicts: verdict.hpp's table of meanings (a Markdown table, docs/findings.md's, generated).
int list_verdicts();

/// `simpson-verify compare OLD NEW [--subset] [--junit FILE] [--format json]`: 0 when the reports
/// agree, 1 on a difference (one line each), 2 on bad input.
int compare_report_directories(const cli_options& o);

/// The whole command line: parses it and runs the command it names; the process's exit code.
int simpson_verify_main(int argc, char** argv, const claim_checker& checker);

/// A run of a scene (or a list asked for): the exit code of simpson-verify; `checker` runs each claim
/// (empty: check_claim).
int run_command(cli_options& o, const CLI::App& app, int argc, char** argv, const claim_checker& checker = {});

}  // namespace simpson::verify

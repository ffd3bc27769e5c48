// simpson-verify: runs a scene of the claims ledger and writes its report.
// Exit codes: 0 every verdict as expected; 1 some verdict differs, or a section's expectation failed (each named on stderr);
// 2 bad input or usage (one line on stderr, nothing written); 3 an internal error (a bug in the
// harness: a check that threw, or an unexpected exception); 128 + n when stopped by signal n.

#include "cli_entry.hpp"

int main(int argc, char** argv) { return simpson::verify::simpson_verify_main(argc, argv); }

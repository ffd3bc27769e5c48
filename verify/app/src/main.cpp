// simpson-verify: runs a scene of the claims ledger and writes its report.
// Exit codes: 0 every verdict as expected; 1 some verdict differs, or a section's expectation failed (each named on stderr);
// 2 bad input or usage (one line on stderr, nothing written); 3 an internal error (a bug in the
// harness: a check that threw, or an unexpected exception); 128 + n when stopped by signal n.

#include "cli_commands.hpp"
#include "cli_options.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>

int main(int argc, char** argv) {
  using namespace simpson::verify;
  CLI::App app{"simpson-verify: proves, rechecks and reports every claim of the symplectic Simpson paper"};
  cli_options o;
  declare_options(app, o);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::fprintf(stderr, "simpson-verify: %s\n", e.what());
    return 2;
  }
  if (*o.compare) {
    if (o.compare_old.empty() || o.compare_new.empty()) {
      std::fprintf(stderr, "simpson-verify: compare needs two report directories: OLD, the reference (e.g. reports/reference/paper), "
                   "then NEW, the run to check\n");
      return 2;
    }
    return compare_report_directories(o);
  }
  return run_command(o, app, argc, argv);
}

// simpson-verify's command line, parsed and dispatched (cli_commands.hpp): main() calls it with the
// harness's own checks; a test's binary with a seam of its own (a check that throws).

#include "cli_commands.hpp"
#include "cli_entry.hpp"
#include "cli_options.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>

namespace simpson::verify {

int simpson_verify_main(int argc, char** argv) { return simpson_verify_main(argc, argv, claim_checker{}); }

int simpson_verify_main(int argc, char** argv, const claim_checker& checker) {
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
  return run_command(o, app, argc, argv, checker);
}

}  // namespace simpson::verify

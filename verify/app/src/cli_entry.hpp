#pragma once
// simpson-verify's entry point alone, for main(): the rest of the command line (cli_commands.hpp)
// includes the whole harness's headers, which main() does not need (16 s to compile with them).

namespace simpson::verify {

/// The whole command line, each claim checked by its own check: the process's exit code.
int simpson_verify_main(int argc, char** argv);

}  // namespace simpson::verify

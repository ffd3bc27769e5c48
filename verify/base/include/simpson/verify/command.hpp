#pragma once
// Running an external program (coqc, gappa) through the shell: its output and exit status.

#include <string>

namespace simpson::verify {

/// A command's output (stdout and stderr together) and its exit status (-1 when it could not run).
struct command_result {
  int status = -1;
  std::string output;
};

/// Runs `command` with /bin/sh, stderr folded into stdout.
command_result run_command(const std::string& command);

/// Whether `program` is found on PATH.
bool program_on_path(const std::string& program);

/// The first `lines` lines of a text.
std::string first_lines(const std::string& text, int lines);

}  // namespace simpson::verify

#pragma once
// Running an external program (coqc, gappa) through the shell: its output and exit status.

#include <filesystem>
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

/// A directory of its own under the system's temporary directory (`<prefix>-XXXXXX`), removed with
/// what it holds when this object goes. Throws std::runtime_error when it cannot be made.
class scratch_directory {
 public:
  explicit scratch_directory(const std::string& prefix = "simpson");
  ~scratch_directory();
  scratch_directory(const scratch_directory&) = delete;
  scratch_directory& operator=(const scratch_directory&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace simpson::verify

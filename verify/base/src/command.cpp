// Running an external program (command.hpp).

#include <simpson/verify/command.hpp>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <sstream>

namespace simpson::verify {

command_result run_command(const std::string& command) {
  command_result out;
  std::FILE* pipe = ::popen(("(" + command + ") 2>&1").c_str(), "r");  // the shell's own messages too
  if (pipe == nullptr) return out;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) out.output += buffer;
  out.status = ::pclose(pipe);
  return out;
}

bool program_on_path(const std::string& program) { return run_command("command -v " + program).status == 0; }

std::string first_lines(const std::string& text, int lines) {
  std::istringstream in(text);
  std::string line, out;
  for (int k = 0; k < lines && std::getline(in, line); ++k) out += (out.empty() ? "" : "\n") + line;
  return out;
}

scratch_directory::scratch_directory(const std::string& prefix) {
  std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot create a temporary directory " + pattern);
  path_ = pattern;
}

scratch_directory::~scratch_directory() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace simpson::verify

#include <simpson/verify/environment.hpp>

#include <simpson/verify/report_directory.hpp>
#include <simpson/verify/sha256.hpp>

#include "build_flags.hpp"
#include "git_commit.hpp"

#include <Eigen/Core>
#include <boost/version.hpp>
#include <fmt/format.h>
#include <ginac/version.h>
#include <gmp.h>
#include <mpfr.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <thread>
#include <sys/utsname.h>

namespace simpson::verify {
namespace {

/// The commit without its "-dirty" suffix, and whether it had one.
std::pair<std::string, bool> git_commit() {
  const std::string text = SIMPSON_GIT_COMMIT;
  const std::string suffix = "-dirty";
  const bool dirty = text.size() > suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
  return {dirty ? text.substr(0, text.size() - suffix.size()) : text, dirty};
}

/// The value of `key` in a "key: value" or KEY="value" file (/proc/cpuinfo, /etc/os-release).
std::string field_of(const std::string& path, const std::string& key, char separator) {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(key, 0) != 0) continue;
    const std::size_t at = line.find(separator);
    if (at == std::string::npos) continue;
    std::string value = line.substr(at + 1);
    const std::size_t first = value.find_first_not_of(" \t\"");
    const std::size_t last = value.find_last_not_of(" \t\"");
    return first == std::string::npos ? std::string() : value.substr(first, last - first + 1);
  }
  return "unknown";
}

/// The first line gnuplot prints for --version ("gnuplot 5.4 patchlevel 4"), or "not found".
std::string gnuplot_version() {
  std::FILE* pipe = ::popen("gnuplot --version 2>/dev/null", "r");
  if (pipe == nullptr) return "not found";
  std::array<char, 256> buffer{};
  std::string line = std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) ? buffer.data() : "";
  ::pclose(pipe);
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  return line.empty() ? "not found" : line;
}

}  // namespace

std::string version_line() {
  const auto [commit, dirty] = git_commit();
  return fmt::format("simpson-verify {} (commit {}, {})", SIMPSON_VERSION, commit,
                     commit == "unknown" ? "not built from a git checkout" : dirty ? "with uncommitted changes" : "clean");
}

run_timestamp run_timestamp_utc() {
  std::time_t now = std::time(nullptr);
  std::string source = "clock";
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH"); epoch != nullptr && *epoch != '\0') {
    char* end = nullptr;
    const long long seconds = std::strtoll(epoch, &end, 10);
    if (end != nullptr && *end == '\0' && seconds >= 0) {
      now = static_cast<std::time_t>(seconds);
      source = "SOURCE_DATE_EPOCH";
    } else {
      source = std::string("clock (SOURCE_DATE_EPOCH '") + epoch + "' ignored: not a non-negative integer)";
    }
  }
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return {text, source};
}

std::string resolved_scene_sha256(const scene& s) {
  json source;
  try {
    source = json::parse(s.source_text);
  } catch (const json::exception&) {
    source = s.source_text;  // a scene built in code, not read
  }
  return sha256_hex(json{{"scene", source}, {"overrides", s.overrides}}.dump());
}

json build_environment(const scene& s, const paper_reading& paper) {
  const auto [commit, dirty] = git_commit();
  ::utsname host{};
  const bool have_host = ::uname(&host) == 0;
  const run_timestamp timestamp = run_timestamp_utc();
  return json{{"tool", "simpson-verify"},
              {"version", SIMPSON_VERSION},
              {"git_commit", commit},
              {"git_dirty", dirty},
              {"os", field_of("/etc/os-release", "PRETTY_NAME=", '=')},
              {"kernel", have_host ? fmt::format("{} {} {}", host.sysname, host.release, host.machine) : "unknown"},
              {"cpu", field_of("/proc/cpuinfo", "model name", ':')},
              {"hardware_threads", std::thread::hardware_concurrency()},
              {"compiler", std::string("g++-compatible ") + __VERSION__},
              {"flags", SIMPSON_CXX_FLAGS},
              {"boost", BOOST_LIB_VERSION},
              {"mpfr", MPFR_VERSION_STRING},
              {"gmp", gmp_version},
              {"eigen", fmt::format("{}.{}.{}", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)},
              {"ginac", fmt::format("{}.{}.{}", GINACLIB_MAJOR_VERSION, GINACLIB_MINOR_VERSION, GINACLIB_MICRO_VERSION)},
              {"cmark_gfm", cmark_gfm_version()},
              {"gnuplot", gnuplot_version()},
              {"timestamp_utc", timestamp.utc},
              {"timestamp_source", timestamp.source},
              {"command_line", s.command_line},
              {"scene_sha256", resolved_scene_sha256(s)},
              {"paper", paper.origin},
              {"paper_sha256", paper.sha256}};
}

}  // namespace simpson::verify

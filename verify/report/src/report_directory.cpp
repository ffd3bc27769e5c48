// Writing a report directory: staged beside it, then swapped into place; plots drawn by gnuplot;
// report.html rendered from report.md (report_html.cpp).

#include <simpson/verify/interruption.hpp>
#include <simpson/verify/report_directory.hpp>

#include <simpson/verify/report_html.hpp>

#include <cmark-gfm.h>
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <csignal>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace simpson::verify {
namespace {

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Runs `gnuplot script` in `dir`, its output to `log`; returns its exit status (127: not found).
/// Not std::system: that ignores SIGINT in this process while gnuplot runs, and a terminal's Ctrl-C
/// (sent to the whole process group) would kill gnuplot alone and let the run go on. Here gnuplot
/// gets the default dispositions, this process keeps its handler, and a child killed by a signal
/// stops the run as that signal would: the caller's throw_if_interrupted() then leaves no report.
int run_gnuplot(const std::filesystem::path& dir, const std::string& script, const std::string& log) {
  const pid_t child = ::fork();
  if (child < 0) throw std::filesystem::filesystem_error("cannot start gnuplot", dir, std::error_code(errno, std::generic_category()));
  if (child == 0) {  // only async-signal-safe calls until exec
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    const int null = ::open("/dev/null", O_RDONLY);  // never a terminal to wait on
    if (null >= 0) {
      ::dup2(null, STDIN_FILENO);
      ::close(null);
    }
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) ::_exit(126);
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    ::close(fd);
    ::execlp("gnuplot", "gnuplot", script.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Polled, not a blocking waitpid: the CLI's handler is installed with SA_RESTART semantics, so a
  // blocking wait would not return when only this process gets the signal, and gnuplot catches
  // SIGINT itself (it interrupts the plot and returns to its prompt) instead of always dying of it.
  int status = 0;
  bool stopping = false;
  for (;;) {
    const pid_t done = ::waitpid(child, &status, WNOHANG);
    if (done == child) break;
    if (done < 0 && errno != EINTR) throw std::filesystem::filesystem_error("cannot wait for gnuplot", dir, std::error_code(errno, std::generic_category()));
    if (!stopping && interruption_signal().load() != 0) {
      ::kill(child, SIGKILL);  // stopping: the plot is discarded with the staging directory
      stopping = true;
    }
    ::usleep(2000);
  }
  throw_if_interrupted();
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    // Killed by an interrupt (a terminal's Ctrl-C reaches the whole group): the run stops too.
    if (signal == SIGINT || signal == SIGTERM || signal == SIGHUP || signal == SIGQUIT) {
      int none = 0;
      interruption_signal().compare_exchange_strong(none, signal == SIGTERM ? SIGTERM : SIGINT);
    }
    throw_if_interrupted();
    return 128 + signal;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

/// Draws one plot in `dir` (where its data files are): <name>.gp, then <name>.svg and <name>.png.
/// Returns an empty string, or why it could not be drawn.
std::string draw(const std::filesystem::path& dir, const plot_spec& plot) {
  // Text that stays readable once the page scales the image to its 1200-pixel column: 12 points up
  // to 1200 pixels wide, growing with the square root of the width beyond (a 1700-pixel plot gets
  // 14 points, about 10 pixels on the page, and its panels keep room for their curves).
  const int font_points = static_cast<int>(std::lround(12.0 * std::sqrt(std::max(1.0, plot.width / 1200.0))));
  const std::string fonts = fmt::format("font 'Sans,{}'", font_points);
  const std::string script = fmt::format(
      "# {}\n# Redraw with: gnuplot {}.gp (in this directory)\n"
      "set terminal svg size {},{} dynamic enhanced {} background rgb 'white'\nset output '{}.svg'\n{}\nunset output\nreset\n"
      "set terminal pngcairo size {},{} enhanced {} background rgb 'white'\nset output '{}.png'\n{}\nunset output\n",
      plot.caption, plot.name, plot.width, plot.height, fonts, plot.name, plot.commands, plot.width, plot.height, fonts,
      plot.name, plot.commands);
  write_file(dir / (plot.name + ".gp"), script);
  const int status = run_gnuplot(dir, plot.name + ".gp", plot.name + ".log");
  std::error_code ignored;
  const std::string log = read_file(dir / (plot.name + ".log"));
  std::filesystem::remove(dir / (plot.name + ".log"), ignored);
  if (status != 0) {
    std::string first_line = log.substr(0, log.find('\n'));
    if (status == 127 || log.find("not found") != std::string::npos) first_line = "gnuplot not found (scripts/install-deps)";
    return plot.name + ": " + (first_line.empty() ? "gnuplot failed" : first_line);
  }
  if (!std::filesystem::exists(dir / (plot.name + ".svg")) || !std::filesystem::exists(dir / (plot.name + ".png"))) {
    return plot.name + ": gnuplot wrote no output";
  }
  if (log.find("warning") != std::string::npos || log.find("rror") != std::string::npos) {
    return plot.name + ": gnuplot: " + log.substr(0, log.find('\n'));
  }
  return {};
}

const std::filesystem::path katex_source = "/usr/share/javascript/katex";

/// katex_file_names() copied from Debian's package into the report directory `dir`.
void copy_katex(const std::filesystem::path& dir) {
  for (const std::string& name : katex_file_names()) {
    const std::filesystem::path to = dir / name;
    std::filesystem::create_directories(to.parent_path());
    std::filesystem::copy_file(katex_source / std::filesystem::path(name).lexically_relative("katex"), to,
                               std::filesystem::copy_options::overwrite_existing);
  }
}

}  // namespace

void write_file(const std::filesystem::path& path, const std::string& content) {
  // POSIX calls, not a stream: each says why it failed (a full disk is ENOSPC, from write or close),
  // where a stream's buffer leaves errno to whatever ran last.
  const auto failed = [&](int error) { throw std::filesystem::filesystem_error("cannot write", path, std::error_code(error, std::generic_category())); };
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) failed(errno);
  for (std::size_t written = 0; written < content.size();) {
    const ::ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : EIO;
      ::close(fd);
      failed(error);
    }
    written += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) failed(errno);
}


std::string cmark_gfm_version() { return cmark_version_string(); }

std::vector<std::string> katex_file_names() {
  std::vector<std::string> names;
  if (!std::filesystem::exists(katex_source / "katex.min.js") || !std::filesystem::exists(katex_source / "katex.min.css")) return names;
  names = {"katex/katex.min.css", "katex/katex.min.js"};
  std::error_code ignored;
  for (const auto& font : std::filesystem::directory_iterator(katex_source / "fonts", ignored)) {
    if (font.path().extension() == ".woff2") names.push_back("katex/fonts/" + font.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

plot_outcome write_report_directory(const std::filesystem::path& dir, const std::vector<section_result>& sections,
                                    const std::function<report_documents(const plot_outcome&)>& documents) {
  std::filesystem::path target = std::filesystem::absolute(dir).lexically_normal();
  if (target.filename().empty()) target = target.parent_path();
  const std::string tag = "." + target.filename().string() + "." + std::to_string(::getpid());
  const std::filesystem::path staging = target.parent_path() / (tag + ".staging"), previous = target.parent_path() / (tag + ".old");
  std::error_code ignored;
  std::filesystem::create_directories(target.parent_path());
  std::filesystem::remove_all(staging, ignored);
  std::filesystem::create_directories(staging);
  plot_outcome plots;
  try {
    for (const section_result& section : sections) {
      for (const data_file& f : section_files(section)) write_file(staging / f.name, f.content);
    }
    for (const section_result& section : sections) {
      for (const plot_spec& plot : section_plots(section)) {
        throw_if_interrupted();
        const std::string failure = draw(staging, plot);
        if (failure.empty()) {
          plots.drawn.push_back(plot.name);
        } else {
          plots.failures.push_back(failure);
          for (const char* ext : {".svg", ".png"}) std::filesystem::remove(staging / (plot.name + ext), ignored);
        }
      }
    }
    const report_documents docs = documents(plots);
    write_file(staging / "report.json", docs.report.dump(2) + "\n");
    write_file(staging / "report.md", docs.markdown);
    write_file(staging / "report.html", render_report_html(docs.markdown, docs.title, !katex_file_names().empty()));
    copy_katex(staging);
    if (!docs.junit.empty()) write_file(staging / "report.junit.xml", docs.junit);
    for (const auto& [name, content] : docs.extra_files) {
      std::filesystem::create_directories((staging / name).parent_path());
      write_file(staging / name, content);
    }
    if (!docs.timing.is_null()) {
      write_file(staging / "timing.json", docs.timing.dump(2) + "\n");
      write_file(staging / "timing.md", docs.timing_markdown);
      write_file(staging / "timing.html", render_report_html(docs.timing_markdown, docs.title + ": run times", !katex_file_names().empty()));
    }
    // Everything is written: the staged directory replaces the previous report whole. SIGINT and
    // SIGTERM wait (blocked) during the two renames, so the swap is never left half done; one that
    // came before it stops the run here, with the previous report untouched.
    sigset_t stop_signals, before;
    sigemptyset(&stop_signals);
    sigaddset(&stop_signals, SIGINT);
    sigaddset(&stop_signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stop_signals, &before);
    try {
      throw_if_interrupted();
      if (std::filesystem::exists(target)) {
        if (!std::filesystem::is_empty(target) && !holds_only_a_report(target)) {
          throw std::invalid_argument("--out '" + dir.string() +
                                      "': files that are not a simpson-verify report appeared during the run; nothing was replaced");
        }
        std::filesystem::rename(target, previous);
        try {
          std::filesystem::rename(staging, target);
        } catch (...) {
          std::filesystem::rename(previous, target, ignored);  // put the previous report back
          throw;
        }
      } else {
        std::filesystem::rename(staging, target);
      }
    } catch (...) {
      pthread_sigmask(SIG_SETMASK, &before, nullptr);
      throw;
    }
    pthread_sigmask(SIG_SETMASK, &before, nullptr);
    std::filesystem::remove_all(previous, ignored);
  } catch (...) {
    std::filesystem::remove_all(staging, ignored);
    throw;
  }
  return plots;
}

bool holds_only_a_report(const std::filesystem::path& dir) {
  std::vector<std::string> listed;
  std::ifstream in(dir / "report.json");
  bool has_list = false;
  if (in) {
    try {
      const json j = json::parse(in);
      if (j.value("tool", "") != "simpson-verify") return false;
      if (j.contains("files")) {
        has_list = true;
        for (const char* list : {"files", "timing_files"}) {
          if (j.contains(list)) {
            for (const json& f : j[list]) listed.push_back(f.get<std::string>());
          }
        }
      }
    } catch (const json::exception&) {
      return false;
    }
  }
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    // katex/: Debian's KaTeX as copy_katex writes it beside report.html (its files and fonts/ only).
    if (entry.is_directory() && name == "katex" && in) {
      for (const auto& inner : std::filesystem::recursive_directory_iterator(entry.path())) {
        const std::string file = inner.path().filename().string();
        const bool asset = inner.is_directory() ? file == "fonts" : file.rfind("katex", 0) == 0 || file.rfind("KaTeX_", 0) == 0;
        if (!asset) return false;
      }
      continue;
    }
    if (entry.is_directory() && has_list) {
      // A directory of the report (certificates/): every file in it listed, nothing deeper.
      for (const auto& inner : std::filesystem::directory_iterator(entry.path())) {
        if (!inner.is_regular_file()) return false;
        if (std::find(listed.begin(), listed.end(), name + "/" + inner.path().filename().string()) == listed.end()) return false;
      }
      continue;
    }
    if (!entry.is_regular_file()) return false;
    if (has_list) {
      if (std::find(listed.begin(), listed.end(), name) == listed.end() && name != "report.json") return false;
      continue;
    }
    // A report from before the file list: report.* and section files only.
    const std::string ext = entry.path().extension().string();
    const bool report_file = name.rfind("report.", 0) == 0;
    if (!in || !(report_file || ext == ".csv" || ext == ".dat" || ext == ".gp" || ext == ".svg" || ext == ".png")) return false;
  }
  return true;
}

void prepare_output_directory(const std::filesystem::path& dir) {
  std::error_code error;
  const auto refuse = [&](const std::string& why) {
    throw std::invalid_argument("--out '" + dir.string() + "': " + why);
  };
  if (std::filesystem::exists(dir, error)) {
    if (!std::filesystem::is_directory(dir)) refuse("cannot create the directory (Not a directory)");
    if (!std::filesystem::is_empty(dir, error) && !holds_only_a_report(dir)) {
      refuse("holds files that are not a simpson-verify report; choose an empty or new directory (nothing was deleted)");
    }
    // The new report replaces the directory whole (a rename): a mount point cannot be renamed, and a
    // read-only one cannot be replaced either. Said now, before anything runs.
    struct stat own {}, above {};
    const std::filesystem::path absolute = std::filesystem::absolute(dir, error).lexically_normal();
    const std::filesystem::path parent = (absolute.filename().empty() ? absolute.parent_path() : absolute).parent_path();
    if (::stat(absolute.c_str(), &own) == 0 && ::stat(parent.c_str(), &above) == 0 && own.st_dev != above.st_dev) {
      refuse(std::string("is a mount point") + (::access(absolute.c_str(), W_OK) != 0 && errno == EROFS ? " (read-only)" : "") +
             "; the report replaces its directory whole, so name a directory inside it");
    }
  }
  // The report is staged beside `dir`: its parent must exist (or be creatable) and be writable.
  std::filesystem::path parent = std::filesystem::absolute(dir, error).parent_path();
  while (!parent.empty() && !std::filesystem::exists(parent, error)) parent = parent.parent_path();
  if (parent.empty() || !std::filesystem::is_directory(parent, error)) {
    refuse("cannot create the directory (Not a directory)");
  }
  // A probe directory, created and removed: permission bits alone do not tell (root, /proc).
  const std::filesystem::path probe = parent / (".simpson-verify-probe." + std::to_string(::getpid()));
  if (!std::filesystem::create_directory(probe, error)) {
    refuse("cannot create the directory (" + (error ? error.message() : std::string("exists")) + ")");
  }
  std::filesystem::remove(probe, error);
}

}  // namespace simpson::verify

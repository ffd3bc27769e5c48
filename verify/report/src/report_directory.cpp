// Writing a report directory: staged beside it, then swapped into place; plots drawn by gnuplot;
// report.html rendered from report.md by cmark-gfm with the SVG plots embedded.

#include <simpson/verify/interruption.hpp>
#include <simpson/verify/report_directory.hpp>

#include <cmark-gfm-core-extensions.h>
#include <cmark-gfm.h>
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace simpson::verify {
namespace {

void write_file(const std::filesystem::path& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << content;
  out.flush();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A path quoted for /bin/sh.
std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// Draws one plot in `dir` (where its data files are): <name>.gp, then <name>.svg and <name>.png.
/// Returns an empty string, or why it could not be drawn.
std::string draw(const std::filesystem::path& dir, const plot_spec& plot) {
  const std::string fonts = "font 'Sans,10'";
  const std::string script = fmt::format(
      "# {}\n# Redraw with: gnuplot {}.gp (in this directory)\n"
      "set terminal svg size {},{} dynamic enhanced {} background rgb 'white'\nset output '{}.svg'\n{}\nunset output\nreset\n"
      "set terminal pngcairo size {},{} enhanced {} background rgb 'white'\nset output '{}.png'\n{}\nunset output\n",
      plot.caption, plot.name, plot.width, plot.height, fonts, plot.name, plot.commands, plot.width, plot.height, fonts,
      plot.name, plot.commands);
  write_file(dir / (plot.name + ".gp"), script);
  const std::string command = "cd " + shell_quote(dir.string()) + " && gnuplot " + shell_quote(plot.name + ".gp") +
                              " > " + shell_quote(plot.name + ".log") + " 2>&1";
  const int status = std::system(command.c_str());
  std::error_code ignored;
  const std::string log = read_file(dir / (plot.name + ".log"));
  std::filesystem::remove(dir / (plot.name + ".log"), ignored);
  if (status != 0) {
    std::string first_line = log.substr(0, log.find('\n'));
    if (status == 127 * 256 || log.find("not found") != std::string::npos) first_line = "gnuplot not found (scripts/install-deps)";
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

std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t k = 0;
  for (; k + 2 < bytes.size(); k += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[k]) << 16) | (static_cast<unsigned char>(bytes[k + 1]) << 8) |
                       static_cast<unsigned char>(bytes[k + 2]);
    for (int s = 18; s >= 0; s -= 6) out += table[(v >> s) & 63];
  }
  if (k < bytes.size()) {
    unsigned v = static_cast<unsigned char>(bytes[k]) << 16;
    if (k + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[k + 1]) << 8;
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += k + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

/// report.md as HTML (GitHub-flavoured tables), each <img src="X.svg"> replaced by the SVG itself
/// as a data URI, so that the one file shows the whole report.
std::string render_html(const std::string& markdown, const std::filesystem::path& dir, const std::string& title) {
  cmark_gfm_core_extensions_ensure_registered();
  const std::unique_ptr<cmark_parser, decltype(&cmark_parser_free)> parser(cmark_parser_new(CMARK_OPT_DEFAULT),
                                                                           cmark_parser_free);
  for (const char* name : {"table", "strikethrough", "autolink"}) {
    if (cmark_syntax_extension* ext = cmark_find_syntax_extension(name)) cmark_parser_attach_syntax_extension(parser.get(), ext);
  }
  cmark_parser_feed(parser.get(), markdown.data(), markdown.size());
  cmark_node* document = cmark_parser_finish(parser.get());
  char* rendered = cmark_render_html(document, CMARK_OPT_DEFAULT, cmark_parser_get_syntax_extensions(parser.get()));
  std::string body(rendered);
  std::free(rendered);
  cmark_node_free(document);
  std::string out;
  std::size_t at = 0;
  const std::string marker = "<img src=\"";
  for (std::size_t found; (found = body.find(marker, at)) != std::string::npos;) {
    const std::size_t start = found + marker.size(), end = body.find('"', start);
    const std::string src = body.substr(start, end - start);
    out += body.substr(at, start - at);
    if (src.size() > 4 && src.substr(src.size() - 4) == ".svg" && std::filesystem::exists(dir / src)) {
      out += "data:image/svg+xml;base64," + base64(read_file(dir / src));
    } else {
      out += src;
    }
    at = end;
  }
  out += body.substr(at);
  // Links between the report's pages go to their HTML renderings.
  for (std::size_t found; (found = out.find("href=\"timing.md\"")) != std::string::npos;) out.replace(found, 16, "href=\"timing.html\"");
  for (std::size_t found; (found = out.find("href=\"report.md\"")) != std::string::npos;) out.replace(found, 16, "href=\"report.html\"");
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + title +
         "</title>\n<style>body{font-family:sans-serif;max-width:1200px;margin:2em auto;padding:0 1em;line-height:1.4}"
         "table{border-collapse:collapse;font-size:90%}td,th{border:1px solid #ccc;padding:2px 6px}"
         "pre{background:#f6f6f6;padding:8px;overflow-x:auto;font-size:85%}img{max-width:100%}</style>\n</head>\n<body>\n" +
         out + "</body>\n</html>\n";
}

}  // namespace

std::string cmark_gfm_version() { return cmark_version_string(); }

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
    write_file(staging / "report.html", render_html(docs.markdown, staging, docs.title));
    if (!docs.junit.empty()) write_file(staging / "report.junit.xml", docs.junit);
    for (const auto& [name, content] : docs.extra_files) {
      std::filesystem::create_directories((staging / name).parent_path());
      write_file(staging / name, content);
    }
    if (!docs.timing.is_null()) {
      write_file(staging / "timing.json", docs.timing.dump(2) + "\n");
      write_file(staging / "timing.md", docs.timing_markdown);
      write_file(staging / "timing.html", render_html(docs.timing_markdown, staging, docs.title + ": run times"));
    }
    throw_if_interrupted();
    // Everything is written: the staged directory replaces the previous report whole.
    if (std::filesystem::exists(target)) {
      if (!std::filesystem::is_empty(target) && !holds_only_a_report(target)) {
        throw std::invalid_argument("--out '" + dir.string() +
                                    "': files that are not a simpson-verify report appeared during the run; nothing was replaced");
      }
      std::filesystem::rename(target, previous);
      std::filesystem::rename(staging, target);
      std::filesystem::remove_all(previous, ignored);
    } else {
      std::filesystem::rename(staging, target);
    }
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

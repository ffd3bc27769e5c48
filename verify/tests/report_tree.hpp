#pragma once
// Checks on a written report directory that every test writing one applies: no bare NaN, infinity
// or null in any file, and an HTML page whose tables are all tables.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace simpson::verify::test {

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// No JSON value, Markdown table cell or CSV field of any file below `dir` is nan, inf or null
/// (a fault is always a word: overflow, underflow, non-finite, unstable, failed).
inline void expect_no_bare_non_finite(const std::filesystem::path& dir) {
  static const std::regex json_bad(R"re(: (null|-?nan|-?inf|NaN|-?Infinity)\b|"-?(nan|inf)")re", std::regex::icase);
  static const std::regex md_bad(R"(\| *-?(nan|inf|null) *\|)", std::regex::icase);
  static const std::regex csv_bad(R"((^|,)-?(nan|inf|null)(,|$))", std::regex::icase | std::regex::multiline);
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    const std::string ext = entry.path().extension().string();
    const std::string text = read_text(entry.path());
    ++files;
    if (ext == ".json") {
      EXPECT_FALSE(std::regex_search(text, json_bad)) << entry.path();
    }
    if (ext == ".md") {
      EXPECT_FALSE(std::regex_search(text, md_bad)) << entry.path();
    }
    if (ext == ".csv") {
      EXPECT_FALSE(std::regex_search(text, csv_bad)) << entry.path();
    }
  }
  EXPECT_GT(files, 0u) << dir;
}

/// report.html renders every Markdown table of report.md as an HTML table: as many <table>
/// elements as report.md has tables, and no paragraph that starts with a raw '|'.
inline void expect_html_tables_rendered(const std::filesystem::path& dir) {
  const std::string md = read_text(dir / "report.md"), html = read_text(dir / "report.html");
  static const std::regex separator(R"(^\|(-+\|)+$)", std::regex::multiline);
  const auto md_tables = std::distance(std::sregex_iterator(md.begin(), md.end(), separator), std::sregex_iterator());
  std::size_t html_tables = 0;
  for (std::size_t at = html.find("<table>"); at != std::string::npos; at = html.find("<table>", at + 1)) ++html_tables;
  EXPECT_GT(md_tables, 0);
  EXPECT_EQ(static_cast<std::size_t>(md_tables), html_tables) << dir;
  EXPECT_EQ(html.find("<p>|"), std::string::npos) << "a table rendered as a paragraph in " << dir;
}

}  // namespace simpson::verify::test

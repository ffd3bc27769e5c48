#include <simpson/verify/paper_source.hpp>

#include "embedded_paper.hpp"

#include <simpson/verify/sha256.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace simpson::verify {
namespace {

/// The math of the display that starts at or before `from` and ends at the next display end.
tex_display display_from(const paper_source& paper, std::size_t from, const std::string& locator) {
  static const char* ends[] = {"\\monendstar", "\\monend", "\\end{equation", "\\end{eqnarray"};
  std::size_t end = std::string::npos;
  for (const char* e : ends) end = std::min(end, paper.text.find(e, from));
  if (end == std::string::npos) {
    throw std::invalid_argument("paper '" + paper.origin + "', " + locator + ": the display has no end");
  }
  std::string tex = paper.text.substr(from, end - from);
  std::replace(tex.begin(), tex.end(), '\n', ' ');
  std::size_t first = from;
  while (first < end && std::isspace(static_cast<unsigned char>(paper.text[first]))) ++first;
  return {locator, line_at(paper.text, first), tex};
}

std::size_t anchor_position(const paper_source& paper, const std::string& anchor) {
  const auto found = find_ignoring_space(paper.text, anchor);
  if (!found) {
    throw std::invalid_argument("paper '" + paper.origin + "': the anchor '" + anchor + "' the ledger needs is not there");
  }
  return found->first;
}

bool is_dollar(const std::string& text, std::size_t k) { return text[k] == '$' && (k == 0 || text[k - 1] != '\\'); }

}  // namespace

std::optional<std::pair<std::size_t, std::size_t>> find_ignoring_space(const std::string& text, const std::string& needle,
                                                                       std::size_t from, bool whole_word, std::size_t within) {
  const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  std::string key;
  for (const char c : needle) {
    if (!space(c)) key += c;
  }
  if (key.empty()) return std::nullopt;
  const std::size_t last = within == std::string::npos ? text.size() : std::min(text.size(), from + within);
  const bool word = whole_word && std::isalnum(static_cast<unsigned char>(key.front())) != 0;
  for (std::size_t start = text.find(key.front(), from); start != std::string::npos && start <= last;
       start = text.find(key.front(), start + 1)) {
    if (word && start > 0 && std::isalnum(static_cast<unsigned char>(text[start - 1])) != 0) continue;  // mid-word
    std::size_t t = start, k = 0;
    while (k < key.size() && t < text.size()) {
      if (space(text[t])) {
        ++t;
      } else if (text[t] == key[k]) {
        ++t;
        ++k;
      } else {
        break;
      }
    }
    if (k == key.size()) return std::make_pair(start, t);
  }
  return std::nullopt;
}

int line_at(const std::string& text, std::size_t offset) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

std::string folded_space(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (std::isspace(static_cast<unsigned char>(c)) != 0) {
      if (!out.empty() && out.back() != ' ') out += ' ';
    } else {
      out += c;
    }
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

std::string without_comments(const std::string& tex) {
  std::string out = tex;
  bool in_comment = false;
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (out[k] == '\n') {
      in_comment = false;
    } else if (in_comment) {
      out[k] = ' ';
    } else if (out[k] == '%' && (k == 0 || out[k - 1] != '\\')) {
      in_comment = true;
      out[k] = ' ';
    }
  }
  return out;
}

paper_source embedded_paper() {
  return {"embedded", without_comments(embedded_paper_text()), sha256_hex(embedded_paper_text()), embedded_paper_text()};
}

namespace {

paper_source read_source(const std::string& path, const std::string& what) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw std::invalid_argument(what + " '" + path + "': is a directory, not a LaTeX file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(what + " '" + path + "': missing or unreadable");
  std::ostringstream text;
  text << in.rdbuf();
  if (!in.good() && !in.eof()) throw std::invalid_argument(what + " '" + path + "': cannot be read");
  if (text.str().find_first_not_of(" \t\r\n") == std::string::npos) {
    throw std::invalid_argument(what + " '" + path + "': the file is empty");
  }
  return {path, without_comments(text.str()), sha256_hex(text.str()), text.str()};
}

}  // namespace

paper_source load_paper(const std::string& path) {
  paper_source paper = read_source(path, "paper");
  if (paper.text.find("symplectic scheme") == std::string::npos || paper.text.find("\\label{Phi3}") == std::string::npos) {
    throw std::invalid_argument("paper '" + path +
                                "': not the symplectic Simpson paper (no title 'symplectic scheme' or no \\label{Phi3})");
  }
  return paper;
}

paper_source load_document(const std::string& path, const std::string& title) {
  paper_source document = read_source(path, "document");
  if (!find_ignoring_space(document.text, title)) {
    throw std::invalid_argument("document '" + path + "': does not print its claims file's title '" + title + "'");
  }
  return document;
}

tex_display find_labelled(const paper_source& paper, const std::string& label) {
  const std::string key = "\\label{" + label + "}";
  const std::size_t at = paper.text.find(key);
  if (at == std::string::npos) {
    throw std::invalid_argument("paper '" + paper.origin + "': the label '" + label + "' the ledger needs is not there");
  }
  return display_from(paper, at + key.size(), "label " + label);
}

tex_display find_anchored(const paper_source& paper, const std::string& anchor) {
  const std::size_t at = anchor_position(paper, anchor);
  static const char* starts[] = {"\\moneqstar", "\\moneq", "\\begin{equation"};
  std::size_t start = std::string::npos, length = 0;
  for (const char* s : starts) {
    const std::size_t found = paper.text.find(s, at);
    if (found < start) {
      start = found;
      length = std::string(s).size();
    }
  }
  if (start == std::string::npos) {
    throw std::invalid_argument("paper '" + paper.origin + "': no display after the anchor '" + anchor + "'");
  }
  if (paper.text.compare(start, 6, "\\begin") == 0) {  // \begin{equation} or \begin{equation*}: after its '}'
    const std::size_t close = paper.text.find('}', start);
    length = close == std::string::npos ? length : close + 1 - start;
  }
  return display_from(paper, start + length, "anchor '" + anchor + "'");
}

}  // namespace simpson::verify

namespace simpson::verify {

tex_display find_inline(const paper_source& paper, const std::string& anchor) {
  const std::size_t at = anchor_position(paper, anchor);
  std::size_t dollars = 0, last = std::string::npos;
  for (std::size_t k = 0; k < at; ++k) {
    if (is_dollar(paper.text, k)) {
      ++dollars;
      last = k;
    }
  }
  std::size_t open = last;
  if (dollars % 2 == 0) {  // the anchor is prose: the first inline formula after it
    open = at;
    while (open < paper.text.size() && !is_dollar(paper.text, open)) ++open;
  }
  std::size_t close = open + 1;
  while (close < paper.text.size() && !is_dollar(paper.text, close)) ++close;
  if (open >= paper.text.size() || close >= paper.text.size()) {
    throw std::invalid_argument("paper '" + paper.origin + "': no inline formula at the anchor '" + anchor + "'");
  }
  std::string tex = paper.text.substr(open + 1, close - open - 1);
  std::replace(tex.begin(), tex.end(), '\n', ' ');
  return {"inline formula at '" + anchor + "'", line_at(paper.text, open), tex};
}

}  // namespace simpson::verify

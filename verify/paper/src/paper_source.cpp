#include <simpson/verify/paper_source.hpp>

#include <simpson/verify/sha256.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace simpson::verify {
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

void replace_text(paper_source& source, std::size_t at, std::size_t length, const std::string& to) {
  if (source.raw.empty()) source.raw = source.text;
  source.raw.replace(at, length, to);
  source.text = without_comments(source.raw);
}

paper_source source_from_text(const std::string& origin, const std::string& text) {
  return {origin, without_comments(text), sha256_hex(text), text};
}

paper_source load_source(const std::string& path, const std::string& what) {
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

paper_source load_document(const std::string& path, const std::string& title) {
  paper_source document = load_source(path, "document");
  if (!find_ignoring_space(document.text, title)) {
    throw std::invalid_argument("document '" + path + "': does not print its claims file's title '" + title + "'");
  }
  return document;
}

}  // namespace simpson::verify

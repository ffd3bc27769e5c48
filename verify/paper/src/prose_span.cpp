#include <simpson/verify/prose_span.hpp>

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <utility>
#include <vector>

namespace simpson::verify {
namespace {

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

/// Runs of white space folded to one space, none at the ends.
std::string folded(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (is_space(c)) {
      if (!out.empty() && out.back() != ' ') out += ' ';
    } else {
      out += c;
    }
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

/// The end of `key` (white space removed) matched at `start` of `text`, white space in the text
/// skipped; npos when it does not match there.
std::size_t match_at(const std::string& text, const std::string& key, std::size_t start) {
  std::size_t t = start;
  for (const char k : key) {
    while (t < text.size() && is_space(text[t])) ++t;
    if (t >= text.size() || text[t] != k) return std::string::npos;
    ++t;
  }
  return t;
}

/// The first [start, end) at or after `from` (and, when `within` is set, starting no later than
/// from + within) where `key` matches.
std::optional<std::pair<std::size_t, std::size_t>> find_key(const std::string& text, const std::string& key, std::size_t from,
                                                            std::size_t within = std::string::npos) {
  const std::size_t last = within == std::string::npos ? text.size() : std::min(text.size(), from + within);
  const bool word = std::isalnum(static_cast<unsigned char>(key.front())) != 0;
  for (std::size_t start = text.find(key.front(), from); start != std::string::npos && start <= last;
       start = text.find(key.front(), start + 1)) {
    if (word && start > 0 && std::isalnum(static_cast<unsigned char>(text[start - 1])) != 0) continue;  // mid-word
    const std::size_t end = match_at(text, key, start);
    if (end != std::string::npos) return std::make_pair(start, end);
  }
  return std::nullopt;
}

struct pattern_part {
  std::string literal;  // white space removed
  std::string hole;     // the hole after the literal, or empty for the last part
};

std::vector<pattern_part> split_pattern(const std::string& pattern) {
  std::vector<pattern_part> parts(1);
  for (std::size_t k = 0; k < pattern.size(); ++k) {
    const char c = pattern[k];
    // A hole starts a word: "\ref{simpson}" and "H_{j+1}" are text.
    if (c == '{' && k + 1 < pattern.size() && std::isalpha(static_cast<unsigned char>(pattern[k + 1])) &&
        (k == 0 || is_space(pattern[k - 1]) || pattern[k - 1] == '(')) {
      const std::size_t close = pattern.find('}', k);
      if (close == std::string::npos) throw std::logic_error("prose pattern '" + pattern + "': unclosed hole");
      const std::string name = pattern.substr(k + 1, close - k - 1);
      if (name.size() < 2 || name.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") != std::string::npos) {
        parts.back().literal += pattern.substr(k, close - k + 1);  // TeX such as {\rm det}: text, not a hole
        k = close;
        continue;
      }
      if (parts.back().literal.empty()) {
        throw std::logic_error("prose pattern '" + pattern + "': a hole must follow printed words");
      }
      parts.back().hole = name;
      parts.emplace_back();
      k = close;
    } else if (!is_space(c)) {
      parts.back().literal += c;
    }
  }
  if (parts.back().literal.empty() && parts.size() > 1) {
    throw std::logic_error("prose pattern '" + pattern + "': a hole must be followed by printed words");
  }
  return parts;
}

int line_at(const std::string& text, std::size_t offset) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

}  // namespace

std::optional<prose_span> find_prose(const paper_source& paper, const std::string& pattern) {
  constexpr std::size_t longest_hole = 240;
  const std::vector<pattern_part> parts = split_pattern(pattern);
  const std::string& text = paper.text;
  for (std::size_t from = 0;;) {
    const auto first = find_key(text, parts.front().literal, from);
    if (!first) return std::nullopt;
    prose_span span;
    std::size_t at = first->second;
    bool matched = true;
    for (std::size_t k = 0; k + 1 < parts.size(); ++k) {
      const auto next = find_key(text, parts[k + 1].literal, at, longest_hole);
      if (!next) {
        matched = false;
        break;
      }
      span.holes[parts[k].hole] = folded(text.substr(at, next->first - at));
      at = next->second;
    }
    if (matched) {
      span.line = line_at(text, first->first);
      span.text = folded(text.substr(first->first, at - first->first));
      return span;
    }
    from = first->first + 1;
  }
}

std::string plain_words(const std::string& tex) {
  std::string out;
  for (std::size_t k = 0; k < tex.size(); ++k) {
    const char c = tex[k];
    if (c == '$' || c == '~') {
      out += ' ';
      continue;
    }
    if (c == '\\' && k + 1 < tex.size()) {
      const char n = tex[k + 1];
      if (n == ',' || n == '!' || n == ';' || n == ':' || n == ' ') {
        out += ' ';
        ++k;
        continue;
      }
      static const char* dropped[] = {"quad", "qquad", "big", "Big", "bigg", "Bigg", "left", "right", "displaystyle"};
      bool was_dropped = false;
      for (const char* word : dropped) {
        const std::string w(word);
        const std::size_t after = k + 1 + w.size();
        if (tex.compare(k + 1, w.size(), w) == 0 && (after >= tex.size() || !std::isalpha(static_cast<unsigned char>(tex[after])))) {
          out += ' ';
          k += w.size();
          was_dropped = true;
          break;
        }
      }
      if (was_dropped) continue;
    }
    out += c;
  }
  return folded(out);
}

}  // namespace simpson::verify

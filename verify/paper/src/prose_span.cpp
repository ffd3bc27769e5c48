#include <simpson/verify/prose_span.hpp>

#include <cctype>
#include <stdexcept>
#include <utility>
#include <vector>

namespace simpson::verify {
namespace {

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

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
      if (close == std::string::npos) throw std::invalid_argument("the sentence's pattern '" + pattern + "' has an unclosed hole");
      const std::string name = pattern.substr(k + 1, close - k - 1);
      if (name.size() < 2 || name.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") != std::string::npos) {
        parts.back().literal += pattern.substr(k, close - k + 1);  // TeX such as {\rm det}: text, not a hole
        k = close;
        continue;
      }
      if (parts.back().literal.empty()) {
        throw std::invalid_argument("the sentence's pattern '" + pattern + "' starts with a hole: a hole must follow printed words");
      }
      parts.back().hole = name;
      parts.emplace_back();
      k = close;
    } else if (!is_space(c)) {
      parts.back().literal += c;
    }
  }
  if (parts.back().literal.empty() && parts.size() > 1) {
    throw std::invalid_argument("the sentence's pattern '" + pattern + "' ends with a hole: a hole must be followed by printed words");
  }
  return parts;
}

}  // namespace

void check_pattern(const std::string& pattern) { (void)split_pattern(pattern); }

namespace {

/// Whether a hole's words stay in the sentence's text: some words, and no display (an environment,
/// \[ \], $$) or paragraph break inside, which a hole of a pattern never means to take.
bool hole_in_prose(const std::string& words) {
  if (words.find_first_not_of(" \t\r\n") == std::string::npos) return false;  // a hole stands for words: never none
  for (const char* display : {"\\begin{", "\\end{", "\\[", "\\]", "$$"}) {
    if (words.find(display) != std::string::npos) return false;
  }
  for (std::size_t k = words.find('\n'); k != std::string::npos; k = words.find('\n', k + 1)) {
    std::size_t next = k + 1;
    while (next < words.size() && words[next] != '\n' && is_space(words[next])) ++next;
    if (next < words.size() && words[next] == '\n') return false;
  }
  return true;
}

/// The span matching `parts` from the literal found at `first`, or none.
std::optional<prose_span> span_from(const std::string& text, const std::vector<pattern_part>& parts, std::pair<std::size_t, std::size_t> first) {
  constexpr std::size_t longest_hole = 240;
  prose_span span;
  std::size_t at = first.second;
  for (std::size_t k = 0; k + 1 < parts.size(); ++k) {
    const auto next = find_ignoring_space(text, parts[k + 1].literal, at, true, longest_hole);
    if (!next) return std::nullopt;
    const std::string words = text.substr(at, next->first - at);
    if (!hole_in_prose(words)) return std::nullopt;
    span.holes[parts[k].hole] = folded_space(words);
    at = next->second;
  }
  span.line = line_at(text, first.first);
  span.text = folded_space(text.substr(first.first, at - first.first));
  return span;
}

}  // namespace

std::optional<prose_span> find_prose(const paper_source& paper, const std::string& pattern) {
  const std::vector<pattern_part> parts = split_pattern(pattern);
  const std::string& text = paper.text;
  std::optional<prose_span> found;
  for (std::size_t from = 0;;) {
    const auto first = find_ignoring_space(text, parts.front().literal, from, true);
    if (!first) return found;
    from = first->first + 1;
    std::optional<prose_span> span = span_from(text, parts, *first);
    if (!span) continue;
    if (!found) {
      found = std::move(span);
      if (parts.size() == 1) return found;  // no hole: the words are the words, wherever they stand
    } else {
      found->also_at.push_back(span->line);
    }
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
  return folded_space(out);
}

}  // namespace simpson::verify

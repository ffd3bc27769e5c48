#pragma once
// Cutting UTF-8 text for a reader: never inside a character (a CI log with a split character is
// shown as binary), and around where two texts differ.

#include <algorithm>
#include <cstddef>
#include <string>

namespace simpson::verify {

/// The start of the UTF-8 character at or before byte `at`.
inline std::size_t utf8_character_start(const std::string& text, std::size_t at) {
  while (at > 0 && at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) --at;
  return at;
}

/// The first byte where `a` and `b` differ, moved back to a character's start.
inline std::size_t utf8_first_difference(const std::string& a, const std::string& b) {
  std::size_t k = 0;
  while (k < a.size() && k < b.size() && a[k] == b[k]) ++k;
  return utf8_character_start(a.size() < b.size() ? b : a, k);
}

/// At most `most` bytes of `text` from about 40 bytes before `at`, cut between characters, with
/// "..." where cut.
inline std::string utf8_around(const std::string& text, std::size_t at, std::size_t most) {
  if (text.size() <= most) return text;
  std::size_t start = at > 40 ? utf8_character_start(text, at - 40) : 0;
  std::size_t end = utf8_character_start(text, std::min(text.size(), start + most));
  if (end == text.size()) start = utf8_character_start(text, text.size() > most ? text.size() - most : 0);
  return (start > 0 ? "..." : "") + text.substr(start, end - start) + (end < text.size() ? "..." : "");
}

}  // namespace simpson::verify

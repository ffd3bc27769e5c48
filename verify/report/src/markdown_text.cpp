#include <simpson/verify/markdown_text.hpp>

#include <algorithm>

namespace simpson::verify {

std::string markdown_escaped(std::string_view text) {
  static constexpr std::string_view syntax = "\\`*_[]<>|~&!";
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  for (const char c : text) {
    if (c == '\n' || c == '\r') {
      out += ' ';
      continue;
    }
    if (syntax.find(c) != std::string_view::npos) out += '\\';
    out += c;
  }
  return out;
}

std::string markdown_code(std::string_view text) {
  std::size_t longest = 0, run = 0;
  for (const char c : text) {
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  const std::string fence(longest + 1, '`');
  std::string body;
  for (const char c : text) body += c == '\n' || c == '\r' ? ' ' : c;
  // A span that starts or ends with a backtick needs a space between it and the fence; CommonMark
  // strips one space on each side when both are there.
  const bool pad = !body.empty() && (body.front() == '`' || body.back() == '`' || body.front() == ' ');
  return fence + (pad ? " " : "") + body + (pad ? " " : "") + fence;
}

}  // namespace simpson::verify

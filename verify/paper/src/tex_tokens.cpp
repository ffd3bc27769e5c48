// TeX's tokens: see tex_tokens.hpp.

#include <simpson/verify/tex_tokens.hpp>

namespace simpson::verify {
namespace {

bool is_letter(char c, bool at_letter) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (at_letter && c == '@'); }
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// The length of the UTF-8 character that starts with `lead` (1 for a stray byte).
std::size_t utf8_length(unsigned char lead) {
  if (lead >= 0xF0) return 4;
  if (lead >= 0xE0) return 3;
  if (lead >= 0xC0) return 2;
  return 1;
}

}  // namespace

std::vector<tex_token> tex_tokenize(const std::string& text, std::size_t base) {
  std::vector<tex_token> out;
  bool at_letter = false;
  std::size_t k = 0;
  const auto push = [&](tex_category c, std::size_t from, std::size_t to) {
    out.push_back({c, text.substr(from, to - from), base + from, to - from});
  };
  while (k < text.size()) {
    const char c = text[k];
    if (c == '%') {  // a comment: to the end of the line, and the line's end with it
      while (k < text.size() && text[k] != '\n') ++k;
      if (k < text.size()) ++k;
      while (k < text.size() && is_blank(text[k])) ++k;  // TeX skips the next line's leading blanks
      continue;
    }
    if (is_blank(c) || c == '\n') {
      const std::size_t from = k;
      int ends = 0;
      while (k < text.size() && (is_blank(text[k]) || text[k] == '\n')) {
        if (text[k] == '\n') ++ends;
        ++k;
      }
      if (ends >= 2) {
        out.push_back({tex_category::paragraph, "\\par", base + from, k - from});
      } else if (!out.empty() && out.back().category == tex_category::control && out.back().length > 1 &&
                 is_letter(out.back().text.back(), at_letter) && out.back().trailing.empty()) {
        out.back().trailing = " ";  // a control word swallows the blanks after it
      } else {
        out.push_back({tex_category::space, " ", base + from, k - from});
      }
      continue;
    }
    if (c == '\\') {
      std::size_t j = k + 1;
      if (j < text.size() && is_letter(text[j], at_letter)) {
        while (j < text.size() && is_letter(text[j], at_letter)) ++j;
      } else if (j < text.size()) {
        j += utf8_length(static_cast<unsigned char>(text[j]));
      }
      push(tex_category::control, k, j);
      if (out.back().text == "\\makeatletter") at_letter = true;
      if (out.back().text == "\\makeatother") at_letter = false;
      k = j;
      continue;
    }
    tex_category category = tex_category::other;
    switch (c) {
      case '{': category = tex_category::begin_group; break;
      case '}': category = tex_category::end_group; break;
      case '$': category = tex_category::math_shift; break;
      case '&': category = tex_category::alignment; break;
      case '#': category = tex_category::parameter; break;
      case '^': category = tex_category::superscript; break;
      case '_': category = tex_category::subscript; break;
      case '~': category = tex_category::active; break;
      default: category = is_letter(c, at_letter) ? tex_category::letter : tex_category::other;
    }
    const std::size_t length = category == tex_category::other ? utf8_length(static_cast<unsigned char>(c)) : 1;
    push(category, k, std::min(text.size(), k + length));
    k += length;
  }
  return out;
}

std::string tex_text(std::vector<tex_token>::const_iterator from, std::vector<tex_token>::const_iterator to) {
  std::string out;
  for (auto it = from; it != to; ++it) {
    if (it->category == tex_category::paragraph) {
      out += ' ';
      continue;
    }
    out += it->text;
    out += it->trailing;
  }
  return out;
}

std::string tex_text(const std::vector<tex_token>& tokens) { return tex_text(tokens.begin(), tokens.end()); }

}  // namespace simpson::verify

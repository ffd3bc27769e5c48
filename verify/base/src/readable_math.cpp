// The canonical text's math as a reader writes it: see readable_math.hpp.

#include <simpson/verify/readable_math.hpp>

#include <algorithm>
#include <cctype>
#include <utility>
#include <vector>

namespace simpson::verify {

std::string readable_math(const std::string& text) {
  static const std::vector<std::pair<std::string, std::string>> greek{
      {"alpha", "α"}, {"beta", "β"}, {"gamma", "γ"}, {"delta", "δ"}, {"epsilon", "ε"}, {"theta", "θ"}, {"lambda", "λ"}, {"mu", "μ"},
      {"xi", "ξ"},    {"pi", "π"},   {"rho", "ρ"},   {"sigma", "σ"}, {"tau", "τ"},      {"phi", "φ"},   {"psi", "ψ"},    {"omega", "ω"}};
  static const char* const superscript[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string out;
  bool math = false;  // inside $…$: TeX, left as it is
  for (std::size_t at = 0; at < text.size();) {
    const char c = text[at];
    if (c == '$') {
      math = !math;
      out += c;
      ++at;
      continue;
    }
    if (math) {
      out += c;
      ++at;
      continue;
    }
    const bool word_start = at == 0 || std::isalnum(static_cast<unsigned char>(text[at - 1])) == 0;
    bool replaced = false;
    for (const auto& [name, letter] : greek) {
      const std::size_t end = at + name.size();
      if (word_start && text.compare(at, name.size(), name) == 0 && (end == text.size() || std::isalpha(static_cast<unsigned char>(text[end])) == 0)) {
        out += letter;
        at = end;
        replaced = true;
        break;
      }
    }
    if (replaced) continue;
    if (word_start && text.compare(at, 5, "sqrt(") == 0) {
      const std::size_t close = text.find(')', at);
      const std::string inner = close == std::string::npos ? "" : text.substr(at + 5, close - at - 5);
      if (!inner.empty() && std::all_of(inner.begin(), inner.end(), [](char d) { return std::isdigit(static_cast<unsigned char>(d)) != 0; })) {
        if (!out.empty() && out.back() == ' ' && out.size() >= 2 && std::isdigit(static_cast<unsigned char>(out[out.size() - 2])) != 0) out.pop_back();
        out += "√" + inner;
        at = close + 1;
        continue;
      }
    }
    if (c == '^' && at + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[at + 1])) != 0) {
      for (++at; at < text.size() && std::isdigit(static_cast<unsigned char>(text[at])) != 0; ++at) out += superscript[text[at] - '0'];
      continue;
    }
    if (c == '*') {  // a product: juxtaposed, but between two digits
      const bool digits = at > 0 && at + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[at - 1])) != 0 &&
                          std::isdigit(static_cast<unsigned char>(text[at + 1])) != 0;
      out += digits ? "·" : "";
      ++at;
      continue;
    }
    out += c;
    ++at;
  }
  return out;
}

}  // namespace simpson::verify

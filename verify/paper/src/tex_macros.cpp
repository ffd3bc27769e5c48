// Macros of a LaTeX source: see tex_macros.hpp.

#include <simpson/verify/tex_macros.hpp>

#include <simpson/verify/paper_source.hpp>

#include <algorithm>
#include <cctype>
#include <vector>

namespace simpson::verify {
namespace {

bool is_letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }

std::size_t skip_space(const std::string& text, std::size_t at) {
  while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at])) != 0) ++at;
  return at;
}

/// The control sequence at `at` ("\\om", "\\,"), or empty when there is none.
std::string control_sequence(const std::string& text, std::size_t at) {
  if (at >= text.size() || text[at] != '\\' || at + 1 >= text.size()) return {};
  std::size_t end = at + 1;
  if (is_letter(text[end])) {
    while (end < text.size() && is_letter(text[end])) ++end;
  } else {
    ++end;
  }
  return text.substr(at, end - at);
}

/// The braced group that starts at `at` (text[at] == '{'): its body, and where it ends (after '}').
bool braced_group(const std::string& text, std::size_t at, std::string& body, std::size_t& end) {
  if (at >= text.size() || text[at] != '{') return false;
  int depth = 0;
  for (std::size_t k = at; k < text.size(); ++k) {
    if (text[k] == '\\') {
      ++k;
      continue;
    }
    if (text[k] == '{') ++depth;
    if (text[k] == '}' && --depth == 0) {
      body = text.substr(at + 1, k - at - 1);
      end = k + 1;
      return true;
    }
  }
  return false;
}

}  // namespace

std::map<std::string, tex_macro> defined_macros(const std::string& text) {
  std::map<std::string, tex_macro> macros;
  for (std::size_t at = text.find('\\'); at != std::string::npos; at = text.find('\\', at + 1)) {
    const std::string command = control_sequence(text, at);
    const bool def = command == "\\def";
    if (!def && command != "\\newcommand" && command != "\\renewcommand" && command != "\\providecommand") continue;
    const int line = line_at(text, at);
    const auto bad = [&](const std::string& why) {
      return std::invalid_argument("line " + std::to_string(line) + ": " + command + ": " + why);
    };
    std::size_t k = skip_space(text, at + command.size());
    std::string name;
    if (k < text.size() && text[k] == '*') k = skip_space(text, k + 1);  // \newcommand*
    if (!def && k < text.size() && text[k] == '{') {
      std::size_t end = 0;
      if (!braced_group(text, k, name, end)) throw bad("the name's group is not closed");
      k = end;
      while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back())) != 0) name.pop_back();
      name.erase(0, skip_space(name, 0));
    } else {
      name = control_sequence(text, k);
      k += name.size();
    }
    if (name.size() < 2 || name[0] != '\\') throw bad("no macro name");
    tex_macro macro;
    macro.line = line;
    k = skip_space(text, k);
    if (!def && k < text.size() && text[k] == '[') {
      const std::size_t close = text.find(']', k);
      if (close == std::string::npos) throw bad("the argument count's '[' is not closed");
      const std::string count = text.substr(k + 1, close - k - 1);
      if (count.size() != 1 || count[0] < '1' || count[0] > '9') throw bad("the argument count '" + count + "' is not 1 to 9");
      macro.arguments = count[0] - '0';
      k = skip_space(text, close + 1);
      if (k < text.size() && text[k] == '[') throw bad("an optional argument with a default is not supported");
    }
    if (def) {  // \def\name#1#2{...}, or with delimiters in the parameter text: \def\name*#1{...}
      while (k < text.size() && text[k] != '{') {
        if (text[k] == '#' && k + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[k + 1])) != 0) {
          ++macro.arguments;
          k += 2;
        } else {
          macro.delimited = true;
          k += text[k] == '\\' ? std::max<std::size_t>(control_sequence(text, k).size(), 1) : 1;
        }
      }
    }
    std::size_t end = 0;
    if (!braced_group(text, k, macro.body, end)) throw bad("no body in braces for " + name);
    for (char& c : macro.body) c = c == '\n' ? ' ' : c;
    macros[name] = macro;
    at = end - 1;
  }
  return macros;
}

std::string expand_macros(const std::string& tex, const std::map<std::string, tex_macro>& macros) {
  if (macros.empty()) return tex;
  std::string text = tex;
  constexpr int most_expansions = 10000;  // a macro that uses itself never ends
  int expansions = 0;
  for (std::size_t at = text.find('\\'); at != std::string::npos; at = text.find('\\', at)) {
    const std::string command = control_sequence(text, at);
    const auto it = macros.find(command);
    if (it == macros.end()) {
      at += command.empty() ? 1 : command.size();
      continue;
    }
    if (++expansions > most_expansions) throw std::invalid_argument("the macro " + command + " expands without end");
    if (it->second.delimited) {
      throw std::invalid_argument("the macro " + command + " (line " + std::to_string(it->second.line) +
                                  ") has delimiters in its parameter text, which the reader does not expand");
    }
    std::size_t k = at + command.size();
    std::vector<std::string> arguments;
    for (int a = 1; a <= it->second.arguments; ++a) {
      k = skip_space(text, k);
      std::string argument;
      std::size_t end = 0;
      if (braced_group(text, k, argument, end)) {
        k = end;
      } else if (k < text.size() && text[k] == '\\') {
        argument = control_sequence(text, k);
        k += argument.size();
      } else if (k < text.size() && text[k] != '}') {
        argument = text.substr(k, 1);
        k += 1;
      } else {
        throw std::invalid_argument("the macro " + command + " is missing its argument " + std::to_string(a));
      }
      arguments.push_back(argument);
    }
    std::string body;
    const std::string& pattern = it->second.body;
    for (std::size_t b = 0; b < pattern.size(); ++b) {
      const int n = pattern[b] == '#' && b + 1 < pattern.size() ? pattern[b + 1] - '0' : 0;
      if (n >= 1 && n <= static_cast<int>(arguments.size())) {
        body += "{" + arguments[static_cast<std::size_t>(n - 1)] + "}";
        ++b;
      } else {
        body += pattern[b];
      }
    }
    // A macro without arguments ending in a letter must not glue onto a following letter.
    if (k < text.size() && is_letter(text[k]) && !body.empty()) body += ' ';
    text.replace(at, k - at, body);
    // Expanded again from the same place: the body may use other macros.
  }
  return text;
}

}  // namespace simpson::verify

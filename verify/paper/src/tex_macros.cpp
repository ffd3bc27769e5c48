// Macros of a LaTeX source, read and expanded as TeX does: see tex_macros.hpp.

#include <simpson/verify/tex_macros.hpp>

#include <algorithm>
#include <cctype>

namespace simpson::verify {
namespace {

using tokens_t = std::vector<tex_token>;

bool is_space(const tex_token& t) { return t.category == tex_category::space; }

// Each helper reads a container of tokens, a vector or the scanner's input stream (a deque whose
// front is the next token: expansion there costs what the expansion holds, not the document).
template <class Tokens>
std::size_t skip_spaces(const Tokens& tokens, std::size_t k) {
  while (k < tokens.size() && is_space(tokens[k])) ++k;
  return k;
}

/// The offset to blame for a fault at tokens[k] (the end of the tokens: the last one).
template <class Tokens>
std::size_t offset_at(const Tokens& tokens, std::size_t k) {
  if (tokens.empty()) return 0;
  return k < tokens.size() ? tokens[k].offset : tokens.back().offset + tokens.back().length;
}

/// The braced group that opens at tokens[k]: its tokens without the braces, and the index after its
/// closing brace. Throws tex_error when it never closes.
template <class Tokens>
std::pair<tokens_t, std::size_t> braced_group(const Tokens& tokens, std::size_t k, const std::string& what) {
  int depth = 0;
  for (std::size_t j = k; j < tokens.size(); ++j) {
    if (tokens[j].category == tex_category::begin_group) ++depth;
    if (tokens[j].category == tex_category::end_group && --depth == 0) {
      return {tokens_t(tokens.begin() + static_cast<std::ptrdiff_t>(k) + 1, tokens.begin() + static_cast<std::ptrdiff_t>(j)), j + 1};
    }
  }
  throw tex_error(what + ": the '{' is never closed", tokens[k].offset, "{");
}

/// An undelimited argument at tokens[k] (spaces before it skipped): a braced group's tokens, or one
/// token; and the index after it.
template <class Tokens>
std::pair<tokens_t, std::size_t> undelimited_argument(const Tokens& tokens, std::size_t k, const std::string& macro, int n) {
  k = skip_spaces(tokens, k);
  if (k >= tokens.size() || tokens[k].category == tex_category::end_group || tokens[k].category == tex_category::paragraph) {
    throw tex_error("the macro " + macro + " is missing its argument " + std::to_string(n), offset_at(tokens, k), macro);
  }
  if (tokens[k].category == tex_category::begin_group) return braced_group(tokens, k, macro + "'s argument " + std::to_string(n));
  return {tokens_t{tokens[k]}, k + 1};
}

/// [ ... ] at tokens[k], the brackets at brace depth 0: its tokens and the index after ']'.
template <class Tokens>
std::pair<tokens_t, std::size_t> bracketed(const Tokens& tokens, std::size_t k, const std::string& what) {
  int depth = 0;
  for (std::size_t j = k + 1; j < tokens.size(); ++j) {
    if (tokens[j].category == tex_category::begin_group) ++depth;
    if (tokens[j].category == tex_category::end_group) --depth;
    if (depth == 0 && tokens[j].is_char(']')) {
      return {tokens_t(tokens.begin() + static_cast<std::ptrdiff_t>(k) + 1, tokens.begin() + static_cast<std::ptrdiff_t>(j)), j + 1};
    }
  }
  throw tex_error(what + ": the '[' is never closed", tokens[k].offset, "[");
}

bool same(const tex_token& a, const tex_token& b) { return a.category == b.category && a.text == b.text; }

/// A delimited argument: the tokens up to the first occurrence of `delimiter` at brace depth 0
/// (one pair of braces around the whole of it removed, as TeX does), and the index after the
/// delimiter.
template <class Tokens>
std::pair<tokens_t, std::size_t> delimited_argument(const Tokens& tokens, std::size_t k, const tokens_t& delimiter, const std::string& macro) {
  int depth = 0;
  for (std::size_t j = k; j < tokens.size(); ++j) {
    if (depth == 0 && j + delimiter.size() <= tokens.size() &&
        std::equal(delimiter.begin(), delimiter.end(), tokens.begin() + static_cast<std::ptrdiff_t>(j), same)) {
      tokens_t argument(tokens.begin() + static_cast<std::ptrdiff_t>(k), tokens.begin() + static_cast<std::ptrdiff_t>(j));
      if (argument.size() >= 2 && argument.front().category == tex_category::begin_group && argument.back().category == tex_category::end_group) {
        const auto [inner, end] = braced_group(argument, 0, macro);
        if (end == argument.size()) argument = inner;
      }
      return {argument, j + delimiter.size()};
    }
    if (tokens[j].category == tex_category::begin_group) ++depth;
    if (tokens[j].category == tex_category::end_group && --depth < 0) break;
  }
  throw tex_error("Use of " + macro + " doesn't match its definition: its delimiter '" + tex_text(delimiter) + "' never comes", offset_at(tokens, k),
                  macro);
}

/// A parameter token #n in `text` at k: n (1 to 9), or 0.
int parameter_number(const tokens_t& text, std::size_t k) {
  if (text[k].category != tex_category::parameter || k + 1 >= text.size()) return 0;
  const std::string& d = text[k + 1].text;
  if (text[k + 1].category != tex_category::other || d.size() != 1 || d[0] < '1' || d[0] > '9') return 0;
  return d[0] - '0';
}

}  // namespace

const tex_macro* tex_macros::find(const std::string& name) const {
  const auto it = macros_.find(name);
  return it == macros_.end() ? nullptr : &it->second;
}

bool is_definition_command(const std::string& name) {
  static const char* names[] = {"\\newcommand", "\\renewcommand", "\\providecommand", "\\def",  "\\gdef",
                                "\\edef",       "\\xdef",         "\\let",            "\\DeclareMathOperator"};
  return std::any_of(std::begin(names), std::end(names), [&](const char* n) { return name == n; });
}

namespace {

template <class Tokens>
std::size_t read_definition_in(const Tokens& tokens, std::size_t at, tex_macros& macros) {
  const std::string command = tokens[at].text;
  const auto fail = [&](const std::string& why, std::size_t k) -> tex_error { return tex_error(command + ": " + why, offset_at(tokens, k), command); };
  std::size_t k = skip_spaces(tokens, at + 1);
  tex_macro macro;
  macro.offset = tokens[at].offset;
  macro.command = command;
  const auto ending = [&](std::size_t after) {  // the source offset where the definition ends
    return after > 0 && after <= tokens.size() ? tokens[after - 1].offset + tokens[after - 1].length : macro.offset;
  };
  const bool latex = command == "\\newcommand" || command == "\\renewcommand" || command == "\\providecommand" || command == "\\DeclareMathOperator";
  bool starred = false;
  if (latex && k < tokens.size() && tokens[k].is_char('*')) {
    starred = true;
    k = skip_spaces(tokens, k + 1);
  }
  // The name: \name, or {\name}.
  if (latex && k < tokens.size() && tokens[k].category == tex_category::begin_group) {
    const auto [inside, end] = braced_group(tokens, k, command);
    tokens_t name;
    for (const tex_token& t : inside) {
      if (!is_space(t)) name.push_back(t);
    }
    if (name.size() != 1 || name.front().category != tex_category::control) throw fail("the name in braces is not one control sequence", k);
    macro.name = name.front().text;
    k = end;
  } else if (k < tokens.size() && (tokens[k].category == tex_category::control || tokens[k].category == tex_category::active)) {
    macro.name = tokens[k].text;
    ++k;
  } else {
    throw fail("no macro name", k);
  }
  if (command == "\\DeclareMathOperator") {
    k = skip_spaces(tokens, k);
    if (k >= tokens.size() || tokens[k].category != tex_category::begin_group) throw fail("the operator's text in braces is missing", k);
    const auto [text, end] = braced_group(tokens, k, command);
    const std::size_t call = tokens[at].offset;
    macro.body.push_back({tex_category::control, starred ? "\\operatorname*" : "\\operatorname", call, 0});
    macro.body.push_back({tex_category::begin_group, "{", call, 0});
    macro.body.insert(macro.body.end(), text.begin(), text.end());
    macro.body.push_back({tex_category::end_group, "}", call, 0});
    macro.end = ending(end);
    macros.define(std::move(macro));
    return end;
  }
  if (command == "\\let") {
    k = skip_spaces(tokens, k);
    if (k < tokens.size() && tokens[k].is_char('=')) k = skip_spaces(tokens, k + 1);
    if (k >= tokens.size()) throw fail("nothing to let " + macro.name + " be", k);
    if (const tex_macro* existing = macros.find(tokens[k].text); existing && tokens[k].category == tex_category::control) {
      tex_macro copy = *existing;
      copy.name = macro.name;
      copy.offset = macro.offset;
      copy.end = ending(k + 1);
      copy.command = command;
      macros.define(std::move(copy));
    } else {
      macro.body.push_back(tokens[k]);
      macro.end = ending(k + 1);
      macros.define(std::move(macro));
    }
    return k + 1;
  }
  if (latex) {
    k = skip_spaces(tokens, k);
    if (k < tokens.size() && tokens[k].is_char('[')) {
      const auto [count, end] = bracketed(tokens, k, command);
      const std::string n = tex_text(count);
      if (n.size() != 1 || n[0] < '1' || n[0] > '9') throw fail("the argument count '" + n + "' is not 1 to 9", k);
      macro.arguments = n[0] - '0';
      k = skip_spaces(tokens, end);
      if (k < tokens.size() && tokens[k].is_char('[')) {
        const auto [first, after] = bracketed(tokens, k, command);
        macro.default_first = first;
        k = skip_spaces(tokens, after);
      }
    }
  } else {
    // \def's parameter text: everything up to the body's brace.
    while (k < tokens.size() && tokens[k].category != tex_category::begin_group) {
      if (tokens[k].category == tex_category::paragraph) throw fail("the parameter text of " + macro.name + " runs into a blank line", k);
      macro.parameter_text.push_back(tokens[k]);
      ++k;
    }
    for (std::size_t j = 0; j < macro.parameter_text.size(); ++j) {
      if (macro.parameter_text[j].category != tex_category::parameter) continue;
      const int n = parameter_number(macro.parameter_text, j);
      if (n != macro.arguments + 1) throw fail("the parameters of " + macro.name + " are not #1, #2, ... in order", k);
      macro.arguments = n;
      ++j;
    }
  }
  if (k >= tokens.size() || tokens[k].category != tex_category::begin_group) throw fail("no body in braces for " + macro.name, k);
  auto [body, end] = braced_group(tokens, k, command + " " + macro.name);
  macro.body = std::move(body);
  if (command == "\\edef" || command == "\\xdef") macro.body = expand_all(macro.body, macros);
  if (command == "\\providecommand" && macros.find(macro.name)) return end;
  macro.end = ending(end);
  macros.define(std::move(macro));
  return end;
}

template <class Tokens>
void expand_in(Tokens& tokens, std::size_t at, const tex_macro& macro) {
  const tex_token call = tokens[at];
  std::vector<tokens_t> arguments;
  std::size_t k = at + 1;
  if (macro.parameter_text.empty()) {
    int first = 1;
    if (macro.default_first) {
      const std::size_t j = skip_spaces(tokens, k);
      if (j < tokens.size() && tokens[j].is_char('[')) {
        auto [argument, end] = bracketed(tokens, j, macro.name);
        arguments.push_back(std::move(argument));
        k = end;
      } else {
        tokens_t given = *macro.default_first;  // the default is the macro's own: at the call, as its body is
        for (tex_token& t : given) {
          t.offset = tokens[at].offset;
          t.length = 0;
          t.macro = tokens[at].macro.empty() ? macro.name : tokens[at].macro;
        }
        arguments.push_back(std::move(given));
      }
      first = 2;
    }
    for (int n = first; n <= macro.arguments; ++n) {
      auto [argument, end] = undelimited_argument(tokens, k, macro.name, n);
      arguments.push_back(std::move(argument));
      k = end;
    }
  } else {
    const tokens_t& text = macro.parameter_text;
    std::size_t p = 0;
    while (p < text.size()) {
      if (parameter_number(text, p) == 0) {  // a delimiter token the call must have next
        if (k >= tokens.size() || !same(tokens[k], text[p])) {
          throw tex_error("Use of " + macro.name + " doesn't match its definition: '" + text[p].text + "' must follow it", offset_at(tokens, k),
                          macro.name);
        }
        ++p;
        ++k;
        continue;
      }
      const int n = parameter_number(text, p);
      p += 2;
      tokens_t delimiter;
      while (p < text.size() && parameter_number(text, p) == 0) delimiter.push_back(text[p++]);
      auto [argument, end] =
          delimiter.empty() ? undelimited_argument(tokens, k, macro.name, n) : delimited_argument(tokens, k, delimiter, macro.name);
      arguments.push_back(std::move(argument));
      k = end;
    }
  }
  tokens_t expansion;
  const std::string origin = call.macro.empty() ? macro.name : call.macro;
  for (std::size_t b = 0; b < macro.body.size(); ++b) {
    const int n = parameter_number(macro.body, b);
    if (n >= 1 && n <= static_cast<int>(arguments.size())) {
      expansion.insert(expansion.end(), arguments[static_cast<std::size_t>(n - 1)].begin(), arguments[static_cast<std::size_t>(n - 1)].end());
      ++b;
      continue;
    }
    if (macro.body[b].category == tex_category::parameter && b + 1 < macro.body.size() && macro.body[b + 1].category == tex_category::parameter) {
      ++b;  // ## is one #
    }
    tex_token t = macro.body[b];
    t.offset = call.offset;
    t.length = 0;
    t.macro = origin;
    expansion.push_back(std::move(t));
  }
  // The blanks the call swallowed stay with the text shown (\dd V reads '{\rm d} V'), never a token.
  if (!expansion.empty() && macro.arguments == 0) expansion.back().trailing += call.trailing;
  tokens.erase(tokens.begin() + static_cast<std::ptrdiff_t>(at), tokens.begin() + static_cast<std::ptrdiff_t>(k));
  tokens.insert(tokens.begin() + static_cast<std::ptrdiff_t>(at), expansion.begin(), expansion.end());
}

}  // namespace

std::size_t read_definition(const std::vector<tex_token>& tokens, std::size_t at, tex_macros& macros) { return read_definition_in(tokens, at, macros); }
std::size_t read_definition(const std::deque<tex_token>& tokens, std::size_t at, tex_macros& macros) { return read_definition_in(tokens, at, macros); }
void expand_at(std::vector<tex_token>& tokens, std::size_t at, const tex_macro& macro) { expand_in(tokens, at, macro); }
void expand_at(std::deque<tex_token>& tokens, std::size_t at, const tex_macro& macro) { expand_in(tokens, at, macro); }

tokens_t expand_all(tokens_t tokens, const tex_macros& macros, int limit) {
  if (macros.empty()) return tokens;
  int expansions = 0;
  for (std::size_t k = 0; k < tokens.size();) {
    const tex_macro* macro = tokens[k].category == tex_category::control || tokens[k].category == tex_category::active ? macros.find(tokens[k].text)
                                                                                                                        : nullptr;
    if (!macro) {
      ++k;
      continue;
    }
    if (++expansions > limit) throw tex_error("the macro " + tokens[k].text + " expands without end", tokens[k].offset, tokens[k].text);
    expand_at(tokens, k, *macro);  // and again from the same place: the body may use other macros
  }
  return tokens;
}

tex_macros defined_macros(const std::string& text) {
  const tokens_t tokens = tex_tokenize(text);
  tex_macros macros;
  for (std::size_t k = 0; k < tokens.size();) {
    if (tokens[k].category == tex_category::control && is_definition_command(tokens[k].text)) {
      k = read_definition(tokens, k, macros);
    } else {
      ++k;
    }
  }
  return macros;
}

}  // namespace simpson::verify

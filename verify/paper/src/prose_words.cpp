// The words of a document's prose: see prose_words.hpp.

#include <simpson/verify/prose_words.hpp>

#include <cctype>
#include <map>
#include <set>
#include <stdexcept>

namespace simpson::verify {

namespace {

bool is_letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }

/// Commands whose arguments a reader never sees: a reference, a key, a file, a length.
const std::set<std::string>& unread_arguments() {
  static const std::set<std::string> names{"label",        "ref",       "eqref",   "pageref", "cite",       "citep",    "citet",      "nocite",
                                           "begin",        "end",       "includegraphics", "bibliography", "bibliographystyle", "bibitem", "url",
                                           "href",         "hspace",    "vspace",  "hskip",   "vskip",      "documentclass", "usepackage", "input",
                                           "include",      "newcommand", "renewcommand", "setlength", "setcounter", "addtocounter", "pagestyle",
                                           "thispagestyle", "color",    "textcolor",
                                           // running heads and feet: the title and the authors again, not prose
                                           "fancyhead", "fancyfoot", "lhead", "chead", "rhead", "lfoot", "cfoot", "rfoot", "markboth", "markright"};
  return names;
}

/// The letter an accent command prints on `base`, in UTF-8; the base alone when the pair is not one.
std::string accented(char accent, char base) {
  static const std::map<std::pair<char, char>, std::string> letters{
      {{'\'', 'a'}, "á"}, {{'\'', 'e'}, "é"}, {{'\'', 'i'}, "í"}, {{'\'', 'o'}, "ó"}, {{'\'', 'u'}, "ú"}, {{'\'', 'E'}, "É"},
      {{'`', 'a'}, "à"},  {{'`', 'e'}, "è"},  {{'`', 'i'}, "ì"},  {{'`', 'o'}, "ò"},  {{'`', 'u'}, "ù"},  {{'`', 'E'}, "È"},
      {{'^', 'a'}, "â"},  {{'^', 'e'}, "ê"},  {{'^', 'i'}, "î"},  {{'^', 'o'}, "ô"},  {{'^', 'u'}, "û"},
      {{'"', 'a'}, "ä"},  {{'"', 'e'}, "ë"},  {{'"', 'i'}, "ï"},  {{'"', 'o'}, "ö"},  {{'"', 'u'}, "ü"},  {{'"', 'O'}, "Ö"}, {{'"', 'U'}, "Ü"},
      {{'~', 'n'}, "ñ"},  {{'~', 'a'}, "ã"},  {{'~', 'o'}, "õ"},  {{'c', 'c'}, "ç"},  {{'c', 'C'}, "Ç"}};
  const auto it = letters.find({accent, base});
  return it != letters.end() ? it->second : std::string(1, base);
}

/// The end of the group that opens at `open` ('{'), or npos.
std::size_t group_end(const std::string& text, std::size_t open) {
  int depth = 0;
  for (std::size_t k = open; k < text.size(); ++k) {
    if (text[k] == '\\') {
      ++k;
      continue;
    }
    if (text[k] == '{') ++depth;
    if (text[k] == '}' && --depth == 0) return k + 1;
  }
  return std::string::npos;
}

std::size_t skip_space(const std::string& text, std::size_t at) {
  while (at < text.size() && (text[at] == ' ' || text[at] == '\t' || text[at] == '\n')) ++at;
  return at;
}

}  // namespace

std::vector<prose_word> prose_words(const paper_source& source, const tex_document& document, const std::string& from) {
  std::string text = source.text;  // comments blanked, offsets kept
  // Math is not prose: blanked where the reader found it (line ends kept, for the lines).
  for (const tex_region& r : document.regions()) {
    for (std::size_t k = r.opener; k < r.end && k < text.size(); ++k) {
      if (text[k] != '\n') text[k] = ' ';
    }
  }
  std::size_t begin = 0, end = text.size();
  if (const std::size_t body = text.find("\\begin{document}"); body != std::string::npos) begin = body + 16;
  if (const std::size_t last = text.find("\\end{document}", begin); last != std::string::npos) end = last;
  if (!from.empty()) {
    const auto at = find_ignoring_space(source.text, from, begin);
    if (!at) throw std::invalid_argument("the prose's start '" + from + "' is not in the source");
    begin = at->first;
  }
  std::vector<prose_word> words;
  std::string word;
  std::size_t word_at = 0;
  // A word glued to a number ("6th", "1950's") is the number's ending, not a word.
  const auto after_digit = [&](std::size_t at) {
    if (at > 0 && text[at - 1] == '\'') --at;
    return at > 0 && std::isdigit(static_cast<unsigned char>(text[at - 1])) != 0;
  };
  const auto close = [&] {
    if (!word.empty() && !after_digit(word_at)) words.push_back({word, line_at(source.text, word_at)});
    word.clear();
  };
  const auto letter = [&](const std::string& l, std::size_t at) {
    if (word.empty()) word_at = at;
    word += l;
  };
  for (std::size_t k = begin; k < end;) {
    const char c = text[k];
    if (c == '\\' && k + 1 < end) {
      const char next = text[k + 1];
      if (next == 'c' && k + 2 < end && !is_letter(text[k + 2])) {  // \c{c}, \c c: a cedilla
        const std::size_t base = skip_space(text, text[k + 2] == '{' ? k + 3 : k + 2);
        if (base < end && is_letter(text[base])) {
          letter(accented('c', text[base]), k);
          k = base + 1 + (text[k + 2] == '{' && base + 1 < end && text[base + 1] == '}' ? 1 : 0);
          continue;
        }
      }
      if (is_letter(next)) {
        std::size_t e = k + 1;
        while (e < end && is_letter(text[e])) ++e;
        const std::string name = text.substr(k + 1, e - k - 1);
        if (unread_arguments().count(name)) {
          std::size_t at = skip_space(text, e + (e < end && text[e] == '*' ? 1 : 0));
          while (at < end && text[at] == '[') {
            const std::size_t closing = text.find(']', at);
            at = closing == std::string::npos ? end : skip_space(text, closing + 1);
          }
          if (at < end && text[at] == '{') {
            const std::size_t g = group_end(text, at);
            e = g == std::string::npos ? end : g;
          }
        }
        close();
        k = e;
        continue;
      }
      if (next == '\'' || next == '`' || next == '^' || next == '"' || next == '~') {  // an accent on a letter, or on {a letter}
        std::size_t base = k + 2;
        const bool braced = base < end && text[base] == '{';
        if (braced) ++base;
        if (base < end && is_letter(text[base])) {
          letter(accented(next, text[base]), k);
          k = base + 1 + (braced && base + 1 < end && text[base + 1] == '}' ? 1 : 0);
          continue;
        }
      }
      close();
      k += 2;  // a control symbol: \, \; \% \& ...
      continue;
    }
    if (is_letter(c) || static_cast<unsigned char>(c) >= 0x80) {  // a letter, or a byte of a UTF-8 one
      letter(std::string(1, c), k);
      ++k;
      continue;
    }
    if (c == '\'' && !word.empty() && k + 1 < end && is_letter(text[k + 1])) {  // Simpson's
      word += c;
      ++k;
      continue;
    }
    if ((c == '{' || c == '}') && !word.empty() && k + 1 < end && is_letter(text[k + 1])) {  // M{\'e}tiers: a group inside a word
      ++k;
      continue;
    }
    close();
    ++k;
  }
  close();
  return words;
}

}  // namespace simpson::verify

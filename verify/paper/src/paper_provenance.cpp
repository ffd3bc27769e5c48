// What text a run checked: see paper_provenance.hpp.

#include <simpson/verify/paper_provenance.hpp>

#include <simpson/verify/tex_macros.hpp>

#include <algorithm>
#include <cctype>
#include <regex>
#include <set>
#include <sstream>

namespace simpson::verify {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// A line that is a comment, and what follows its first "%" (one "%" only: "%%%" lines are remarks).
bool single_comment(const std::string& line, std::string& rest) {
  const std::size_t at = line.find_first_not_of(" \t");
  if (at == std::string::npos || line[at] != '%' || (at + 1 < line.size() && line[at + 1] == '%')) return false;
  rest = line.substr(at + 1);
  return true;
}

/// What opens and what closes a numbered display in this source: `\begin{equation}` and
/// `\end{equation}`, and every macro the source defines whose body holds one of them (a document
/// that writes `\newcommand{\moneq}{\vspace*{-7pt} \begin{equation}}` opens its displays with
/// \moneq).
struct display_delimiters {
  std::regex start;             // an opener, then \label{...}: the label in group 1
  std::vector<std::string> end; // the closers
};

std::string regex_escaped(const std::string& text) {
  static const std::regex special(R"([.^$|()\[\]{}*+?\\])");
  return std::regex_replace(text, special, R"(\$&)");
}

display_delimiters delimiters_of(const std::string& text) {
  std::vector<std::string> openers{"\\begin{equation}"}, closers{"\\end{equation}"};
  tex_macros macros;
  try {
    macros = defined_macros(text);
  } catch (const std::exception&) {  // definitions that do not read: the environment's own delimiters only
  }
  for (const auto& [name, macro] : macros.all()) {
    std::string body;
    for (const tex_token& t : macro.body) body += t.text;
    if (body.find("\\begin{equation}") != std::string::npos) openers.push_back(name);
    if (body.find("\\end{equation}") != std::string::npos) closers.push_back(name);
  }
  std::string alternatives;
  for (const std::string& o : openers) alternatives += (alternatives.empty() ? "" : "|") + regex_escaped(o) + (o.back() == '}' ? "" : "(?![A-Za-z])");
  return {std::regex("(?:" + alternatives + R"()\s*\\label\{([^}]*)\})"), closers};
}

bool closes(const std::string& line, const display_delimiters& d) {
  for (const std::string& c : d.end) {
    for (std::size_t at = line.find(c); at != std::string::npos; at = line.find(c, at + 1)) {
      const std::size_t after = at + c.size();
      if (c.back() == '}' || after >= line.size() || std::isalpha(static_cast<unsigned char>(line[after])) == 0) return true;
    }
  }
  return false;
}

/// [first, last] line indices (0-based) of the live display labelled `label`, or none (first > last).
std::pair<std::size_t, std::size_t> live_display(const std::vector<std::string>& live, const std::string& label, const display_delimiters& d) {
  for (std::size_t k = 0; k < live.size(); ++k) {
    std::smatch m;
    if (std::regex_search(live[k], m, d.start) && m[1] == label) {
      for (std::size_t e = k; e < live.size(); ++e) {
        if (closes(live[e], d)) return {k, e};
      }
    }
  }
  return {1, 0};
}

}  // namespace

paper_provenance read_provenance(const paper_source& paper) {
  paper_provenance p;
  p.sha256 = paper.sha256;
  const std::string& text = paper.text;
  // The title: the \LARGE lines, in order.
  static const std::regex large(R"(\\LARGE\s+([^}]*)\})");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), large); it != std::sregex_iterator(); ++it) {
    p.title += (p.title.empty() ? "" : " ") + folded_space((*it)[1].str());
  }
  // Otherwise \title{...}, as a note writes it.
  static const std::regex title(R"(\\title\{([^}]*)\})");
  std::smatch t;
  if (p.title.empty() && std::regex_search(text, t, title)) p.title = folded_space(t[1].str());
  // The edition line: the sentence that begins with "Edition".
  static const std::regex edition(R"(Edition[^.}]*\.)");
  std::smatch m;
  if (std::regex_search(text, m, edition)) {
    p.edition = folded_space(m.str());
    p.edition_line = line_at(text, static_cast<std::size_t>(m.position()));
  }
  // Citations, and the bibliography that would resolve them.
  static const std::regex cite(R"(\\cite(\[[^\]]*\])?\{([^}]*)\})");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), cite); it != std::sregex_iterator(); ++it) {
    std::istringstream keys((*it)[2].str());
    for (std::string key; std::getline(keys, key, ',');) {
      p.citations.push_back({folded_space(key), line_at(text, static_cast<std::size_t>(it->position()))});
    }
  }
  static const std::regex bibitem(R"(\\bibitem(\[[^\]]*\])?\{([^}]*)\})");
  std::set<std::string> defined;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), bibitem); it != std::sregex_iterator(); ++it) defined.insert((*it)[2].str());
  p.bibliography = !defined.empty() || text.find("\\bibliography{") != std::string::npos ||
                   text.find("\\begin{thebibliography}") != std::string::npos;
  std::set<std::string> seen;
  for (const citation_use& c : p.citations) {
    if (!defined.count(c.key) && seen.insert(c.key).second) p.unresolved.push_back(c.key);
  }
  // A \bibliography{file} resolves through a .bib file this source does not carry: its keys are
  // unresolved here too, unless a \bibitem defines them.
  return p;
}

std::vector<std::string> citations_in_sentence(const paper_source& paper, int line, const std::string& span_text) {
  const std::string& text = paper.text;
  std::size_t from = 0;
  for (int k = 1; k < line && from != std::string::npos; ++k) {
    from = text.find('\n', from);
    if (from != std::string::npos) ++from;
  }
  if (from == std::string::npos) return {};
  const auto span = find_ignoring_space(text, span_text, from);
  if (!span) return {};
  const auto ends_sentence = [&](std::size_t at) {
    return text[at] == '.' && (at + 1 == text.size() || std::isspace(static_cast<unsigned char>(text[at + 1])));
  };
  std::size_t begin = span->first;
  while (begin > 0 && !ends_sentence(begin - 1)) --begin;
  std::size_t end = span->second;
  while (end < text.size() && !ends_sentence(end)) ++end;
  const std::string sentence = text.substr(begin, end - begin);
  std::vector<std::string> keys;
  static const std::regex cite(R"(\\cite(\[[^\]]*\])?\{([^}]*)\})");
  for (auto it = std::sregex_iterator(sentence.begin(), sentence.end(), cite); it != std::sregex_iterator(); ++it) {
    std::istringstream list((*it)[2].str());
    for (std::string key; std::getline(list, key, ',');) keys.push_back(folded_space(key));
  }
  return keys;
}

std::vector<earlier_display> commented_displays(const paper_source& paper) {
  const std::vector<std::string> raw = lines_of(paper.raw), live = lines_of(paper.text);
  const display_delimiters d = delimiters_of(paper.text);
  std::vector<earlier_display> out;
  for (std::size_t k = 0; k < raw.size(); ++k) {
    std::string rest;
    std::smatch m;
    if (!single_comment(raw[k], rest) || !std::regex_search(rest, m, d.start)) continue;
    const std::string label = m[1];
    const auto [first, last] = live_display(live, label, d);
    if (first > last) continue;  // no live display with that label: not an earlier version of one
    earlier_display e{label, static_cast<int>(k) + 1, {}};
    for (std::size_t j = k; j < raw.size(); ++j) {
      std::string body;
      if (!single_comment(raw[j], body)) break;
      e.tex += body + "\n";
      if (closes(body, d)) {
        out.push_back(e);
        break;
      }
    }
  }
  return out;
}

paper_source with_earlier_display(const paper_source& paper, const earlier_display& earlier) {
  // In the source as read (its other comments kept, which TeX drops with their lines' ends), the live
  // display's lines blanked and the earlier one's put in uncommented, line for line.
  const std::vector<std::string> live = lines_of(paper.text);
  std::vector<std::string> raw = lines_of(paper.raw.empty() ? paper.text : paper.raw);
  const auto [first, last] = live_display(live, earlier.label, delimiters_of(paper.text));
  for (std::size_t k = first; k <= last && k < raw.size(); ++k) raw[k].assign(raw[k].size(), ' ');
  const std::vector<std::string> block = lines_of(earlier.tex);
  for (std::size_t k = 0; k < block.size(); ++k) {
    const std::size_t at = static_cast<std::size_t>(earlier.line) - 1 + k;
    if (at < raw.size()) raw[at] = block[k];
  }
  paper_source out = paper;
  out.origin = paper.origin + ", with the earlier (" + earlier.label + ") of line " + std::to_string(earlier.line);
  out.raw.clear();
  for (const std::string& line : raw) out.raw += line + "\n";
  out.text = without_comments(out.raw);
  return out;
}

}  // namespace simpson::verify

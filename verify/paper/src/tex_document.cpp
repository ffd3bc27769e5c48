// A LaTeX document read as TeX reads it: see tex_document.hpp.

#include <simpson/verify/tex_document.hpp>

#include <cctype>
#include <algorithm>
#include <deque>
#include <map>
#include <optional>
#include <set>

namespace simpson::verify {
namespace {

using tokens_t = std::vector<tex_token>;

struct math_environment {
  bool aligned;  // rows with alignment points
  bool rows;     // \\ separates rows (gather: rows without alignment points)
  bool one_equation;  // multline: its rows are one equation's lines
  int arguments;  // alignat{n}: one
};

const std::map<std::string, math_environment>& math_environments() {
  static const std::map<std::string, math_environment> envs{
      {"equation", {false, false, false, 0}},  {"equation*", {false, false, false, 0}}, {"displaymath", {false, false, false, 0}},
      {"math", {false, false, false, 0}},      {"align", {true, true, false, 0}},       {"align*", {true, true, false, 0}},
      {"flalign", {true, true, false, 0}},     {"flalign*", {true, true, false, 0}},    {"alignat", {true, true, false, 1}},
      {"alignat*", {true, true, false, 1}},    {"eqnarray", {true, true, false, 0}},    {"eqnarray*", {true, true, false, 0}},
      {"gather", {false, true, false, 0}},     {"gather*", {false, true, false, 0}},    {"multline", {false, true, true, 0}},
      {"multline*", {false, true, true, 0}}};
  return envs;
}

bool is_text_command(const std::string& name) {
  static const std::set<std::string> names{"\\text", "\\textrm", "\\textit", "\\textbf", "\\textnormal", "\\mbox", "\\hbox", "\\textsf", "\\texttt"};
  return names.count(name) > 0;
}

template <class Tokens>
std::size_t skip_space_tokens(const Tokens& t, std::size_t k) {
  while (k < t.size() && t[k].category == tex_category::space) ++k;
  return k;
}

/// The index after the braced group that opens at t[k] (t[k] is '{'), or none when it never closes.
template <class Tokens>
std::optional<std::size_t> group_end(const Tokens& t, std::size_t k) {
  int depth = 0;
  for (std::size_t j = k; j < t.size(); ++j) {
    if (t[j].category == tex_category::begin_group) ++depth;
    if (t[j].category == tex_category::end_group && --depth == 0) return j + 1;
  }
  return std::nullopt;
}

/// \begin{name} or \end{name} at t[k]: the name and the index after it.
template <class Tokens>
std::optional<std::pair<std::string, std::size_t>> environment_at(const Tokens& t, std::size_t k) {
  const std::size_t open = skip_space_tokens(t, k + 1);
  if (open >= t.size() || t[open].category != tex_category::begin_group) return std::nullopt;
  const std::optional<std::size_t> end = group_end(t, open);
  if (!end) return std::nullopt;
  std::string name;
  for (std::size_t j = open + 1; j + 1 < *end; ++j) name += t[j].text;
  name.erase(std::remove(name.begin(), name.end(), ' '), name.end());
  return std::make_pair(name, *end);
}

int line_of_offset(const std::string& text, std::size_t offset) { return line_at(text, std::min(offset, text.size())); }

/// The labels in `tokens` (\label{...} at any depth).
std::vector<std::string> labels_in(const tokens_t& tokens) {
  std::vector<std::string> out;
  for (std::size_t k = 0; k < tokens.size(); ++k) {
    if (!tokens[k].is_control("\\label")) continue;
    const std::size_t open = skip_space_tokens(tokens, k + 1);
    if (open >= tokens.size() || tokens[open].category != tex_category::begin_group) continue;
    const std::optional<std::size_t> end = group_end(tokens, open);
    if (end) out.push_back(tex_text(tokens.begin() + static_cast<std::ptrdiff_t>(open) + 1, tokens.begin() + static_cast<std::ptrdiff_t>(*end) - 1));
  }
  return out;
}

/// The offset of the first token of `tokens` the source itself holds that is math: not a space, not
/// inside a \label{...}, not \nonumber; the row's `fallback` when there is none.
std::size_t first_math_offset(const tokens_t& tokens, std::size_t fallback) {
  for (std::size_t k = 0; k < tokens.size(); ++k) {
    const tex_token& t = tokens[k];
    if (t.is_control("\\label")) {
      const std::size_t open = skip_space_tokens(tokens, k + 1);
      if (open < tokens.size() && tokens[open].category == tex_category::begin_group) {
        if (const std::optional<std::size_t> end = group_end(tokens, open)) k = *end - 1;
      }
      continue;
    }
    if (t.category == tex_category::space || t.length == 0 || t.is_control("\\nonumber") || t.is_control("\\notag")) continue;
    return t.offset;
  }
  return fallback;
}

/// Splits `body` at its top-level \\ (outside groups and environments), each with its [dimension]
/// and * consumed; `breaks` gets each separator's source span.
std::vector<tokens_t> split_rows(const tokens_t& body, std::vector<std::pair<std::size_t, std::size_t>>& breaks) {
  std::vector<tokens_t> rows(1);
  int depth = 0;
  for (std::size_t k = 0; k < body.size(); ++k) {
    const tex_token& t = body[k];
    if (t.category == tex_category::begin_group || t.is_control("\\begin")) ++depth;
    if (t.category == tex_category::end_group || t.is_control("\\end")) --depth;
    if (depth == 0 && t.is_control("\\\\")) {
      std::size_t j = k + 1;
      if (j < body.size() && body[j].is_char('*')) ++j;
      const std::size_t bracket = skip_space_tokens(body, j);
      if (bracket < body.size() && body[bracket].is_char('[')) {
        std::size_t close = bracket + 1;
        while (close < body.size() && !body[close].is_char(']')) ++close;
        if (close >= body.size()) throw tex_error("a '\\\\[' that is never closed", body[bracket].offset, "\\\\[");
        j = close + 1;
      }
      breaks.emplace_back(t.offset, body[j - 1].offset + body[j - 1].length);
      k = j - 1;
      rows.emplace_back();
      continue;
    }
    rows.back().push_back(t);
  }
  // A last row of nothing but spacing (after a final \\): amsmath drops it.
  const auto blank = [](const tokens_t& row) {
    return std::all_of(row.begin(), row.end(), [](const tex_token& t) { return t.category == tex_category::space; });
  };
  if (rows.size() > 1 && blank(rows.back())) {
    rows.pop_back();
    breaks.pop_back();
  }
  return rows;
}

/// The document read from its first token to its last, as TeX's eyes and mouth read it: the input
/// is a stream whose front is the next token; a definition is read off it, a macro's call replaced
/// there by its expansion (so an expansion costs what it holds, never what the document holds).
class scanner {
 public:
  scanner(const std::string& text, tex_macros& macros, std::vector<tex_region>& regions) : text_(text), macros_(macros), regions_(regions) {
    const tokens_t tokens = tex_tokenize(text);
    in_.assign(tokens.begin(), tokens.end());
  }

  void run() {
    bool began = false, ended = false;
    while (!in_.empty()) {
      const tex_token tok = in_.front();
      if (tok.category == tex_category::control || tok.category == tex_category::active) {
        if (defined_or_expanded(tok)) continue;
        if (tok.is_control("\\verb")) {  // \verb|...|: the tokens up to the delimiter again, whatever they are
          const std::string delimiter = in_.size() > 1 ? in_[1].text : "";
          std::size_t j = 2;
          while (j < in_.size() && in_[j].text != delimiter) ++j;
          drop(std::min(j + 1, in_.size()));
          continue;
        }
        if (tok.is_control("\\(") || tok.is_control("\\[")) {
          drop(1);
          region(tok.offset, tok.text, false);
          continue;
        }
        if (tok.is_control("\\begin")) {
          const auto env = environment_at(in_, 0);
          if (!env) throw tex_error("\\begin without its environment's name in braces", tok.offset, "\\begin");
          drop(env->second);
          if (env->first == "document") began = true;
          if (math_environments().count(env->first)) {
            region(tok.offset, env->first, false);
          } else if (env->first == "verbatim" || env->first == "comment" || env->first == "lstlisting" || env->first == "verbatim*") {
            after_verbatim(env->first, tok.offset);
          }
          continue;
        }
        if (tok.is_control("\\end")) {
          const auto env = environment_at(in_, 0);
          if (env && env->first == "document") {
            ended = true;
            break;  // TeX reads nothing after it
          }
          if (env && math_environments().count(env->first)) {
            throw tex_error("\\end{" + env->first + "} with no \\begin{" + env->first + "}", tok.offset, "\\end");
          }
        }
        if (tok.is_control("\\)") || tok.is_control("\\]")) throw tex_error(tok.text + " with no math to close", tok.offset, tok.text);
        drop(1);
        continue;
      }
      if (tok.category == tex_category::math_shift) {
        const bool display = in_.size() > 1 && in_[1].category == tex_category::math_shift;
        drop(display ? 2 : 1);
        region(tok.offset, display ? "$$" : "$", !display);
        continue;
      }
      drop(1);
    }
    if (began && !ended) {
      throw tex_error("the document ends without \\end{document}: truncated?", text_.empty() ? 0 : text_.size() - 1, "\\end{document}");
    }
  }

 private:
  void drop(std::size_t n) {
    n = std::min(n, in_.size());
    in_.erase(in_.begin(), in_.begin() + static_cast<std::ptrdiff_t>(n));
    consumed_ += n;
  }

  /// At a definition, reads it; at a macro of the document, expands it: what TeX's mouth does before
  /// its stomach sees a token. False for any other token.
  bool defined_or_expanded(const tex_token& tok) {
    if (tok.category == tex_category::control && is_definition_command(tok.text)) {
      drop(read_definition(in_, 0, macros_));
      return true;
    }
    if (const tex_macro* macro = macros_.find(tok.text)) {
      expand(*macro);
      return true;
    }
    return false;
  }

  void expand(const tex_macro& macro) {
    // A macro whose expansion starts with itself (\def\a{\a\a}) loops at one place; TeX's own limit
    // is its memory ("capacity exceeded"), ours a count, at one place and in all.
    same_place_ = consumed_ == last_place_ ? same_place_ + 1 : 0;
    last_place_ = consumed_;
    if (++expansions_ > 20000 || same_place_ > 1000) throw tex_error("the macro " + macro.name + " expands without end", in_.front().offset, macro.name);
    expand_at(in_, 0, macro);
    // A macro that multiplies its tokens on every expansion: refused before the machine's memory is.
    if (in_.size() > 4'000'000) throw tex_error("the macro " + macro.name + " expands to more than 4 million tokens", in_.front().offset, macro.name);
  }

  void after_verbatim(const std::string& name, std::size_t opener) {
    while (!in_.empty()) {
      if (in_.front().is_control("\\end")) {
        const auto env = environment_at(in_, 0);
        if (env && env->first == name) {
          drop(env->second);
          return;
        }
      }
      drop(1);
    }
    throw tex_error("\\begin{" + name + "} is never closed: truncated?", opener, "\\begin{" + name + "}");
  }

  /// The math from the front of the input to its closer, which is consumed too.
  void region(std::size_t opener, const std::string& environment, bool inline_dollar) {
    tex_region r;
    r.environment = environment;
    r.opener = opener;
    r.display = !(inline_dollar || environment == "\\(" || environment == "math");
    const auto env = math_environments().find(environment);
    if (env != math_environments().end()) {
      r.aligned = env->second.aligned;
      for (int a = 0; a < env->second.arguments; ++a) {  // alignat{2}
        const std::size_t open = skip_space_tokens(in_, 0);
        const std::optional<std::size_t> end = open < in_.size() && in_[open].category == tex_category::begin_group ? group_end(in_, open) : std::nullopt;
        if (!end) throw tex_error("\\begin{" + environment + "} without its argument", opener, environment);
        drop(*end);
      }
    }
    const std::string what = environment == "$" ? "the formula '$'" : environment == "$$" ? "the display '$$'" : environment == "\\(" ? "the formula '\\('"
                             : environment == "\\[" ? "the display '\\['" : "\\begin{" + environment + "}";
    r.begin = in_.empty() ? text_.size() : in_.front().offset;
    tokens_t body;
    int same = 0;  // nested \begin{environment}s
    for (;;) {
      if (in_.empty()) throw tex_error(what + " opened here is never closed: truncated?", opener, environment);
      const tex_token tok = in_.front();
      if (tok.category == tex_category::control || tok.category == tex_category::active) {
        if (defined_or_expanded(tok)) continue;
        if (is_text_command(tok.text)) {  // \text{... $x$ ...}: its group as it is, math shifts and all
          const std::size_t open = skip_space_tokens(in_, 1);
          if (open < in_.size() && in_[open].category == tex_category::begin_group) {
            const std::optional<std::size_t> end = group_end(in_, open);
            if (!end) throw tex_error(tok.text + "'s '{' is never closed", tok.offset, tok.text);
            body.insert(body.end(), in_.begin(), in_.begin() + static_cast<std::ptrdiff_t>(*end));
            drop(*end);
            continue;
          }
        }
        if ((tok.is_control("\\)") && environment == "\\(") || (tok.is_control("\\]") && environment == "\\[")) {
          r.end = tok.offset;
          drop(1);
          finish(r, body);
          return;
        }
        if (tok.is_control("\\begin") || tok.is_control("\\end")) {
          const auto e = environment_at(in_, 0);
          if (e && e->first == environment) {
            if (tok.is_control("\\begin")) {
              ++same;
            } else if (same-- == 0) {
              r.end = tok.offset;
              drop(e->second);
              finish(r, body);
              return;
            }
          }
          if (e && tok.is_control("\\end") && e->first == "document") {
            throw tex_error(what + " opened here is never closed (\\end{document} comes first)", opener, environment);
          }
        }
      }
      if (tok.category == tex_category::math_shift) {
        if (environment == "$") {
          r.end = tok.offset;
          drop(1);
          finish(r, body);
          return;
        }
        if (environment == "$$" && in_.size() > 1 && in_[1].category == tex_category::math_shift) {
          r.end = tok.offset;
          drop(2);
          finish(r, body);
          return;
        }
        throw tex_error("a '$' inside " + what + " (opened on line " + std::to_string(line_of_offset(text_, opener)) + ")", tok.offset, "$");
      }
      if (tok.category == tex_category::paragraph) {
        throw tex_error("a blank line inside " + what + " (opened on line " + std::to_string(line_of_offset(text_, opener)) +
                            "): a closing '$' or \\end missing?",
                        tok.offset, "\\par");
      }
      body.push_back(tok);
      drop(1);
    }
  }

  void finish(tex_region& r, const tokens_t& body) {
    const auto env = math_environments().find(r.environment);
    std::vector<tokens_t> rows{body};
    std::vector<std::pair<std::size_t, std::size_t>> breaks;
    if (env != math_environments().end() && env->second.rows) {
      rows = split_rows(body, breaks);
      if (env->second.one_equation) {  // multline: one equation over several lines
        tokens_t joined;
        for (const tokens_t& row : rows) joined.insert(joined.end(), row.begin(), row.end());
        rows = {joined};
        breaks.clear();
      }
    }
    for (std::size_t k = 0; k < rows.size(); ++k) {
      tokens_t& tokens = rows[k];
      tex_row row;
      // Its span in the source: between the line breaks around it (a row's last token may be a
      // macro's argument, whose closing brace the expansion took).
      row.begin = r.begin;
      if (k > 0) {
        row.begin = breaks[k - 1].second;
      } else {  // after what opened the display (\moneq's own tokens are the macro's, not the source's)
        const auto first = std::find_if(tokens.begin(), tokens.end(), [](const tex_token& t) { return t.length > 0; });
        if (first != tokens.end()) row.begin = first->offset;
      }
      row.end = k < breaks.size() ? breaks[k].first : r.end;
      row.labels = labels_in(tokens);
      row.line = r.display ? line_of_offset(text_, first_math_offset(tokens, r.begin)) : line_of_offset(text_, r.opener);
      row.tokens = std::move(tokens);
      r.rows.push_back(std::move(row));
    }
    regions_.push_back(std::move(r));
  }

  const std::string& text_;
  std::deque<tex_token> in_;
  tex_macros& macros_;
  std::vector<tex_region>& regions_;
  long expansions_ = 0;
  std::size_t consumed_ = 0;  // tokens read off the input: an expansion with none read since the last is at the same place
  std::size_t last_place_ = std::string::npos;
  long same_place_ = 0;
};

// --- equations

bool is_relation(const tex_node& n) { return n.kind == tex_node_kind::atom && n.atom_class == tex_class::rel; }
bool is_comma(const tex_node& n) { return n.kind == tex_node_kind::atom && n.atom_class == tex_class::punct && n.text == ","; }
bool is_blank(const tex_node& n) { return n.kind == tex_node_kind::label || (n.kind == tex_node_kind::group && n.children.empty()); }

/// The parts of a list at its top-level commas (outside parentheses and brackets).
std::vector<tex_list> at_commas(const tex_list& list) {
  std::vector<tex_list> parts(1);
  int depth = 0;
  for (const tex_node& n : list) {
    depth += delimiter_depth_change(n);
    if (depth == 0 && is_comma(n)) {
      parts.emplace_back();
      continue;
    }
    parts.back().push_back(n);
  }
  return parts;
}

/// The environment a list holds alone (spacing and labels aside), its rows equations: a system
/// (array, aligned, gathered, split, alignedat), alone or in \left\{ ... \right.; none otherwise.
const tex_node* system_in(const tex_list& list) {
  std::vector<const tex_node*> nodes;
  for (const tex_node& n : list) {
    if (!is_blank(n)) nodes.push_back(&n);
  }
  if (nodes.size() != 1) return nullptr;
  const tex_node* n = nodes.front();
  if (n->kind == tex_node_kind::delimited && n->close == ".") return system_in(n->children);
  static const std::set<std::string> systems{"array", "aligned", "gathered", "split", "alignedat"};
  if (n->kind != tex_node_kind::environment || !systems.count(n->text)) return nullptr;
  for (const auto& row : n->rows) {
    for (const tex_node& cell : row) {
      if (std::any_of(cell.children.begin(), cell.children.end(), is_relation)) return n;
    }
  }
  return nullptr;
}

/// Every token index of `list` moved by `base` (a row's tokens placed after the rows before it).
void shift_tokens(tex_list& list, std::size_t base) {
  for (tex_node& n : list) {
    n.first_token += base;
    n.last_token += base;
    shift_tokens(n.children, base);
    shift_tokens(n.sup, base);
    shift_tokens(n.sub, base);
    for (auto& r : n.rows) shift_tokens(r, base);
  }
}

struct equation_part {
  tex_list nodes;
  std::vector<std::string> texts;  // the TeX of each row it was joined from
};

std::string text_of_nodes(const tex_list& nodes, const tokens_t& tokens) {
  std::size_t first = std::string::npos, last = 0;
  for (const tex_node& n : nodes) {
    if ((n.last_token == 0 && n.first_token == 0) || n.kind == tex_node_kind::label) continue;
    first = std::min(first, n.first_token);
    last = std::max(last, n.last_token);
  }
  if (first == std::string::npos || last > tokens.size()) return "";
  return folded_space(tex_text(tokens.begin() + static_cast<std::ptrdiff_t>(first), tokens.begin() + static_cast<std::ptrdiff_t>(last)));
}

/// Appends `part` to `out`, or to the equation above when it starts with a relation ("= ..."
/// continues it: a chain over rows).
void append_part(equation_part part, std::vector<equation_part>& out) {
  const auto first = std::find_if(part.nodes.begin(), part.nodes.end(), [](const tex_node& n) { return !is_blank(n); });
  if (!out.empty() && first != part.nodes.end() && is_relation(*first)) {
    out.back().nodes.insert(out.back().nodes.end(), part.nodes.begin(), part.nodes.end());
    out.back().texts.insert(out.back().texts.end(), part.texts.begin(), part.texts.end());
  } else {
    out.push_back(std::move(part));
  }
}

/// A row's last words that quantify over an index, `\text{for all } j` (for every, each, any;
/// the index inside the text or after it) or `\forall j`, taken off the part: the equation is read
/// for a symbolic index, which is what they say. Other words stay, and the reader refuses them.
void strip_quantifier(tex_list& part) {
  const auto last = [&]() -> const tex_node* {
    for (auto it = part.rbegin(); it != part.rend(); ++it) {
      if (!is_blank(*it)) return &*it;
    }
    return nullptr;
  };
  const auto pop_last = [&] {
    while (!part.empty() && is_blank(part.back())) part.pop_back();
    if (!part.empty()) part.pop_back();
  };
  const auto one_letter = [](const tex_node& n) {
    return n.kind == tex_node_kind::atom && ((n.text.size() == 1 && std::isalpha(static_cast<unsigned char>(n.text[0]))) || n.text == "\\ell");
  };
  const auto words = [](std::string text) {  // spaces collapsed, a $x$ inside kept as x
    std::string out;
    for (const char ch : text) {
      if (ch == '$') continue;
      if (std::isspace(static_cast<unsigned char>(ch))) {
        if (!out.empty() && out.back() != ' ') out += ' ';
      } else {
        out += ch;
      }
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
  };
  static const std::set<std::string> phrases{"for all", "for every", "for each", "for any"};
  const tex_node* end = last();
  if (!end) return;
  if (end->kind == tex_node_kind::text) {  // \text{for all $j$}, \text{ for every j}
    const std::string w = words(end->text);
    const std::size_t space = w.rfind(' ');
    if (space != std::string::npos && phrases.count(w.substr(0, space)) && w.size() - space == 2 && std::isalpha(static_cast<unsigned char>(w.back()))) pop_last();
    return;
  }
  if (!one_letter(*end) || part.size() < 2) return;
  tex_list rest = part;
  while (!rest.empty() && is_blank(rest.back())) rest.pop_back();
  rest.pop_back();
  while (!rest.empty() && is_blank(rest.back())) rest.pop_back();
  if (rest.empty()) return;
  const tex_node& before = rest.back();
  const bool quantifier = (before.kind == tex_node_kind::text && phrases.count(words(before.text))) ||
                          (before.kind == tex_node_kind::atom && before.text == "\\forall");
  if (!quantifier) return;
  rest.pop_back();
  part = rest;
}

void add_parts(const tex_list& list, const tokens_t& tokens, std::vector<equation_part>& out) {
  if (const tex_node* system = system_in(list)) {
    for (const auto& row : system->rows) {
      tex_list joined;
      for (const tex_node& cell : row) joined.insert(joined.end(), cell.children.begin(), cell.children.end());
      add_parts(joined, tokens, out);
    }
    return;
  }
  for (tex_list& part : at_commas(list)) {
    // A last period, comma, colon or semicolon is the sentence's.
    while (!part.empty() && (is_blank(part.back()) || (part.back().kind == tex_node_kind::atom &&
                                                       (part.back().text == "." || part.back().text == ":" || part.back().text == ";")))) {
      part.pop_back();
    }
    strip_quantifier(part);
    while (!part.empty() && is_blank(part.back())) part.pop_back();
    if (part.empty()) continue;
    append_part({part, {text_of_nodes(part, tokens)}}, out);
  }
}

tex_equation equation_of(const equation_part& part, const tokens_t& tokens) {
  tex_equation e;
  for (const std::string& t : part.texts) e.tex += (e.tex.empty() || t.empty() ? "" : " ") + t;
  e.sides.emplace_back();
  int depth = 0;
  for (const tex_node& n : part.nodes) {
    depth += delimiter_depth_change(n);
    if (depth == 0 && is_relation(n)) {
      e.relations.push_back(n.text);
      e.sides.emplace_back();
      continue;
    }
    if (!is_blank(n)) e.sides.back().push_back(n);
  }
  for (std::size_t s = 0; s < e.sides.size(); ++s) {
    if (e.sides[s].empty()) {
      const std::size_t at = part.nodes.empty() ? 0 : part.nodes.front().offset;
      throw tex_error(s == 0 ? "an equation that starts with '" + e.relations.front() + "' and continues none"
                             : "an equation with nothing after its '" + e.relations[s - 1] + "'",
                      at, s == 0 ? e.relations.front() : e.relations[s - 1]);
    }
    e.side_tex.push_back(text_of_nodes(e.sides[s], tokens));
  }
  return e;
}

}  // namespace

tex_document::tex_document(const paper_source& source) : origin_(source.origin), text_(source.raw.empty() ? source.text : source.raw) {
  scanner(text_, macros_, regions_).run();
}

tex_document read_document(const paper_source& source, const std::string& what) {
  try {
    return tex_document(source);
  } catch (const tex_error& e) {
    throw std::invalid_argument(what + " '" + source.origin + "', " + describe(e, source.raw.empty() ? source.text : source.raw));
  }
}

tex_document::located tex_document::labelled(const std::string& label) const {
  std::optional<located> found;
  for (const tex_region& r : regions_) {
    for (std::size_t row = 0; row < r.rows.size(); ++row) {
      for (const std::string& l : r.rows[row].labels) {
        if (l != label) continue;
        if (found) throw std::invalid_argument("\\label{" + label + "} twice");
        found = located{&r, r.rows.size() > 1 ? static_cast<int>(row) : -1};
      }
    }
  }
  if (!found) throw std::invalid_argument("no \\label{" + label + "}");
  return *found;
}

const tex_region* tex_document::display_after(std::size_t offset) const {
  for (const tex_region& r : regions_) {
    if (r.display && r.opener >= offset) return &r;
  }
  return nullptr;
}

const tex_region* tex_document::inline_at(std::size_t offset) const {
  for (const tex_region& r : regions_) {
    if (!r.display && r.opener <= offset && offset < r.end) return &r;
  }
  for (const tex_region& r : regions_) {
    if (!r.display && r.opener >= offset) return &r;
  }
  return nullptr;
}

std::vector<tex_equation> equations_of(const tex_region& region, int row) {
  // Each row's parts, in order, a row that starts with a relation continuing the one above; an
  // equation's TeX and sides refer to the tokens of the rows it spans.
  std::vector<tex_equation> out;
  std::vector<equation_part> parts;
  tokens_t all;  // the rows' tokens, one after the other: the parts' token indices point into it
  for (std::size_t k = 0; k < region.rows.size(); ++k) {
    if (row >= 0 && static_cast<int>(k) != row) continue;
    const std::size_t base = all.size();
    all.insert(all.end(), region.rows[k].tokens.begin(), region.rows[k].tokens.end());
    tex_list list = parse_tex_tree(region.rows[k].tokens, {region.aligned});
    shift_tokens(list, base);
    add_parts(list, all, parts);
  }
  for (const equation_part& p : parts) out.push_back(equation_of(p, all));
  return out;
}

int line_of(const tex_region& region, int row) {
  if (region.rows.empty()) return 0;
  return region.rows[row < 0 ? 0 : static_cast<std::size_t>(row)].line;
}

std::string describe(const tex_error& e, const std::string& text) {
  std::string out = "line " + std::to_string(line_at(text, std::min(e.offset(), text.size()))) + ": " + e.what();
  if (!e.hint().empty()) out += " (" + e.hint() + ")";
  return out;
}

}  // namespace simpson::verify

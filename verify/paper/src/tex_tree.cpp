// TeX math as TeX groups it: see tex_tree.hpp. The tables of tex_commands.cpp are the whole vocabulary;
// a control sequence in none of them is refused, named. The normal form: tex_normal_form.cpp.

#include <simpson/verify/tex_tree.hpp>

#include "tex_commands.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>

namespace simpson::verify {
namespace {

using namespace tex_commands;

using tokens_t = std::vector<tex_token>;

class tree_parser {
 public:
  explicit tree_parser(const tokens_t& tokens) : t_(tokens) {}

  tex_list top(tex_list_rules rules) {
    tex_list out = list();
    for (;;) {
      if (at_end()) return out;
      const tex_token& t = peek();
      if (t.category == tex_category::alignment && rules.alignment_tabs) {
        ++k_;
        tex_list more = list();
        out.insert(out.end(), more.begin(), more.end());
        continue;
      }
      if (t.category == tex_category::end_group) fail("a '}' that closes no '{'", t);
      if (t.category == tex_category::alignment) fail("an '&' outside an alignment (an environment's cells, or align's rows)", t, "&");
      if (t.is_control("\\\\")) fail("a line break '\\\\' outside an environment (write the display as align, or use split or aligned)", t, "\\\\");
      if (t.is_control("\\right")) fail("a \\right with no \\left", t);
      if (t.is_control("\\middle")) fail("a \\middle with no \\left", t);
      if (t.is_control("\\end")) fail("an \\end with no \\begin", t);
      fail("unexpected", t);
    }
  }

 private:
  // --- tokens
  bool at_end() {
    skip_spaces();
    return k_ >= t_.size();
  }
  const tex_token& peek() {
    skip_spaces();
    return t_[k_];
  }
  void skip_spaces() {
    while (k_ < t_.size() && t_[k_].category == tex_category::space) ++k_;
  }
  std::size_t here() const { return k_ < t_.size() ? t_[k_].offset : (t_.empty() ? 0 : t_.back().offset + t_.back().length); }
  [[noreturn]] void fail(const std::string& why, const tex_token& t, const std::string& hint = {}) {
    std::string message = why + (why == "unexpected" ? " '" + t.text + "'" : "");
    if (!t.macro.empty()) message += " (from the macro " + t.macro + ")";
    throw tex_error(message, t.offset, t.text, hint);
  }
  [[noreturn]] void fail_here(const std::string& why) {
    if (k_ < t_.size()) fail(why, t_[k_]);
    throw tex_error(why + " at the end of the formula", here());
  }
  std::size_t end_of(std::size_t k) const { return t_[k].length ? t_[k].offset + t_[k].length : 0; }

  // --- lists
  /// Atoms up to a terminator ('}', '&', '\\', \end, \right, \middle, or the end), a {a \over b}
  /// split where it is; the terminator is left for the caller.
  tex_list list(bool stop_at_over = false) {
    tex_list out;
    std::optional<std::size_t> over;  // index in `out` where \over split it
    std::string over_kind;
    tex_token over_token;
    std::size_t over_index = 0;
    bool spaced = false;  // a space command read since the last node: the next one is marked
    while (!at_end()) {
      const tex_token& t = peek();
      if (t.category == tex_category::end_group || t.category == tex_category::alignment || t.is_control("\\\\") || t.is_control("\\end") ||
          t.is_control("\\right") || t.is_control("\\middle")) {
        break;
      }
      if (t.is_control("\\over") || t.is_control("\\atop") || t.is_control("\\choose")) {
        if (stop_at_over) break;  // a font switch's reach ends where \over splits its group
        if (over) fail("a second " + t.text + " in one group (TeX: 'Ambiguous; you need another { and }')", t);
        over = out.size();
        over_kind = t.text;
        over_token = t;
        over_index = k_;
        ++k_;
        continue;
      }
      if (const auto switched = font_switches().find(t.text); t.category == tex_category::control && switched != font_switches().end()) {
        const std::size_t start = t.offset, index = k_;
        ++k_;
        tex_node font{tex_node_kind::font, switched->second};
        font.offset = start;
        font.children = list(true);
        font.first_token = index;
        font.last_token = k_;
        out.push_back(std::move(font));
        continue;
      }
      const std::size_t before = out.size();
      if (atom_into(out)) {
        spaced = true;
      } else if (out.size() > before) {
        out.back().spaced = spaced;
        spaced = false;
      }
    }
    if (!over) return out;
    tex_node fraction{tex_node_kind::fraction, over_kind == "\\over" ? "\\frac" : over_kind == "\\atop" ? "\\atop" : "\\binom"};
    fraction.offset = over_token.offset;
    tex_node numerator{tex_node_kind::group}, denominator{tex_node_kind::group};
    numerator.children.assign(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(*over));
    denominator.children.assign(out.begin() + static_cast<std::ptrdiff_t>(*over), out.end());
    fraction.children = {std::move(numerator), std::move(denominator)};
    fraction.first_token = out.empty() ? over_index : std::min(over_index, out.front().first_token);
    fraction.last_token = std::max(k_, over_index + 1);
    return {std::move(fraction)};
  }

  /// Nested groups, arguments and environments beyond this depth are refused: TeX itself has a
  /// limit (its save stack), and the reader's recursion must not meet the machine's.
  static constexpr int deepest = 400;
  struct nested {
    int& depth;
    nested(int& d, const tex_token& at, tree_parser& p) : depth(d) {
      if (++depth > deepest) p.fail("groups nested more than " + std::to_string(deepest) + " deep", at);
    }
    ~nested() { --depth; }
  };

  tex_node group() {  // at '{'
    const std::size_t open = k_;
    const nested guard(depth_, t_[open], *this);
    ++k_;
    tex_node g{tex_node_kind::group};
    g.offset = t_[open].offset;
    g.children = list();
    if (at_end() || peek().category != tex_category::end_group) {
      if (at_end()) fail("a '{' that is never closed", t_[open]);
      fail("unexpected '" + peek().text + "' inside a group", peek());
    }
    g.end = end_of(k_);
    ++k_;
    return g;
  }

  // --- atoms
  /// One atom, or the scripts of the last atom of `out`, or nothing (a command consumed by rule).
  /// True when what it consumed was a space command (\, \: \; \> \  \quad \qquad ~ and the
  /// named widths), which the next node records: the reader ends an operator's argument there.
  bool atom_into(tex_list& out) {
    const std::size_t count = out.size();
    const std::size_t from = (skip_spaces(), k_);
    static const std::set<std::string> spaces{"\\,", "\\:", "\\;", "\\>", "\\ ", "\\quad", "\\qquad", "\\enspace", "\\thinspace", "\\medspace", "\\thickspace"};
    if (!at_end() && (peek().category == tex_category::active || (peek().category == tex_category::control && spaces.count(peek().text) > 0))) {
      atom(out);
      return true;
    }
    const bool script = peek().category == tex_category::superscript || peek().category == tex_category::subscript || peek().is_char('\'');
    atom(out);
    if (!script && out.size() > count) {
      out.back().first_token = from;
      out.back().last_token = k_;
    }
    return false;
  }

  void atom(tex_list& out) {
    const tex_token& t = peek();
    if (t.category == tex_category::paragraph) fail("a blank line inside a formula: a '$' or an \\end missing?", t);
    if (t.category == tex_category::superscript || t.category == tex_category::subscript || t.is_char('\'')) {
      scripts_into(out);
      return;
    }
    if (t.category == tex_category::begin_group) {
      out.push_back(group());
      return;
    }
    if (t.category == tex_category::math_shift) fail("a '$' inside a formula", t);
    if (t.category == tex_category::parameter) fail("a '#' outside a macro's definition", t);
    if (t.category == tex_category::active) {  // ~, a space that does not break
      ++k_;
      return;
    }
    if (t.category != tex_category::control) {
      out.push_back(character());
      return;
    }
    if (std::optional<tex_node> node = command()) out.push_back(std::move(*node));
  }

  tex_node character() {
    const tex_token& t = t_[k_];
    tex_node a{tex_node_kind::atom, t.text};
    a.offset = t.offset;
    a.end = end_of(k_);
    if (t.category == tex_category::letter) {
      a.atom_class = tex_class::ord;
    } else if (const auto c = character_class(t.text)) {
      a.atom_class = *c;
    } else {
      fail("the character '" + t.text + "' in a formula", t, t.text.size() > 1 ? "write it as a TeX command (\\omega for ω, - for −)" : "");
    }
    ++k_;
    return a;
  }

  /// x^a, x_a, x' (primes), attached to the last atom of `out` (an empty base when there is none).
  void scripts_into(tex_list& out) {
    const nested guard(depth_, t_[k_], *this);
    tex_node base;
    const std::size_t from = k_;
    if (!out.empty() && out.back().kind == tex_node_kind::scripts) {
      base = std::move(out.back());
      out.pop_back();
    } else {
      base.kind = tex_node_kind::scripts;
      tex_node inner{tex_node_kind::group};
      inner.offset = here();
      if (!out.empty()) {
        inner = std::move(out.back());
        out.pop_back();
      }
      base.offset = inner.offset;
      base.spaced = inner.spaced;  // \, \dot\phi^2: the space is before the whole
      base.first_token = inner.children.empty() && inner.kind == tex_node_kind::group && inner.last_token == 0 ? from : inner.first_token;
      base.children = {std::move(inner)};
    }
    const tex_token& t = peek();
    if (t.is_char('\'')) {
      if (!base.sup.empty()) fail("a prime after a superscript (TeX: 'Double superscript')", t);
      tex_node primes{tex_node_kind::group};
      primes.offset = t.offset;
      while (!at_end() && peek().is_char('\'')) {
        tex_node prime{tex_node_kind::atom, "\\prime"};
        prime.offset = peek().offset;
        primes.children.push_back(prime);
        ++k_;
      }
      if (!at_end() && peek().category == tex_category::superscript) {  // V'^2: one superscript, \prime 2
        ++k_;
        tex_node more = argument("a superscript");
        if (more.kind == tex_node_kind::group) {
          primes.children.insert(primes.children.end(), more.children.begin(), more.children.end());
        } else {
          primes.children.push_back(std::move(more));
        }
      }
      base.sup = {std::move(primes)};
    } else {
      const bool superscript = t.category == tex_category::superscript;
      std::vector<tex_node>& slot = superscript ? base.sup : base.sub;
      if (!slot.empty()) fail(superscript ? "a second superscript on one atom (TeX: 'Double superscript')" : "a second subscript on one atom (TeX: 'Double subscript')", t);
      ++k_;
      slot = {argument(superscript ? "a superscript" : "a subscript")};
    }
    base.last_token = k_;
    out.push_back(std::move(base));
  }

  /// A command's argument, or a script's: a braced group, or one token (a symbol, or a fraction
  /// or font command with its own arguments, as KaTeX allows: x^\frac12).
  tex_node argument(const std::string& of) {
    if (at_end()) fail_here("missing the argument of " + of);
    const tex_token& t = peek();
    if (t.category == tex_category::begin_group) return group();
    if (t.category == tex_category::control) {
      const std::string& name = t.text;
      if (symbol_commands().count(name) || fraction_commands().count(name) || font_commands().count(name) || text_commands().count(name) ||
          name == "\\operatorname") {
        std::optional<tex_node> node = command();
        if (node) return *node;
      }
      fail("the command " + name + " as the argument of " + of + " (KaTeX: 'Got function with no arguments')", t, "put it in braces: {" + name + " ...}");
    }
    if (t.category == tex_category::letter || t.category == tex_category::other) return character();
    fail("missing the argument of " + of, t);
  }

  std::optional<tex_node> command() {
    const tex_token t = t_[k_];
    const nested guard(depth_, t, *this);
    const std::string& name = t.text;
    ++k_;
    const auto node_of = [&](tex_node_kind kind, std::string text) {
      tex_node n{kind, std::move(text)};
      n.offset = t.offset;
      return n;
    };
    if (ignored_commands().count(name)) return std::nullopt;
    if (name == "\\hspace" || name == "\\vspace" || name == "\\hphantom" || name == "\\vphantom") {
      if (name == "\\hphantom" || name == "\\vphantom") fail(name + ": an invisible box (its content would be read as part of the formula)", t);
      if (!at_end() && peek().is_char('*')) ++k_;
      if (at_end() || peek().category != tex_category::begin_group) fail(name + " without its length in braces", t);
      skip_group();
      return std::nullopt;
    }
    if (name == "\\kern" || name == "\\mkern" || name == "\\hskip" || name == "\\vskip" || name == "\\mskip") {
      dimension(t, name == "\\hskip" || name == "\\vskip" || name == "\\mskip");
      return std::nullopt;
    }
    if (name == "\\label") {
      tex_node label = node_of(tex_node_kind::label, raw_group(t));
      return label;
    }
    if (name == "\\tag") {
      if (!at_end() && peek().is_char('*')) ++k_;
      raw_group(t);
      return std::nullopt;
    }
    if (const auto s = symbol_commands().find(name); s != symbol_commands().end()) {
      tex_node a = node_of(tex_node_kind::atom, name);
      a.atom_class = s->second;
      a.end = t.length ? t.offset + t.length : 0;
      return a;
    }
    if (operator_commands().count(name)) return node_of(tex_node_kind::op, name);
    if (fraction_commands().count(name)) {
      tex_node f = node_of(tex_node_kind::fraction, name.find("binom") != std::string::npos ? "\\binom" : "\\frac");
      f.children.push_back(as_group(argument(name + "'s numerator")));
      f.children.push_back(as_group(argument(name + "'s denominator")));
      return f;
    }
    if (name == "\\sqrt") {
      tex_node r = node_of(tex_node_kind::root, name);
      std::optional<tex_node> index;
      if (!at_end() && peek().is_char('[')) index = bracketed_list();
      r.children.push_back(as_group(argument("\\sqrt")));
      if (index) r.children.push_back(std::move(*index));
      return r;
    }
    if (const auto f = font_commands().find(name); f != font_commands().end()) {
      tex_node font = node_of(tex_node_kind::font, f->second);
      font.children = {argument(name)};
      return font;
    }
    if (name == "\\operatorname") {
      if (!at_end() && peek().is_char('*')) ++k_;
      tex_node font = node_of(tex_node_kind::font, "operatorname");
      tex_node body = argument(name);
      font.children = body.kind == tex_node_kind::group ? body.children : tex_list{body};
      return font;
    }
    if (text_commands().count(name)) return node_of(tex_node_kind::text, raw_group(t));
    if (accent_commands().count(name)) {
      tex_node a = node_of(tex_node_kind::accent, name);
      a.children = {argument(name)};
      return a;
    }
    if (sizing_commands().count(name)) {
      if (at_end() || !is_delimiter(peek())) fail(name + " without a delimiter after it", t);
      tex_node d = node_of(tex_node_kind::atom, peek().text);
      d.atom_class = delimiter_class(d.text);
      if (name.back() == 'l') d.atom_class = tex_class::open;
      if (name.back() == 'r') d.atom_class = tex_class::close;
      d.sized = true;
      ++k_;
      return d;
    }
    if (name == "\\left") return delimited(t);
    if (name == "\\begin") return environment(t);
    if (name == "\\not") fail("\\not (a negated relation)", t);
    fail("the command " + name + " is not one the reader knows (nor a macro of the document)", t);
  }

  static tex_node as_group(tex_node n) {
    if (n.kind == tex_node_kind::group) return n;
    tex_node g{tex_node_kind::group};
    g.offset = n.offset;
    g.children = {std::move(n)};
    return g;
  }

  /// A braced group's tokens as text (a label, a \text), consumed.
  std::string raw_group(const tex_token& command) {
    if (at_end() || peek().category != tex_category::begin_group) fail(command.text + " without its argument in braces", command);
    const std::size_t from = k_;
    skip_group();
    return tex_text(t_.begin() + static_cast<std::ptrdiff_t>(from) + 1, t_.begin() + static_cast<std::ptrdiff_t>(k_) - 1);
  }

  void skip_group() {  // at '{'
    const std::size_t open = k_;
    int depth = 0;
    for (; k_ < t_.size(); ++k_) {
      if (t_[k_].category == tex_category::begin_group) ++depth;
      if (t_[k_].category == tex_category::end_group && --depth == 0) {
        ++k_;
        return;
      }
    }
    fail("a '{' that is never closed", t_[open]);
  }

  /// [ ... ] as a group (a root's index).
  tex_node bracketed_list() {
    const std::size_t open = k_;
    ++k_;
    tex_node g{tex_node_kind::group};
    g.offset = t_[open].offset;
    while (!at_end() && !peek().is_char(']')) {
      if (peek().category == tex_category::end_group) fail("a '[' that is never closed", t_[open]);
      atom_into(g.children);
    }
    if (at_end()) fail("a '[' that is never closed", t_[open]);
    ++k_;
    return g;
  }

  /// A TeX dimension after \kern (a glue after \hskip: plus and minus parts too): signs, a number,
  /// a unit.
  void dimension(const tex_token& command, bool glue) {
    const auto one = [&](bool fil) {
      while (!at_end() && (peek().is_char('-') || peek().is_char('+'))) ++k_;
      bool digits = false;
      while (k_ < t_.size() && (t_[k_].category == tex_category::other) && (std::isdigit(static_cast<unsigned char>(t_[k_].text[0])) || t_[k_].text == "." || t_[k_].text == ",")) {
        digits = true;
        ++k_;
      }
      if (!digits) fail("a dimension after " + command.text + " (a number and a unit: 3mu, -7pt)", command);
      std::string unit;
      skip_spaces();
      while (k_ < t_.size() && t_[k_].category == tex_category::letter && unit.size() < 6) unit += t_[k_++].text;
      static const std::set<std::string> units{"pt", "pc", "in", "bp", "cm", "mm", "dd", "cc", "sp", "em", "ex", "mu", "truept", "truecm"};
      static const std::set<std::string> fils{"fil", "fill", "filll"};
      if (!units.count(unit) && !(fil && fils.count(unit))) fail("a dimension after " + command.text + " with the unit '" + unit + "'", command);
    };
    one(false);
    if (!glue) return;
    for (const char* part : {"plus", "minus"}) {
      const std::size_t saved = k_;
      std::string word;
      skip_spaces();
      while (k_ < t_.size() && t_[k_].category == tex_category::letter && word.size() < 5) word += t_[k_++].text;
      if (word == part) {
        one(true);
      } else {
        k_ = saved;
      }
    }
  }

  std::string delimiter_after(const tex_token& command) {
    if (at_end() || !is_delimiter(peek())) fail(command.text + " without a delimiter after it", command);
    return t_[k_++].text;
  }

  tex_node delimited(const tex_token& left) {
    tex_node d{tex_node_kind::delimited, delimiter_after(left)};
    d.offset = left.offset;
    for (;;) {
      tex_list part = list();
      d.children.insert(d.children.end(), part.begin(), part.end());
      if (at_end()) fail("a \\left that is never closed by \\right", left);
      const tex_token& t = peek();
      if (t.is_control("\\right")) {
        ++k_;
        d.close = delimiter_after(t);
        return d;
      }
      if (t.is_control("\\middle")) {
        ++k_;
        tex_node m{tex_node_kind::atom, delimiter_after(t)};
        m.atom_class = tex_class::rel;
        m.offset = t.offset;
        d.children.push_back(std::move(m));
        continue;
      }
      fail("unexpected '" + t.text + "' between \\left and \\right", t);
    }
  }

  std::string environment_name(const tex_token& command) {
    if (at_end() || peek().category != tex_category::begin_group) fail(command.text + " without its environment's name in braces", command);
    return raw_group(command);
  }

  tex_node environment(const tex_token& begin) {
    std::string name = environment_name(begin);
    name.erase(std::remove(name.begin(), name.end(), ' '), name.end());
    if (!known_environment(name)) {
      fail("the environment '" + name + "' inside a formula is not one the reader knows", begin,
           "matrix, pmatrix, bmatrix, Bmatrix, vmatrix, Vmatrix, array, cases, aligned, gathered, alignedat, split");
    }
    tex_node env{tex_node_kind::environment, name};
    env.offset = begin.offset;
    if (name == "array") {
      if (!at_end() && peek().is_char('[')) bracketed_list();  // [t], [b]: a position
      raw_group(begin);                                        // the column specification
    }
    if (name == "alignedat") raw_group(begin);  // the number of columns
    env.rows.emplace_back();
    for (;;) {
      tex_node cell{tex_node_kind::group};
      cell.offset = here();
      cell.children = list();
      env.rows.back().push_back(std::move(cell));
      if (at_end()) fail("\\begin{" + name + "} is never closed by \\end{" + name + "}", begin);
      const tex_token& t = peek();
      if (t.category == tex_category::alignment) {
        ++k_;
        continue;
      }
      if (t.is_control("\\\\")) {
        ++k_;
        if (k_ < t_.size() && t_[k_].is_char('*')) ++k_;
        if (!at_end() && peek().is_char('[')) {  // \\[2pt]: the space below the row
          const tex_token bracket = peek();
          ++k_;
          while (!at_end() && !peek().is_char(']')) ++k_;
          if (at_end()) fail("a '\\\\[' that is never closed", bracket);
          ++k_;
        }
        env.rows.emplace_back();
        continue;
      }
      if (t.is_control("\\end")) {
        const tex_token end = t;
        ++k_;
        std::string closing = environment_name(end);
        closing.erase(std::remove(closing.begin(), closing.end(), ' '), closing.end());
        if (closing != name) fail("\\begin{" + name + "} closed by \\end{" + closing + "}", end);
        // A last row of nothing but a line break's: amsmath drops it.
        if (env.rows.size() > 1 && env.rows.back().size() == 1 && env.rows.back().front().children.empty()) env.rows.pop_back();
        return env;
      }
      fail("unexpected '" + t.text + "' in \\begin{" + name + "}", t);
    }
  }

  const tokens_t& t_;
  std::size_t k_ = 0;
  int depth_ = 0;
};

}  // namespace

tex_list parse_tex_tree(const tokens_t& tokens, tex_list_rules rules) { return tree_parser(tokens).top(rules); }


}  // namespace simpson::verify

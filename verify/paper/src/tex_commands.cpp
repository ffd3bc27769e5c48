// The TeX reader's vocabulary: see tex_commands.hpp.

#include "tex_commands.hpp"

#include <algorithm>
#include <cctype>

namespace simpson::verify::tex_commands {

/// Symbol commands and their class.
const std::map<std::string, tex_class>& symbol_commands() {
  static const std::map<std::string, tex_class> table = [] {
    std::map<std::string, tex_class> t;
    for (const char* g : {"alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta", "theta", "vartheta", "iota", "kappa",
                          "lambda", "mu", "nu", "xi", "pi", "varpi", "rho", "varrho", "sigma", "varsigma", "tau", "upsilon", "phi", "varphi",
                          "chi", "psi", "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Upsilon", "Phi", "Psi", "Omega",
                          "ell", "hbar", "infty", "partial", "nabla", "prime", "imath", "jmath", "emptyset", "aleph", "forall", "exists",
                          "neg", "top", "bot", "ldots", "cdots", "dots", "vdots", "ddots", "%", "$", "#", "&", "_", "|", "Vert", "vert"}) {
      t[std::string("\\") + g] = tex_class::ord;
    }
    for (const char* b : {"cdot", "times", "pm", "mp", "ast", "star", "circ", "bullet", "div", "wedge", "vee", "cap", "cup", "setminus",
                          "otimes", "oplus"}) {
      t[std::string("\\") + b] = tex_class::bin;
    }
    for (const char* r : {"leq", "le", "geq", "ge", "neq", "ne", "equiv", "simeq", "approx", "sim", "cong", "propto", "to", "mapsto",
                          "longmapsto", "rightarrow", "leftarrow", "Rightarrow", "Leftarrow", "Leftrightarrow", "iff", "implies", "impliedby",
                          "longrightarrow", "Longrightarrow", "in", "notin", "subset", "subseteq", "ll", "gg", "coloneqq", "doteq", "perp",
                          "parallel", "mid"}) {
      t[std::string("\\") + r] = tex_class::rel;
    }
    for (const char* o : {"{", "lbrace", "langle", "lfloor", "lceil", "lvert", "lVert"}) t[std::string("\\") + o] = tex_class::open;
    for (const char* c : {"}", "rbrace", "rangle", "rfloor", "rceil", "rvert", "rVert"}) t[std::string("\\") + c] = tex_class::close;
    t["\\colon"] = tex_class::punct;
    return t;
  }();
  return table;
}

const std::set<std::string>& operator_commands() {
  static const std::set<std::string> names{"\\sum",  "\\prod", "\\int",  "\\oint", "\\iint", "\\iiint", "\\lim",  "\\det",  "\\sin",  "\\cos",
                                           "\\tan",  "\\cot",  "\\sec",  "\\csc",  "\\exp",  "\\log",   "\\ln",   "\\max",  "\\min",  "\\sup",
                                           "\\inf",  "\\arg",  "\\dim",  "\\ker",  "\\deg",  "\\gcd",   "\\Pr",   "\\sinh", "\\cosh", "\\tanh",
                                           "\\arcsin", "\\arccos", "\\arctan", "\\liminf", "\\limsup", "\\coprod", "\\bigcup", "\\bigcap"};
  return names;
}

/// Commands that take no argument and leave nothing in the tree: spacing, style, numbering.
const std::set<std::string>& ignored_commands() {
  static const std::set<std::string> names{"\\,",          "\\:",          "\\;",           "\\!",          "\\>",        "\\ ",
                                           "\\quad",       "\\qquad",      "\\enspace",     "\\thinspace",  "\\medspace", "\\thickspace",
                                           "\\negthinspace", "\\negmedspace", "\\negthickspace", "\\nobreak", "\\allowbreak", "\\relax",
                                           "\\displaystyle", "\\textstyle", "\\scriptstyle", "\\scriptscriptstyle", "\\nonumber", "\\notag",
                                           "\\limits",     "\\nolimits",   "\\/",           "\\hfill",      "\\hline",    "\\strut",
                                           "\\mathstrut",  "\\smallskip",  "\\medskip",     "\\bigskip",    "\\noindent", "\\nonumber"};
  return names;
}

const std::map<std::string, std::string>& font_commands() {  // a font command and KaTeX's name for its font
  static const std::map<std::string, std::string> fonts{
      {"\\mathrm", "mathrm"},     {"\\mathit", "mathit"},       {"\\mathbf", "mathbf"},     {"\\mathsf", "mathsf"},     {"\\mathtt", "mathtt"},
      {"\\mathcal", "mathcal"},   {"\\mathbb", "mathbb"},       {"\\mathfrak", "mathfrak"}, {"\\mathscr", "mathscr"},   {"\\boldsymbol", "boldsymbol"},
      {"\\bm", "boldsymbol"},     {"\\mathnormal", "mathnormal"}, {"\\pmb", "boldsymbol"}};
  return fonts;
}

const std::map<std::string, std::string>& font_switches() {  // {\rm d}: the rest of the group
  static const std::map<std::string, std::string> fonts{{"\\rm", "mathrm"}, {"\\it", "mathit"}, {"\\bf", "mathbf"},
                                                        {"\\sf", "mathsf"}, {"\\tt", "mathtt"}, {"\\cal", "mathcal"}};
  return fonts;
}

const std::set<std::string>& text_commands() {
  static const std::set<std::string> names{"\\text", "\\textrm", "\\textit", "\\textbf", "\\textnormal", "\\mbox", "\\hbox", "\\textsf", "\\texttt"};
  return names;
}

const std::set<std::string>& accent_commands() {
  static const std::set<std::string> names{"\\dot", "\\ddot", "\\dddot", "\\hat", "\\widehat", "\\bar", "\\overline", "\\tilde", "\\widetilde",
                                           "\\vec", "\\acute", "\\grave", "\\breve", "\\check", "\\mathring", "\\underline"};
  return names;
}

const std::set<std::string>& fraction_commands() {
  static const std::set<std::string> names{"\\frac", "\\dfrac", "\\tfrac", "\\cfrac", "\\binom", "\\dbinom", "\\tbinom"};
  return names;
}

const std::set<std::string>& sizing_commands() {
  static const std::set<std::string> names{"\\big",  "\\Big",  "\\bigg",  "\\Bigg",  "\\bigl", "\\Bigl", "\\biggl", "\\Biggl",
                                           "\\bigr", "\\Bigr", "\\biggr", "\\Biggr", "\\bigm", "\\Bigm", "\\biggm", "\\Biggm"};
  return names;
}

/// The class of a character in math.
std::optional<tex_class> character_class(const std::string& c) {
  static const std::map<std::string, tex_class> table{{"+", tex_class::bin},  {"-", tex_class::bin},   {"*", tex_class::bin},
                                                      {"=", tex_class::rel},  {"<", tex_class::rel},   {">", tex_class::rel},
                                                      {":", tex_class::rel},  {"(", tex_class::open},  {"[", tex_class::open},
                                                      {")", tex_class::close}, {"]", tex_class::close}, {"!", tex_class::close},
                                                      {"?", tex_class::close}, {",", tex_class::punct}, {";", tex_class::punct},
                                                      {".", tex_class::ord},  {"/", tex_class::ord},   {"|", tex_class::ord}};
  const auto it = table.find(c);
  if (it != table.end()) return it->second;
  if (c.size() == 1 && std::isdigit(static_cast<unsigned char>(c[0]))) return tex_class::ord;
  return std::nullopt;
}

bool is_delimiter(const tex_token& t) {
  if (t.category == tex_category::control) {
    static const std::set<std::string> names{"\\{",     "\\}",     "\\lbrace", "\\rbrace", "\\langle", "\\rangle", "\\vert",  "\\Vert", "\\|",
                                             "\\lvert", "\\rvert", "\\lVert",  "\\rVert",  "\\lfloor", "\\rfloor", "\\lceil", "\\rceil", "\\backslash"};
    return names.count(t.text) > 0;
  }
  static const std::set<std::string> chars{"(", ")", "[", "]", "|", "/", ".", "<", ">"};
  return chars.count(t.text) > 0;
}

tex_class delimiter_class(const std::string& d) {
  static const std::set<std::string> open{"(", "[", "\\{", "\\lbrace", "\\langle", "\\lfloor", "\\lceil", "\\lvert", "\\lVert"};
  static const std::set<std::string> close{")", "]", "\\}", "\\rbrace", "\\rangle", "\\rfloor", "\\rceil", "\\rvert", "\\rVert"};
  if (open.count(d)) return tex_class::open;
  if (close.count(d)) return tex_class::close;
  return tex_class::ord;
}

/// An environment's delimiters, as KaTeX wraps it: pmatrix in ( ), cases in \{ and nothing.
std::pair<std::string, std::string> environment_delimiters(const std::string& name) {
  if (name == "pmatrix") return {"(", ")"};
  if (name == "bmatrix") return {"[", "]"};
  if (name == "Bmatrix") return {"\\{", "\\}"};
  if (name == "vmatrix") return {"|", "|"};
  if (name == "Vmatrix") return {"\\Vert", "\\Vert"};
  if (name == "cases" || name == "dcases") return {"\\{", "."};
  return {"", ""};
}

bool known_environment(const std::string& name) {
  static const std::set<std::string> names{"matrix", "pmatrix", "bmatrix", "Bmatrix",  "vmatrix",  "Vmatrix",    "smallmatrix",
                                           "array",  "cases",   "dcases",  "aligned",  "gathered", "alignedat",  "split"};
  return names.count(name) > 0;
}

}  // namespace simpson::verify::tex_commands

#pragma once
// TeX math as TeX groups it, before any meaning is given to it: what each command takes as its
// arguments (\frac12 is 1 over 2, h^24 is h² then 4), which atom a script attaches to, where a
// {a \over b} splits its group, \left...\right, environments and their cells. Spacing, style and
// size commands are consumed here, each by its rule (\vspace*{-7pt}, \\[2pt], \kern 3mu, \Big(),
// and \label and \tag kept aside; nothing else is dropped. A token no rule consumes is refused
// (tex_error). The tree is what KaTeX's parser makes of the same TeX, node for node, after their
// common normal form (normal_form): the test suite compares the two on every display of the paper
// and of the note corpus.

#include <simpson/verify/tex_tokens.hpp>

#include <string>
#include <vector>

namespace simpson::verify {

/// TeX's classes of math atoms (The TeXbook, chapter 17).
enum class tex_class { ord, op, bin, rel, open, close, punct };

enum class tex_node_kind {
  atom,         // one symbol: a letter, a digit, a character or a symbol command; `text`, `atom_class`
  group,        // { ... }: `children`
  fraction,     // \frac{a}{b}, \dfrac, \tfrac, \cfrac, {a \over b}: children {numerator, denominator}, groups
  root,         // \sqrt[n]{x}: children {radicand} or {radicand, index}, groups
  scripts,      // children {base}; `sup` and `sub` hold one node each when present
  delimited,    // \left( ... \right): `text` the left delimiter, `close` the right one, `children` the body
  environment,  // \begin{pmatrix} ...: `text` the name, `rows` its cells (each a group)
  font,         // \mathrm{d}, {\rm d}, \mathcal O, \operatorname{tr}: `text` the font, children its body
  op,           // \sum, \int, \det, \sin: `text`
  accent,       // \dot q: `text` the accent, children {base}
  text,         // \text{if }: `text` its text
  label,        // \label{x}: `text` the label, consumed by rule and kept for the display it names
};

struct tex_node {
  tex_node_kind kind = tex_node_kind::atom;
  std::string text{};
  tex_class atom_class = tex_class::ord;
  std::vector<tex_node> children{};
  std::vector<tex_node> sup{}, sub{};             // scripts: empty, or one node
  std::string close{};                            // delimited: the right delimiter
  std::vector<std::vector<tex_node>> rows{};      // environment: rows of cells
  std::size_t offset = 0;                          // where it starts in the source
  std::size_t end = 0;                             // where it ends in the source (0 when a macro made it)
  bool sized = false;                              // atom: a delimiter of \big, \Big, ... (its size dropped)
  bool spaced = false;                             // a space command (\, \; \quad ~ ...) before it: what it follows ends there
  std::size_t first_token = 0, last_token = 0;     // [first, last) of the tokens parsed, in the list given
};

using tex_list = std::vector<tex_node>;

/// How a node moves the depth of ( [ delimiters at its level: +1 for an opening one, -1 for a
/// closing one, 0 otherwise. A scripted delimiter counts as its nucleus: the ')' of (a + b)^2 closes.
inline int delimiter_depth_change(const tex_node& n) {
  const tex_node* nucleus = &n;
  while (nucleus->kind == tex_node_kind::scripts && !nucleus->children.empty()) nucleus = &nucleus->children.front();
  if (nucleus->kind != tex_node_kind::atom) return 0;
  return nucleus->atom_class == tex_class::open ? 1 : nucleus->atom_class == tex_class::close ? -1 : 0;
}

/// What a list may hold at its top level: an alignment row's & (align, eqnarray: alignment points,
/// consumed), or nothing of the kind (an equation's body: & and \\ refused there).
struct tex_list_rules {
  bool alignment_tabs = false;
};

/// Parses `tokens` (a math list, the document's macros already expanded) into the tree. Throws
/// tex_error naming the construct no rule consumes, a group never closed, a double superscript, a
/// second \over in a group, an environment not closed or closed by another name.
tex_list parse_tex_tree(const std::vector<tex_token>& tokens, tex_list_rules rules = {});

/// The normal form the oracle compares: a list is "[a b c]" (one item: the item alone), an atom its
/// text, and each other node "(kind ...)": (frac n d), (sqrt x [n]), (sup b s), (sub b s),
/// (supsub b sup sub), (left l r body), (array [row] ...), (font name body), (accent a b),
/// (text t), (operatorname body). Spacing, style, labels and empty groups inside lists leave no
/// trace; pmatrix is (left ( ) (array ...)), as KaTeX represents it.
std::string normal_form(const tex_list& list);
std::string normal_form(const tex_node& node);

/// The labels of `list` (its \label nodes, at any depth), in order.
std::vector<std::string> labels_of(const tex_list& list);

}  // namespace simpson::verify

// The normal form of a tree, as KaTeX's parse would give it (the TeX oracle compares the two), and the
// labels a tree carries: see tex_tree.hpp.

#include <simpson/verify/tex_tree.hpp>

#include "tex_commands.hpp"

#include <string>
#include <vector>

namespace simpson::verify {
namespace {

using namespace tex_commands;

std::string joined(const std::vector<std::string>& items) {
  if (items.size() == 1) return items.front();
  std::string out = "[";
  for (std::size_t k = 0; k < items.size(); ++k) out += (k ? " " : "") + items[k];
  return out + "]";
}

void items_into(const tex_list& list, std::vector<std::string>& items);

std::string form_of_list(const tex_list& list) {
  std::vector<std::string> items;
  items_into(list, items);
  return joined(items);
}

std::string form_of_group_or_node(const tex_node& n) {  // a script, an argument: its list, unwrapped
  if (n.kind == tex_node_kind::group) return form_of_list(n.children);
  std::vector<std::string> items;
  items_into({n}, items);
  return joined(items);
}

std::string canonical_atom(const std::string& text) {
  static const std::map<std::string, std::string> same{{"\\le", "\\leq"},       {"\\ge", "\\geq"},     {"\\ne", "\\neq"},
                                                       {"\\dots", "\\ldots"},   {"\\lbrace", "\\{"},   {"\\rbrace", "\\}"},
                                                       {"\\to", "\\rightarrow"}, {"\\vert", "|"},      {"\\|", "\\Vert"},
                                                       {"\\implies", "\\Longrightarrow"}};
  const auto it = same.find(text);
  return it == same.end() ? text : it->second;
}

void items_into(const tex_list& list, std::vector<std::string>& items) {
  for (const tex_node& n : list) {
    switch (n.kind) {
      case tex_node_kind::atom: items.push_back(canonical_atom(n.text)); break;
      case tex_node_kind::group:
        if (!n.children.empty()) items.push_back(form_of_list(n.children));
        break;
      case tex_node_kind::fraction: {
        const std::string kind = n.text == "\\binom" ? "binom" : n.text == "\\atop" ? "atop" : "frac";
        items.push_back("(" + kind + " " + form_of_group_or_node(n.children[0]) + " " + form_of_group_or_node(n.children[1]) + ")");
        break;
      }
      case tex_node_kind::root:
        items.push_back("(sqrt " + form_of_group_or_node(n.children[0]) + (n.children.size() > 1 ? " " + form_of_group_or_node(n.children[1]) : "") + ")");
        break;
      case tex_node_kind::scripts: {
        std::string base = n.children.front().kind == tex_node_kind::group ? form_of_list(n.children.front().children) : form_of_group_or_node(n.children.front());
        if (!n.sup.empty() && !n.sub.empty()) {
          items.push_back("(supsub " + base + " " + form_of_group_or_node(n.sup.front()) + " " + form_of_group_or_node(n.sub.front()) + ")");
        } else if (!n.sup.empty()) {
          items.push_back("(sup " + base + " " + form_of_group_or_node(n.sup.front()) + ")");
        } else {
          items.push_back("(sub " + base + " " + form_of_group_or_node(n.sub.front()) + ")");
        }
        break;
      }
      case tex_node_kind::delimited:
        items.push_back("(left " + canonical_atom(n.text) + " " + canonical_atom(n.close) + " " + form_of_list(n.children) + ")");
        break;
      case tex_node_kind::environment: {
        std::string rows;
        for (const auto& row : n.rows) {
          std::string cells;
          for (const tex_node& cell : row) cells += " " + form_of_list(cell.children);
          rows += " (row" + cells + ")";
        }
        const std::string array = "(array" + rows + ")";
        const auto [l, r] = environment_delimiters(n.text);
        items.push_back(l.empty() ? array : "(left " + canonical_atom(l) + " " + canonical_atom(r) + " " + array + ")");
        break;
      }
      case tex_node_kind::font:
        items.push_back(n.text == "operatorname" ? "(operatorname " + form_of_list(n.children) + ")"
                                                 : "(font " + n.text + " " + form_of_list(n.children) + ")");
        break;
      case tex_node_kind::op: items.push_back(n.text); break;
      case tex_node_kind::accent: items.push_back("(accent " + n.text + " " + form_of_group_or_node(n.children.front()) + ")"); break;
      case tex_node_kind::text: {
        std::string t;
        for (const char c : n.text) {
          if (c != ' ') t += c;
        }
        items.push_back("(text " + t + ")");
        break;
      }
      case tex_node_kind::label: break;
    }
  }
}

void labels_into(const tex_list& list, std::vector<std::string>& out) {
  for (const tex_node& n : list) {
    if (n.kind == tex_node_kind::label) out.push_back(n.text);
    labels_into(n.children, out);
    labels_into(n.sup, out);
    labels_into(n.sub, out);
    for (const auto& row : n.rows) labels_into(row, out);
  }
}

}  // namespace

std::string normal_form(const tex_list& list) { return form_of_list(list); }
std::string normal_form(const tex_node& node) { return form_of_list({node}); }

std::vector<std::string> labels_of(const tex_list& list) {
  std::vector<std::string> out;
  labels_into(list, out);
  return out;
}

}  // namespace simpson::verify

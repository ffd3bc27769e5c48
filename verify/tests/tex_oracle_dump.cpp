// Our side of the TeX oracle (tex_oracle_test.js): for every row of math in the documents given, the
// TeX as the source prints it, the definitions of the document's macros it uses (as the source
// prints them, for KaTeX to expand itself), and our tree's normal form (tex_tree.hpp), or the
// construct our reader refused. One JSON object per line.
//
//   tex_oracle_dump FILE.tex...

#include <simpson/verify/json.hpp>
#include <simpson/verify/tex_document.hpp>
#include <simpson/verify/tex_tree.hpp>

#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

namespace {

using namespace simpson::verify;

/// The source span of the tokens the source itself holds (a macro's own tokens have none).
std::pair<std::size_t, std::size_t> source_span(const std::vector<tex_token>& tokens) {
  std::size_t from = std::string::npos, to = 0;
  for (const tex_token& t : tokens) {
    if (t.length == 0 || t.category == tex_category::space) continue;
    from = std::min(from, t.offset);
    to = std::max(to, t.offset + t.length);
  }
  return {from, to};
}

/// The control sequences in `text`.
std::set<std::string> commands_in(const std::string& text) {
  std::set<std::string> out;
  for (const tex_token& t : tex_tokenize(text)) {
    if (t.category == tex_category::control) out.insert(t.text);
  }
  return out;
}

/// The definitions, as printed, of the document's macros `text` uses, and of those they use.
json definitions_for(const std::string& text, const tex_document& document) {
  json out = json::array();
  std::set<std::string> seen;
  std::vector<std::string> todo;
  for (const std::string& name : commands_in(text)) todo.push_back(name);
  while (!todo.empty()) {
    const std::string name = todo.back();
    todo.pop_back();
    const tex_macro* m = document.macros().find(name);
    if (!m || !seen.insert(name).second) continue;
    out.push_back({{"name", m->name},
                   {"command", m->command},
                   {"arguments", m->arguments},
                   {"default", m->default_first ? json(tex_text(*m->default_first)) : json(nullptr)},
                   {"parameters", tex_text(m->parameter_text)},
                   {"body", tex_text(m->body)},
                   {"source", document.text().substr(m->offset, m->end - m->offset)}});
    for (const std::string& inner : commands_in(tex_text(m->body))) todo.push_back(inner);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: tex_oracle_dump FILE.tex...\n";
    return 2;
  }
  for (int a = 1; a < argc; ++a) {
    std::ifstream in(argv[a], std::ios::binary);
    if (!in) {
      std::cerr << "tex_oracle_dump: cannot read " << argv[a] << "\n";
      return 2;
    }
    std::ostringstream text;
    text << in.rdbuf();
    const paper_source source{argv[a], without_comments(text.str()), "", text.str()};
    try {
      const tex_document document = read_document(source);
      for (const tex_region& region : document.regions()) {
        for (const tex_row& row : region.rows) {
          if (source_span(row.tokens).first == std::string::npos) continue;  // nothing of the source's own
          const std::size_t from = row.begin, to = std::max(row.begin, row.end);
          const std::string tex = document.text().substr(from, to - from);
          json line = {{"file", argv[a]},
                       {"line", line_at(document.text(), from)},
                       {"environment", region.environment},
                       {"aligned", region.aligned},
                       {"tex", tex},
                       {"definitions", definitions_for(tex, document)}};
          try {
            line["ours"] = normal_form(parse_tex_tree(row.tokens, {region.aligned}));
          } catch (const tex_error& e) {
            line["refused"] = describe(e, document.text());
          }
          std::cout << line.dump() << "\n";
        }
      }
    } catch (const std::invalid_argument& e) {
      std::cout << json{{"file", argv[a]}, {"document_refused", e.what()}}.dump() << "\n";
    }
  }
  return 0;
}

// The TeX the reader accepts and refuses, generated from the corpus (docs/tex-support.md, by
// scripts/generated-docs): every row of math of each document read as its claims file's
// declarations decide, each construct counted in the rows that read whole; then the refusal corpus,
// each fragment with the reader's own message. Exits 1 when a fragment of the refusal corpus reads:
// a refusal that became a reading must be looked at (ctest tex.refusals).
//
//   tex_support_dump --refusals FILE [DOCUMENT.tex CLAIMS.toml]...
//
// The refusal corpus: one TeX fragment a line, read as one side; `#` starts a comment line; a line
// `declare: symbols a b; functions V L(q,\dot{q})` sets the declarations of the fragments after it (TeX names).

#include <simpson/verify/claim_declarations.hpp>
#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/tex_document.hpp>
#include <simpson/verify/tex_math.hpp>

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

namespace {

using namespace simpson::verify;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument("cannot read " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string cell(const std::string& text) {
  std::string out;
  for (const char c : text) out += c == '|' ? std::string("\\|") : c == '\n' ? std::string(" ") : std::string(1, c);
  return out;
}

/// A code span that holds `text` whatever backticks it has.
std::string code(const std::string& text) {
  const std::string escaped = cell(text);
  return escaped.find('`') == std::string::npos ? "`" + escaped + "`" : "`` " + escaped + " ``";
}

/// The constructs of a row as the reader meets them (the document's macros expanded): its control
/// sequences, its environments (\begin{pmatrix} is "pmatrix"), a prime.
std::set<std::string> constructs_of(const std::vector<tex_token>& tokens) {
  std::set<std::string> out;
  for (std::size_t k = 0; k < tokens.size(); ++k) {
    const tex_token& t = tokens[k];
    if (t.category == tex_category::control && t.text != "\\end" && t.text != "\\begin" && t.text != "\\label") out.insert(t.text);
    if (t.category == tex_category::control && t.text == "\\begin") {
      std::string name;
      for (std::size_t j = k + 2; j < tokens.size() && tokens[j].category != tex_category::end_group; ++j) name += tokens[j].text;
      out.insert("{" + name + "}");
    }
    if (t.text == "'") out.insert("'");
    if (t.category == tex_category::alignment) out.insert("&");
  }
  return out;
}

struct use {
  std::size_t rows = 0;
  std::set<std::string> documents;
};

struct refusal {
  std::string tex, message;
};

/// What a document's rows make of each construct: rows read whole (every side of every equation).
struct document_reading {
  std::size_t rows = 0, read = 0;
  std::map<std::string, std::size_t> refusals;  // the reader's message (its first clause), how many rows
};

document_reading read_rows(const std::string& tex_path, const std::string& claims_path, std::map<std::string, use>& accepted,
                           std::map<std::string, std::set<std::string>>& definers) {
  const std::string name = std::filesystem::path(tex_path).stem().string();
  const claims_file_contents contents = read_claims_contents(slurp(claims_path), claims_path, [](const std::string&, const std::string&) { return true; });
  const claim_declarations declared = read_declarations(contents, claims_path);
  const std::string text = slurp(tex_path);
  const tex_document document = read_document(paper_source{tex_path, without_comments(text), "", text});
  for (const auto& [macro, m] : document.macros().all()) definers[m.command].insert(name);
  document_reading out;
  for (const tex_region& region : document.regions()) {
    for (std::size_t r = 0; r < region.rows.size(); ++r) {
      ++out.rows;
      try {
        for (const tex_equation& e : equations_of(region, static_cast<int>(r))) {
          for (const tex_list& side : e.sides) (void)read_math(side, declared.reading, paper_symbols());
        }
      } catch (const tex_error& e) {
        std::string why = e.what();
        if (std::getenv("TEX_SUPPORT_ROWS")) std::cerr << name << " line " << region.rows[r].line << ": " << why << "\n";
        why = why.substr(0, why.find(": "));
        ++out.refusals[why];
        continue;
      }
      ++out.read;
      for (const std::string& c : constructs_of(region.rows[r].tokens)) {
        ++accepted[c].rows;
        accepted[c].documents.insert(name);
      }
    }
  }
  return out;
}

std::vector<std::string> names_of(const std::string& list) {
  std::vector<std::string> out;
  std::istringstream in(list);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

/// The refusal corpus read: every fragment with its message; `read` gets those that read.
std::vector<refusal> refusals_of(const std::string& path, std::vector<std::string>& read) {
  std::vector<refusal> out;
  tex_declarations declared;
  std::istringstream lines(slurp(path));
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (line.rfind("declare:", 0) == 0) {
      declared = {};
      std::string rest = line.substr(8);
      for (std::size_t at = 0; at < rest.size();) {
        const std::size_t end = std::min(rest.find(';', at), rest.size());
        std::vector<std::string> words = names_of(rest.substr(at, end - at));
        if (!words.empty()) {
          const bool functions = words.front() == "functions";
          for (std::size_t k = 1; k < words.size(); ++k) {
            if (!functions) {
              declared.symbols.insert(reader_name(words[k]));
              continue;
            }
            const function_declaration f = read_function_declaration(words[k]);  // V, or L(q,\dot{q}) with its variables
            declared.functions.insert(f.name);
            if (f.variables) declared.variables[f.name] = *f.variables;
          }
        }
        at = end + 1;
      }
      continue;
    }
    try {
      const GiNaC::ex e = read_tex(line, declared, paper_symbols());
      read.push_back(line + "  read as  " + canonical_text(e));
    } catch (const tex_error& e) {
      out.push_back({line, e.what() + (e.hint().empty() ? std::string() : " (" + e.hint() + ")")});
    }
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::string refusal_file;
  std::vector<std::pair<std::string, std::string>> documents;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--refusals" && a + 1 < argc) {
      refusal_file = argv[++a];
    } else if (a + 1 < argc) {
      documents.emplace_back(arg, argv[++a]);
    } else {
      std::cerr << "usage: tex_support_dump --refusals FILE [DOCUMENT.tex CLAIMS.toml]...\n";
      return 2;
    }
  }
  if (refusal_file.empty()) {
    std::cerr << "usage: tex_support_dump --refusals FILE [DOCUMENT.tex CLAIMS.toml]...\n";
    return 2;
  }
  try {
    std::map<std::string, use> accepted;
    std::map<std::string, std::set<std::string>> definers;
    std::string per_document = "| document | rows of math | read whole | not read (the reader's reason, rows) |\n|---|---|---|---|\n";
    for (const auto& [tex, claims] : documents) {
      const document_reading d = read_rows(tex, claims, accepted, definers);
      std::string why;
      for (const auto& [message, rows] : d.refusals) why += (why.empty() ? "" : "; ") + fmt::format("{} ({})", cell(message), rows);
      per_document += fmt::format("| {} | {} | {} | {} |\n", std::filesystem::path(tex).stem().string(), d.rows, d.read, why.empty() ? "none" : why);
    }
    std::string md = "### The corpus, row by row\n\nEach row of math (an inline formula, a display, a row of an align), read as its claims file's "
                     "declarations decide: every side of every equation into GiNaC.\n\n" + per_document;
    md += "\n### Constructs read\n\nEvery construct of a row read whole, with the rows and documents it is read in (the documents' "
          "own macros expanded first, so their pieces are counted).\n\n| construct | rows | documents |\n|---|---|---|\n";
    for (const auto& [construct, u] : accepted) {
      std::string in;
      for (const std::string& d : u.documents) in += (in.empty() ? "" : ", ") + d;
      md += fmt::format("| {} | {} | {} |\n", code(construct), u.rows, in);
    }
    md += "\nMacros defined with: ";
    bool first = true;
    for (const auto& [command, in] : definers) {
      std::string where;
      for (const std::string& d : in) where += (where.empty() ? "" : ", ") + d;
      md += fmt::format("{}{} ({})", first ? "" : "; ", code(command), where);
      first = false;
    }
    std::vector<std::string> read;
    const std::vector<refusal> refused = refusals_of(refusal_file, read);
    md += fmt::format(".\n\n### Refused\n\nThe refusal corpus ({}): each fragment read as one side, and the reader's message, as a "
                      "user sees it after the document's line.\n\n| TeX | the reader says |\n|---|---|\n",
                      std::filesystem::path(refusal_file).filename().string());
    for (const refusal& r : refused) md += fmt::format("| {} | {} |\n", code(r.tex), cell(r.message));
    std::cout << md;
    for (const std::string& r : read) std::cerr << "tex_support_dump: the refusal corpus's fragment reads: " << r << "\n";
    return read.empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "tex_support_dump: " << e.what() << "\n";
    return 2;
  }
}

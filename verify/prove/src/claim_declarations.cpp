// A claims file's declarations, read: see claim_declarations.hpp.

#include <simpson/verify/claim_declarations.hpp>

#include <simpson/verify/tex_tree.hpp>

#include <algorithm>

namespace simpson::verify {

std::string reader_name(const std::string& tex) {
  try {
    const tex_list list = parse_tex_tree(tex_tokenize(tex));
    if (list.size() != 1) throw std::invalid_argument("'" + tex + "' is not one name");
    return symbol_name(list.front());
  } catch (const tex_error& e) {
    throw std::invalid_argument("'" + tex + "' is not one name: " + e.what());
  }
}

function_declaration read_function_declaration(const std::string& tex) {
  tex_list list;
  try {
    list = parse_tex_tree(tex_tokenize(tex));
  } catch (const tex_error& e) {
    throw std::invalid_argument("'" + tex + "' is not one name: " + e.what());
  }
  const auto is = [](const tex_node& n, const char* text) { return n.kind == tex_node_kind::atom && n.text == text; };
  if (list.size() < 3 || !is(list[1], "(") || !is(list.back(), ")")) return {reader_name(tex), std::nullopt};
  function_declaration out;
  try {
    out.name = symbol_name(list.front());
    std::vector<std::string> variables;
    tex_list part;
    const auto take = [&] {
      if (part.size() != 1) throw std::invalid_argument("'" + tex + "': a function's variables are names, one between each two commas");
      const std::string name = symbol_name(part.front());
      if (std::find(variables.begin(), variables.end(), name) != variables.end()) {
        throw std::invalid_argument("'" + tex + "': the variable " + name + " is written twice");
      }
      variables.push_back(name);
      part.clear();
    };
    for (std::size_t k = 2; k + 1 < list.size(); ++k) {
      if (is(list[k], ",")) {
        take();
      } else {
        part.push_back(list[k]);
      }
    }
    take();
    out.variables = std::move(variables);
  } catch (const tex_error& e) {
    throw std::invalid_argument("'" + tex + "' is not a function of names: " + e.what());
  }
  return out;
}

claim_declarations read_declarations(const claims_file_contents& contents, const std::string& file) {
  claim_declarations out;
  out.complete = contents.document.has_value();
  if (!contents.symbols) return out;
  out.written = *contents.symbols;
  const auto names = [&](const std::vector<std::string>& list, const std::string& field, std::set<std::string>& into) {
    for (const std::string& tex : list) {
      std::string name;
      try {
        name = reader_name(tex);
      } catch (const std::invalid_argument& e) {
        throw claims_file_error(file, out.written.line, field, e.what());
      }
      const auto reserved = reserved_names().find(name);
      if (reserved != reserved_names().end()) {
        throw claims_file_error(file, out.written.line, field, "'" + tex + "' cannot be declared: " + reserved->second);
      }
      into.insert(name);
    }
  };
  names(out.written.positive, "symbols.positive", out.positive);
  names(out.written.real, "symbols.real", out.real);
  for (const std::string& tex : out.written.functions) {  // V, or L(q, \dot q) with its variables
    function_declaration f;
    try {
      f = read_function_declaration(tex);
    } catch (const std::invalid_argument& e) {
      throw claims_file_error(file, out.written.line, "symbols.functions", e.what());
    }
    const auto reserved = reserved_names().find(f.name);
    if (reserved != reserved_names().end()) {
      throw claims_file_error(file, out.written.line, "symbols.functions", "'" + tex + "' cannot be declared: " + reserved->second);
    }
    // L(q, \dot q) and L(\theta, \dot\theta, \dot\phi): one name, two declarations; the later would win.
    if (!out.reading.functions.insert(f.name).second) {
      throw claims_file_error(file, out.written.line, "symbols.functions",
                              "'" + tex + "' declares " + f.name + " a second time; a note with two systems names their functions apart (L, L_s)");
    }
    if (f.variables) out.reading.variables[f.name] = *f.variables;
  }
  names(out.written.solutions, "symbols.solutions", out.solutions);
  out.reading.functions.insert(out.solutions.begin(), out.solutions.end());
  out.reading.symbols = out.positive;
  out.reading.symbols.insert(out.real.begin(), out.real.end());
  return out;
}

}  // namespace simpson::verify

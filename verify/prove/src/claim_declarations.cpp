// A claims file's declarations, read: see claim_declarations.hpp.

#include <simpson/verify/claim_declarations.hpp>

#include <simpson/verify/tex_tree.hpp>

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
  names(out.written.functions, "symbols.functions", out.reading.functions);
  names(out.written.solutions, "symbols.solutions", out.solutions);
  out.reading.functions.insert(out.solutions.begin(), out.solutions.end());
  out.reading.symbols = out.positive;
  out.reading.symbols.insert(out.real.begin(), out.real.end());
  return out;
}

}  // namespace simpson::verify

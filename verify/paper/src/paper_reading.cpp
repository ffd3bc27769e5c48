#include <simpson/verify/paper_reading.hpp>

#include <simpson/verify/formula_reference.hpp>

#include <stdexcept>

namespace simpson::verify {

const printed_formula& paper_reading::at(const std::string& name) const {
  const auto it = formulas.find(name);
  if (it == formulas.end()) throw std::logic_error("paper_reading: no formula '" + name + "'");
  return it->second;
}

namespace {

printed_formula read_formula(const tex_document& document, const tex_declarations& declared, const formula_location& where) {
  std::string reference = where.where == formula_location::kind::labelled ? where.key
                          : where.where == formula_location::kind::anchored_display ? "after:" + where.key
                                                                                     : "inline:" + where.key;
  if (where.equation > 0) reference += "#" + std::to_string(where.equation + 1);
  const referenced_formula read = read_reference(document, declared, reference);
  const std::string at = "paper '" + document.origin() + "', " + read.locator;
  if (read.sides.size() < 2) throw std::invalid_argument(at + ": no '=', '<' or '\\equiv' in the formula");
  printed_formula f{where.name, {read.place, read.line, read.tex}, read.tex, read.sides.front(), {}, {}};
  for (const int wanted : where.sides) {
    const int index = wanted < 0 ? static_cast<int>(read.sides.size()) + wanted : wanted;
    if (index < 0 || index >= static_cast<int>(read.sides.size())) {
      throw std::invalid_argument(at + ": the formula has " + std::to_string(read.sides.size()) + " sides, not " +
                                  std::to_string(std::abs(wanted) + (wanted < 0 ? 0 : 1)));
    }
    GiNaC::ex side = read_side(read, static_cast<std::size_t>(index), declared);
    if (GiNaC::is_a<GiNaC::matrix>(side.evalm())) side = side.evalm();
    f.sides.push_back(side);
  }
  f.value = f.sides.back();
  return f;
}

}  // namespace

paper_reading read_note(const paper_source& source) {
  paper_reading reading;
  reading.origin = source.origin;
  reading.sha256 = source.sha256;
  reading.source = source;
  reading.document = std::make_shared<const tex_document>(read_document(source));
  return reading;
}

paper_reading read_paper(const paper_source& paper, const tex_declarations& declared, const std::vector<formula_location>& formulas) {
  paper_reading reading;
  reading.origin = paper.origin;
  reading.sha256 = paper.sha256;
  reading.source = paper;
  reading.document = std::make_shared<const tex_document>(read_document(paper, "paper"));
  for (const formula_location& where : formulas) reading.formulas.emplace(where.name, read_formula(*reading.document, declared, where));
  return reading;
}

}  // namespace simpson::verify

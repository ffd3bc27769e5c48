#include <simpson/verify/paper_reading.hpp>

#include <stdexcept>

namespace simpson::verify {

const std::vector<formula_location>& ledger_formulas() {
  static const std::vector<formula_location> formulas{
      {"qm-oscillateur-harmonique", "qm-oscillateur-harmonique", ""},
      {"Lagrangien-reduit", "Lagrangien-reduit", ""},
      {"truncation-error", "", "one obtains without difficulty the relation"},
      {"discriminant-factorized", "", "can be factorized"},
      {"moment-ordre-3", "moment-ordre-3", ""},
      {"Phi3", "Phi3", ""},
      {"hamiltonien-discret", "hamiltonien-discret", ""},
  };
  return formulas;
}

const printed_formula& paper_reading::at(const std::string& name) const {
  const auto it = formulas.find(name);
  if (it == formulas.end()) throw std::logic_error("paper_reading: no formula '" + name + "'");
  return it->second;
}

paper_reading read_paper(const paper_source& paper) {
  paper_reading reading;
  reading.origin = paper.origin;
  for (const formula_location& where : ledger_formulas()) {
    const tex_display display = where.label.empty() ? find_anchored(paper, where.anchor) : find_labelled(paper, where.label);
    const std::vector<std::string> sides = relation_sides(display.tex);
    if (sides.size() < 2) {
      throw std::invalid_argument("paper '" + paper.origin + "', " + display.locator + " (line " + std::to_string(display.line) +
                                  "): no '=' or '\\equiv' in the formula");
    }
    printed_formula f{where.name, display, sides.front(), sides.back(), {}};
    try {
      f.value = parse_tex_math(f.rhs, reading.symbols);
      if (GiNaC::is_a<GiNaC::matrix>(f.value.evalm())) f.value = f.value.evalm();
    } catch (const tex_parse_error& e) {
      throw std::invalid_argument("paper '" + paper.origin + "', " + display.locator + " (line " + std::to_string(display.line) +
                                  "): cannot parse the formula: " + e.what());
    }
    reading.formulas.emplace(where.name, std::move(f));
  }
  return reading;
}

}  // namespace simpson::verify

#include <simpson/verify/paper_reading.hpp>

#include <stdexcept>

namespace simpson::verify {

const std::vector<formula_location>& printed_formula_locations() {
  using k = formula_location::kind;
  static const std::vector<formula_location> formulas{
      // What the bespoke checks read (check_registry.hpp's add_printed); a proof shape reads its
      // record's references instead (formula_reference.hpp).
      // §5
      {"equation-milieu-intervalle", k::labelled, "equation-milieu-intervalle", 0, {0}},
      {"stabilite", k::labelled, "stabilite", 0, {0, 1, 2}},
      // §6
      {"Phi3", k::labelled, "Phi3"},
  };
  return formulas;
}

const printed_formula& paper_reading::at(const std::string& name) const {
  const auto it = formulas.find(name);
  if (it == formulas.end()) throw std::logic_error("paper_reading: no formula '" + name + "'");
  return it->second;
}

namespace {

tex_display locate(const paper_source& paper, const formula_location& where) {
  switch (where.where) {
    case formula_location::kind::labelled: return find_labelled(paper, where.key);
    case formula_location::kind::anchored_display: return find_anchored(paper, where.key);
    case formula_location::kind::inline_formula: return find_inline(paper, where.key);
  }
  throw std::logic_error("locate: unknown kind");
}

printed_formula read_formula(const paper_source& paper, const formula_location& where) {
  const tex_display display = locate(paper, where);
  const std::string at = "paper '" + paper.origin + "', " + display.locator + " (line " + std::to_string(display.line) + ")";
  const std::vector<std::string> equations = display_equations(display.tex);
  if (where.equation >= static_cast<int>(equations.size())) {
    throw std::invalid_argument(at + ": equation " + std::to_string(where.equation + 1) + " of the display is not there (it has " +
                                std::to_string(equations.size()) + ")");
  }
  const std::string& tex = equations[static_cast<std::size_t>(where.equation)];
  const std::vector<std::string> sides = relation_sides(tex);
  if (sides.size() < 2) throw std::invalid_argument(at + ": no '=', '<' or '\\equiv' in the formula");
  printed_formula f{where.name, display, tex, sides.front(), {}, {}};
  for (const int wanted : where.sides) {
    const int index = wanted < 0 ? static_cast<int>(sides.size()) + wanted : wanted;
    if (index < 0 || index >= static_cast<int>(sides.size())) {
      throw std::invalid_argument(at + ": the formula has " + std::to_string(sides.size()) + " sides, not " +
                                  std::to_string(std::abs(wanted) + (wanted < 0 ? 0 : 1)));
    }
    try {
      GiNaC::ex side = parse_tex_math(sides[static_cast<std::size_t>(index)], paper_symbols());
      if (GiNaC::is_a<GiNaC::matrix>(side.evalm())) side = side.evalm();
      f.sides.push_back(side);
    } catch (const tex_parse_error& e) {
      throw std::invalid_argument(at + ": cannot parse the formula: " + e.what());
    }
  }
  f.value = f.sides.back();
  return f;
}

}  // namespace

paper_reading read_paper(const paper_source& paper) {
  paper_reading reading;
  reading.origin = paper.origin;
  reading.sha256 = paper.sha256;
  reading.source = paper;
  for (const formula_location& where : printed_formula_locations()) reading.formulas.emplace(where.name, read_formula(paper, where));
  return reading;
}

}  // namespace simpson::verify

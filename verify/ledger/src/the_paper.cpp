// The paper the book checks: see the_paper.hpp.

#include <simpson/verify/the_paper.hpp>

#include "embedded_paper.hpp"

#include <algorithm>
#include <stdexcept>

namespace simpson::verify {

paper_source embedded_paper() { return source_from_text("embedded", embedded_paper_text()); }

paper_source load_paper(const std::string& path) {
  paper_source paper = load_source(path, "paper");
  // Which of three it is: another document (no title), the paper cut short (its title, no end), or
  // the paper without the display its claims start from.
  const bool titled = paper.text.find("symplectic scheme") != std::string::npos;
  const bool ended = paper.text.find("\\end{document}") != std::string::npos;
  if (!titled) throw std::invalid_argument("paper '" + path + "': not the symplectic Simpson paper (its title, 'symplectic scheme', is not in it)");
  if (paper.text.find("\\label{Phi3}") == std::string::npos) {
    const std::size_t lines = static_cast<std::size_t>(std::count(paper.raw.begin(), paper.raw.end(), '\n')) + (paper.raw.back() == '\n' ? 0 : 1);
    throw std::invalid_argument("paper '" + path + "': " +
                                (ended ? std::string("the paper without the display \\label{Phi3} (Section 6's map), which its claims read")
                                       : "truncated: it ends at line " + std::to_string(lines) + " without \\end{document}, before \\label{Phi3} (Section 6's map)"));
  }
  return paper;
}

const std::vector<formula_location>& printed_formula_locations() {
  using k = formula_location::kind;
  static const std::vector<formula_location> formulas{
      // What the bespoke checks read (check_registry.hpp's add_printed); a proof shape reads its
      // record's references instead (formula_reference.hpp).
      // §2
      {"matrice-symplectique-ordre-2", k::labelled, "matrice-symplectique-ordre-2"},
      // §5
      {"equation-milieu-intervalle", k::labelled, "equation-milieu-intervalle", 0, {0}},
      {"stabilite", k::labelled, "stabilite", 0, {0, 1, 2}},
      // §6
      {"Phi3", k::labelled, "Phi3"},
  };
  return formulas;
}

}  // namespace simpson::verify

#pragma once
// The formulas of our core that the paper prints, each instantiated with GiNaC expressions: the
// book's list of what core_bindings.hpp binds to the print. The only file of the binding that
// includes core headers.

#include <ginac/ginac.h>

#include <functional>
#include <string>
#include <vector>

namespace simpson::verify::detail {

/// What a core formula is given: the parameters m, ω, h, its variables in its own order, and the
/// potential V and its derivative V' (the document's declared function, uninterpreted).
struct core_arguments {
  GiNaC::ex m, omega, h;
  std::vector<GiNaC::ex> variables;
  std::function<GiNaC::ex(const GiNaC::ex&)> potential, force_gradient;
};

/// One formula of the core: its name (the template it instantiates), the paper's label it
/// implements, its variables (the core's names, in order) and its value.
struct core_formula {
  std::string name;
  std::string implements;  // the paper's label, as the core's comment gives it
  std::vector<std::string> variables;
  std::string summary;
  std::function<GiNaC::ex(const core_arguments&)> value;
};

/// Every formula of the core that the paper prints (core/include/simpson/*.hpp), once.
const std::vector<core_formula>& core_formulas();
const core_formula* find_core_formula(const std::string& name);

}  // namespace simpson::verify::detail

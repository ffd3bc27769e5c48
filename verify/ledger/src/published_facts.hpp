#pragma once
// The facts the experiments publish that a record may observe (`observes = "table1.printed-orders"`):
// each one's name, what it states, and how the run publishes it: the experiment's own function
// (table1_facts.hpp, fpu_section.hpp, nonlinear_section.hpp), given what it reads from the run's
// document. The book holds no code that decides them.

#include <simpson/verify/claim.hpp>
#include <simpson/verify/published_fact.hpp>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace simpson::verify::detail {

struct fact_publisher {
  std::string states;  // what the fact states, in words (--list-facts)
  std::function<published_fact(const run_context&)> publish;
  /// The formulas of our core (core_formulas.hpp) that are the experiment's scheme: a record of a
  /// document other than the paper observes the fact only with a `core` binding of one of them, the
  /// proof that the document's printed scheme is the one the experiment runs. None: no document may
  /// observe it (no formula of the core is that scheme yet).
  std::vector<std::string> schemes;
};

/// Every fact a record may observe, by "section.name".
const std::map<std::string, fact_publisher>& published_facts();

}  // namespace simpson::verify::detail

// What the Coq goals of the ledger's checks share: a sign goal on a region, and the reason a record
// gives for having none.

#include "check_registry.hpp"
#include "printed_check_support.hpp"

namespace simpson::verify::detail {

using GiNaC::ex;

proof_goal sign_goal(const std::string& name, const ex& lhs, int sign, std::vector<ex> positive, GiNaC::exmap inside) {
  proof_goal g;
  g.name = name;
  g.lhs = lhs;
  g.rhs = 0;
  g.sign = sign;
  g.factored = GiNaC::factor(GiNaC::normal(lhs));
  g.inside = std::move(inside);
  bool in_region = true;
  for (const ex& e : positive) {
    const ex at = GiNaC::normal(e.subs(g.inside));
    in_region = in_region && GiNaC::is_a<GiNaC::numeric>(at) && GiNaC::ex_to<GiNaC::numeric>(at).is_positive();
  }
  const ex at = GiNaC::normal(lhs.subs(g.inside) * sign);
  g.holds = in_region && GiNaC::is_a<GiNaC::numeric>(at) && GiNaC::ex_to<GiNaC::numeric>(at).is_positive();
  g.positive = std::move(positive);
  return g;
}

std::string without_coq_statement(const claim& c, const std::string& otherwise) { return c.coq_none.empty() ? otherwise : c.coq_none; }

}  // namespace simpson::verify::detail

#pragma once
// The bespoke checks a claims file can name (bespoke/): each registered once under its name, with
// all its facets, in the one file that holds it: the check itself (our kernel), the GiNaC check of
// the printed formulas it reads, if any, and the Coq goals of our kernel's proof, if any. A record
// names the check (`check = "derivation-phi3"`), nothing else: the ledger finds every facet through
// that one name.

#include <simpson/verify/the_paper.hpp>
#include "derivation_support.hpp"

#include <simpson/prove/decide.hpp>
#include <simpson/verify/claim.hpp>
#include <simpson/verify/claim_declarations.hpp>
#include <simpson/verify/claims_file.hpp>

#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace simpson::verify::detail {

/// A bespoke check: our kernel's evidence (its exact proof, and the numeric rechecks by enclosure).
using check_function = std::function<decider_evidence(const run_context&)>;
using coq_goals_function = std::function<std::vector<proof_goal>()>;

struct registered_check {
  check_function check;
  /// The printed formulas the claim reads (names of printed_formula_locations()) and GiNaC's check of
  /// them; empty when the claim reads none.
  std::vector<std::string> formulas;
  printed_check printed;
  /// The Coq goals of our kernel's proof; empty when the check writes its own certificate, reads a
  /// printed formula (the goals are then GiNaC's), or its record says why there is none (coq_none).
  coq_goals_function coq_goals;
};

class check_registry {
 public:
  /// Registers `check` under `name`; throws std::logic_error for a name registered twice.
  void add(const std::string& name, check_function check) {
    if (!checks_.emplace(name, registered_check{std::move(check), {}, {}, {}}).second) {
      throw std::logic_error("check '" + name + "' registered twice");
    }
  }
  /// The GiNaC check of the printed formulas for the check `name`, registered before.
  void add_printed(const std::string& name, std::vector<std::string> formulas, printed_check printed) {
    registered_check& c = existing(name, "printed check");
    if (c.printed) throw std::logic_error("check '" + name + "' has two printed checks");
    c.formulas = std::move(formulas);
    c.printed = std::move(printed);
  }
  /// The Coq goals of our kernel's proof for the check `name`, registered before.
  void add_coq_goals(const std::string& name, coq_goals_function goals) {
    registered_check& c = existing(name, "Coq goals");
    if (c.coq_goals) throw std::logic_error("check '" + name + "' has two sets of Coq goals");
    c.coq_goals = std::move(goals);
  }
  /// The check registered under `name`, or null.
  const registered_check* find(const std::string& name) const {
    const auto it = checks_.find(name);
    return it == checks_.end() ? nullptr : &it->second;
  }
  const std::map<std::string, registered_check>& all() const { return checks_; }

 private:
  registered_check& existing(const std::string& name, const std::string& facet) {
    const auto it = checks_.find(name);
    if (it == checks_.end()) throw std::logic_error(facet + " for '" + name + "', which is not a registered check");
    return it->second;
  }

  std::map<std::string, registered_check> checks_;
};

/// Every check of the ledger, registered once with its facets.
const check_registry& registered_checks();

/// A bespoke check's evidence with its facets: the GiNaC check of the printed formulas it reads
/// (GiNaC's answer on the print, the two kernels on the derived statement), and the Coq goals,
/// GiNaC's or our kernel's proof's; `coq_none`, the record's reason when there are none.
decider_evidence with_facets(decider_evidence e, const registered_check& check, const std::string& claim_id, const std::string& statement,
                             const std::string& coq_none, const run_context& ctx);

/// What decides a record a bespoke check decides (`check`: the book's, or a test's stand-in): the
/// check, our core bound to the print, then its facets.
judge bespoke_judge(const claim_record& r, const registered_check& check,
                    const std::shared_ptr<const claim_declarations>& declared);


}  // namespace simpson::verify::detail

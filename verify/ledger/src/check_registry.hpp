#pragma once
// The checks a claims file can name: each a C++ function registered under its name. A record of
// claims/paper.toml says which check decides it (`check = "phi3-det"`); the ledger joins the two.

#include <simpson/verify/claim.hpp>

#include <functional>
#include <map>
#include <stdexcept>
#include <string>

namespace simpson::verify::detail {

using check_function = std::function<claim_result(const run_context&)>;

class check_registry {
 public:
  /// Registers `check` under `name`; throws std::logic_error for a name registered twice.
  void add(const std::string& name, check_function check) {
    if (!checks_.emplace(name, std::move(check)).second) throw std::logic_error("check '" + name + "' registered twice");
  }
  /// The check registered under `name`, or null.
  const check_function* find(const std::string& name) const {
    const auto it = checks_.find(name);
    return it == checks_.end() ? nullptr : &it->second;
  }
  const std::map<std::string, check_function>& all() const { return checks_; }

 private:
  std::map<std::string, check_function> checks_;
};

/// Every check of the ledger, registered once.
const check_registry& registered_checks();

}  // namespace simpson::verify::detail

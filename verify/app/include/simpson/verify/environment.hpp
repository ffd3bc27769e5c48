#pragma once
// What a report was built with: compiler, flags, library versions, git commit.

#include <simpson/verify/json.hpp>

namespace simpson::verify {

/// Compiler, flags, library versions and git commit of this build.
json build_environment();

}  // namespace simpson::verify

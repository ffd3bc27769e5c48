#pragma once
// The JSON type of every report and piece of evidence: nlohmann's, with members kept in the order
// they were written (so reports read in a fixed order and compare byte for byte).

#include <nlohmann/json.hpp>

namespace simpson::verify {

using json = nlohmann::ordered_json;

}  // namespace simpson::verify

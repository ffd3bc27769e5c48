// The digest of what a claim read (claim_reads.hpp).

#include <simpson/verify/claim_reads.hpp>
#include <simpson/verify/sha256.hpp>

namespace simpson::verify {

std::string reads_digest(const json& printed, const json& quoted) {
  std::string text;
  if (printed.is_object() && printed.contains("formulas") && printed["formulas"].is_array()) {
    for (const json& f : printed["formulas"]) text += "formula\n" + f.value("reference", std::string()) + "\n" + f.value("tex", std::string()) + "\n";
  }
  if (quoted.is_array()) {
    for (const json& q : quoted) text += "sentence\n" + q.value("pattern", std::string()) + "\n" + q.value("text", std::string()) + "\n";
  }
  return text.empty() ? std::string() : sha256_hex(text).substr(0, 16);
}

}  // namespace simpson::verify

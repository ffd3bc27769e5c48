// libFuzzer target: the claims-file reader must turn any input into records or a
// claims_file_error, never crash, hang, leak or throw anything else; and what it accepts must keep
// the file's rules (unique kebab-case ids, a class for every expected finding, causes that exist,
// one of a check, a shape with its arguments and an observed fact, a document with its title).

#include <simpson/verify/claims_file.hpp>

#include <cstddef>
#include <cstdint>
#include <set>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace simpson::verify;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const claims_file_contents contents =
        read_claims_contents(text, "fuzz", [](const std::string& field, const std::string& name) {
          if (field == "shape") return name == "identity";
          if (field == "observes") return name == "table1.printed-orders";
          return field == "check" ? name == "phi3-det" || name == "scaling" : name == "phi3-det";
        });
    const std::vector<claim_record>& records = contents.records;
    if (contents.document && contents.document->title.empty()) __builtin_trap();
    std::set<std::string> ids;
    for (const claim_record& r : records) {
      if (r.id.empty() || !ids.insert(r.id).second || r.line < 1) __builtin_trap();
      const bool is_finding = r.expected == verdict::erratum || r.expected == verdict::fails || r.expected == verdict::unverifiable;
      if (is_finding != (r.kind != finding::none)) __builtin_trap();
      if (!r.check.empty() + !r.shape.empty() + !r.observes.empty() != 1) __builtin_trap();  // one of the three
      if (!r.check.empty() && r.check != "phi3-det" && r.check != "scaling") __builtin_trap();
      if (!r.shape.empty() && r.shape != "identity") __builtin_trap();
      if (!r.observes.empty() && r.observes != "table1.printed-orders") __builtin_trap();
      if (r.shape.empty() && (!r.with.empty() || r.statement.empty())) __builtin_trap();
    }
    for (const claim_record& r : records) {
      if (!r.follows_from.empty() && !ids.count(r.follows_from)) __builtin_trap();
    }
  } catch (const claims_file_error&) {
  }
  return 0;
}

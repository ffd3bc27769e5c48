#include <simpson/verify/printed_statement.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace simpson::verify {

printed_statement printed_of(const claim_outcome& o) {
  const json& printed = o.result.printed;
  if (printed.is_null() || !printed.contains("formulas") || printed["formulas"].empty()) {
    std::string text, lines, source;
    for (const json& q : o.result.quoted) {
      if (!q.value("found", false)) continue;
      text += (text.empty() ? "" : " … ") + q.value("text", std::string());
      lines += (lines.empty() ? "" : ", ") + std::to_string(q.value("line", 0));
      source = q.value("source", std::string("?"));
    }
    if (!text.empty()) return {text, fmt::format("{}, line {}", source, lines), false, true};
    return {o.checked->statement, "typed from the prose", false};
  }
  std::string text, lines;
  std::vector<int> seen;
  for (const json& f : printed["formulas"]) {
    text += (text.empty() ? "" : " ; ") + f.value("tex", std::string());
    const int line = f.value("line", 0);
    if (line == 0 || std::find(seen.begin(), seen.end(), line) != seen.end()) continue;  // a record's own TeX; two formulas of one line
    seen.push_back(line);
    lines += (lines.empty() ? "" : ", ") + std::to_string(line);
  }
  const bool several = seen.size() > 1;
  return {text, fmt::format("{}, line{} {}", printed.value("source", std::string("?")), several ? "s" : "", lines), true};
}

}  // namespace simpson::verify

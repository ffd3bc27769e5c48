// The words a prose claim judges: see quoted_words.hpp.

#include <simpson/verify/quoted_words.hpp>

#include <simpson/verify/ledger.hpp>
#include <simpson/verify/paper_reading.hpp>

namespace simpson::verify {

const paper_reading& paper_of(const run_context& ctx) {
  if (ctx.paper != nullptr) return *ctx.paper;
  static const paper_reading embedded = read_paper(embedded_paper(), paper_book().declarations->reading);
  return embedded;
}

quoted_sentence quote(const run_context& ctx, const std::string& pattern) {
  return quote_sentence(paper_of(ctx).source, pattern, ctx.quotes);
}

}  // namespace simpson::verify
